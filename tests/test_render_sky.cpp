// osgWater::Sky, drawn: the view shows Preetham's clear sky along each pixel's ray, as its CPU
// mirror (Sky::getRadiance) gives it, exposed and encoded; calm water reflects it as the Optics
// mirror says (eq. 9 with the sky along each exact mirror ray).
#include "GLHarness.h"
#include "optics/Srgb.h"
#include <osgWater/Sky>
#include <osgWater/WaterNode>
#include <algorithm>
#include <cmath>
#include <iostream>

using namespace testing_gl;
using namespace osgWater;


// Looking up 30 degrees, away from a sun 32 degrees up behind the eye's right shoulder (its
// circumsolar sky would saturate the view): every pixel is the mirror's
// sky along its ray, exposed and encoded, within 2/255 (the shader's single precision and fitted
// curve); with the exposure halved, half the light before the encoding; exposed one and a half times
// through ACES's tone curve, the curve's light (28 levels from what the clip curve would show)
TEST(RenderSky, TheViewShowsTheClearSkyAlongEachPixelsRay)
{
    Harness h(160, 120);
    REQUIRE_GL(h);
    const struct { float exposure; WaterSettings::ToneCurve curve; } cases[] = {
        { 1.0f, WaterSettings::TONE_CLIP }, { 0.5f, WaterSettings::TONE_CLIP }, { 1.5f, WaterSettings::TONE_ACES }
    };
    for (const auto& setup : cases) {
        const float exposure = setup.exposure;
        osg::ref_ptr<WaterNode> water = new WaterNode;
        water->getSettings()->setExposure(exposure);
        water->getSettings()->setToneCurve(setup.curve);
        osg::ref_ptr<Sky> sky = new Sky;
        sky->setSunDirection(osg::Vec3(0.6f, -0.6f, 0.53f));
        water->addChild(sky.get());
        h.setScene(water.get());
        h.lookAt(osg::Vec3d(0, 0, 2), osg::Vec3d(0, 10, 8));
        h.frame(0.0);
        osg::ref_ptr<osg::Image> img = h.readColor();
        ASSERT_TRUE(allFinite(img.get()));
        double worst = 0.0, worstOtherCurve = 0.0, spread = 0.0;
        float lo = 1.0f, hi = 0.0f;
        const auto other = setup.curve == WaterSettings::TONE_ACES ? WaterSettings::TONE_CLIP : WaterSettings::TONE_ACES;
        for (int y = 0; y < img->t(); ++y)
            for (int x = 0; x < img->s(); ++x) {
                const osg::Vec3 light = sky->getRadiance(h.pixelRay(x, y));
                const glm::vec3 linear(light.x(), light.y(), light.z());
                const glm::vec3 expected = optics::display(linear, exposure, setup.curve);
                const glm::vec3 otherCurve = optics::display(linear, exposure, other);
                const float* c = pixel(img.get(), x, y);
                for (int k = 0; k < 3; ++k) {
                    worst = std::max(worst, double(std::fabs(c[k] - expected[k])));
                    worstOtherCurve = std::max(worstOtherCurve, double(std::fabs(c[k] - otherCurve[k])));
                }
                lo = std::min(lo, c[2]);
                hi = std::max(hi, c[2]);
            }
        spread = hi - lo;
        std::cout << "exposure " << exposure << ", " << WaterSettings::toneCurveName(setup.curve) << ": worst "
                  << worst * 255.0 << "/255 (" << worstOtherCurve * 255.0 << "/255 from the other curve), blue from " << lo
                  << " to " << hi << "\n";
        EXPECT_LT(worst, 2.0 / 255.0) << "exposure " << exposure;
        EXPECT_GT(worstOtherCurve, 10.0 / 255.0) << "the curves differ where this view is seen";
        EXPECT_GT(spread, 0.03) << "the sky varies across the view"; // the curve compresses it
    }
}

// Calm water over a bed reflects the sky: each water pixel is eq. 9 of the sky along its exact
// mirror ray and the bed along its refracted one, within 2/255 (the reflection pass's half floats
// and its texels' filtering)
TEST(RenderSky, CalmWaterReflectsTheSkyAsTheMirrorSays)
{
    Harness h(200, 150);
    REQUIRE_GL(h);
    osg::ref_ptr<WaterNode> water = flatWaterOverBed(1.5f);
    osg::ref_ptr<Sky> sky = new Sky;
    sky->setSunDirection(osg::Vec3(0.0f, -0.8f, 0.6f)); // behind the eye: the reflected rays stay below 1
    water->addChild(sky.get());
    h.setScene(water.get());
    h.lookAt(osg::Vec3d(0, 0, 3), osg::Vec3d(0, 10, -1));
    h.frame(0.0);
    osg::ref_ptr<osg::Image> img = h.readColor();
    ASSERT_TRUE(allFinite(img.get()));
    const ReflectedColour skyLight = [&](const osg::Vec3d&, const osg::Vec3d& Rr) {
        const osg::Vec3 light = sky->getRadiance(Rr);
        const glm::vec3 display = optics::encodeSrgb(glm::vec3(light.x(), light.y(), light.z()));
        return osg::Vec3(display.x, display.y, display.z);
    };
    const MirrorComparison m = compareFlatWaterWithOptics(h, img.get(), *water->getSettings(), osg::Matrixd(), 0.0, -1.5,
                                                          kBedGrey, 3, nullptr, skyLight);
    std::cout << m.checked << " water pixels, worst " << m.worst * 255.0 << "/255\n";
    EXPECT_FALSE(m.bedMissed);
    EXPECT_GT(m.checked, 500);
    EXPECT_LT(m.worst, 2.0 / 255.0) << "worst at pixel " << m.worstPixel.x() << ", " << m.worstPixel.y();
}
