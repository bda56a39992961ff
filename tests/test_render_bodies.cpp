// Water where applications put it: under a MatrixTransform (moved, turned about z, scaled),
// checked against the same water untransformed.
#include "GLHarness.h"
#include "WarnCapture.h"
#include <osgWater/WaterNode>
#include <osg/MatrixTransform>
#include <algorithm>
#include <cmath>
#include <vector>

using namespace testing_gl;
using namespace osgWater;

namespace {

Wave wave(float dx, float dy, float wavelength, float amplitude)
{
    Wave w;
    w.direction.set(dx, dy);
    w.wavelength = wavelength;
    w.amplitude = amplitude;
    return w;
}

// a small lake with waves, a checker bed and a red quad above it to reflect; caustics and glow on
osg::ref_ptr<WaterNode> wavyLake()
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setSize(60.0f);
    water->getSurface()->setWaves({ wave(1.0f, 0.3f, 4.0f, 0.04f), wave(-0.4f, 1.0f, 2.5f, 0.02f) });
    water->addChild(checkerPlane(-1.5f, 60.0f, 4.0f)); // large cells: few edges to land apart
    water->addChild(emissiveQuad(osg::Vec3(-1, 10, 0.5f), osg::Vec3(1, 10, 0.5f), osg::Vec3(1, 10, 2.5f),
                                 osg::Vec3(-1, 10, 2.5f), osg::Vec4(1, 0, 0, 1)));
    return water;
}

// share of the pixels of `a` that no pixel of `b` within one pixel matches to `tol` in every
// channel (an edge landing one pixel over, the horizon say, is not a difference)
double shareDiffering(const osg::Image* a, const osg::Image* b, float tol)
{
    auto same = [&](const float* p, int x, int y) {
        if (x < 0 || y < 0 || x >= b->s() || y >= b->t()) return false;
        const float* q = pixel(b, x, y);
        return std::fabs(p[0] - q[0]) <= tol && std::fabs(p[1] - q[1]) <= tol && std::fabs(p[2] - q[2]) <= tol;
    };
    int differ = 0;
    for (int y = 0; y < a->t(); ++y)
        for (int x = 0; x < a->s(); ++x) {
            const float* p = pixel(a, x, y);
            bool matched = false;
            for (int dy = -1; dy <= 1 && !matched; ++dy)
                for (int dx = -1; dx <= 1 && !matched; ++dx) matched = same(p, x + dx, y + dy);
            if (!matched) ++differ;
        }
    return double(differ) / (a->s() * a->t());
}

}

TEST(RenderBodies, ATransformedWaterLooksAsTheSameWaterSeenFromTheMovedEye)
{
    // the same water twice: at the root, and under T (moved, turned 40 degrees about z, scaled 2x),
    // the second seen from T(eye) towards T(centre): every pass works in the water's local frame
    // and counts local metres, so the images must agree up to edges landing a pixel apart.
    // Above the water (reflection, refraction, caustics) and below it (fog, the surface from below).
    Harness h(160, 120);
    REQUIRE_GL(h);
    const osg::Matrixd T = osg::Matrixd::scale(2, 2, 2) * osg::Matrixd::rotate(osg::DegreesToRadians(40.0), 0, 0, 1)
                         * osg::Matrixd::translate(100, -50, 20);
    const osg::Vec3d centre(0, 6, -1);
    for (const osg::Vec3d& eye : { osg::Vec3d(0, -8, 3), osg::Vec3d(0, -8, -0.7) }) {
        SCOPED_TRACE(eye.z() > 0 ? "above" : "below");
        h.setScene(wavyLake().get());
        h.lookAt(eye, centre);
        h.frame(2.0);
        osg::ref_ptr<osg::Image> plain = h.readColor();

        osg::ref_ptr<osg::MatrixTransform> moved = new osg::MatrixTransform(T);
        osg::ref_ptr<WaterNode> water = wavyLake();
        moved->addChild(water.get());
        h.setScene(moved.get());
        h.lookAt(eye * T, centre * T);
        h.frame(2.0);
        osg::ref_ptr<osg::Image> transformed = h.readColor();
        ASSERT_TRUE(allFinite(transformed.get()));
        ASSERT_NE(water->getViewPasses(h.camera()), nullptr);
        EXPECT_EQ(water->getViewPasses(h.camera())->getEyeBelow(), eye.z() < 0);
        const double share = shareDiffering(plain.get(), transformed.get(), 0.03f);
        RecordProperty(eye.z() > 0 ? "share_differing_above" : "share_differing_below", std::to_string(share));
        EXPECT_LT(share, 0.002) << "pixels differing by more than 0.03 from every neighbour";
    }
}

TEST(RenderBodies, ANonUniformScaleIsWarnedAboutOnce)
{
    Harness h(64, 48);
    REQUIRE_GL(h);
    osg::ref_ptr<osg::MatrixTransform> squashed = new osg::MatrixTransform(osg::Matrixd::scale(1, 1, 3));
    squashed->addChild(wavyLake().get());
    h.setScene(squashed.get());
    h.lookAt(osg::Vec3d(0, -8, 9), osg::Vec3d(0, 6, -3));
    ScopedWarnCapture capture;
    h.frame(0.0);
    h.frame(0.1);
    const std::string text = capture.str();
    const size_t first = text.find("non-uniform scale");
    ASSERT_NE(first, std::string::npos) << text;
    EXPECT_EQ(text.find("non-uniform scale", first + 1), std::string::npos) << "said once";
}
