// Procedural caustics (Sanchez-Crespo 2003), the CPU mirror: calibrated on flat water, bright lines
// where the paper's construction puts them over a single sine wave, no NaN at grazing suns.
#include "caustics/ProceduralCaustics.h"
#include "optics/Optics.h"
#include <osgWater/WaterSurface>
#include <gtest/gtest.h>
#include <cmath>

using namespace osgWater;
using namespace osgWater::procedural;

namespace {

const double kAir = 1.0, kWater = 1.333;

osg::ref_ptr<WaterSurface> sineWave(double amplitude, double wavelength)
{
    osg::ref_ptr<WaterSurface> s = new WaterSurface;
    Wave w;
    w.direction.set(1.0f, 0.0f);
    w.amplitude = float(amplitude);
    w.wavelength = float(wavelength);
    w.phase = 0.0f;
    s->setWaves({w});
    return s;
}

glm::dvec3 sunAt(double elevationDegrees)
{
    const double e = elevationDegrees * M_PI / 180.0;
    return glm::dvec3(std::cos(e), 0.0, std::sin(e));
}

} // namespace

TEST(ProceduralCaustics, TheSunAndHaloMapIsOneOnTheDiscAndFadesToNothingAtTenTimesItsRadius)
{
    const SunHalo map;
    EXPECT_NEAR(map.discRadius * 2.0 * 180.0 / M_PI, 0.53, 1e-9);
    EXPECT_EQ(sunHalo(0.0, map), 1.0);
    EXPECT_EQ(sunHalo(0.99 * map.discRadius, map), 1.0);
    EXPECT_EQ(sunHalo(map.haloRadius, map), 0.0);
    EXPECT_EQ(sunHalo(1.5 * map.haloRadius, map), 0.0);  // and dark beyond it, to the horizon
    EXPECT_EQ(sunHalo(1.5, map), 0.0);
    double previous = sunHalo(1.001 * map.discRadius, map);
    EXPECT_NEAR(previous, map.haloLevel, 0.01);
    for (double a = 1.1 * map.discRadius; a < map.haloRadius; a += 0.1 * map.discRadius) {
        const double v = sunHalo(a, map);
        EXPECT_LE(v, previous);
        previous = v;
    }
    EXPECT_EQ(sunHalo(std::nan(""), map), 0.0);
}

TEST(ProceduralCaustics, FlatWaterGivesTheCalibratedTransmittedAttenuatedLightEverywhere)
{
    osg::ref_ptr<WaterSurface> flat = new WaterSurface;
    flat->setWaves({});
    flat->setLevel(1.5);
    const double k = 0.12;
    for (double elevation : {90.0, 60.0, 25.0, 5.0}) {
        const glm::dvec3 sun = sunAt(elevation);
        const double transmitted = 1.0 - optics::fresnelExact(float(sun.z), float(kAir), float(kWater));
        // the light's path through flat water to a bed point d below the level, at the refracted angle
        const double sinT = kAir / kWater * std::cos(elevation * M_PI / 180.0), cosT = std::sqrt(1.0 - sinT * sinT);
        for (double x : {-7.0, 0.0, 3.3})
            for (double depth : {0.5, 2.0, 9.0}) {
                const Backtrace tr = backtrace(glm::dvec3(x, 1.0, 1.5 - depth), sun, *flat, 0.0, kAir, kWater);
                ASSERT_TRUE(tr.valid);
                EXPECT_NEAR(tr.angleToSun, 0.0, 1e-6);
                EXPECT_NEAR(tr.pathInWater, depth / cosT, 1e-9);
                EXPECT_NEAR(causticLight(tr, transmitted, k), transmitted * std::exp(-k * depth / cosT), 1e-9)
                    << elevation << " " << depth;
                EXPECT_EQ(causticLight(tr, transmitted, k, false), 1.0);  // the paper's value: the sun's centre
            }
    }
}

TEST(ProceduralCaustics, OverASineWaveTheLinesLieWhereTheWaveIsLevelAlongTheBackwardRay)
{
    // h = a sin(kx): level (normal straight up) at kx = pi/2 + m pi. The backward ray from the bed
    // leaves towards the sun exactly there, so the brightest bed points are those whose backward
    // ray meets the crests and troughs: straight below them for the paper's overhead sun, shifted
    // by the depth along the refracted ray for a low one.
    const double a = 0.03, L = 1.0, kw = 2.0 * M_PI / L, depth = 3.0;
    osg::ref_ptr<WaterSurface> wave = sineWave(a, L);
    for (double elevation : {90.0, 40.0}) {
        const glm::dvec3 sun = sunAt(elevation);
        const bool vertical = elevation == 90.0;
        // scan a wavelength of bed at fine steps; in each half wavelength (by the wave's phase where
        // the backward ray met it) the point whose exit ray points nearest the sun
        const int steps = 4000;
        double nearest[2] = {10.0, 10.0}, nearestX[2] = {0.0, 0.0}, light[2] = {0.0, 0.0};
        for (int i = 0; i < steps; ++i) {
            const double x = L * i / steps;
            const Backtrace tr = backtrace(glm::dvec3(x, 0.0, -depth), sun, *wave, 0.0, kAir, kWater, vertical);
            ASSERT_TRUE(tr.valid);
            const double phase = std::fmod(kw * tr.surface.x + 4.0 * M_PI, 2.0 * M_PI);
            const int half = phase < M_PI ? 0 : 1;
            if (tr.angleToSun < nearest[half]) {
                nearest[half] = tr.angleToSun;
                nearestX[half] = x;
                light[half] = causticLight(tr, 1.0, 0.0, false);
            }
        }
        for (int half = 0; half < 2; ++half) {
            EXPECT_LT(nearest[half], 1e-3);
            EXPECT_EQ(light[half], 1.0);  // on the sun's disc
            // the analytic line: the level point's x, moved back along the backward ray to the bed
            const double level = (M_PI / 2.0 + half * M_PI) / kw;
            const double surfaceZ = half == 0 ? a : -a;
            double shift = 0.0;
            if (!vertical) {
                const double sinT = kAir / kWater * std::cos(elevation * M_PI / 180.0);
                shift = (surfaceZ + depth) * sinT / std::sqrt(1.0 - sinT * sinT);
            }
            // the backward ray runs towards the sun (+x): the bed point lies `shift` before the level point
            const double expected = std::fmod(level - shift + 4.0 * L, L);
            double off = std::fabs(nearestX[half] - expected);
            off = std::min(off, L - off);
            EXPECT_LT(off, 2.0 * L / steps) << "elevation " << elevation << " half " << half;
        }
    }
    // the steepest point (kx = 0, slope a k) sends the paper's vertical backward ray off by about
    // (n - 1) a k: beyond the halo, dark
    const Backtrace steep = backtrace(glm::dvec3(0.0, 0.0, -depth), sunAt(90.0), *wave, 0.0, kAir, kWater, true);
    EXPECT_GT(steep.angleToSun, SunHalo().haloRadius);
    EXPECT_EQ(causticLight(steep, 1.0, 0.0), 0.0);
}

TEST(ProceduralCaustics, GrazingAndSetSunsGiveNoNaN)
{
    osg::ref_ptr<WaterSurface> wave = sineWave(0.05, 1.0);
    for (double z : {1e-9, 1e-4, 0.0, -0.2}) {
        const glm::dvec3 sun = glm::normalize(glm::dvec3(1.0, 0.3, z));
        for (double x = 0.0; x < 1.0; x += 0.05) {
            const Backtrace tr = backtrace(glm::dvec3(x, 0.0, -2.0), sun, *wave, 0.0, kAir, kWater);
            const double v = causticLight(tr, 0.5, 0.1);
            EXPECT_TRUE(std::isfinite(v)) << z << " " << x;
            EXPECT_GE(v, 0.0);
            EXPECT_LE(v, 1.0);
            if (z <= 0.0) EXPECT_FALSE(tr.valid);
            if (tr.valid) {
                EXPECT_TRUE(std::isfinite(tr.angleToSun));
                EXPECT_TRUE(std::isfinite(tr.surface.x) && std::isfinite(tr.surface.z));
            }
        }
    }
    // a bed point above the water has no caustics
    const Backtrace above = backtrace(glm::dvec3(0.0, 0.0, 1.0), sunAt(60.0), *wave, 0.0, kAir, kWater);
    EXPECT_FALSE(above.valid);
}
