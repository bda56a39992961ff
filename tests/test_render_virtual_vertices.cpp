// Refraction by virtual vertices drawn on the GPU (WaterSettings::VIRTUAL_VERTICES): the refraction
// pass draws a finely tessellated checkerboard bed where it appears through the water. On flat water
// the drawn image must be Snell's within half a pixel; over a gentle wave each shown point must lie
// where the CPU mirror (osgWater/optics/VirtualVertices.h, double precision) puts its virtual vertex. The pass
// targets are the view's size, so a texel is a pixel.
#include "GLHarness.h"
#include <osgWater/WaterNode>
#include "optics/VirtualVertices.h"
#include "optics/Srgb.h"
#include <algorithm>
#include <cmath>
#include <vector>

using namespace testing_gl;
using namespace osgWater;

namespace {

const float kDepth = 2.0f, kCell = 0.5f;
const double kEta = 1.0 / 1.333;

struct VirtualScene {
    Harness h;
    osg::ref_ptr<WaterNode> water = new WaterNode;
    osg::Vec3d eye{ 0, -4, 3 };

    explicit VirtualScene(const std::vector<Wave>& waves) : h(200, 150)
    {
        if (!h.ok()) return;
        water->getSurface()->setWaves(waves);
        water->getSurface()->setSize(400.0f);
        WaterSettings* s = water->getSettings();
        s->setReflectionEnabled(false); // F = 0: the water shows the refracted bed alone
        s->setAttenuation(0.0f);        // no water colour mixed in
        s->setCausticsEnabled(false);
        s->setRefractionLookup(WaterSettings::VIRTUAL_VERTICES);
        s->setPassTargetScale(1.0f);    // a texel of the pass is a pixel of the view
        // 0.25 m quads: the bed's own triangles bend little under the water's warp
        water->addChild(checkerPlane(-kDepth, 40.0f, kCell, 160));
        h.setScene(water.get());
        h.lookAt(eye, osg::Vec3d(0, 6, -2));
    }

    // the unit eye ray through pixel coordinates (px, py) (pixel centres at + 0.5)
    osg::Vec3d ray(double px, double py)
    {
        const osg::Matrixd inv = osg::Matrixd::inverse(h.camera()->getViewMatrix() * h.camera()->getProjectionMatrix());
        const double nx = px / h.width() * 2 - 1, ny = py / h.height() * 2 - 1;
        osg::Vec3d d = osg::Vec3d(nx, ny, 1) * inv - osg::Vec3d(nx, ny, -1) * inv;
        d.normalize();
        return d;
    }

    // Snell on flat water in double precision, independent of the kit: the bed point seen at (px, py)
    bool flatHit(double px, double py, osg::Vec3d& X)
    {
        const osg::Vec3d d = ray(px, py);
        if (d.z() > -0.1) return false;
        const osg::Vec3d U = eye + d * (-eye.z() / d.z());
        const double ci = -d.z(), k = 1.0 - kEta * kEta * (1.0 - ci * ci);
        const osg::Vec3d R = d * kEta + osg::Vec3d(0, 0, 1) * (kEta * ci - std::sqrt(k));
        X = U + R * ((-kDepth - U.z()) / R.z());
        return std::fabs(X.x()) < 18.0 && std::fabs(X.y()) < 18.0; // well inside the bed
    }

    // where a point appears in the view, pixel coordinates
    osg::Vec2d project(const osg::Vec3d& p)
    {
        const osg::Vec4d c = osg::Vec4d(p, 1.0) * h.camera()->getViewMatrix() * h.camera()->getProjectionMatrix();
        return osg::Vec2d((c.x() / c.w() * 0.5 + 0.5) * h.width(), (c.y() / c.w() * 0.5 + 0.5) * h.height());
    }
};

double quantile(std::vector<double> v, double q)
{
    if (v.empty()) return 1e9;
    std::sort(v.begin(), v.end());
    return v[size_t(q * (v.size() - 1))];
}

}

TEST(RenderVirtualVertices, OnFlatWaterTheCheckerboardIsDrawnWithinHalfAPixelOfSnell)
{
    VirtualScene sc({});
    REQUIRE_GL(sc.h);
    // the true place of what each pixel shows (debug output, a = 4) against Snell's hit there, in
    // pixels: through the inverse of the bed's Jacobian with respect to the pixel
    sc.water->setDebugOutput(DEBUG_BOTTOM_HIT);
    sc.h.frame(0.0);
    osg::ref_ptr<osg::Image> shown = sc.h.readColor();
    ASSERT_TRUE(allFinite(shown.get()));
    std::vector<double> errPx;
    int notShown = 0;
    for (int y = 0; y < sc.h.height(); ++y)
        for (int x = 0; x < sc.h.width(); ++x) {
            osg::Vec3d X, Xx, Xy;
            if (!sc.flatHit(x + 0.5, y + 0.5, X) || !sc.flatHit(x + 1.5, y + 0.5, Xx) || !sc.flatHit(x + 0.5, y + 1.5, Xy))
                continue;
            const float* w = pixel(shown.get(), x, y);
            if (!(w[3] > 3.5f && w[3] < 4.5f)) { ++notShown; continue; }
            const osg::Vec3d e = osg::Vec3d(w[0], w[1], w[2]) - X, a = Xx - X, b = Xy - X;
            const double det = a.x() * b.y() - a.y() * b.x();
            errPx.push_back(std::hypot((e.x() * b.y() - e.y() * b.x()) / det, (a.x() * e.y() - a.y() * e.x()) / det));
        }
    ASSERT_GT(errPx.size(), 10000u);
    EXPECT_EQ(notShown, 0);
    std::printf("virtual vertices on flat water: %zu pixels, error median %.4f px, p99 %.4f px, max %.4f px\n",
                errPx.size(), quantile(errPx, 0.5), quantile(errPx, 0.99), quantile(errPx, 1.0));
    // tolerance: half a pixel everywhere but at 0.1% of the pixels (the bed's seams); the solved
    // sight point is exact on flat water, what is left is the 0.25 m triangles' linear warp and float
    EXPECT_LT(quantile(errPx, 0.999), 0.5);
    EXPECT_LT(quantile(errPx, 0.5), 0.1);

    // the colours: every pixel whose Snell point lies more than half a pixel from a cell's edge
    // shows that cell
    sc.water->setDebugOutput(DEBUG_NONE);
    sc.h.frame(0.0);
    osg::ref_ptr<osg::Image> img = sc.h.readColor();
    int checked = 0, wrong = 0;
    for (int y = 0; y < sc.h.height(); ++y)
        for (int x = 0; x < sc.h.width(); ++x) {
            osg::Vec3d X;
            if (!sc.flatHit(x + 0.5, y + 0.5, X)) continue;
            const float c = checkerAt(X.x(), X.y(), kCell);
            bool nearEdge = false;
            for (const osg::Vec2d& o : { osg::Vec2d(-0.5, 0), osg::Vec2d(0.5, 0), osg::Vec2d(0, -0.5), osg::Vec2d(0, 0.5) }) {
                osg::Vec3d Y;
                nearEdge = nearEdge || !sc.flatHit(x + 0.5 + o.x(), y + 0.5 + o.y(), Y) || checkerAt(Y.x(), Y.y(), kCell) != c;
            }
            if (nearEdge) continue;
            ++checked;
            wrong += std::fabs(pixel(img.get(), x, y)[1] - c) > 0.25f;
        }
    ASSERT_GT(checked, 5000);
    EXPECT_LE(wrong, checked / 1000) << wrong << " of " << checked << " pixels show the wrong cell";

    // the virtual vertex's distance along its sight ray (eq. 2.4: eta times the true one) moves no
    // pixel, but the water reads the path under water from it: white cells fade towards the water
    // colour as exp(-k |X - U|), the thesis's model
    const float k = 0.3f;
    WaterSettings* s = sc.water->getSettings();
    s->setWaterModel(WaterSettings::WATER_THESIS);
    s->setAttenuation(k);
    sc.h.frame(0.0);
    img = sc.h.readColor();
    const float water = s->getBodyColor().y();
    std::vector<double> fadeErr;
    for (int y = 0; y < sc.h.height(); ++y)
        for (int x = 0; x < sc.h.width(); ++x) {
            osg::Vec3d X, Y;
            if (!sc.flatHit(x + 0.5, y + 0.5, X) || checkerAt(X.x(), X.y(), kCell) != 1.0f) continue;
            bool nearEdge = false;
            for (const osg::Vec2d& o : { osg::Vec2d(-1, 0), osg::Vec2d(1, 0), osg::Vec2d(0, -1), osg::Vec2d(0, 1) })
                nearEdge = nearEdge || !sc.flatHit(x + 0.5 + o.x(), y + 0.5 + o.y(), Y) || checkerAt(Y.x(), Y.y(), kCell) != 1.0f;
            if (nearEdge) continue;
            const osg::Vec3d d = sc.ray(x + 0.5, y + 0.5), U = sc.eye + d * (-sc.eye.z() / d.z());
            const double expected = optics::encodeSrgb(float(water + std::exp(-k * (X - U).length()) * (1.0 - water)));
            fadeErr.push_back(std::fabs(pixel(img.get(), x, y)[1] - expected));
        }
    ASSERT_GT(fadeErr.size(), 2000u);
    // tolerance: 0.01 (the fade in linear light, encoded), beyond the 8-bit view's 0.004 step
    EXPECT_LT(quantile(fadeErr, 0.99), 0.01) << "the path under water the virtual vertices imply";
}

TEST(RenderVirtualVertices, OverAGentleWaveEachShownPointIsWhereTheCpuMirrorPutsItsVirtualVertex)
{
    // one long wave (6 m, 5 cm: no zones of convergence at this depth): the membrane's facets are
    // an eighth of its length; the CPU mirror builds the same facets, grid-aligned, with the same
    // analytic normals at their vertices
    VirtualScene sc({ makeWave(0.6f, 0.8f, 6.0f, 0.05f) });
    REQUIRE_GL(sc.h);
    sc.water->setDebugOutput(DEBUG_BOTTOM_HIT);
    sc.h.frame(0.0);
    osg::ref_ptr<osg::Image> shown = sc.h.readColor();
    ASSERT_TRUE(allFinite(shown.get()));

    const WaterSurface& surface = *sc.water->getSurface();
    const double cell = virtualvertices::membraneCellSize(surface);
    ASSERT_NEAR(cell, 0.75, 1e-6);
    virtualvertices::Membrane m;
    const int i0 = -28, i1 = 28, j0 = -8, j1 = 32; // the water the view sees, x -21..21, y -6..24
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            const double x = i * cell, y = j * cell;
            m.positions.push_back(glm::dvec3(x, y, surface.height(x, y, 0.0)));
            const osg::Vec3d n = surface.normal(x, y, 0.0);
            m.normals.push_back(glm::dvec3(n.x(), n.y(), n.z()));
        }
    const int row = i1 - i0 + 1;
    for (int j = 0; j < j1 - j0; ++j)
        for (int i = 0; i < i1 - i0; ++i) { // the GPU's split: (0,0) (1,0) (1,1) and (0,0) (1,1) (0,1)
            const int k = j * row + i;
            m.facets.push_back(glm::ivec3(k, k + 1, k + row + 1));
            m.facets.push_back(glm::ivec3(k, k + row + 1, k + row));
        }
    const virtualvertices::Cells cells =
        virtualvertices::buildCells(m, glm::dvec3(sc.eye.x(), sc.eye.y(), sc.eye.z()), 1.0, 1.333);

    std::vector<double> errPx;
    int missing = 0;
    for (int y = 0; y < sc.h.height(); y += 3)
        for (int x = 0; x < sc.h.width(); x += 3) {
            osg::Vec3d X;
            if (!sc.flatHit(x + 0.5, y + 0.5, X)) continue; // roughly: stay well inside the bed
            const float* p = pixel(shown.get(), x, y);
            if (!(p[3] > 3.5f && p[3] < 4.5f)) { ++missing; continue; }
            const virtualvertices::VirtualVertex v =
                virtualvertices::virtualVertex(cells, glm::dvec3(p[0], p[1], p[2]), virtualvertices::SightPoint::Solved);
            if (!v.found) { ++missing; continue; }
            const osg::Vec2d at = sc.project(osg::Vec3d(v.position.x, v.position.y, v.position.z));
            errPx.push_back((at - osg::Vec2d(x + 0.5, y + 0.5)).length());
        }
    ASSERT_GT(errPx.size(), 1500u);
    EXPECT_EQ(missing, 0);
    std::printf("virtual vertices over a wave: %zu pixels, GPU against CPU median %.4f px, p99 %.4f px\n",
                errPx.size(), quantile(errPx, 0.5), quantile(errPx, 0.99));
    // tolerance: half a pixel at p99 (the bed's triangles drawn linearly between virtual vertices
    // and float arithmetic on the GPU)
    EXPECT_LT(quantile(errPx, 0.99), 0.5);
    EXPECT_LT(quantile(errPx, 0.5), 0.1);
}
