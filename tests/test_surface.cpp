// WaterSurface: the thesis's grid, analytic normals, amplitude, huge times.
#include <osgWater/WaterSurface>
#include "surface/WaveCascades.h"
#include <gtest/gtest.h>
#include <cmath>
#include <limits>

using namespace osgWater;

TEST(Surface, TheGridLayoutIsTheThesisMesh)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    s->setMeshLayout(WaterSurface::MESH_GRID);
    osg::Geometry* g = s->getGeometry();
    ASSERT_TRUE(g);
    ASSERT_EQ(s->getNumDrawables(), 1u);
    EXPECT_EQ(g->getVertexArray()->getNumElements(), 2401u);                 // 49 x 49
    EXPECT_EQ(g->getPrimitiveSet(0)->getNumIndices() / 3, 4608u);            // 2 x 48 x 48
    EXPECT_TRUE(s->usesGrid());
}

// the default: rings around the eye. Their CPU vertices (what a polytope intersector or the
// statistics read) lie flat at the level, rings evenly spaced out to the square's corners, from
// which water.vert reads each vertex's ring and direction back; the bound is the square
TEST(Surface, TheDefaultLayoutIsRingsAroundTheEye)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    s->setSize(40.0f);
    s->setCenter(osg::Vec2(10.0f, -5.0f));
    s->setLevel(2.0);
    EXPECT_EQ(s->getMeshLayout(), WaterSurface::MESH_EYE_RINGS);
    osg::Geometry* g = s->getGeometry();
    ASSERT_TRUE(g);
    const unsigned int m = WaterSurface::RING_SEGMENTS, n = WaterSurface::RING_COUNT;
    const osg::Vec3Array* v = dynamic_cast<const osg::Vec3Array*>(g->getVertexArray());
    ASSERT_TRUE(v);
    ASSERT_EQ(v->size(), (n + 1) * m);
    EXPECT_EQ(g->getNumTexCoordArrays(), 0u); // one array (see WaterSurface::buildRings)
    EXPECT_EQ(g->getPrimitiveSet(0)->getNumIndices() / 3, 2u * n * m);
    const double spacing = 20.0 * std::sqrt(2.0) / n;
    for (unsigned int i = 0; i <= n; ++i)
        for (unsigned int j = 0; j < m; ++j) {
            const osg::Vec3& p = (*v)[i * m + j];
            EXPECT_FLOAT_EQ(p.z(), 2.0f);
            const osg::Vec2d d(p.x() - 10.0, p.y() + 5.0);
            // the shader's reading: the ring to the nearest whole spacing (float: well within a half)
            EXPECT_NEAR(d.length() / spacing, double(i), 1e-4) << i << " " << j;
            if (i > 0) EXPECT_NEAR(std::atan2(d.y(), d.x()), std::remainder(2.0 * osg::PI * j / m, 2.0 * osg::PI), 1e-5);
        }
    // the bound is the square between troughs and crests, not the disc the vertex array reaches
    const osg::BoundingBox& b = g->getBoundingBox();
    EXPECT_NEAR(b.xMin(), -10.0f, 1e-4f);
    EXPECT_NEAR(b.xMax(), 30.0f, 1e-4f);
    EXPECT_NEAR(b.yMax(), 15.0f, 1e-4f);
    EXPECT_NEAR(b.zMax(), 2.0f + s->getMaxAmplitude(), 1e-4f);
}

// each ring spans the same angle from the eye, at any height: the cell, over its distance from
// the eye, is the radial growth c, which is the larger of what takes the last ring to the reach
// and the angle between segments (a ring is never thinner than its cells are wide: past the reach,
// the square's edge holds the rest)
TEST(Surface, EveryRingCellSpansAboutTheSameAngleFromTheEye)
{
    for (double height : { 0.0, 1e-6, 0.5, 4.5, 48.0, 500.0 })
        for (double reach : { 5.0, 99.0, 3000.0 }) {
            const double h = std::max(height, WaterSurface::RING_INNER_HEIGHT);
            const double around = 2.0 * osg::PI / WaterSurface::RING_SEGMENTS;
            const double c = std::max(std::asinh(reach / h) / WaterSurface::RING_COUNT, around);
            EXPECT_DOUBLE_EQ(WaterSurface::ringRadius(0, height, reach), 0.0);
            EXPECT_GE(WaterSurface::ringRadius(WaterSurface::RING_COUNT, height, reach), reach * (1.0 - 1e-9));
            if (std::asinh(reach / h) / WaterSurface::RING_COUNT >= around) // the last ring is the reach
                EXPECT_NEAR(WaterSurface::ringRadius(WaterSurface::RING_COUNT, height, reach), reach, 1e-9 * reach);
            else // the rings in use end at the first past the reach
                EXPECT_LT(WaterSurface::ringRadius(unsigned(std::ceil(std::asinh(reach / h) / c)) - 1, height, reach), reach);
            double last = -1.0;
            for (unsigned int i = 0; i <= WaterSurface::RING_COUNT; ++i) {
                const double r = WaterSurface::ringRadius(i, height, reach);
                EXPECT_GT(r, last);
                last = r;
                const double distance = std::sqrt(r * r + h * h);
                const double angle = WaterSurface::ringCellSize(i, height, reach) / distance;
                EXPECT_NEAR(angle, c, 1e-9 * c) << height << " " << reach << " " << i;
                EXPECT_GE(angle, around * (1.0 - 1e-9));
                if (i + 1 <= WaterSurface::RING_COUNT) // the next ring is one radial cell out (to first order)
                    EXPECT_NEAR(WaterSurface::ringRadius(i + 1, height, reach) - r, c * distance, 0.05 * c * distance + 1e-12);
            }
        }
}

TEST(Surface, RingsFadeWavesTheirCellsCannotResolve)
{
    EXPECT_DOUBLE_EQ(WaterSurface::ringWaveFade(4.0, 1.0), 1.0);
    EXPECT_DOUBLE_EQ(WaterSurface::ringWaveFade(40.0, 1.0), 1.0);
    EXPECT_DOUBLE_EQ(WaterSurface::ringWaveFade(2.0, 1.0), 0.0); // Nyquist: gone
    EXPECT_DOUBLE_EQ(WaterSurface::ringWaveFade(1.0, 1.0), 0.0);
    EXPECT_DOUBLE_EQ(WaterSurface::ringWaveFade(3.0, 1.0), 0.5);
    EXPECT_DOUBLE_EQ(WaterSurface::ringWaveFade(6.0, 2.0), 0.5); // cells per wave is what counts
    double last = 0.0;
    for (double cells = 2.0; cells <= 4.0; cells += 0.1) {
        EXPECT_GE(WaterSurface::ringWaveFade(cells, 1.0), last);
        last = WaterSurface::ringWaveFade(cells, 1.0);
    }
    EXPECT_DOUBLE_EQ(WaterSurface::ringWaveFade(1.0, 0.0), 1.0); // a point: nothing to fade
}

// reading a file sets level, size, centre, resolution and waves one by one: the grid is built once,
// when something needs it, and the bound and traversals always see the latest values
TEST(Surface, GridIsBuiltWhenNeededFromTheLatestValues)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    s->setMeshLayout(WaterSurface::MESH_GRID);
    s->setResolution(1025);
    s->setSize(10.0f);
    s->setLevel(5.0);
    s->setCenter(osg::Vec2(100.0f, 0.0f));
    s->setResolution(3);
    EXPECT_EQ(s->getNumDrawables(), 0u); // nothing built yet, not even the 1025 x 1025 grid
    const osg::BoundingSphere bs = s->getBound(); // the bound builds it
    EXPECT_NEAR(bs.center().x(), 100.0f, 1e-4f);
    EXPECT_NEAR(bs.center().z(), 5.0f, 1e-4f);
    ASSERT_EQ(s->getNumDrawables(), 1u);
    EXPECT_EQ(s->getDrawable(0)->asGeometry()->getVertexArray()->getNumElements(), 9u);
    s->setLevel(-2.0); // a change after the build: the bound follows
    EXPECT_NEAR(s->getBound().center().z(), -2.0f, 1e-4f);
    EXPECT_NEAR(s->getGeometry()->getBoundingBox().center().z(), -2.0f, 1e-4f);
}

// an animation may set the waves every frame: the mesh stays (the shaders displace it), its bound follows
TEST(Surface, NewWavesKeepTheMeshAndGrowItsBound)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    osg::Geometry* before = s->getGeometry();
    std::vector<Wave> waves = defaultWaves();
    waves[0].amplitude = 2.0f;
    s->setWaves(waves);
    EXPECT_EQ(s->getGeometry(), before);
    EXPECT_NEAR(before->getBoundingBox().zMax(), s->getMaxAmplitude(), 1e-5f);
    EXPECT_NEAR(s->getBound().radius(), osg::Vec3(50.0f, 50.0f, s->getMaxAmplitude()).length(), 1e-3f);
}

TEST(Surface, MaxAmplitudeBoundsTheHeight)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    s->setLevel(2.0);
    const float a = s->getMaxAmplitude();
    EXPECT_NEAR(a, 0.075f, 1e-6f);
    double hmax = 0.0;
    for (double x = -20.0; x < 20.0; x += 0.37)
        for (double y = -20.0; y < 20.0; y += 0.41) hmax = std::max(hmax, std::fabs(s->height(x, y, 3.7) - 2.0));
    EXPECT_LE(hmax, a + 1e-9);
    EXPECT_GT(hmax, 0.5 * a);
    // the drawable's bound includes the crests and troughs the vertex shader makes
    const osg::BoundingBox& bb = s->getGeometry()->getBoundingBox();
    EXPECT_LE(bb.zMin(), 2.0f - a + 1e-5f);
    EXPECT_GE(bb.zMax(), 2.0f + a - 1e-5f);
}

TEST(Surface, MaxSlopeBoundsTheGradientAndIsTightForSimpleWaves)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    auto wave = [](float dx, float dy, float length, float a) {
        Wave w;
        w.direction.set(dx, dy);
        w.wavelength = length;
        w.amplitude = a;
        return w;
    };
    const double c = 0.05 * 2.0 * osg::PI / 4.0; // a k of a 4 m wave 5 cm high
    s->setWaves({ wave(1, 0, 4, 0.05f) });
    EXPECT_NEAR(s->getMaxSlope(), c, 0.01 * c) << "one wave: a k";
    s->setWaves({ wave(1, 0, 4, 0.05f), wave(1, 0, 4, 0.05f) });
    EXPECT_NEAR(s->getMaxSlope(), 2 * c, 0.01 * c) << "parallel: the sum";
    s->setWaves({ wave(1, 0, 4, 0.05f), wave(0, 1, 4, 0.05f) });
    EXPECT_NEAR(s->getMaxSlope(), std::sqrt(2.0) * c, 0.01 * c) << "crossed: both at their peaks, sqrt 2 a k";

    // the default waves: every gradient on a fine sampling of space and time stays within the bound
    s = new WaterSurface;
    const double bound = s->getMaxSlope();
    double sum = 0.0, steepest = 0.0;
    for (const Wave& w : s->getWaves()) sum += w.amplitude * w.wavenumber();
    for (double t = 0.0; t < 20.0; t += 1.3)
        for (double x = -20.0; x < 20.0; x += 0.23)
            for (double y = -20.0; y < 20.0; y += 0.29) {
                const osg::Vec3d n = s->normal(x, y, t);
                steepest = std::max(steepest, std::sqrt(n.x() * n.x() + n.y() * n.y()) / n.z());
            }
    EXPECT_LE(steepest, bound);
    EXPECT_LE(bound, sum) << "never looser than the sum of the slopes";
    osg::ref_ptr<osg::Geometry> mesh = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    v->push_back(osg::Vec3(0, 0, 0));
    v->push_back(osg::Vec3(1, 0, 0));
    v->push_back(osg::Vec3(0, 1, 0));
    mesh->setVertexArray(v.get());
    mesh->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, 3));
    s->setMesh(mesh.get());
    ASSERT_FALSE(s->usesGrid());
    EXPECT_EQ(s->getMaxSlope(), 1.0) << "a user mesh: 45 degrees";
}

TEST(Surface, NormalsAreTheAnalyticGradient)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    const double h = 1e-5, t = 12.25;
    for (double x = -3.0; x < 3.0; x += 1.1)
        for (double y = -2.0; y < 2.0; y += 0.9) {
            const double hx = (s->height(x + h, y, t) - s->height(x - h, y, t)) / (2 * h);
            const double hy = (s->height(x, y + h, t) - s->height(x, y - h, t)) / (2 * h);
            osg::Vec3d fd(-hx, -hy, 1.0);
            fd.normalize();
            const osg::Vec3d n = s->normal(x, y, t);
            EXPECT_NEAR((n - fd).length(), 0.0, 1e-6);
        }
}

TEST(Surface, HugeTimesStayFiniteAndPeriodic)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    for (double t : { 0.0, 1e6, 1e9, 1e12, 1e300 }) {
        for (unsigned int i = 0; i < s->getWaves().size(); ++i) {
            const float p = s->wrappedPhase(i, t);
            EXPECT_GE(p, 0.0f);
            EXPECT_LT(p, 6.2832f);
        }
        EXPECT_TRUE(std::isfinite(s->height(1.0, 2.0, t)));
    }
    EXPECT_TRUE(std::isfinite(s->height(1.0, 2.0, NAN)));
    EXPECT_TRUE(std::isfinite(s->height(1.0, 2.0, INFINITY)));
}

TEST(Surface, UserMeshReplacesTheGrid)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    v->push_back(osg::Vec3(0, 0, 0.0f));
    v->push_back(osg::Vec3(1, 0, 0.2f));
    v->push_back(osg::Vec3(0, 1, -0.1f));
    g->setVertexArray(v.get());
    g->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, 3));
    s->setMesh(g.get());
    EXPECT_FALSE(s->usesGrid());
    EXPECT_EQ(s->getGeometry(), g.get());
    EXPECT_NEAR(s->getMaxAmplitude(), 0.2f, 1e-6f);
    s->setMesh(nullptr);
    EXPECT_TRUE(s->usesGrid());
}

TEST(Surface, BadParametersAreClamped)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    s->setResolution(0);
    EXPECT_EQ(s->getResolution(), 2u);
    s->setSize(NAN);
    EXPECT_GT(s->getSize(), 0.0f);
    std::vector<Wave> w(12);
    w[0].wavelength = NAN;
    w[1].amplitude = -1.0f;
    w[2].direction.set(0.0f, 0.0f);
    s->setWaves(w);
    EXPECT_EQ(s->getWaves().size(), WaterSurface::MAX_WAVES);
    EXPECT_GT(s->getWaves()[0].wavelength, 0.0f);
    EXPECT_EQ(s->getWaves()[1].amplitude, 0.0f);
    EXPECT_NEAR(s->getWaves()[2].direction.length(), 1.0f, 1e-6f);
    EXPECT_TRUE(std::isfinite(s->height(0.5, 0.5, 1.0)));
}

// The waves' phase omega t is computed in double precision on the CPU and wrapped before it
// reaches the GPU: at t = 1e7 s the surface must still match an evaluation in long double.
TEST(Surface, AtTenMillionSecondsTheSurfaceMatchesALongDoubleEvaluation)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    s->setLevel(2.5);
    const long double twoPi = 6.283185307179586476925286766559L, g = 9.81L;
    for (double t : { 1.0e7, 1.0e7 + 0.37, 9.87654321e6 })
        for (double x = -40.0; x <= 40.0; x += 13.7)
            for (double y = -40.0; y <= 40.0; y += 11.3) {
                long double h = 2.5L;
                for (const Wave& w : s->getWaves()) {
                    const long double k = twoPi / (long double)w.wavelength;
                    const long double omega = std::sqrt(g * k);
                    h += (long double)w.amplitude
                         * std::sin(k * ((long double)w.direction.x() * x + (long double)w.direction.y() * y)
                                    - omega * (long double)t + (long double)w.phase);
                }
                EXPECT_NEAR(s->height(x, y, t), double(h), 1.0e-3) << "t " << t << " at " << x << ", " << y;
                EXPECT_NEAR(s->height(x, y, t), double(h), 1.0e-5) << "well inside the 1 mm bound";
            }
}

TEST(Surface, WavesTileOverASquareWhenEachRunsWholeCyclesAlongBothAxes)
{
    const double tile = 4.0;
    auto wave = [](float dx, float dy, float wavelength) {
        Wave w;
        w.direction.set(dx, dy);
        w.wavelength = wavelength;
        w.amplitude = 0.1f;
        return w;
    };
    EXPECT_TRUE(WaterSurface::wavesTileOver({ wave(1, 0, 2.0f) }, tile)) << "two cycles along x";
    EXPECT_TRUE(WaterSurface::wavesTileOver({ wave(0.6f, 0.8f, 0.8f) }, tile)) << "3 along x, 4 along y";
    EXPECT_TRUE(WaterSurface::wavesTileOver({ wave(1, 0, 2.0f), wave(0, -1, 4.0f / 3.0f) }, tile));
    EXPECT_FALSE(WaterSurface::wavesTileOver({ wave(1, 0, 1.7f) }, tile)) << "2.35 cycles";
    EXPECT_FALSE(WaterSurface::wavesTileOver({ wave(0.6f, 0.8f, 2.0f) }, tile)) << "1.2 and 1.6 cycles";
    EXPECT_FALSE(WaterSurface::wavesTileOver({ wave(1, 0, 2.0f) }, 0.0)) << "no tile";
    Wave still = wave(1, 0, 1.7f);
    still.amplitude = 0.0f;
    EXPECT_TRUE(WaterSurface::wavesTileOver({ still }, tile)) << "a still wave repeats over anything";
}

TEST(Surface, WavesSnappedToATileRepeatOverItAndStayClose)
{
    const double tile = 8.0;
    const std::vector<Wave> lake = defaultWaves(); // none of which repeats over 8 m
    ASSERT_FALSE(WaterSurface::wavesTileOver(lake, tile));
    const std::vector<Wave> snapped = WaterSurface::wavesSnappedToTile(lake, tile);
    ASSERT_EQ(snapped.size(), lake.size());
    EXPECT_TRUE(WaterSurface::wavesTileOver(snapped, tile));
    for (size_t i = 0; i < lake.size(); ++i) {
        const osg::Vec2 k0 = lake[i].direction * float(1.0 / lake[i].wavelength);
        const osg::Vec2 k1 = snapped[i].direction * float(1.0 / snapped[i].wavelength);
        // rounded to the lattice of 1 / 8 m cycles: at most half a step off along each axis
        EXPECT_LE(std::fabs(k1.x() - k0.x()), 0.5 / tile + 1e-6) << i;
        EXPECT_LE(std::fabs(k1.y() - k0.y()), 0.5 / tile + 1e-6) << i;
        EXPECT_NEAR(snapped[i].direction.length(), 1.0f, 1e-6f);
        EXPECT_EQ(snapped[i].amplitude, lake[i].amplitude);
        EXPECT_EQ(snapped[i].phase, lake[i].phase);
    }
    Wave longWave = lake[0];
    longWave.wavelength = 50.0f; // longer than the tile: one cycle over it
    const Wave s = WaterSurface::wavesSnappedToTile({ longWave }, tile)[0];
    EXPECT_NEAR(s.wavelength, 8.0f, 1e-5f);
    EXPECT_NEAR(s.direction.x(), 1.0f, 1e-6f);
}

// The wind's waves: the surface answers from the cascades of its wind over its own square (the
// fetch, by default, the water's size), about its level; a still wind is flat water; bad winds
// are clamped.
TEST(Surface, TheWindsWavesAreTheCascadesOfItsWindOverItsSquare)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    s->setSize(140.0f);
    s->setLevel(1.5);
    WindWaves wind;
    wind.speed = 6.0f;
    wind.direction.set(0.0f, 2.0f); // normalised
    wind.seed = 4;
    s->setWind(wind);
    EXPECT_EQ(s->getWind().direction, osg::Vec2(0.0f, 1.0f));
    EXPECT_EQ(s->getWaveModel(), WaterSurface::WAVES_SUM); // the sum stays the default
    const double sumHeight = s->height(3.0, 4.0, 2.0);
    s->setWaveModel(WaterSurface::WAVES_WIND);
    // the spectrum's own: a 6 m/s wind towards +y over 140 m
    WaveCascades::Params p;
    p.sea.windSpeed = 6.0;
    p.sea.fetch = 140.0;
    p.sea.windDirection = 0.5 * osg::PI;
    p.extent = 140.0;
    p.seed = 4;
    WaveCascades cascades(p);
    double spread = 0.0;
    for (double t : { 2.0, 2.5, 1.0e6 })
        for (double x : { -60.0, 3.0, 41.7 }) {
            cascades.update(t);
            EXPECT_NEAR(s->height(x, 4.0, t), 1.5 + cascades.height(x, 4.0), 1e-6) << x << " at " << t;
            const osg::Vec3d n = s->normal(x, 4.0, t), m = cascades.normal(x, 4.0);
            EXPECT_NEAR((n - m).length(), 0.0, 1e-6);
            spread = std::max(spread, std::fabs(s->height(x, 4.0, t) - 1.5));
        }
    EXPECT_NE(s->height(3.0, 4.0, 2.0), sumHeight);
    EXPECT_GT(spread, 1e-3); // waves, not a flat sheet
    // the bounds: six standard deviations of the bins' heights and slopes
    EXPECT_NEAR(s->getMaxAmplitude(), 6.0 * std::sqrt(cascades.binVariance()), 1e-6);
    EXPECT_NEAR(s->getMaxSlope(), 6.0 * std::sqrt(cascades.binSlopeVariance()), 1e-6);
    EXPECT_NEAR(s->getMaxPhaseSpeed(), cascades.maxPhaseSpeed(), 1e-9);
    EXPECT_GT(s->getMaxAmplitude(), spread);
    // the shortest wave: the wind's cascades reach down to where their slopes make Cox and Munk's
    // (6 cm ripples on this lake; the sum's, its 1.3 m wave)
    EXPECT_NEAR(s->getShortestWavelength(), WaveCascades::shortestWave(p.sea), 1e-9);
    EXPECT_GT(s->getShortestWavelength(), WaveCascades::SHORTEST_WAVE);
    s->setWaveModel(WaterSurface::WAVES_SUM);
    EXPECT_FLOAT_EQ(float(s->getShortestWavelength()), 1.3f);
    s->setWaveModel(WaterSurface::WAVES_WIND);

    // no wind: flat water at the level, nothing to clear
    wind.speed = 0.0f;
    s->setWind(wind);
    EXPECT_EQ(s->height(3.0, 4.0, 2.0), 1.5);
    EXPECT_EQ(s->getMaxAmplitude(), 0.0f);
    EXPECT_EQ(s->getShortestWavelength(), 0.0);
}

TEST(Surface, BadWindsAreClamped)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    WindWaves w;
    w.speed = std::nanf("");
    w.direction.set(0.0f, 0.0f);
    w.fetch = -3.0f;
    w.depth = std::numeric_limits<float>::infinity();
    w.spread = 7.0f;
    w.swell = std::nanf("");
    w.choppiness = 5.0f;
    s->setWind(w);
    const WindWaves& used = s->getWind();
    EXPECT_EQ(used.speed, 5.0f);
    EXPECT_EQ(used.direction, osg::Vec2(1.0f, 0.0f));
    EXPECT_EQ(used.fetch, 0.0f);
    EXPECT_EQ(used.depth, 1.0e5f);
    EXPECT_EQ(used.spread, 1.0f);
    EXPECT_EQ(used.swell, 0.0f);
    EXPECT_EQ(used.choppiness, 1.0f);
    w = WindWaves();
    w.choppiness = std::nanf("");
    s->setWind(w);
    EXPECT_EQ(s->getWind().choppiness, 0.0f);
    w.speed = 1.0e6f;
    s->setWind(w);
    EXPECT_EQ(s->getWind().speed, 40.0f);
    s->setWaveModel(WaterSurface::WaveModel(7));
    EXPECT_EQ(s->getWaveModel(), WaterSurface::WAVES_SUM);
    s->setWaveModel(WaterSurface::WAVES_WIND);
    EXPECT_TRUE(std::isfinite(s->height(1.0, 2.0, 3.0)));
    EXPECT_EQ(s->height(std::nan(""), 2.0, 3.0), 0.0);
}
