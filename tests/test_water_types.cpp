// The per-channel water model: its presets against their published sources, the closed forms it
// rests on, its values through a file (bad values: test_bad_values.cpp). No GPU.
#include <osgWater/WaterTypes>
#include <osgWater/WaterSettings>
#include "frame/SceneLighting.h"
#include "optics/Optics.h"
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>
#include <gtest/gtest.h>
#include "WarnCapture.h"
#include <cmath>

using namespace osgWater;

namespace {
// depth at which a line of sight keeps 10% of the bed's light in the green channel
float clarity(const WaterType& t) { return std::log(10.0f) / (t.optics.absorption.y() + t.optics.scattering.y()); }
}

TEST(WaterTypes, PureWaterIsPopeAndFryAbsorptionAndMorelScattering)
{
    const WaterOptics w = pureWater();
    // Pope & Fry (1997) at 650, 550, 450 nm
    EXPECT_FLOAT_EQ(w.absorption.x(), 0.340f);
    EXPECT_FLOAT_EQ(w.absorption.y(), 0.0565f);
    EXPECT_FLOAT_EQ(w.absorption.z(), 0.00922f);
    // Morel (1974): 0.0031 per metre at 450 nm, wavelength^-4.32, half of it backwards
    EXPECT_FLOAT_EQ(w.scattering.z(), 0.0031f);
    EXPECT_NEAR(w.scattering.y(), 0.0031 * std::pow(550.0 / 450.0, -4.32), 1e-7);
    EXPECT_NEAR(w.scattering.x(), 0.0031 * std::pow(650.0 / 450.0, -4.32), 1e-7);
    for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(w.backscattering[i], 0.5f * w.scattering[i]);
    // the defaults of the per-channel model are pure water
    osg::ref_ptr<WaterSettings> s = new WaterSettings;
    EXPECT_EQ(s->getAbsorption(), w.absorption);
    EXPECT_EQ(s->getScattering(), w.scattering);
}

TEST(WaterTypes, ConstituentsAddTheirSpectralShapes)
{
    WaterConstituents c;
    c.cdomAbsorption440 = 1.0f;
    const WaterOptics pure = pureWater(), cdom = naturalWater(c);
    // Bricaud et al. (1981): exp(-0.014 (l - 440)) at 650 / 550 / 450 nm
    EXPECT_NEAR(cdom.absorption.z() - pure.absorption.z(), std::exp(-0.014 * 10.0), 1e-6);
    EXPECT_NEAR(cdom.absorption.y() - pure.absorption.y(), std::exp(-0.014 * 110.0), 1e-6);
    EXPECT_NEAR(cdom.absorption.x() - pure.absorption.x(), std::exp(-0.014 * 210.0), 1e-6);
    EXPECT_EQ(cdom.scattering, pure.scattering); // dissolved: it does not scatter
    WaterConstituents p;
    p.particleScattering550 = 1.0f;
    const WaterOptics particles = naturalWater(p);
    EXPECT_NEAR(particles.scattering.y() - pure.scattering.y(), 1.0, 1e-6);
    EXPECT_NEAR(particles.scattering.z() - pure.scattering.z(), 550.0 / 450.0, 1e-6);
    EXPECT_NEAR(particles.backscattering.y() - pure.backscattering.y(), 0.0183, 1e-6); // Petzold
}

TEST(WaterTypes, PresetsLookLikeTheirNames)
{
    ASSERT_EQ(waterTypes().size(), 3u);
    const WaterType* lake = findWaterType("clear-lake");
    const WaterType* pond = findWaterType("murky-pond");
    const WaterType* sea = findWaterType("tropical-sea");
    ASSERT_TRUE(lake && pond && sea);
    EXPECT_EQ(findWaterType("lava"), nullptr);
    EXPECT_EQ(waterTypeNames(), "clear-lake, murky-pond, tropical-sea");
    // clarity: the bed of a clear lake shows to some metres, of the tropical sea to tens, of a pond to one
    EXPECT_GT(clarity(*lake), 5.0f);
    EXPECT_LT(clarity(*lake), 15.0f);
    EXPECT_GT(clarity(*sea), 15.0f);
    EXPECT_LT(clarity(*pond), 2.0f);
    // every natural water takes red first; the sea's blue goes furthest, the pond's blue least far
    for (const WaterType& t : waterTypes()) EXPECT_GT(t.optics.absorption.x(), t.optics.absorption.y()) << t.name;
    EXPECT_LT(sea->optics.absorption.z(), sea->optics.absorption.y());
    EXPECT_GT(pond->optics.absorption.z(), pond->optics.absorption.y());
    // the deep colour: the sea is blue, the pond is not
    osg::ref_ptr<WaterSettings> s = new WaterSettings;
    applyWaterType(*s, *sea);
    const osg::Vec3 seaColor = s->getBodyColor();
    EXPECT_GT(seaColor.z(), seaColor.y());
    EXPECT_GT(seaColor.y(), seaColor.x());
    applyWaterType(*s, *pond);
    EXPECT_LT(s->getBodyColor().z(), s->getBodyColor().x());
}

// By name: a known preset applies; a typo is said, with the names there are, and changes nothing
// (it used to be a null pointer for the caller to dereference)
TEST(WaterTypes, AnUnknownNameIsSaidAndKeepsTheSettings)
{
    osg::ref_ptr<WaterSettings> s = new WaterSettings;
    EXPECT_TRUE(applyWaterType(*s, "tropical-sea"));
    EXPECT_EQ(s->getWaterModel(), WaterSettings::WATER_PER_CHANNEL);
    EXPECT_EQ(s->getAbsorption(), findWaterType("tropical-sea")->optics.absorption);
    ScopedWarnCapture warnings;
    EXPECT_FALSE(applyWaterType(*s, "clear-lak"));
    EXPECT_NE(warnings.str().find("clear-lak"), std::string::npos) << warnings.str();
    EXPECT_NE(warnings.str().find(waterTypeNames()), std::string::npos) << warnings.str();
    EXPECT_EQ(s->getAbsorption(), findWaterType("tropical-sea")->optics.absorption); // kept
}

TEST(WaterTypes, TheThesisModelIsOneKAndTheWaterColour)
{
    osg::ref_ptr<WaterSettings> s = new WaterSettings;
    EXPECT_EQ(s->getWaterModel(), WaterSettings::WATER_THESIS); // table 1 stays the default
    s->setAttenuation(0.3f);
    s->setWaterColor(osg::Vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(s->getViewExtinction(), osg::Vec3(0.3f, 0.3f, 0.3f));
    EXPECT_EQ(s->getSunExtinction(), osg::Vec3(0.3f, 0.3f, 0.3f));
    EXPECT_EQ(s->getBodyColor(), osg::Vec3(0.1f, 0.2f, 0.3f));
    EXPECT_FLOAT_EQ(photonExtinction(*s), 0.3f);
    EXPECT_EQ(channelExtinction(*s), osg::Vec3f()); // one k: the photons are right in every channel
}

TEST(WaterTypes, PerChannelExtinctionAndBodyColourFollowTheirDefinitions)
{
    osg::ref_ptr<WaterSettings> s = new WaterSettings;
    s->setWaterModel(WaterSettings::WATER_PER_CHANNEL);
    s->setAbsorption(osg::Vec3(0.4f, 0.1f, 0.05f));
    s->setScattering(osg::Vec3(0.2f, 0.3f, 0.4f));
    s->setBackscattering(osg::Vec3(0.01f, 0.02f, 0.03f));
    s->setSunDirection(osg::Vec3(0.0f, 0.0f, 1.0f)); // overhead: no refraction of the sun's path
    s->setSunColor(osg::Vec3(1.0f, 1.0f, 1.0f));
    s->setAmbientColor(osg::Vec3(0.5f, 0.5f, 0.5f));
    EXPECT_LT((s->getViewExtinction() - osg::Vec3(0.6f, 0.4f, 0.45f)).length(), 1e-6f); // c = a + b
    EXPECT_LT((s->getSunExtinction() - osg::Vec3(0.41f, 0.12f, 0.08f)).length(), 1e-6f); // K = a + b_b
    EXPECT_FLOAT_EQ(photonExtinction(*s), 0.12f);                              // green
    const osg::Vec3f extra = channelExtinction(*s);
    EXPECT_NEAR(extra.x(), 0.41f - 0.12f, 1e-6f);
    EXPECT_NEAR(extra.z(), 0.08f - 0.12f, 1e-6f);
    // light on the water 1.5: R of Gordon et al. (1975) at u = bb / (a + bb)
    const double u = 0.02 / 0.12;
    EXPECT_NEAR(s->getBodyColor().y(), 1.5 * (0.0001 + 0.3244 * u + 0.1425 * u * u + 0.1308 * u * u * u), 1e-6);
    // a sun 60 degrees from the zenith: the path below is depth / cos of the refracted angle
    s->setSunDirection(osg::Vec3(std::sin(osg::PI / 3.0), 0.0f, std::cos(osg::PI / 3.0)));
    const double sinT = std::sin(osg::PI / 3.0) / s->getWaterIOR();
    EXPECT_NEAR(channelExtinction(*s).x(), (0.41 - 0.12) / std::sqrt(1.0 - sinT * sinT), 1e-5);
}

TEST(WaterTypes, APresetGoesThroughAFileExactly)
{
    osg::ref_ptr<WaterSettings> s = new WaterSettings;
    applyWaterType(*s, *findWaterType("tropical-sea"));
    for (const char* ext : { "osgt", "osgb" }) {
        const std::string file = std::string(OSGWATER_TEST_TMP) + "/sea." + ext;
        ASSERT_TRUE(osgDB::writeObjectFile(*s, file));
        osg::ref_ptr<WaterSettings> t = dynamic_cast<WaterSettings*>(osgDB::readObjectFile(file));
        ASSERT_TRUE(t.valid()) << ext;
        EXPECT_EQ(t->getWaterModel(), WaterSettings::WATER_PER_CHANNEL) << ext;
        EXPECT_EQ(t->getAbsorption(), s->getAbsorption()) << ext;
        EXPECT_EQ(t->getScattering(), s->getScattering()) << ext;
        EXPECT_EQ(t->getBackscattering(), s->getBackscattering()) << ext;
    }
}
