// Pass matrices, without a GPU: mirror, FOV extension, near/far, refraction-camera rotation, planes.
#include "frame/PassMath.h"
#include <osg/io_utils>
#include <osg/Polytope>
#include <gtest/gtest.h>
#include <cmath>

using namespace osgWater;

namespace {
osg::Matrixd lookAt(const osg::Vec3d& eye, const osg::Vec3d& center)
{
    return osg::Matrixd::lookAt(eye, center, osg::Vec3d(0.0, 0.0, 1.0));
}
osg::Vec2d toNdc(const osg::Vec3d& p, const osg::Matrixd& mvp)
{
    const osg::Vec4d c = osg::Vec4d(p, 1.0) * mvp;
    return osg::Vec2d(c.x() / c.w(), c.y() / c.w());
}
}

TEST(PassMath, MirrorReflectsAboutTheWaterLevel)
{
    const osg::Matrixd m = mirrorMatrix(1.5);
    const osg::Vec3d p = osg::Vec3d(2.0, -3.0, 4.0) * m;
    EXPECT_NEAR(p.x(), 2.0, 1e-12);
    EXPECT_NEAR(p.y(), -3.0, 1e-12);
    EXPECT_NEAR(p.z(), -1.0, 1e-12);
    const osg::Vec3d q = osg::Vec3d(7.0, 1.0, 1.5) * m; // points on the plane stay put
    EXPECT_NEAR(q.z(), 1.5, 1e-12);
}

TEST(PassMath, MirroredCameraSeesTheMirrorImageWhereTheEyeSeesTheSurface)
{
    // the reflection lookup is exact for flat water: U + c R projects through the mirrored view onto U's pixel
    const osg::Matrixd view = lookAt(osg::Vec3d(0, -10, 4), osg::Vec3d(0, 10, 0));
    const osg::Matrixd proj = osg::Matrixd::perspective(45.0, 1.0, 0.1, 100.0);
    const osg::Vec3d eye(0, -10, 4), U(1.0, 6.0, 0.0);
    osg::Vec3d I = U - eye;
    I.normalize();
    const osg::Vec3d Rr(I.x(), I.y(), -I.z());
    for (double c : { 0.5, 1.0, 10.0 }) {
        const osg::Vec2d a = toNdc(U + Rr * c, mirrorMatrix(0.0) * view * proj);
        const osg::Vec2d b = toNdc(U, view * proj);
        EXPECT_NEAR(a.x(), b.x(), 1e-9);
        EXPECT_NEAR(a.y(), b.y(), 1e-9);
    }
}

TEST(PassMath, ExtendedFovWidensTangentsByTheFactor)
{
    const osg::Matrixd proj = osg::Matrixd::perspective(40.0, 1.5, 0.5, 200.0);
    const osg::Matrixd ext = extendFov(proj, 1.5);
    double l0, r0, b0, t0, n0, f0, l1, r1, b1, t1, n1, f1;
    ASSERT_TRUE(proj.getFrustum(l0, r0, b0, t0, n0, f0));
    ASSERT_TRUE(ext.getFrustum(l1, r1, b1, t1, n1, f1));
    EXPECT_NEAR(r1 / n1, 1.5 * r0 / n0, 1e-9);
    EXPECT_NEAR(t1 / n1, 1.5 * t0 / n0, 1e-9);
    EXPECT_NEAR(n1, n0, 1e-6);
    EXPECT_NEAR(f1, f0, 1e-3);
}

TEST(PassMath, WithNearFarKeepsTheFieldOfView)
{
    const osg::Matrixd proj = osg::Matrixd::perspective(60.0, 1.0, 1.0, 1000.0);
    const osg::Matrixd p2 = withNearFar(proj, 0.25, 40.0);
    double l, r, b, t, n, f;
    ASSERT_TRUE(p2.getFrustum(l, r, b, t, n, f));
    EXPECT_NEAR(n, 0.25, 1e-9);
    EXPECT_NEAR(f, 40.0, 1e-6);
    EXPECT_NEAR(t / n, std::tan(osg::DegreesToRadians(30.0)), 1e-9);
    const osg::Matrixd o = withNearFar(osg::Matrixd::ortho(-2, 2, -1, 1, 0, 10), 1.0, 5.0);
    ASSERT_TRUE(o.getOrtho(l, r, b, t, n, f));
    EXPECT_NEAR(r, 2.0, 1e-9);
    EXPECT_NEAR(n, 1.0, 1e-9);
    EXPECT_NEAR(f, 5.0, 1e-9);
}

TEST(PassMath, NearFarEnclosesTheBound)
{
    const osg::Matrixd view = lookAt(osg::Vec3d(0, -50, 0), osg::Vec3d(0, 0, 0));
    double n, f;
    ASSERT_TRUE(nearFarForBound(view, osg::BoundingSphere(osg::Vec3(0, 0, 0), 10.0f), n, f));
    EXPECT_NEAR(n, 40.0, 1e-6);
    EXPECT_GE(f, 60.0);
    EXPECT_LT(f, 60.1);
    ASSERT_TRUE(nearFarForBound(view, osg::BoundingSphere(osg::Vec3(0, -50, 0), 10.0f), n, f)); // eye inside
    EXPECT_GT(n, 0.0);
    EXPECT_FALSE(nearFarForBound(view, osg::BoundingSphere(osg::Vec3(0, -100, 0), 10.0f), n, f)); // behind
}

TEST(PassMath, PlaneToEyeGivesTheSameSignedDistance)
{
    const osg::Matrixd view = lookAt(osg::Vec3d(3, -7, 2), osg::Vec3d(1, 5, -1));
    const osg::Vec4d plane(0.0, 0.0, -1.0, 0.25); // keep z <= 0.25
    const osg::Vec4d pe = planeToEye(plane, view);
    for (const osg::Vec3d& p : { osg::Vec3d(1, 2, 3), osg::Vec3d(-4, 0, -2), osg::Vec3d(0, 0, 0.25) }) {
        const osg::Vec3d e = p * view;
        const double local = plane.x() * p.x() + plane.y() * p.y() + plane.z() * p.z() + plane.w();
        const double eye = pe.x() * e.x() + pe.y() * e.y() + pe.z() * e.z() + pe.w();
        EXPECT_NEAR(local, eye, 1e-9);
    }
}

namespace {

// the ray through the bottom-centre of a camera's screen: its direction, and its origin (the eye)
osg::Vec3d bottomCentreRay(const osg::Matrixd& view, const osg::Matrixd& proj, osg::Vec3d& origin)
{
    const osg::Matrixd inv = osg::Matrixd::inverse(view * proj);
    const osg::Vec3d a = osg::Vec3d(0, -1, -1) * inv, b = osg::Vec3d(0, -1, 1) * inv;
    origin = eyePosition(view);
    osg::Vec3d d = b - a;
    d.normalize();
    return d;
}

}

TEST(PassMath, RefractionRotationTurnsTheBottomRayOntoItsRefraction)
{
    const osg::Matrixd view = lookAt(osg::Vec3d(0, -20, 5), osg::Vec3d(0, 0, 0));
    const osg::Matrixd proj = osg::Matrixd::perspective(45.0, 1.0, 0.1, 100.0);
    const double eta = 1.0 / 1.333;
    const osg::Matrixd rv = rotatedRefractionView(view, proj, 0.0, eta);
    osg::Vec3d c0, c1;
    const osg::Vec3d I = bottomCentreRay(view, proj, c0), R = bottomCentreRay(rv, proj, c1);
    // eq. 2 in closed form: sin(theta_t) = eta sin(theta_i), measured from the vertical
    const double si = std::sqrt(I.x() * I.x() + I.y() * I.y());
    const double st = std::sqrt(R.x() * R.x() + R.y() * R.y());
    EXPECT_NEAR(st, eta * si, 1e-9);
    EXPECT_LT(R.z(), 0.0);
    // both rays pass through O on the water (eq. 1): the rotation is about O
    const double t0 = -c0.z() / I.z(), t1 = -c1.z() / R.z();
    const osg::Vec3d O0 = c0 + I * t0, O1 = c1 + R * t1;
    EXPECT_NEAR((O0 - O1).length(), 0.0, 1e-6);
    EXPECT_NEAR((c0 - O0).length(), (c1 - O1).length(), 1e-6); // rigid rotation
    // looking at the sky: unchanged
    const osg::Matrixd sky = lookAt(osg::Vec3d(0, -20, 5), osg::Vec3d(0, 0, 30));
    EXPECT_EQ(rotatedRefractionView(sky, proj, 0.0, eta), sky);
}

TEST(PassMath, TheApparentEyeLiesOnTheRefractedBottomRayNTimesAsFarFromO)
{
    // the rotated camera moved back along the refracted ray: the bottom-centre ray is the same line
    // (through O, along R), the camera 1 / eta times as far from O as the eye; a scale that is not
    // a positive number is the thesis's rigid rotation
    const osg::Matrixd view = lookAt(osg::Vec3d(3, -20, 5), osg::Vec3d(0, 0, 0));
    const osg::Matrixd proj = osg::Matrixd::perspective(45.0, 1.0, 0.1, 100.0);
    const double eta = 1.0 / 1.333, level = 0.4;
    const osg::Matrixd rigid = rotatedRefractionView(view, proj, level, eta);
    const osg::Matrixd apparent = rotatedRefractionView(view, proj, level, eta, 1.0 / eta);
    osg::Vec3d c0, c1, c2;
    const osg::Vec3d I = bottomCentreRay(view, proj, c0), R1 = bottomCentreRay(rigid, proj, c1), R2 = bottomCentreRay(apparent, proj, c2);
    EXPECT_NEAR((R1 - R2).length(), 0.0, 1e-9); // the same direction: only the position moved
    const osg::Vec3d O = c0 + I * ((level - c0.z()) / I.z());
    const osg::Vec3d O2 = c2 + R2 * ((level - c2.z()) / R2.z());
    EXPECT_NEAR((O2 - O).length(), 0.0, 1e-6);
    EXPECT_NEAR((c2 - O).length(), (c0 - O).length() / eta, 1e-6);
    for (double bad : { 0.0, -2.0, std::nan("") }) {
        const osg::Matrixd m = rotatedRefractionView(view, proj, level, eta, bad);
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(m(r, c), rigid(r, c), 1e-12);
    }
}

TEST(PassMath, RefractionRotationIsContinuousAsTheEyeComesDownToTheLevel)
{
    // an eye in a trough is below the level but in the air: the rotation must not switch off there
    const osg::Matrixd proj = osg::Matrixd::perspective(50.0, 1.0, 0.01, 100.0);
    const double eta = 1.0 / 1.333;
    auto rotated = [&](double z) {
        return rotatedRefractionView(lookAt(osg::Vec3d(0, -20, z), osg::Vec3d(0, 0, z - 3.0)), proj, 0.0, eta);
    };
    const osg::Matrixd above = rotated(1e-9), at = rotated(0.0), below = rotated(-1e-9);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            EXPECT_NEAR(above(r, c), at(r, c), 1e-6);
            EXPECT_NEAR(below(r, c), at(r, c), 1e-6);
        }
    // under the level it turns about the eye itself, by the same angle as at the level
    const osg::Matrixd view = lookAt(osg::Vec3d(0, -20, -0.2), osg::Vec3d(0, 0, -3.2));
    const osg::Matrixd rv = rotatedRefractionView(view, proj, 0.0, eta);
    EXPECT_NEAR((eyePosition(rv) - eyePosition(view)).length(), 0.0, 1e-9);
    EXPECT_GT((osg::Matrixd::transform3x3(rv, osg::Vec3d(0, 0, 1)) - osg::Matrixd::transform3x3(view, osg::Vec3d(0, 0, 1))).length(), 0.1);
}

TEST(PassMath, ProjectToTextureCentre)
{
    const osg::Matrixd view = lookAt(osg::Vec3d(0, -10, 0), osg::Vec3d(0, 0, 0));
    const osg::Matrixd proj = osg::Matrixd::perspective(45.0, 1.0, 1.0, 100.0);
    const osg::Vec3d t = projectToTexture(osg::Vec3d(0, 0, 0), view, proj);
    EXPECT_NEAR(t.x(), 0.5, 1e-12);
    EXPECT_NEAR(t.y(), 0.5, 1e-12);
    EXPECT_GT(t.z(), 0.0);
    EXPECT_LT(t.z(), 1.0);
}

TEST(PassMath, SunCameraEnclosesTheBoxAndLooksAlongTheSun)
{
    const osg::BoundingBox box(-70.0f, -50.0f, -9.0f, 70.0f, 50.0f, 0.2f);
    for (const osg::Vec3d& sun : { osg::Vec3d(0, 0, 1), osg::Vec3d(0.3, 0.4, 0.866), osg::Vec3d(0, 1, 1e-4),
                                   osg::Vec3d(0, 1, 0) }) {
        osg::Vec3d L = sun;
        L.normalize();
        const osg::Matrixd view = sunView(L, box);
        const osg::Matrixd proj = sunProjection(view, box);
        // the camera looks along -L: eye-space -Z is the direction of the sun's rays
        const osg::Vec3d fwd = osg::Matrixd::transform3x3(view, osg::Vec3d(0, 0, -1));
        EXPECT_NEAR((fwd + L).length(), 0.0, 1e-9);
        for (unsigned int i = 0; i < 8; ++i) {
            // in front of the camera: the photon search takes points with eye z >= 0 for misses
            EXPECT_LT((osg::Vec3d(box.corner(i)) * view).z(), -1e-3);
            const osg::Vec3d t = projectToTexture(osg::Vec3d(box.corner(i)), view, proj);
            for (int k = 0; k < 3; ++k) {
                EXPECT_GE(t[k], 0.0);
                EXPECT_LE(t[k], 1.0);
            }
        }
        // points along one sun ray share a texel: depth alone changes
        const osg::Vec3d a = projectToTexture(osg::Vec3d(3, -4, -2), view, proj);
        const osg::Vec3d b = projectToTexture(osg::Vec3d(3, -4, -2) + L * 5.0, view, proj);
        EXPECT_NEAR(a.x(), b.x(), 1e-9);
        EXPECT_NEAR(a.y(), b.y(), 1e-9);
        EXPECT_LT(b.z(), a.z()); // nearer the sun: smaller depth
    }
    // an overhead sun maps x and y linearly onto the texture axes
    const osg::Matrixd view = sunView(osg::Vec3d(0, 0, 1), box);
    const osg::Matrixd proj = sunProjection(view, box);
    const osg::Vec3d lo = projectToTexture(osg::Vec3d(-70, -50, 0), view, proj);
    const osg::Vec3d hi = projectToTexture(osg::Vec3d(70, 50, 0), view, proj);
    // (the window is padded by 1e-3 of the box radius)
    EXPECT_NEAR(lo.x(), 0.0, 2e-3);
    EXPECT_NEAR(lo.y(), 0.0, 2e-3);
    EXPECT_NEAR(hi.x(), 1.0, 2e-3);
    EXPECT_NEAR(hi.y(), 1.0, 2e-3);
}

namespace {
// the view frustum's planes in the local frame, as the cull visitor holds them
std::vector<osg::Plane> frustumPlanes(const osg::Vec3d& eye, const osg::Vec3d& center, double aspect)
{
    osg::Polytope p;
    p.setToUnitFrustum(true, true);
    p.transformProvidingInverse(lookAt(eye, center) * osg::Matrixd::perspective(45.0, aspect, 0.1, 2000.0));
    return std::vector<osg::Plane>(p.getPlaneList().begin(), p.getPlaneList().end());
}
}

TEST(PassMath, WaterBoxOutOfViewWhenLookingAtTheSkyFromTheShore)
{
    // the lake's surface box: 140 m square, waves +-0.13 m
    const osg::BoundingBox lake(-70, -70, -0.13, 70, 70, 0.13);
    const osg::Vec3d eye(0, -66, 6);
    // every frustum edge points at least ~7 degrees above the horizon: nothing of the box is inside
    EXPECT_FALSE(boxInsidePlanes(lake, frustumPlanes(eye, osg::Vec3d(0, -120, 40), 16.0 / 9.0)));
    // yet no single plane has the whole box outside (the box reaches behind the eye): the
    // plane-by-plane test OSG's culling does would keep it
    osg::Polytope p;
    p.setToUnitFrustum(true, true);
    p.transformProvidingInverse(lookAt(eye, osg::Vec3d(0, -120, 40)) * osg::Matrixd::perspective(45.0, 16.0 / 9.0, 0.1, 2000.0));
    EXPECT_TRUE(p.contains(lake));
    // looking down at the water, or level across it: in view
    EXPECT_TRUE(boxInsidePlanes(lake, frustumPlanes(eye, osg::Vec3d(0, 0, -3), 16.0 / 9.0)));
    EXPECT_TRUE(boxInsidePlanes(lake, frustumPlanes(osg::Vec3d(0, -30, 0.3), osg::Vec3d(0, 20, 0.3), 1.0)));
    // a frustum that sees only a corner region of a face (no box corner inside it)
    EXPECT_TRUE(boxInsidePlanes(lake, frustumPlanes(osg::Vec3d(0, 0, 10), osg::Vec3d(0, 0, -10) + osg::Vec3d(0, 1e-3, 0), 1.0)));
    EXPECT_FALSE(boxInsidePlanes(osg::BoundingBox(), frustumPlanes(eye, osg::Vec3d(0, 0, -3), 1.0)));
}

TEST(PassMath, NearPlaneReachesTheWaterOnlyWhenItCrossesTheWaveBand)
{
    // 60 degree field of view, near 0.5: the near rectangle reaches 0.29 m above and below the eye's
    // line of sight when looking horizontally
    const osg::Matrixd proj = osg::Matrixd::perspective(60.0, 1.0, 0.5, 100.0);
    const double level = 0.0, band = 0.1;
    // 2 m above the water, looking down at 45 degrees: the near plane stays 1.5 m above the crests
    EXPECT_FALSE(nearPlaneReachesWater(lookAt({ 0, 0, 2 }, { 0, 10, -8 }), proj, level, band));
    // 0.3 m above, looking horizontally: its lower edge dips to 0.01 m, below the crests at 0.1 m
    EXPECT_TRUE(nearPlaneReachesWater(lookAt({ 0, 0, 0.3 }, { 0, 10, 0.3 }), proj, level, band));
    // 0.5 m above, looking horizontally: the lower edge at 0.21 m stays above the crests
    EXPECT_FALSE(nearPlaneReachesWater(lookAt({ 0, 0, 0.5 }, { 0, 10, 0.5 }), proj, level, band));
    // looking straight down from 0.55 m: the near plane at 0.05 m, below the crests
    EXPECT_TRUE(nearPlaneReachesWater(osg::Matrixd::lookAt(osg::Vec3d(0, 0, 0.55), osg::Vec3d(0, 0, -1), osg::Vec3d(0, 1, 0)), proj, level, band));
    // under water: 3 m down looking up at 45 degrees stays below the troughs; 0.3 m down does not
    EXPECT_FALSE(nearPlaneReachesWater(lookAt({ 0, 0, -3 }, { 0, 10, 7 }), proj, level, band));
    EXPECT_TRUE(nearPlaneReachesWater(lookAt({ 0, 0, -0.3 }, { 0, 10, -0.3 }), proj, level, band));
    // the eye within the wave band: anything goes
    EXPECT_TRUE(nearPlaneReachesWater(lookAt({ 0, 0, 0.05 }, { 0, 10, 5 }), proj, level, band));
    // a raised level counts: 2 m above z = 0 is 0.2 m above water at level 1.8
    EXPECT_TRUE(nearPlaneReachesWater(lookAt({ 0, 0, 2 }, { 0, 10, 2 }), proj, 1.8, band));
}

TEST(PassMath, PassTargetsFollowTheViewportWhenScaled)
{
    EXPECT_EQ(passTargetSize(1280, 720, 0.0, 512), osg::Vec2i(512, 512)) << "0: the fixed square";
    EXPECT_EQ(passTargetSize(1280, 720, 0.5, 512), osg::Vec2i(640, 360)) << "the view's aspect";
    EXPECT_EQ(passTargetSize(0, 0, 0.5, 512), osg::Vec2i(512, 512)) << "no viewport: the fixed square";
    EXPECT_EQ(passTargetSize(100, 20, 0.1, 512), osg::Vec2i(16, 16)) << "at least 16 texels a side";
    EXPECT_EQ(passTargetSize(8192, 100, 1.0, 512), osg::Vec2i(4096, 100)) << "at most 4096";
    EXPECT_EQ(passTargetSize(1280, 720, NAN, 256), osg::Vec2i(256, 256));
}

TEST(PassMath, FocusedCountsKeepTheSpacing)
{
    EXPECT_EQ(focusedCount(512, 1.0), 512) << "the whole window: the set count";
    EXPECT_EQ(focusedCount(512, 2.0), 512) << "never more than the set count";
    EXPECT_EQ(focusedCount(512, 0.5), 256) << "half the window, half the count";
    EXPECT_EQ(focusedCount(512, 0.546), 280) << "rounded up to a multiple of 8";
    EXPECT_EQ(focusedCount(512, 0.01), 32) << "at least 32";
    EXPECT_EQ(focusedCount(16, 0.01), 16) << "a set count under 32 is kept";
    EXPECT_EQ(focusedCount(512, NAN), 32);
    EXPECT_EQ(focusedCount(512, 0.0), 32);
}
