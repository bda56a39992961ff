// Water where applications put it: under a MatrixTransform (moved, turned about z, scaled) and
// several bodies at different levels, each rendering its own passes and appearing in the other's
// as a guest without recursion. Checked against the Optics mirror and the same water untransformed.
#include "node/WaterNodeImpl.h"
#include "GLHarness.h"
#include "WarnCapture.h"
#include <osgWater/WaterNode>
#include "optics/Optics.h"
#include "optics/Srgb.h"
#include "frame/PassMath.h"
#include <osg/MatrixTransform>
#include <algorithm>
#include <cmath>
#include <vector>

using namespace testing_gl;
using namespace osgWater;

namespace {

// a small lake with waves, a checker bed and a red quad above it to reflect; caustics and glow on
osg::ref_ptr<WaterNode> wavyLake()
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setSize(60.0f);
    water->getSurface()->setWaves({ makeWave(1.0f, 0.3f, 4.0f, 0.04f), makeWave(-0.4f, 1.0f, 2.5f, 0.02f) });
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
        ASSERT_NE(osgWater::internals(*water).getViewPasses(h.camera()), nullptr);
        EXPECT_EQ(osgWater::internals(*water).getViewPasses(h.camera())->getEyeBelow(), eye.z() < 0);
        const double share = shareDiffering(plain.get(), transformed.get(), 0.03f);
        RecordProperty(eye.z() > 0 ? "share_differing_above" : "share_differing_below", std::to_string(share));
        EXPECT_LT(share, 0.002) << "pixels differing by more than 0.03 from every neighbour";
    }
}

TEST(RenderBodies, ATransformedWaterHoldsToTheOpticsMirror)
{
    // flat water over a grey bed 1.5 m down, under T (moved, turned, scaled 2x): every water pixel
    // is eq. 9 of eq. 5 of the bed and the sky along the pixel's ray taken into the water's frame,
    // with the path under water in local metres
    Harness h(160, 120);
    REQUIRE_GL(h);
    const float depth = 1.5f;
    osg::ref_ptr<WaterNode> water = flatWaterOverBed(depth);
    water->getSettings()->setFovExtension(1.5f, 1.5f, 10.0f);
    water->getSettings()->setAttenuation(0.3f);
    const osg::Matrixd T = osg::Matrixd::scale(2, 2, 2) * osg::Matrixd::rotate(osg::DegreesToRadians(40.0), 0, 0, 1)
                         * osg::Matrixd::translate(100, -50, 20);
    osg::ref_ptr<osg::MatrixTransform> moved = new osg::MatrixTransform(T);
    moved->addChild(water.get());
    h.setScene(moved.get());
    const osg::Vec3d eyeLocal(0, -3, 2.5);
    h.lookAt(eyeLocal * T, osg::Vec3d(0, 8, -1.5) * T);
    h.frame(0.0);
    osg::ref_ptr<osg::Image> img = h.readColor();
    ASSERT_TRUE(allFinite(img.get()));

    const MirrorComparison m = compareFlatWaterWithOptics(h, img.get(), *water->getSettings(), osg::Matrixd::inverse(T),
                                                          0.0, -depth, kBedGrey, 7);
    EXPECT_FALSE(m.bedMissed);
    EXPECT_GT(m.checked, 100);
    EXPECT_LT(m.worst, 2.0 / 255.0) << "eq. 9 in linear light, half-float pass textures: tolerance 2/255";
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

namespace {

// A lake (level 0) holding a pond (level 3, 8 m square at (0, 12)) with a bed 1 m down, 6 m wide
// and 12 m long (it runs on under the banks ahead and behind, where the eye's rays through the
// pond go on to; beside the pond there is none, so the pond's surface shows from below there);
// the lake's bed 1.5 m down. Emissive beds: lighting cannot change them. No glow.
struct TwoBodies {
    osg::ref_ptr<WaterNode> lake = new WaterNode, pond = new WaterNode;
    const osg::Vec3 lakeBed{ 0.3f, 0.3f, 0.3f }, pondBed{ 0.6f, 0.5f, 0.4f };
    const double pondLevel = 3.0, pondBedZ = 2.0, pondY = 12.0;

    TwoBodies()
    {
        for (WaterNode* w : { lake.get(), pond.get() }) {
            w->getSurface()->setWaves({});
            w->getSettings()->setGlowEnabled(false);
            w->getSettings()->setFovExtension(1.5f, 1.5f, 10.0f);
        }
        lake->getSurface()->setSize(200.0f);
        pond->getSurface()->setSize(8.0f);
        pond->getSurface()->setCenter(osg::Vec2(0.0f, float(pondY)));
        pond->getSurface()->setLevel(pondLevel);
        const float b = 100.0f, p = 3.0f, z = float(pondBedZ), y = float(pondY);
        lake->addChild(emissiveQuad(osg::Vec3(-b, -b, -1.5f), osg::Vec3(b, -b, -1.5f), osg::Vec3(b, b, -1.5f),
                                    osg::Vec3(-b, b, -1.5f), osg::Vec4(lakeBed, 1)));
        pond->addChild(emissiveQuad(osg::Vec3(-p, y - 2 * p, z), osg::Vec3(p, y - 2 * p, z), osg::Vec3(p, y + 2 * p, z),
                                    osg::Vec3(-p, y + 2 * p, z), osg::Vec4(pondBed, 1)));
        lake->addChild(pond.get());
    }
};

}

TEST(RenderBodies, APondAboveALakeRendersItsOwnPassesAndIsAGuestInTheLakes)
{
    Harness h(200, 150);
    REQUIRE_GL(h);
    TwoBodies s;
    h.setScene(s.lake.get());
    const osg::Vec3d eye(0, -4, 7);
    h.lookAt(eye, osg::Vec3d(0, 12, 2.5));
    h.frame(0.0);
    osg::ref_ptr<osg::Image> img = h.readColor();
    ASSERT_TRUE(allFinite(img.get()));

    // no recursion: the pond has passes for the view, none for the lake's passes
    ViewPasses* lakePasses = osgWater::internals(*s.lake).getViewPasses(h.camera());
    ASSERT_NE(lakePasses, nullptr);
    ASSERT_NE(osgWater::internals(*s.pond).getViewPasses(h.camera()), nullptr);
    EXPECT_EQ(osgWater::internals(*s.pond).getViewPasses(lakePasses->getReflectionCamera()), nullptr);
    EXPECT_EQ(osgWater::internals(*s.pond).getViewPasses(lakePasses->getRefractionCamera()), nullptr);

    // 1. the pond, through its own passes: eq. 9 of eq. 5 of its bed and the sky, per pixel well
    //    inside the pond
    const WaterSettings& ps = *s.pond->getSettings();
    const MirrorComparison m = compareFlatWaterWithOptics(
        h, img.get(), ps, osg::Matrixd(), s.pondLevel, s.pondBedZ, s.pondBed, 2,
        [&](const osg::Vec3d& U) { return std::fabs(U.x()) <= 2.0 && std::fabs(U.y() - s.pondY) <= 2.0; });
    EXPECT_FALSE(m.bedMissed);
    EXPECT_GT(m.checked, 40);
    EXPECT_LT(m.worst, 2.0 / 255.0) << "the pond's own passes: eq. 9 in linear light, tolerance 2/255";

    // 2. the pond in the lake's reflection: its bed, and its surface as a guest (body colour and
    //    the sky's light by Fresnel at the mirrored eye, seen from below)
    ReflectionCamera* rc = lakePasses->getReflectionCamera();
    osg::ref_ptr<osg::Image> refl = h.readTexture(rc->getColorTexture());
    auto reflected = [&](const osg::Vec3d& p) {
        const osg::Vec3d t = projectToTexture(p, rc->getViewMatrix(), rc->getProjectionMatrix());
        const float* c = pixel(refl.get(), int(t.x() * refl->s()), int(t.y() * refl->t()));
        return osg::Vec3(c[0], c[1], c[2]);
    };
    // (the pass holds linear light: the bed's display colour decoded)
    const osg::Vec3 bedSeen = reflected(osg::Vec3d(0, s.pondY, s.pondBedZ));
    const glm::vec3 bed = optics::decodeSrgb(glm::vec3(s.pondBed.x(), s.pondBed.y(), s.pondBed.z()));
    EXPECT_LT((bedSeen - osg::Vec3(bed.x, bed.y, bed.z)).length(), 0.02f) << "the pond's bed in the lake's reflection";
    const osg::Vec3d ring(3.6, s.pondY, s.pondLevel); // pond surface beyond its bed
    const osg::Vec3d mirroredEye = osg::Vec3d(0, 0, 0) * osg::Matrixd::inverse(rc->getViewMatrix());
    osg::Vec3d E = mirroredEye - ring;
    E.normalize();
    const float F = optics::fresnelSchlick(float(std::fabs(E.z())), ps.getNormalReflectance(), ps.getFresnelExponent());
    const osg::Vec3 body = ps.getBodyColor(), ambient = ps.getAmbientColor();
    const osg::Vec3 guestE = body + (ambient - body) * F;
    const osg::Vec3 guestSeen = reflected(ring);
    EXPECT_LT((guestSeen - guestE).length(), 0.02f) << "guest surface: (" << guestSeen.x() << ", " << guestSeen.y()
                                                    << ", " << guestSeen.z() << ")";
}
