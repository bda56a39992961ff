// WaterSettings: thesis table 1 defaults, and clamping of absurd input with a warning.
#include <osgWater/WaterSettings>
#include <osgWater/WaterSurface>
#include <osg/Notify>
#include "WarnCapture.h"
#include <gtest/gtest.h>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace osgWater;


TEST(Settings, DefaultsAreThesisTable1)
{
    osg::ref_ptr<WaterSettings> s = new WaterSettings;
    EXPECT_FLOAT_EQ(s->getReflectionScale(), 1.0f);   // c
    EXPECT_FLOAT_EQ(s->getAttenuation(), 0.5f);       // k
    EXPECT_EQ(s->getWaterColor(), osg::Vec3(0.0f, 0.2f, 0.1f));
    EXPECT_FLOAT_EQ(s->getFresnelExponent(), 5.0f);   // q
    EXPECT_FLOAT_EQ(s->getFresnelReciprocalPower(), 6.62f); // the fit for water (docs/FRESNEL.md)
    EXPECT_FLOAT_EQ(s->getFovExtensionNear(), 1.5f);  // FOV_ext
    EXPECT_EQ(s->getReflectionTextureSize(), 512);
    EXPECT_EQ(s->getRefractionTextureSize(), 512);
    EXPECT_EQ(s->getSearchSteps(), 3);
    EXPECT_EQ(s->getRefractionLookup(), WaterSettings::ITERATIVE);
    EXPECT_NEAR(s->getAirIOR() / s->getWaterIOR(), 0.75f, 1e-3f); // the shader's 0.75
    EXPECT_EQ(s->getCausticsResolution(), 256);                     // thesis §9.2
    EXPECT_TRUE(s->getCausticsFiltering());                         // "with enabled filtering"
    EXPECT_TRUE(s->getCausticsFocused());                           // the passes cover only the lit water
    EXPECT_FLOAT_EQ(s->getGlowExponent(), 200.0f);                  // thesis §9.3 pow(R.E, 200)
    EXPECT_FLOAT_EQ(s->getExposure(), 1.0f);                        // linear light 1 shows as white
    EXPECT_FLOAT_EQ(s->getGlowRadius(), 3.0f);                      // thesis's 7x7 filter
    EXPECT_FLOAT_EQ(s->getGlowResolution(), 0.25f);                 // 1/4 per axis
    EXPECT_FLOAT_EQ(s->getUnderwaterLookupScale(), 1.5f);           // m of eq. 13
    EXPECT_EQ(s->getUnderwaterModel(), WaterSettings::UNDERWATER_PHYSICAL);
}

TEST(Settings, FovExtensionFallsWithEyeHeight)
{
    osg::ref_ptr<WaterSettings> s = new WaterSettings;
    EXPECT_NEAR(s->fovExtensionAt(0.0), 1.5f, 1e-6f);   // thesis: ~50% near the surface
    EXPECT_NEAR(s->fovExtensionAt(1e6), 1.2f, 1e-6f);   // ~20% far away
    EXPECT_NEAR(s->fovExtensionAt(-3.0), s->fovExtensionAt(3.0), 1e-7f);
    EXPECT_GT(s->fovExtensionAt(2.0), s->fovExtensionAt(20.0));
    EXPECT_TRUE(std::isfinite(s->fovExtensionAt(NAN)));
}

TEST(Settings, AbsurdValuesAreClampedWithAWarning)
{
    osg::ref_ptr<WaterSettings> s = new WaterSettings;
    {
        ScopedWarnCapture w;
        s->setReflectionTextureSize(-5);
        EXPECT_NE(w.str().find("reflectionTextureSize"), std::string::npos);
    }
    EXPECT_EQ(s->getReflectionTextureSize(), 16);
    {
        ScopedWarnCapture w;
        s->setRefractionTextureSize(1000000000);
        EXPECT_NE(w.str().find("clamped"), std::string::npos);
    }
    EXPECT_EQ(s->getRefractionTextureSize(), 4096);
    {
        ScopedWarnCapture w;
        s->setWaterColor(osg::Vec3(NAN, 2.0f, -1.0f));
        EXPECT_NE(w.str().find("NaN"), std::string::npos);
    }
    EXPECT_EQ(s->getWaterColor(), osg::Vec3(0.0f, 1.0f, 0.0f));
    s->setSearchSteps(0);
    EXPECT_EQ(s->getSearchSteps(), 1);
    s->setSearchSteps(99);
    EXPECT_EQ(s->getSearchSteps(), 8);
    s->setAttenuation(NAN);
    EXPECT_FLOAT_EQ(s->getAttenuation(), 0.5f);
    s->setAttenuation(INFINITY);
    EXPECT_FLOAT_EQ(s->getAttenuation(), 100.0f);
    s->setWaterIOR(0.1f);
    EXPECT_FLOAT_EQ(s->getWaterIOR(), 1.0f);
    s->setFovExtension(NAN, 0.5f, -1.0f);
    EXPECT_FLOAT_EQ(s->getFovExtensionNear(), 1.5f);
    EXPECT_FLOAT_EQ(s->getFovExtensionFar(), 1.0f);
    EXPECT_GT(s->getFovExtensionFalloff(), 0.0f);
    {
        ScopedWarnCapture w;
        s->setCausticsIntensity(NAN);
        EXPECT_NE(w.str().find("causticsIntensity"), std::string::npos);
    }
    EXPECT_FLOAT_EQ(s->getCausticsIntensity(), 1.0f);
    s->setCausticsIntensity(-3.0f);
    EXPECT_FLOAT_EQ(s->getCausticsIntensity(), 0.0f);
    s->setCausticsResolution(0);
    EXPECT_EQ(s->getCausticsResolution(), 16);
    s->setPhotonGridSize(1 << 20);
    EXPECT_EQ(s->getPhotonGridSize(), 4096);
    {
        ScopedWarnCapture w;
        s->setGlowResolution(INFINITY);
        EXPECT_NE(w.str().find("glowResolution"), std::string::npos);
    }
    EXPECT_FLOAT_EQ(s->getGlowResolution(), 1.0f);
    s->setGlowResolution(0.0f);
    EXPECT_FLOAT_EQ(s->getGlowResolution(), 1.0f / 64.0f);
    s->setGlowRadius(NAN);
    EXPECT_FLOAT_EQ(s->getGlowRadius(), 3.0f);
    s->setGlowRadius(1e9f);
    EXPECT_FLOAT_EQ(s->getGlowRadius(), 32.0f);
    s->setGlowExponent(0.0f);
    EXPECT_FLOAT_EQ(s->getGlowExponent(), 1.0f);
    s->setGlowIntensity(-1.0f);
    EXPECT_FLOAT_EQ(s->getGlowIntensity(), 0.0f);
    s->setSunDirection(osg::Vec3(0.0f, 0.0f, 0.0f));
    EXPECT_NEAR(s->getSunDirection().length(), 1.0f, 1e-6f);
}

// A quality that is no preset is said and changes nothing (it used to pass silently, leaving the
// settings to read as custom); custom itself changes nothing quietly
TEST(Settings, AQualityThatIsNoPresetIsSaidAndChangesNothing)
{
    osg::ref_ptr<WaterSettings> s = new WaterSettings;
    s->setQuality(WaterSettings::QUALITY_EXACT);
    ScopedWarnCapture warnings;
    s->setQuality(WaterSettings::Quality(99));
    EXPECT_EQ(s->getQuality(), WaterSettings::QUALITY_EXACT);
    EXPECT_NE(warnings.str().find("quality 99"), std::string::npos) << warnings.str();
    s->setQuality(WaterSettings::QUALITY_CUSTOM);
    EXPECT_EQ(s->getQuality(), WaterSettings::QUALITY_EXACT);
    EXPECT_EQ(warnings.str().find("quality -1"), std::string::npos) << warnings.str();
}

// Each enum's list of names (what help texts and messages show) holds one name per value, from the
// first value to the last, each reading back as its value
template <typename E>
void expectEveryValueNamedOnce(const std::string& names, const char* (*nameOf)(E), bool (*fromName)(const std::string&, E&),
                               E first, E last)
{
    std::vector<std::string> listed;
    std::stringstream in(names);
    for (std::string name; std::getline(in, name, '|');) listed.push_back(name);
    ASSERT_EQ(int(listed.size()), int(last) - int(first) + 1) << names;
    for (int v = int(first); v <= int(last); ++v) {
        EXPECT_EQ(listed[v - int(first)], nameOf(E(v))) << names;
        E back;
        EXPECT_TRUE(fromName(listed[v - int(first)], back) && int(back) == v) << listed[v - int(first)];
    }
}

TEST(Settings, EveryNameListHoldsEachValueOnceInOrder)
{
    using S = WaterSettings;
    expectEveryValueNamedOnce(S::fresnelModelNames(), S::fresnelModelName, S::fresnelModelFromName, S::FRESNEL_SCHLICK,
                              S::FRESNEL_RECIPROCAL);
    expectEveryValueNamedOnce(S::refractionLookupNames(), S::refractionLookupName, S::refractionLookupFromName, S::ONE_STEP,
                              S::VIRTUAL_VERTICES);
    expectEveryValueNamedOnce(S::reflectionLookupNames(), S::reflectionLookupName, S::reflectionLookupFromName,
                              S::REFLECTION_OFFSET, S::REFLECTION_SEARCH);
    expectEveryValueNamedOnce(S::underwaterModelNames(), S::underwaterModelName, S::underwaterModelFromName,
                              S::UNDERWATER_PHYSICAL, S::UNDERWATER_THESIS);
    expectEveryValueNamedOnce(S::causticsGatherNames(), S::causticsGatherName, S::causticsGatherFromName, S::GATHER_AUTO,
                              S::GATHER_CPU);
    expectEveryValueNamedOnce(S::causticsMethodNames(), S::causticsMethodName, S::causticsMethodFromName, S::CAUSTICS_PHOTONS,
                              S::CAUSTICS_PROCEDURAL_SCREEN);
    expectEveryValueNamedOnce(S::qualityNames(), S::qualityName, S::qualityFromName, S::QUALITY_FAST, S::QUALITY_EXACT);
    S::Quality q;
    EXPECT_FALSE(S::qualityFromName("custom", q)); // a name, but no preset to apply
    expectEveryValueNamedOnce(WaterSurface::meshLayoutNames(), WaterSurface::meshLayoutName, WaterSurface::meshLayoutFromName,
                              WaterSurface::MESH_GRID, WaterSurface::MESH_EYE_RINGS);
    expectEveryValueNamedOnce(WaterSurface::waveModelNames(), WaterSurface::waveModelName, WaterSurface::waveModelFromName,
                              WaterSurface::WAVES_SUM, WaterSurface::WAVES_WIND);
}

TEST(Settings, SettersBumpTheRevision)
{
    osg::ref_ptr<WaterSettings> s = new WaterSettings;
    const unsigned int r0 = s->getRevision();
    s->setFresnelModel(WaterSettings::FRESNEL_EXACT);
    EXPECT_GT(s->getRevision(), r0);
    const unsigned int r1 = s->getRevision();
    s->setSearchSteps(5);
    EXPECT_GT(s->getRevision(), r1);
}

TEST(Settings, NormalReflectanceIsEquation8)
{
    osg::ref_ptr<WaterSettings> s = new WaterSettings;
    const float r = (1.0f - 0.75f) / (1.0f + 0.75f);
    EXPECT_NEAR(s->getNormalReflectance(), r * r, 1e-4f);
}
