// The clear sky (sky/ClearSky): Preetham's fits at the zenith against the paper's appendix worked
// by hand, and the shape of a clear sky: blue at the zenith and whiter toward the sun and in haze,
// brighter on the sun's side, darkest opposite it; sRGB's white at D65's chromaticity; bad
// suns and turbidities give a finite sky; the node's bad settings are clamped with a warning. No GPU.
#include "optics/Srgb.h"
#include "sky/ClearSky.h"
#include <osgWater/Sky>
#include <osgWater/WaterSettings>
#include <osg/Notify>
#include "WarnCapture.h"
#include <algorithm>
#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <string>

using namespace osgWater;

namespace {
const double kPi = 3.14159265358979323846;

// a direction at zenith angle theta and azimuth phi (radians), z up
glm::dvec3 toward(double theta, double phi)
{
    return glm::dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}
}

// Turbidity 2.5, the sun 0.5 rad from the zenith: the appendix's zenith luminance
// (4.0453 T - 4.9710) tan chi - 0.2155 T + 2.4192, chi = (4/9 - T/120)(pi - 2 theta_s), and its
// chromaticity polynomials, evaluated by hand to 8.4572 kcd/m^2 at (0.25332, 0.25893); and the
// luminance 1 rad from the zenith on the far side (gamma 1.5) to 5.5135 kcd/m^2
TEST(Sky, TheZenithAndASkyPointAreTheAppendixsWorkedByHand)
{
    const double t = 2.5, sunTheta = 0.5;
    EXPECT_NEAR(sky::zenithLuminance(t, sunTheta), 8.45723, 1e-4);
    EXPECT_NEAR(sky::zenithChromaticity(t, sunTheta).x, 0.253324, 1e-5);
    EXPECT_NEAR(sky::zenithChromaticity(t, sunTheta).y, 0.258927, 1e-5);
    const sky::ClearSky s(toward(sunTheta, 0.0), t);
    const glm::dvec3 zenith = s.xyY(glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_NEAR(zenith.z, 8.45723, 1e-4);
    EXPECT_NEAR(zenith.x, 0.253324, 1e-5);
    EXPECT_NEAR(s.xyY(toward(1.0, kPi)).z, 5.51345, 1e-4);
}

// A clear sky's shape, at three suns and two turbidities: blue at the zenith (x and y under D65's
// 0.3127, 0.3290), whiter near the sun; brighter on the sun's side than at the same height on the
// far side; mirror-symmetric about the sun's vertical plane, in which its darkest point lies on the
// far side; hazier air brighter and whiter at the zenith. (Preetham's fits do not put the
// brightest sky around a high sun in very clear air: their horizon band outshines it at
// turbidity 2.)
TEST(Sky, AClearSkyIsBlueOverheadBrighterTowardTheSunAndDarkestOppositeIt)
{
    for (double sunTheta : { 0.3, 0.8, 1.2 })
        for (double t : { 2.0, 6.0 }) {
            const std::string name = std::to_string(sunTheta) + " rad, turbidity " + std::to_string(t);
            const sky::ClearSky s(toward(sunTheta, 0.0), t);
            const glm::dvec3 zenith = s.xyY(glm::dvec3(0.0, 0.0, 1.0));
            EXPECT_LT(zenith.x, 0.3127) << name;
            EXPECT_LT(zenith.y, 0.3290) << name;
            EXPECT_GT(s.xyY(toward(sunTheta + 0.05, 0.0)).x, zenith.x) << name;
            for (double theta : { 0.2, 0.7, 1.2, 1.5 }) {
                EXPECT_GT(s.xyY(toward(theta, 0.0)).z, s.xyY(toward(theta, kPi)).z) << name << ", at " << theta;
                EXPECT_NEAR(s.xyY(toward(theta, 1.0)).z, s.xyY(toward(theta, -1.0)).z, 1e-9) << name << ", at " << theta;
            }
            double darkest = 1e30, darkestPhi = 0.0;
            for (int i = 0; i <= 90; ++i)
                for (int j = 0; j < 180; ++j) {
                    const double theta = i * (0.5 * kPi - 0.01) / 90.0, phi = j * 2.0 * kPi / 180.0;
                    const double y = s.xyY(toward(theta, phi)).z;
                    if (y < darkest) { darkest = y; darkestPhi = phi; }
                }
            EXPECT_NEAR(darkestPhi, kPi, 1e-9) << name;
        }
    const sky::ClearSky clear(toward(0.8, 0.0), 2.0), hazy(toward(0.8, 0.0), 6.0);
    const glm::dvec3 c = clear.xyY(glm::dvec3(0.0, 0.0, 1.0)), h = hazy.xyY(glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_GT(h.z, c.z);
    EXPECT_GT(h.x, c.x);
    EXPECT_GT(h.y, c.y);
}

// The light comes out in linear sRGB: D65's chromaticity is its white, and the matrix back is the
// inverse of the one there
TEST(Sky, D65sChromaticityIsSrgbsWhite)
{
    const glm::dvec3 white = optics::linearSrgbFromXyz(optics::xyzFromChromaticity(0.3127, 0.3290, 1.0));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(white[i], 1.0, 2e-3) << i; // the chromaticity's four digits
    const glm::dvec3 rgb(0.2, 0.5, 0.9), back = optics::linearSrgbFromXyz(optics::xyzFromLinearSrgb(rgb));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(back[i], rgb[i], 1e-12) << i;
    // a clear sky's zenith is blue in sRGB too
    const glm::dvec3 zenith = sky::ClearSky(toward(0.8, 0.0), 2.0).linearSrgb(glm::dvec3(0.0, 0.0, 1.0));
    EXPECT_GT(zenith.b, zenith.r);
    EXPECT_GT(zenith.b, zenith.g);
}

// A sun below the horizon is taken on it, a sun of no direction at the zenith, a turbidity out of
// range clamped: every direction, the horizon and below included, gives finite, positive light
TEST(Sky, BadSunsAndTurbiditiesGiveAFiniteSky)
{
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const glm::dvec3 suns[] = { glm::dvec3(0.0, 1.0, -0.5), glm::dvec3(0.0), glm::dvec3(nan, 0.0, 1.0), glm::dvec3(inf, 1.0, 1.0),
                                glm::dvec3(0.0, 0.0, -1.0), glm::dvec3(1.0, 0.0, 0.0) };
    for (const glm::dvec3& sun : suns)
        for (double t : { nan, -3.0, 0.0, 1.0e9, 3.0 }) {
            const sky::ClearSky s(sun, t);
            EXPECT_GE(s.turbidity(), sky::MIN_TURBIDITY);
            EXPECT_LE(s.turbidity(), sky::MAX_TURBIDITY);
            for (const glm::dvec3& d : { glm::dvec3(0.0, 0.0, 1.0), glm::dvec3(1.0, 0.0, 0.0), glm::dvec3(0.0, 1.0, -1.0), glm::dvec3(0.0),
                                          glm::dvec3(nan, 1.0, 0.0), s.towardSun() }) {
                const glm::dvec3 c = s.xyY(d);
                EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)) << sun.x << " " << t;
                EXPECT_GT(c.z, 0.0) << sun.x << " " << sun.z << " " << t;
            }
        }
}

// The node's settings: a turbidity out of range or NaN and a scale below zero are clamped with a
// warning, a sun of no direction refused with one (the sky keeps its sun); its light is the model's
// times the scale, zero or more
TEST(Sky, TheNodesBadSettingsAreClampedWithAWarning)
{
    osg::ref_ptr<Sky> s = new Sky;
    EXPECT_EQ(s->getSunDirection(), WaterSettings::defaultSunDirection());
    {
        ScopedWarnCapture warnings;
        s->setTurbidity(50.0f);
        EXPECT_EQ(s->getTurbidity(), float(sky::MAX_TURBIDITY));
        s->setTurbidity(std::nanf(""));
        EXPECT_EQ(s->getTurbidity(), 2.5f);
        s->setLuminanceScale(-1.0f);
        EXPECT_EQ(s->getLuminanceScale(), 0.0f);
        const osg::Vec3 before = s->getSunDirection();
        s->setSunDirection(osg::Vec3(0.0f, 0.0f, 0.0f));
        EXPECT_EQ(s->getSunDirection(), before);
        EXPECT_NE(warnings.str().find("turbidity"), std::string::npos) << warnings.str();
        EXPECT_NE(warnings.str().find("sun direction"), std::string::npos) << warnings.str();
    }
    s->setLuminanceScale(0.1f);
    s->setSunDirection(osg::Vec3(0.0f, 3.0f, 4.0f));
    EXPECT_NEAR(s->getSunDirection().length(), 1.0f, 1e-6f);
    const glm::dvec3 model = sky::ClearSky(glm::dvec3(0.0, 0.6, 0.8), 2.5).linearSrgb(glm::dvec3(1.0, 0.0, 0.5));
    const osg::Vec3 light = s->getRadiance(osg::Vec3(1.0f, 0.0f, 0.5f));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(light[i], 0.1 * std::max(model[i], 0.0), 1e-6) << i;
}
