// Every numeric setting of WaterSettings and WaterSurface, fed negative, zero, NaN, Inf and absurd
// values: the value kept is finite and in range, and a changed value says so in exactly one warning
// naming the setting; a value kept as given says nothing.
#include <osgWater/WaterSettings>
#include <osgWater/WaterSurface>
#include "WarnCapture.h"
#include <gtest/gtest.h>
#include <climits>
#include <cmath>
#include <functional>
#include <limits>

using namespace osgWater;

namespace {

size_t countWarnings(const std::string& text)
{
    size_t n = 0;
    for (size_t p = text.find("osgWater::"); p != std::string::npos; p = text.find("osgWater::", p + 1)) ++n;
    return n;
}

struct FloatSetting {
    const char* name;
    std::function<void(WaterSettings&, WaterSurface&, float)> set;
    std::function<float(const WaterSettings&, const WaterSurface&)> get;
    float lo, hi;
};

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

#define SETTING(NAME, SETTER, GETTER, LO, HI)                                                       \
    FloatSetting { NAME, [](WaterSettings& s, WaterSurface&, float v) { s.SETTER(v); },              \
                   [](const WaterSettings& s, const WaterSurface&) { return float(s.GETTER()); }, LO, HI }
#define COLOR(NAME, SETTER, GETTER, HI)                                                                       \
    FloatSetting { NAME, [](WaterSettings& s, WaterSurface&, float v) { s.SETTER(osg::Vec3(v, 0.5f, v)); },   \
                   [](const WaterSettings& s, const WaterSurface&) { return s.GETTER().x() + s.GETTER().z(); }, \
                   0.0f, 2.0f * HI }
#define WAVE(NAME, FIELD, LO, HI)                                                                       \
    FloatSetting { NAME, [](WaterSettings&, WaterSurface& w, float v) {                                 \
                       std::vector<Wave> waves(1); waves[0].FIELD = v; w.setWaves(waves); },          \
                   [](const WaterSettings&, const WaterSurface& w) { return float(w.getWaves()[0].FIELD); }, LO, HI }

std::vector<FloatSetting> floatSettings()
{
    return {
        SETTING("airIOR", setAirIOR, getAirIOR, 1.0f, 3.0f),
        SETTING("waterIOR", setWaterIOR, getWaterIOR, 1.0f, 3.0f),
        SETTING("attenuation", setAttenuation, getAttenuation, 0.0f, 100.0f),
        SETTING("fresnelExponent", setFresnelExponent, getFresnelExponent, 0.1f, 64.0f),
        SETTING("fresnelReciprocalPower", setFresnelReciprocalPower, getFresnelReciprocalPower, 1.0f, 32.0f),
        SETTING("reflectionPlaneHeight", setReflectionPlaneHeight, getReflectionPlaneHeight, 0.0f, 10000.0f),
        SETTING("refractionPlaneDepth", setRefractionPlaneDepth, getRefractionPlaneDepth, 0.0f, 10000.0f),
        SETTING("reflectionScale", setReflectionScale, getReflectionScale, 0.0f, 1000.0f),
        SETTING("errorBudget", setErrorBudget, getErrorBudget, 1.0f / 64.0f, 16.0f),
        SETTING("oneStepScale", setOneStepScale, getOneStepScale, 0.0f, 100.0f),
        SETTING("oneStepMaxDepth", setOneStepMaxDepth, getOneStepMaxDepth, 0.0f, 1.0e4f),
        SETTING("underwaterLookupScale", setUnderwaterLookupScale, getUnderwaterLookupScale, 0.0f, 1000.0f),
        SETTING("clipOffset", setClipOffset, getClipOffset, 0.0f, 100.0f),
        SETTING("causticsIntensity", setCausticsIntensity, getCausticsIntensity, 0.0f, 100.0f),
        SETTING("causticsMotionTolerance", setCausticsMotionTolerance, getCausticsMotionTolerance, 0.0f, 16.0f),
        SETTING("causticsTileSize", setCausticsTileSize, getCausticsTileSize, 0.0f, 10000.0f),
        SETTING("passTargetScale", setPassTargetScale, getPassTargetScale, 0.0f, 2.0f),
        SETTING("glowIntensity", setGlowIntensity, getGlowIntensity, 0.0f, 100.0f),
        SETTING("glowRadius", setGlowRadius, getGlowRadius, 0.0f, 32.0f),
        SETTING("glowResolution", setGlowResolution, getGlowResolution, 1.0f / 64.0f, 1.0f),
        SETTING("glowExponent", setGlowExponent, getGlowExponent, 1.0f, 10000.0f),
        SETTING("exposure", setExposure, getExposure, 0.0f, 1000.0f),
        SETTING("fovExtensionNear", setFovExtensionNear, getFovExtensionNear, 1.0f, 4.0f),
        SETTING("fovExtensionFar", setFovExtensionFar, getFovExtensionFar, 1.0f, 4.0f),
        SETTING("fovExtensionFalloff", setFovExtensionFalloff, getFovExtensionFalloff, 0.01f, 1.0e5f),
        COLOR("waterColor", setWaterColor, getWaterColor, 1.0f),
        COLOR("sunColor", setSunColor, getSunColor, 100.0f),
        COLOR("ambientColor", setAmbientColor, getAmbientColor, 100.0f),
        COLOR("absorption", setAbsorption, getAbsorption, 100.0f),
        COLOR("scattering", setScattering, getScattering, 100.0f),
        COLOR("backscattering", setBackscattering, getBackscattering, 100.0f),
        FloatSetting{ "sunDirection",
                      [](WaterSettings& s, WaterSurface&, float v) { s.setSunDirection(osg::Vec3(v, v, v)); },
                      [](const WaterSettings& s, const WaterSurface&) { return s.getSunDirection().length(); },
                      0.999f, 1.001f },
        FloatSetting{ "level", [](WaterSettings&, WaterSurface& w, float v) { w.setLevel(v); },
                      [](const WaterSettings&, const WaterSurface& w) { return float(w.getLevel()); }, -1e7f, 1e7f },
        FloatSetting{ "size", [](WaterSettings&, WaterSurface& w, float v) { w.setSize(v); },
                      [](const WaterSettings&, const WaterSurface& w) { return w.getSize(); }, 0.01f, 1e7f },
        FloatSetting{ "center", [](WaterSettings&, WaterSurface& w, float v) { w.setCenter(osg::Vec2(v, v)); },
                      [](const WaterSettings&, const WaterSurface& w) { return w.getCenter().x(); }, -1e7f, 1e7f },
        WAVE("wavelength", wavelength, 0.01f, 1e6f),
        WAVE("amplitude", amplitude, 0.0f, 1e3f),
        WAVE("phase", phase, -std::numeric_limits<float>::max(), std::numeric_limits<float>::max()),
        FloatSetting{ "direction",
                      [](WaterSettings&, WaterSurface& w, float v) {
                          std::vector<Wave> waves(1); waves[0].direction.set(v, 0.0f); w.setWaves(waves); },
                      [](const WaterSettings&, const WaterSurface& w) { return w.getWaves()[0].direction.length(); },
                      0.999f, 1.001f },
    };
}

struct IntSetting {
    const char* name;
    std::function<void(WaterSettings&, WaterSurface&, long long)> set;
    std::function<long long(const WaterSettings&, const WaterSurface&)> get;
    long long lo, hi;
};

#define ISETTING(NAME, SETTER, GETTER, LO, HI)                                                        \
    IntSetting { NAME, [](WaterSettings& s, WaterSurface&, long long v) { s.SETTER(int(v)); },          \
                 [](const WaterSettings& s, const WaterSurface&) { return (long long)s.GETTER(); }, LO, HI }

std::vector<IntSetting> intSettings()
{
    return {
        ISETTING("searchSteps", setSearchSteps, getSearchSteps, 1, 8),
        ISETTING("reflectionTextureSize", setReflectionTextureSize, getReflectionTextureSize, 16, 4096),
        ISETTING("refractionTextureSize", setRefractionTextureSize, getRefractionTextureSize, 16, 4096),
        ISETTING("causticsResolution", setCausticsResolution, getCausticsResolution, 16, 4096),
        ISETTING("photonGridSize", setPhotonGridSize, getPhotonGridSize, 16, 4096),
        ISETTING("environmentMapSize", setEnvironmentMapSize, getEnvironmentMapSize, 16, 2048),
        IntSetting{ "resolution", [](WaterSettings&, WaterSurface& w, long long v) { w.setResolution((unsigned int)v); },
                    [](const WaterSettings&, const WaterSurface& w) { return (long long)w.getResolution(); }, 2, 1025 },
    };
}

}

TEST(BadValues, EveryFloatSettingKeepsAFiniteInRangeValueAndWarnsOnce)
{
    const float values[] = { -1.0f, 0.0f, kNaN, kInf, -kInf, 1e30f, -1e30f, 1e-30f };
    for (const FloatSetting& f : floatSettings())
        for (float v : values) {
            osg::ref_ptr<WaterSettings> s = new WaterSettings;
            osg::ref_ptr<WaterSurface> w = new WaterSurface;
            ScopedWarnCapture capture;
            f.set(*s, *w, v);
            const float kept = f.get(*s, *w);
            const std::string text = capture.str();
            SCOPED_TRACE(std::string(f.name) + " = " + std::to_string(v) + ", warnings: " + text);
            EXPECT_TRUE(std::isfinite(kept));
            EXPECT_GE(kept, f.lo);
            EXPECT_LE(kept, f.hi);
            EXPECT_LE(countWarnings(text), 1u) << "one warning per bad value";
            if (countWarnings(text) == 1) EXPECT_NE(text.find(f.name), std::string::npos) << "the warning names the setting";
            if (!std::isfinite(v)) EXPECT_EQ(countWarnings(text), 1u) << "a non-finite value is never kept silently";
        }
}

TEST(BadValues, EveryIntegerSettingIsClampedWithOneWarning)
{
    const long long values[] = { -1, 0, 1, INT_MIN, INT_MAX, 1LL << 20 };
    for (const IntSetting& f : intSettings())
        for (long long v : values) {
            osg::ref_ptr<WaterSettings> s = new WaterSettings;
            osg::ref_ptr<WaterSurface> w = new WaterSurface;
            ScopedWarnCapture capture;
            f.set(*s, *w, v);
            const long long kept = f.get(*s, *w);
            const std::string text = capture.str();
            SCOPED_TRACE(std::string(f.name) + " = " + std::to_string(v) + ", warnings: " + text);
            EXPECT_GE(kept, f.lo);
            EXPECT_LE(kept, f.hi);
            const bool changed = f.name == std::string("resolution") ? (long long)(unsigned int)v != kept : v != kept;
            EXPECT_EQ(countWarnings(text), changed ? 1u : 0u);
            if (changed) EXPECT_NE(text.find(std::to_string(kept)), std::string::npos) << "the warning gives the value used";
        }
}

TEST(BadValues, AGoodValueIsKeptSilently)
{
    osg::ref_ptr<WaterSettings> s = new WaterSettings;
    osg::ref_ptr<WaterSurface> w = new WaterSurface;
    ScopedWarnCapture capture;
    s->setWaterIOR(1.5f);
    s->setWaterColor(osg::Vec3(0.1f, 0.2f, 0.3f));
    s->setSunDirection(osg::Vec3(0.0f, 0.0f, -1.0f)); // a sun below the horizon is a direction like any other
    w->setLevel(-3.0);
    w->setCenter(osg::Vec2(5.0f, -5.0f));
    EXPECT_EQ(capture.str(), "");
    EXPECT_FLOAT_EQ(s->getWaterIOR(), 1.5f);
    EXPECT_EQ(s->getSunDirection(), osg::Vec3(0.0f, 0.0f, -1.0f));
}

TEST(BadValues, EnumsThatNameNoModelFallBackToTheDefaultWithOneWarning)
{
    // a file can hold any int where an enum goes (osgDB maps unknown names to numbers)
    struct EnumSetting {
        const char* name;
        std::function<int(WaterSettings&, int)> setGet;
        int last, fallback;
    };
    const EnumSetting enums[] = {
        { "fresnelModel", [](WaterSettings& s, int v) { s.setFresnelModel(WaterSettings::FresnelModel(v)); return int(s.getFresnelModel()); }, 3, 0 },
        { "refractionLookup", [](WaterSettings& s, int v) { s.setRefractionLookup(WaterSettings::RefractionLookup(v)); return int(s.getRefractionLookup()); }, 4, 1 },
        { "reflectionLookup", [](WaterSettings& s, int v) { s.setReflectionLookup(WaterSettings::ReflectionLookup(v)); return int(s.getReflectionLookup()); }, 2, 2 },
        { "underwaterModel", [](WaterSettings& s, int v) { s.setUnderwaterModel(WaterSettings::UnderwaterModel(v)); return int(s.getUnderwaterModel()); }, 1, 0 },
        { "waterModel", [](WaterSettings& s, int v) { s.setWaterModel(WaterSettings::WaterModel(v)); return int(s.getWaterModel()); }, 1, 0 },
        { "causticsGather", [](WaterSettings& s, int v) { s.setCausticsGather(WaterSettings::CausticsGather(v)); return int(s.getCausticsGather()); }, 3, 0 },
        { "causticsMethod", [](WaterSettings& s, int v) { s.setCausticsMethod(WaterSettings::CausticsMethod(v)); return int(s.getCausticsMethod()); }, 3, 0 },
        { "toneCurve", [](WaterSettings& s, int v) { s.setToneCurve(WaterSettings::ToneCurve(v)); return int(s.getToneCurve()); }, 1, 0 },
    };
    for (const EnumSetting& e : enums)
        for (int v : { INT_MIN, -1, 0, 1, e.last, e.last + 1, 1000, INT_MAX }) {
            osg::ref_ptr<WaterSettings> s = new WaterSettings;
            ScopedWarnCapture capture;
            const int kept = e.setGet(*s, v);
            const bool valid = v >= 0 && v <= e.last;
            SCOPED_TRACE(std::string(e.name) + " = " + std::to_string(v) + ", warnings: " + capture.str());
            EXPECT_EQ(kept, valid ? v : e.fallback);
            EXPECT_EQ(countWarnings(capture.str()), valid ? 0u : 1u);
            if (!valid) EXPECT_NE(capture.str().find(e.name), std::string::npos);
        }
    for (int v : { INT_MIN, -1, 0, 1, 2, 1000, INT_MAX }) {
        osg::ref_ptr<WaterSurface> s = new WaterSurface;
        ScopedWarnCapture capture;
        s->setMeshLayout(WaterSurface::MeshLayout(v));
        const bool valid = v == 0 || v == 1;
        SCOPED_TRACE("meshLayout = " + std::to_string(v) + ", warnings: " + capture.str());
        EXPECT_EQ(int(s->getMeshLayout()), valid ? v : int(WaterSurface::MESH_EYE_RINGS));
        EXPECT_EQ(countWarnings(capture.str()), valid ? 0u : 1u);
        if (!valid) EXPECT_NE(capture.str().find("meshLayout"), std::string::npos);
    }
}

TEST(BadValues, AMeshWithBadVerticesOrIndicesIsRefusedWithOneWarning)
{
    auto mesh = [](float z, unsigned short lastIndex) {
        osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
        osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
        v->push_back(osg::Vec3(-5, -5, 0));
        v->push_back(osg::Vec3(5, -5, 0));
        v->push_back(osg::Vec3(5, 5, z));
        v->push_back(osg::Vec3(5, 5, z)); // duplicate vertex, zero-area triangle: fine
        g->setVertexArray(v.get());
        osg::ref_ptr<osg::DrawElementsUShort> e = new osg::DrawElementsUShort(GL_TRIANGLES);
        for (unsigned short i : { 0, 1, 2, 2, 3, 2, 0, 1 }) e->push_back(i);
        e->push_back(lastIndex);
        g->addPrimitiveSet(e.get());
        return g;
    };
    {
        osg::ref_ptr<WaterSurface> w = new WaterSurface;
        ScopedWarnCapture capture;
        w->setMesh(mesh(0.0f, 3).get());
        EXPECT_FALSE(w->usesGrid());
        EXPECT_EQ(capture.str(), "");
    }
    const struct { float z; unsigned short last; const char* says; } bad[] = {
        { kNaN, 3, "vertex coordinate" }, { kInf, 3, "vertex coordinate" }, { 1e30f, 3, "vertex coordinate" },
        { 0.0f, 4, "indexes vertex 4 of 4" }, { 0.0f, 65535, "indexes vertex 65535" } };
    for (const auto& b : bad) {
        osg::ref_ptr<WaterSurface> w = new WaterSurface;
        ScopedWarnCapture capture;
        w->setMesh(mesh(b.z, b.last).get());
        SCOPED_TRACE(capture.str());
        EXPECT_TRUE(w->usesGrid());
        EXPECT_EQ(countWarnings(capture.str()), 1u);
        EXPECT_NE(capture.str().find(b.says), std::string::npos);
        EXPECT_TRUE(std::isfinite(w->getMaxAmplitude()));
    }
}
