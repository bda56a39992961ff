// The eye under water (thesis §7.5): eq. 10 fog, the surface seen from below with total
// internal reflection, the eye's side decided by the wave at the eye, and a camera crossing the
// surface with a near plane that cuts it.
#include "node/WaterNodeImpl.h"
#include "GLHarness.h"
#include <osgWater/WaterNode>
#include "optics/Optics.h"
#include "optics/Srgb.h"
#include <osgWater/WaterTypes>
#include <cmath>
#include <algorithm>
#include <iostream>

using namespace testing_gl;
using namespace osgWater;

namespace {

osg::ref_ptr<WaterNode> flatWater(float k)
{
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setWaves({});
    water->getSurface()->setSize(400.0f);
    WaterSettings* s = water->getSettings();
    s->setCausticsEnabled(false); // emissive test objects: caustics cannot change them
    s->setGlowEnabled(false);
    s->setAttenuation(k);
    return water;
}

osg::Vec3 at(const osg::Image* img, const osg::Vec2d& p)
{
    const float* v = pixel(img, int(p.x()), int(p.y()));
    return osg::Vec3(v[0], v[1], v[2]);
}

// eq. 10 per channel in linear light: the Optics mirror's attenuation and tint of an object's
// display colour c (decoded) towards the water's body colour w (linear)
osg::Vec3 fog(const osg::Vec3& c, const osg::Vec3& w, const osg::Vec3& k, double d)
{
    const glm::vec3 t = optics::waterTint(optics::decodeSrgb(glm::vec3(c.x(), c.y(), c.z())), glm::vec3(w.x(), w.y(), w.z()),
                                          optics::attenuation(glm::vec3(k.x(), k.y(), k.z()), float(d)));
    return osg::Vec3(t.x, t.y, t.z);
}

}

// The thesis's one k (0.1 per metre here: the far quad stays visible) and each per-channel preset.
class RenderUnderwaterFog : public ::testing::TestWithParam<std::string> {};

TEST_P(RenderUnderwaterFog, ObjectsFadeToTheWaterColourWithDistanceFromTheEye)
{
    // eq. 10: C = C_water + exp(-k |A - C1|) (C_obj - C_water), checked per pixel against the
    // distance along that pixel's ray; a far copy of the object must be nearer the water colour.
    Harness h(200, 150);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = flatWater(0.1f);
    if (const WaterType* type = findWaterType(GetParam())) applyWaterType(*water->getSettings(), *type);
    const osg::Vec4 red(1, 0, 0, 1);
    water->addChild(emissiveQuad(osg::Vec3(-1.6f, 3, -3.6f), osg::Vec3(-0.2f, 3, -3.6f), osg::Vec3(-0.2f, 3, -2.4f),
                                 osg::Vec3(-1.6f, 3, -2.4f), red));
    water->addChild(emissiveQuad(osg::Vec3(0.8f, 12, -5.4f), osg::Vec3(6.4f, 12, -5.4f), osg::Vec3(6.4f, 12, -0.6f),
                                 osg::Vec3(0.8f, 12, -0.6f), red));
    h.setScene(water.get());
    const osg::Vec3d eye(0, 0, -3);
    h.lookAt(eye, osg::Vec3d(0, 10, -3), 60.0);
    h.frame(0.0);
    ASSERT_TRUE(osgWater::internals(*water).getViewPasses(h.camera()) && osgWater::internals(*water).getViewPasses(h.camera())->getEyeBelow());
    osg::ref_ptr<osg::Image> img = h.readColor();
    ASSERT_TRUE(allFinite(img.get()));

    const WaterSettings& s = *water->getSettings();
    const osg::Vec3 W = s.getBodyColor();
    const osg::Vec3d nearP(-0.9, 3, -3), farP(3.6, 12, -3);
    const osg::Vec3 nearC = at(img.get(), h.pixelOf(nearP)), farC = at(img.get(), h.pixelOf(farP));
    const osg::Vec3 nearE = shown(fog(osg::Vec3(1, 0, 0), W, s.getViewExtinction(), (nearP - eye).length()));
    const osg::Vec3 farE = shown(fog(osg::Vec3(1, 0, 0), W, s.getViewExtinction(), (farP - eye).length()));
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(nearC[i], nearE[i], 0.01) << "near, channel " << i;
        EXPECT_NEAR(farC[i], farE[i], 0.01) << "far, channel " << i;
    }
    const osg::Vec3 waterShown = shown(W);
    if ((nearE - waterShown).length() > 0.05f) // monotonic in distance (a murky water hides both quads alike)
        EXPECT_LT((farC - waterShown).length(), (nearC - waterShown).length());
    // a ray that meets nothing under water ends in water: the backdrop, not the clear colour
    const osg::Vec3 nothing = at(img.get(), h.pixelOf(osg::Vec3d(0, 40, -20)));
    EXPECT_NEAR((nothing - waterShown).length(), 0.0f, 0.01f);
}

INSTANTIATE_TEST_SUITE_P(Models, RenderUnderwaterFog, waterModels(), waterModelTestName);

TEST(RenderUnderwater, TheWaveAtTheEyeDecidesWhichSideItIsOn)
{
    // one long wave (amplitude 0.5 m): an eye 0.2 m above the mean level under a crest is under
    // water; 0.2 m below the mean level over a trough it is above.
    Harness h(64, 48);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = flatWater(0.5f);
    water->getSurface()->setWaves({ makeWave(1.0f, 0.0f, 40.0f, 0.5f) });
    water->addChild(checkerPlane(-5.0f, 100.0f, 1.0f));
    h.setScene(water.get());
    const double xCrest = 10.0, xTrough = -10.0; // sin(k x) = +1 and -1 at t = 0 (k = 2 pi / 40)
    ASSERT_NEAR(water->getSurface()->height(xCrest, 0, 0.0), 0.5, 1e-6);
    ASSERT_NEAR(water->getSurface()->height(xTrough, 0, 0.0), -0.5, 1e-6);
    struct Case { double x, z; bool below; } cases[] = { { xCrest, 0.2, true }, { xTrough, -0.2, false },
                                                          { xCrest, 0.6, false }, { xTrough, -0.6, true } };
    for (const Case& c : cases) {
        h.lookAt(osg::Vec3d(c.x, 0, c.z), osg::Vec3d(c.x, 10, c.z - 1), 45.0);
        h.frame(0.0);
        ViewPasses* p = osgWater::internals(*water).getViewPasses(h.camera());
        ASSERT_TRUE(p);
        EXPECT_EQ(p->getEyeBelow(), c.below) << "eye at x " << c.x << " z " << c.z;
        osg::ref_ptr<osg::Image> img = h.readColor();
        EXPECT_TRUE(allFinite(img.get()));
    }
}

namespace {

// Looking up from (0, 0, -2) at `deg` from the vertical, over a red floor at z = -6 and under an
// empty (clear-colour) sky: the colour of the pixel on that ray.
struct LookUp {
    osg::Vec3 beyond, within; // 60 and 30 degrees from the vertical
};

LookUp lookUp(WaterSettings::UnderwaterModel model, bool& ok, std::string& why)
{
    Harness h(160, 160);
    ok = h.ok();
    why = h.why();
    if (!ok) return {};
    osg::ref_ptr<WaterNode> water = flatWater(0.02f);
    water->getSettings()->setUnderwaterModel(model);
    water->getSettings()->setFresnelModel(WaterSettings::FRESNEL_EXACT);
    water->addChild(emissiveQuad(osg::Vec3(-100, -100, -6), osg::Vec3(100, -100, -6), osg::Vec3(100, 100, -6),
                                 osg::Vec3(-100, 100, -6), osg::Vec4(1, 0, 0, 1)));
    h.setScene(water.get());
    const osg::Vec3d eye(0, 0, -2);
    const double c45 = std::sqrt(0.5);
    h.lookAt(eye, eye + osg::Vec3d(0, c45, c45), 50.0); // rows span 20..70 degrees from the vertical
    h.frame(0.0);
    osg::ref_ptr<osg::Image> img = h.readColor();
    EXPECT_TRUE(allFinite(img.get()));
    auto ray = [&](double deg) {
        const double t = osg::DegreesToRadians(deg);
        return at(img.get(), h.pixelOf(eye + osg::Vec3d(0, std::sin(t), std::cos(t))));
    };
    return { ray(60.0), ray(30.0) };
}

}

TEST(RenderUnderwater, BeyondTheCriticalAngleTheSurfaceMirrorsTheWaterWithinItShowsTheSky)
{
    bool ok;
    std::string why;
    const LookUp phys = lookUp(WaterSettings::UNDERWATER_PHYSICAL, ok, why);
    if (!ok) {
        if (std::getenv("CI")) FAIL() << "CI is set and no GL context: " << why;
        GTEST_SKIP() << why;
    }
    const osg::Vec3 sky(0.2f, 0.3f, 0.8f), W(0.0f, 0.2f, 0.1f), red(1, 0, 0);
    const osg::Vec3 k(0.02f, 0.02f, 0.02f);
    // 60 degrees > 48.6: total internal reflection, F = 1: the red floor, through the water path
    // eye -> surface -> floor (2 / cos 60 + 6 / cos 60 = 16 m). The reflection lookup's point on the
    // floor is approximate (W = U + m R), so allow +-4 m of path: +-0.03 in the red channel.
    const osg::Vec3 beyondE = shown(fog(red, W, k, 16.0));
    EXPECT_NEAR(phys.beyond.x(), beyondE.x(), 0.03);
    EXPECT_NEAR(phys.beyond.z(), beyondE.z(), 0.03);
    EXPECT_GT(phys.beyond.x(), phys.beyond.z()) << "beyond the critical angle: the floor, not the sky";
    // 30 degrees: the sky through the surface (exact Fresnel from below), tinted over 2 / cos 30 m,
    // plus the small reflected share of the floor
    const double t = osg::DegreesToRadians(30.0);
    const float F = optics::fresnelExact(float(std::cos(t)), 1.333f, 1.0f);
    const osg::Vec3 refr = fog(sky, W, k, 2.0 / std::cos(t));
    const osg::Vec3 withinE = shown(refr + (fog(red, W, k, 8.0 / std::cos(t)) - refr) * F);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(phys.within[i], withinE[i], 0.03) << "channel " << i;
    EXPECT_GT(phys.within.z(), phys.within.x()) << "within the Snell window: the sky";

    // the thesis's eq. 12 never reflects totally: at 60 degrees it still shows mostly sky
    const LookUp thesis = lookUp(WaterSettings::UNDERWATER_THESIS, ok, why);
    EXPECT_GT(thesis.beyond.z(), thesis.beyond.x());
}

TEST(RenderUnderwater, CrossingTheSurfaceNeverLosesTheWater)
{
    // A camera on a vertical path through the (waving) surface, -10 mm .. +10 mm around the
    // surface at its position, looking along the water with a 0.3 m near plane that cuts the
    // surface. Reflection off and a bright green water colour make every pixel that sees water
    // (from above, from below, or through it) green-dominated; the raw bed (grey levels) and
    // the sky (clear colour, blue) are not. The water must cover the lower half above the
    // surface and nearly everything below it, in every frame.
    Harness h(96, 72);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = flatWater(0.3f);
    water->getSurface()->setWaves({ makeWave(0.6f, 0.8f, 3.0f, 0.02f) });
    water->getSettings()->setReflectionEnabled(false);
    water->getSettings()->setWaterColor(osg::Vec3(0.0f, 0.6f, 0.0f));
    water->addChild(checkerPlane(-1.5f, 300.0f, 0.5f));
    h.setScene(water.get());
    const double t = 3.0, x = 0.3, y = -0.2;
    const double surface = water->getSurface()->height(x, y, t);
    double previous = -1.0;
    for (int mm = -10; mm <= 10; ++mm) {
        const osg::Vec3d eye(x, y, surface + mm * 1e-3);
        h.lookAt(eye, eye + osg::Vec3d(0, 10, 0), 45.0);
        h.camera()->setProjectionMatrixAsPerspective(45.0, double(h.width()) / h.height(), 0.3, 500.0);
        h.frame(t);
        osg::ref_ptr<osg::Image> img = h.readColor();
        ASSERT_TRUE(allFinite(img.get())) << mm << " mm";
        int wet = 0, lowerWet = 0, lower = 0;
        double luminance = 0.0;
        for (int r = 0; r < h.height(); ++r)
            for (int c = 0; c < h.width(); ++c) {
                const float* p = pixel(img.get(), c, r);
                const bool green = p[1] - std::max(p[0], p[2]) > 0.05f;
                wet += green;
                luminance += p[0] + p[1] + p[2];
                if (r < h.height() / 2 - 2) { ++lower; lowerWet += green; }
            }
        const double coverage = double(wet) / (h.width() * h.height());
        EXPECT_EQ(lowerWet, lower) << "a hole in the water below the horizon at " << mm << " mm";
        EXPECT_GT(coverage, 0.45) << mm << " mm";
        if (mm < 0) EXPECT_GT(coverage, 0.97) << "under water everything is seen through water, " << mm << " mm";
        EXPECT_GT(luminance / (3.0 * h.width() * h.height()), 0.05) << "black frame at " << mm << " mm";
        // no jump within one side of the surface (the waterline itself is between -1 and 0 mm)
        if (previous >= 0.0 && mm != 0) EXPECT_NEAR(coverage, previous, 0.05) << mm << " mm";
        previous = coverage;
    }
}

TEST(RenderUnderwater, ACameraCrossingTheSurfaceInMillimetreStepsChangesTheImageSmoothly)
{
    // All effects on, waves, the eye moving 1 mm a frame from 40 mm above to 40 mm below the surface
    // at its position, looking 10 degrees down, then 10 degrees up. Between two frames on the same
    // side of the surface the mean colour may change by at most kStep per channel; only the step
    // that crosses the surface (the waterline) may jump.
    const float kStep = 0.005f; // 3x the largest change measured (0.0014, pitch +10)
    Harness h(64, 48);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = new WaterNode;
    water->getSurface()->setSize(200.0f);
    water->addChild(checkerPlane(-2.0f, 200.0f, 1.0f));
    water->addChild(emissiveQuad(osg::Vec3(-1, 6, -2), osg::Vec3(1, 6, -2), osg::Vec3(1, 6, 2), osg::Vec3(-1, 6, 2),
                                 osg::Vec4(1, 0.5f, 0, 1)));
    h.setScene(water.get());
    const double t = 2.0, x = 0.4, y = -0.3;
    const double surface = water->getSurface()->height(x, y, t);
    for (double pitch : { -10.0, 10.0 }) {
        osg::Vec3 previous;
        bool previousBelow = false;
        float worst = 0.0f;
        int jumps = 0;
        for (int mm = 40; mm >= -40; --mm) {
            const osg::Vec3d eye(x, y, surface + mm * 1e-3 + 0.5e-3); // never exactly on it
            const osg::Vec3d dir(0.0, std::cos(osg::DegreesToRadians(pitch)), std::sin(osg::DegreesToRadians(pitch)));
            h.lookAt(eye, eye + dir * 10.0, 50.0);
            h.frame(t);
            osg::ref_ptr<osg::Image> img = h.readColor();
            ASSERT_TRUE(img.valid() && allFinite(img.get()));
            osg::Vec3 mean;
            for (int r = 0; r < img->t(); ++r)
                for (int c = 0; c < img->s(); ++c)
                    mean += osg::Vec3(pixel(img.get(), c, r)[0], pixel(img.get(), c, r)[1], pixel(img.get(), c, r)[2]);
            mean /= float(img->s() * img->t());
            const bool below = water->eyeHeightAboveSurface(eye, t) < 0.0;
            if (mm < 40) {
                const osg::Vec3 d = mean - previous;
                const float step = std::max({ std::fabs(d.x()), std::fabs(d.y()), std::fabs(d.z()) });
                if (below == previousBelow) worst = std::max(worst, step);
                if (std::getenv("OSGWATER_TEST_VERBOSE")) std::cout << pitch << " " << mm << " mm " << step << (below ? " below" : "") << std::endl;
                if (below != previousBelow) ++jumps;
                EXPECT_TRUE(below == previousBelow || step <= 1.0f);
                if (below == previousBelow)
                    EXPECT_LE(step, kStep) << "pitch " << pitch << ", " << mm << " mm: mean colour jumped";
            }
            previous = mean;
            previousBelow = below;
        }
        EXPECT_EQ(jumps, 1) << "the path crosses the surface exactly once";
        std::cout << "pitch " << pitch << ": largest change between frames on one side " << worst << std::endl;
    }
}
