// Asking the water where it is: heights and normals of the animated surface at the frame's time,
// and line-segment picking that meets the animated surface (the grid's CPU geometry is flat).
// Expectations from the wave formula evaluated here in long double, not from the kit's own code.
#include <osgWater/WaterNode>
#include <osg/MatrixTransform>
#include <osgUtil/IntersectionVisitor>
#include <osgUtil/LineSegmentIntersector>
#include "UpdateTraversal.h"
#include "WarnCapture.h"
#include <gtest/gtest.h>
#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

using namespace osgWater;
using testing_update::update;

namespace {

// h(x, y, t) = level + sum a sin(k (d . p) - sqrt(g k) t + phase)
long double waveHeight(const WaterSurface& s, long double x, long double y, long double t)
{
    const long double twoPi = 6.283185307179586476925286766559L;
    long double h = s.getLevel();
    for (const Wave& w : s.getWaves()) {
        const long double k = twoPi / (long double)w.wavelength;
        h += (long double)w.amplitude
             * std::sin(k * ((long double)w.direction.x() * x + (long double)w.direction.y() * y) - std::sqrt(9.81L * k) * t
                        + (long double)w.phase);
    }
    return h;
}

// the nearest hit of a segment in the node's frame, or false
bool pick(osg::Node* root, const osg::Vec3d& a, const osg::Vec3d& b, osgUtil::LineSegmentIntersector::Intersection& hit)
{
    osg::ref_ptr<osgUtil::LineSegmentIntersector> lsi = new osgUtil::LineSegmentIntersector(a, b);
    osgUtil::IntersectionVisitor iv(lsi.get());
    root->accept(iv);
    if (!lsi->containsIntersections()) return false;
    hit = lsi->getFirstIntersection();
    return true;
}

// The kit wraps each wave's phase omega t - phase in double and hands it on as a float, as the
// shader gets it: the heights it reports are the drawn surface's, within 2^-24 x 2 pi x the sum of
// the amplitudes of the exact wave sum (3e-8 m for the default waves)
const double kPhaseRounding = 1e-7;

}

TEST(Queries, HeightAndNormalFollowTheLastFramesTime)
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setLevel(1.5);
    EXPECT_EQ(water->getSimulationTime(), 0.0);
    update(water.get(), 12.25, 1);
    EXPECT_EQ(water->getSimulationTime(), 12.25);
    const WaterSurface& s = *water->getSurface();
    for (double x : { -30.0, -1.3, 0.0, 7.7, 42.0 })
        for (double y : { -12.0, 0.4, 25.5 }) {
            osg::Vec3d n;
            const double h = water->getSurfaceHeightAt(x, y, &n);
            EXPECT_NEAR(h, double(waveHeight(s, x, y, 12.25L)), kPhaseRounding) << x << ", " << y;
            // the normal is perpendicular to the surface: finite differences of the formula
            const long double e = 1e-4L;
            const long double hx = (waveHeight(s, x + e, y, 12.25L) - waveHeight(s, x - e, y, 12.25L)) / (2 * e);
            const long double hy = (waveHeight(s, x, y + e, 12.25L) - waveHeight(s, x, y - e, 12.25L)) / (2 * e);
            osg::Vec3d expected(-double(hx), -double(hy), 1.0);
            expected.normalize();
            EXPECT_NEAR(n.length(), 1.0, 1e-12);
            EXPECT_NEAR((n - expected).length(), 0.0, 1e-6) << x << ", " << y;
            // the overload with a time
            EXPECT_NEAR(water->getSurfaceHeightAt(x, y, 3.0), double(waveHeight(s, x, y, 3.0L)), kPhaseRounding);
        }
    // a user mesh: the level, straight up
    osg::ref_ptr<osg::Geometry> mesh = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    v->push_back(osg::Vec3(-5, -5, 1.5f)); v->push_back(osg::Vec3(5, -5, 1.5f)); v->push_back(osg::Vec3(0, 5, 1.5f));
    mesh->setVertexArray(v.get());
    mesh->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, 3));
    water->getSurface()->setMesh(mesh.get());
    osg::Vec3d n;
    EXPECT_EQ(water->getSurfaceHeightAt(1.0, 2.0, &n), 1.5);
    EXPECT_EQ(n, osg::Vec3d(0.0, 0.0, 1.0));
}

// A point that is no place (NaN or infinite coordinates) gets the level water's answer, under
// either wave model, and the user is told once, not once a query
TEST(Queries, NoPlaceAnswersTheLevelAndTheUpNormalAndSaysSoOnce)
{
    for (WaterSurface::WaveModel model : { WaterSurface::WAVES_SUM, WaterSurface::WAVES_WIND }) {
        osg::ref_ptr<WaterNode> water = new WaterNode;
        water->getSurface()->setLevel(2.5);
        water->getSurface()->setWaveModel(model);
        ScopedWarnCapture warnings;
        const double places[][2] = { { NAN, 1.0 }, { 1.0, INFINITY }, { -INFINITY, NAN } };
        for (const auto& p : places) {
            osg::Vec3d n;
            EXPECT_EQ(water->getSurfaceHeightAt(p[0], p[1], 3.0, &n), 2.5) << p[0] << ", " << p[1];
            EXPECT_EQ(n, osg::Vec3d(0.0, 0.0, 1.0)) << p[0] << ", " << p[1];
        }
        const std::string said = warnings.str();
        EXPECT_NE(said.find("no place"), std::string::npos) << said;
        EXPECT_EQ(said.find("no place"), said.rfind("no place")) << "said once: " << said;
        // a place still gets the waves
        EXPECT_NE(water->getSurfaceHeightAt(1.0, 2.0, 3.0), 2.5);
    }
}

TEST(Queries, QueriesAreSafeWhileFramesAdvance)
{
    // four threads query while the update traversal advances the time: every answer is the
    // surface at one of the frames' times
    osg::ref_ptr<WaterNode> water = new WaterNode;
    const WaterSurface& s = *water->getSurface();
    std::atomic<bool> done{ false };
    std::atomic<int> wrong{ 0 }, asked{ 0 };
    std::vector<std::thread> readers;
    for (int r = 0; r < 4; ++r)
        readers.emplace_back([&] {
            while (!done) {
                const double t = water->getSimulationTime();
                const double h = water->getSurfaceHeightAt(3.0, -2.0, t);
                if (std::fabs(h - double(waveHeight(s, 3.0L, -2.0L, t))) > kPhaseRounding) ++wrong;
                ++asked;
            }
        });
    for (unsigned int f = 1; f <= 2000 || asked < 10000; ++f) update(water.get(), f / 60.0, f);
    done = true;
    for (std::thread& t : readers) t.join();
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(asked, 0);
}

// The wind's cascades are one set of arrays brought to whichever time is asked. Threads asking at
// two times at once, heights and rays alike, must each get the surface at their own time: the
// same answers, bit for bit, as one thread asking alone. (The rays' march holds the cascades for
// its whole length, and a thread at the other time must wait for it, not change them under it.)
TEST(Queries, WindQueriesFromThreadsAtTwoTimesAreEachTheSurfaceAtTheirOwn)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    s->setWaveModel(WaterSurface::WAVES_WIND);
    const double times[2] = { 1.5, 7.25 };
    const int n = 16;
    auto place = [](int i) { return osg::Vec2d(-20.0 + 2.7 * i, 13.0 - 1.9 * i); };
    auto ray = [&](int i, osg::Vec3d& a, osg::Vec3d& b) {
        const osg::Vec2d p = place(i);
        a.set(p.x() - 15.0, p.y(), 0.4);
        b.set(p.x() + 15.0, p.y() + 3.0, -0.6);
    };
    double heights[2][n], hits[2][n];
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < n; ++i) {
            heights[k][i] = s->height(place(i).x(), place(i).y(), times[k]);
            osg::Vec3d a, b, point, normal;
            ray(i, a, b);
            ASSERT_TRUE(s->intersect(a, b, times[k], hits[k][i], point, normal)) << i;
        }
    ASSERT_NE(heights[0][0], heights[1][0]) << "the two times must differ in their waves";
    std::atomic<int> wrong{ 0 }, asked{ 0 };
    std::vector<std::thread> threads;
    for (int r = 0; r < 4; ++r)
        threads.emplace_back([&, r] {
            const int k = r % 2;
            for (int round = 0; round < 40; ++round)
                for (int i = 0; i < n; ++i) {
                    if (s->height(place(i).x(), place(i).y(), times[k]) != heights[k][i]) ++wrong;
                    osg::Vec3d a, b, point, normal;
                    double ratio = -1.0;
                    ray(i, a, b);
                    if (!s->intersect(a, b, times[k], ratio, point, normal) || ratio != hits[k][i]) ++wrong;
                    asked += 2;
                }
        });
    for (std::thread& t : threads) t.join();
    EXPECT_EQ(wrong, 0) << "of " << asked;
}

TEST(Queries, PickingMeetsTheAnimatedSurfaceNotTheFlatGrid)
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setLevel(0.5);
    water->getSurface()->setWaves({ Wave{ osg::Vec2(1, 0), 6.0f, 0.4f, 0.3f }, Wave{ osg::Vec2(0.6f, 0.8f), 2.5f, 0.1f, 1.0f } });
    update(water.get(), 7.5, 1);
    const WaterSurface& s = *water->getSurface();
    int hits = 0;
    for (double x = -20.0; x <= 20.0; x += 3.7)
        for (double y : { -15.0, 2.2, 18.0 }) {
            // vertical, oblique and grazing (1:20) rays from above
            const osg::Vec3d targets[] = { osg::Vec3d(x, y, -10), osg::Vec3d(x + 8, y - 3, -10), osg::Vec3d(x + 40, y, -1.5) };
            for (const osg::Vec3d& b : targets) {
                const osg::Vec3d a(x, y, 10);
                const osg::Vec3d a2 = b.z() > -5 ? osg::Vec3d(x, y, 0.5 + 0.5) : a;
                osgUtil::LineSegmentIntersector::Intersection hit;
                if (!pick(water.get(), a2, b, hit)) continue;
                ++hits;
                const osg::Vec3d p = hit.getWorldIntersectPoint();
                EXPECT_NEAR(p.z(), double(waveHeight(s, p.x(), p.y(), 7.5L)), 1e-6) << "not on the surface";
                // on the segment, and the first crossing: above the surface all the way before it
                EXPECT_NEAR((a2 + (b - a2) * hit.ratio - p).length(), 0.0, 1e-9);
                for (int i = 0; i < 200; ++i) {
                    const osg::Vec3d q = a2 + (b - a2) * (hit.ratio * i / 200.0);
                    EXPECT_GT(q.z(), double(waveHeight(s, q.x(), q.y(), 7.5L)) - 1e-9) << "an earlier crossing was missed";
                }
                osg::Vec3d n;
                water->getSurfaceHeightAt(p.x(), p.y(), &n);
                EXPECT_NEAR((hit.getWorldIntersectNormal() - n).length(), 0.0, 1e-9);
            }
        }
    EXPECT_GT(hits, 30);
    // from below, the first crossing from below; outside the grid's square, nothing
    osgUtil::LineSegmentIntersector::Intersection hit;
    ASSERT_TRUE(pick(water.get(), osg::Vec3d(1, 2, -3), osg::Vec3d(4, 2, 5), hit));
    EXPECT_NEAR(hit.getWorldIntersectPoint().z(), double(waveHeight(s, hit.getWorldIntersectPoint().x(), 2.0L, 7.5L)), 1e-6);
    EXPECT_FALSE(pick(water.get(), osg::Vec3d(80, 0, 10), osg::Vec3d(80, 0, -10), hit)) << "beyond the 100 m grid";
}

// A ray that clips a crest over a few centimetres (a horizontal ray 0.1 mm under the crests of a
// 4 m wave: a chord of 3.3 cm, an eighth of what the query once stepped near the water) meets that
// crest, from every start; 0.1 mm over the crests it meets nothing. Expected crossings from the
// sine in closed form: a sin(k x + phase) = a - delta first at k x + phase = pi/2 - acos(1 - delta / a).
TEST(Queries, ARayThatClipsACrestOverCentimetresMeetsIt)
{
    osg::ref_ptr<WaterSurface> surface = new WaterSurface;
    WaterSurface& s = *surface;
    s.setSize(200.0f);
    const Wave wave{ osg::Vec2(1, 0), 4.0f, 0.3f, 0.7f };
    s.setWaves({ wave });
    const double a = wave.amplitude, k = wave.wavenumber(), delta = 1e-4, t = 0.0;
    const double twoPi = 2.0 * osg::PI, into = std::acos(1.0 - delta / a);
    int met = 0;
    for (int i = 0; i < 97; ++i) {
        const double x0 = -30.0 + i * 0.0413 * twoPi / k; // starts all along the wave's cycle
        const double phase0 = k * x0 + double(wave.phase);
        // the first crest band ahead of the start (a start inside one is above the ray: skipped)
        double centre = osg::PI / 2 + twoPi * std::ceil((phase0 - osg::PI / 2) / twoPi);
        if (centre - into < phase0) continue;
        const double expected = x0 + (centre - into - phase0) / k;
        double ratio;
        osg::Vec3d point, normal;
        const osg::Vec3d from(x0, 1.0, a - delta), to(x0 + 20.0, 1.0, a - delta);
        ASSERT_TRUE(s.intersect(from, to, t, ratio, point, normal)) << "from x = " << x0;
        EXPECT_NEAR(point.x(), expected, 1e-6) << "from x = " << x0 << ": a clipped crest was passed";
        ++met;
        EXPECT_FALSE(s.intersect(osg::Vec3d(x0, 1.0, a + delta), osg::Vec3d(x0 + 20.0, 1.0, a + delta), t, ratio, point, normal))
            << "from x = " << x0 << ": nothing rises above the crests";
    }
    EXPECT_GT(met, 80);
}

// Under the wind's waves picking meets the same sampled surface the height query reads (whose
// texels WaveCascades.* check against the spectrum's direct sums), at its first crossing
TEST(Queries, PickingMeetsTheWindsWavesAtTheirFirstCrossing)
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setLevel(0.5);
    WindWaves wind;
    wind.speed = 8.0f;
    water->getSurface()->setWind(wind);
    water->getSurface()->setWaveModel(WaterSurface::WAVES_WIND);
    update(water.get(), 4.0, 1);
    const WaterSurface& s = *water->getSurface();
    int hits = 0;
    for (double x = -20.0; x <= 20.0; x += 5.3)
        for (double y : { -15.0, 2.2 }) {
            // vertical, oblique and grazing (1:20) rays from above
            const osg::Vec3d a(x, y, 0.5 + 0.4), targets[] = { osg::Vec3d(x, y, -10), osg::Vec3d(x + 8, y - 3, -10),
                                                               osg::Vec3d(x + 20, y, 0.5 - 0.6) };
            for (const osg::Vec3d& b : targets) {
                osgUtil::LineSegmentIntersector::Intersection hit;
                if (!pick(water.get(), a, b, hit)) continue;
                ++hits;
                const osg::Vec3d p = hit.getWorldIntersectPoint();
                EXPECT_NEAR(p.z(), s.height(p.x(), p.y(), 4.0), 1e-6) << "not on the surface";
                for (int i = 0; i < 400; ++i) {
                    const osg::Vec3d q = a + (b - a) * (hit.ratio * i / 400.0);
                    EXPECT_GT(q.z(), s.height(q.x(), q.y(), 4.0) - 1e-9) << "an earlier crossing was missed";
                }
                osg::Vec3d n;
                water->getSurfaceHeightAt(p.x(), p.y(), &n);
                EXPECT_NEAR((hit.getWorldIntersectNormal() - n).length(), 0.0, 1e-9);
            }
        }
    EXPECT_GE(hits, 20);
}

TEST(Queries, PickingThroughATransformReportsWorldPoints)
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    osg::ref_ptr<osg::MatrixTransform> moved = new osg::MatrixTransform(osg::Matrixd::translate(100.0, -50.0, 3.0));
    moved->addChild(water.get());
    update(moved.get(), 2.0, 1);
    osgUtil::LineSegmentIntersector::Intersection hit;
    ASSERT_TRUE(pick(moved.get(), osg::Vec3d(104, -47, 20), osg::Vec3d(104, -47, -20), hit));
    const osg::Vec3d p = hit.getWorldIntersectPoint();
    EXPECT_NEAR(p.x(), 104.0, 1e-9);
    EXPECT_NEAR(p.z(), 3.0 + double(waveHeight(*water->getSurface(), 4.0L, 3.0L, 2.0L)), 1e-6);
}
