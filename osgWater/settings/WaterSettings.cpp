#include <osgWater/WaterSettings>
#include "optics/Optics.h"
#include <osgWater/WaterTypes>
#include "settings/Clamp.h"
#include "settings/EnumNames.h"
#include <osg/Notify>
#include <osg/Math>
#include <osg/io_utils>
#include <algorithm>
#include <cmath>

using namespace osgWater;

namespace {

const char* const kOwner = "osgWater::WaterSettings";
float clampOr(const char* name, float v, float lo, float hi, float fallback)
{
    return detail::clampOr(kOwner, name, v, lo, hi, fallback);
}
int clampInt(const char* name, int v, int lo, int hi) { return detail::clampInt(kOwner, name, v, lo, hi); }

osg::Vec3 clampColor(const char* name, const osg::Vec3& c, const osg::Vec3& fallback, float hi)
{
    // one warning for the whole colour, naming the value used
    osg::Vec3 r;
    bool changed = false;
    for (int i = 0; i < 3; ++i) {
        r[i] = std::isnan(c[i]) ? fallback[i] : std::min(std::max(c[i], 0.0f), hi);
        changed = changed || !(r[i] == c[i]);
    }
    if (changed)
        OSG_WARN << "osgWater::WaterSettings: " << name << " = (" << c << ") has NaN or values out of [0, " << hi
                 << "], using (" << r << ")" << std::endl;
    return r;
}

}

WaterSettings::WaterSettings()
    : _airIOR(1.0f), _waterIOR(1.333f),
      _waterColor(0.0f, 0.2f, 0.1f), _attenuation(0.5f), _waterModel(WATER_THESIS),
      _absorption(defaultAbsorption()), _scattering(defaultScattering()), _backscattering(defaultBackscattering()),
      _fresnelModel(FRESNEL_EXACT), _fresnelExponent(5.0f), _fresnelReciprocalPower(6.62f),
      _reflectionScale(1.0f),
      _refractionLookup(ITERATIVE), _reflectionLookup(REFLECTION_SEARCH), _reflectionPlaneHeight(0.0f),
      _refractionPlaneDepth(0.0f), _searchSteps(3), _errorBudget(0.25f),
      _oneStepScale(1.0f), _oneStepMaxDepth(20.0f), _underwaterLookupScale(1.5f),
      _fovExtNear(1.5f), _fovExtFar(1.2f), _fovExtFalloff(10.0f),
      _clipOffset(0.05f),
      _reflectionTextureSize(512), _refractionTextureSize(512), _passTargetScale(0.0f),
      _causticsMotionTolerance(0.5f),
      _refractionCameraRotation(true), _refractionCameraApparentEye(true), _reflectionEnabled(true), _refractionEnabled(true),
      _causticsEnabled(true), _causticsFiltering(true), _causticsFocused(true), _causticsResolution(256), _photonGridSize(512),
      _causticsIntensity(1.0f), _causticsGather(GATHER_AUTO), _causticsMethod(CAUSTICS_PHOTONS),
      _causticsSupersampling(false), _reflectiveCaustics(false), _causticsTileSize(0.0f), _environmentMapEnabled(false), _environmentMapSize(256),
      _underwaterModel(UNDERWATER_PHYSICAL), _glowEnabled(true), _glowIntensity(1.0f), _glowRadius(3.0f),
      _glowResolution(0.25f), _glowExponent(200.0f),
      _sunDirection(defaultSunDirection()), _sunColor(1.0f, 1.0f, 0.9f), _ambientColor(0.35f, 0.38f, 0.45f),
      _exposure(1.0f), _toneCurve(TONE_CLIP), _revision(0)
{
}

osg::Vec3 WaterSettings::defaultSunDirection()
{
    osg::Vec3 d(0.3f, 0.4f, 0.866f);
    d.normalize();
    return d;
}

osg::Vec3 WaterSettings::defaultAbsorption() { return pureWater().absorption; }
osg::Vec3 WaterSettings::defaultScattering() { return pureWater().scattering; }
osg::Vec3 WaterSettings::defaultBackscattering() { return pureWater().backscattering; }

WaterSettings::WaterSettings(const WaterSettings& o, const osg::CopyOp& copyop)
    : osg::Object(o, copyop),
      _airIOR(o._airIOR), _waterIOR(o._waterIOR), _waterColor(o._waterColor), _attenuation(o._attenuation),
      _waterModel(o._waterModel), _absorption(o._absorption), _scattering(o._scattering),
      _backscattering(o._backscattering),
      _fresnelModel(o._fresnelModel), _fresnelExponent(o._fresnelExponent),
      _fresnelReciprocalPower(o._fresnelReciprocalPower), _reflectionScale(o._reflectionScale),
      _refractionLookup(o._refractionLookup), _reflectionLookup(o._reflectionLookup),
      _reflectionPlaneHeight(o._reflectionPlaneHeight), _refractionPlaneDepth(o._refractionPlaneDepth), _searchSteps(o._searchSteps), _errorBudget(o._errorBudget),
      _oneStepScale(o._oneStepScale), _oneStepMaxDepth(o._oneStepMaxDepth),
      _underwaterLookupScale(o._underwaterLookupScale),
      _fovExtNear(o._fovExtNear), _fovExtFar(o._fovExtFar), _fovExtFalloff(o._fovExtFalloff),
      _clipOffset(o._clipOffset),
      _reflectionTextureSize(o._reflectionTextureSize), _refractionTextureSize(o._refractionTextureSize),
      _passTargetScale(o._passTargetScale), _causticsMotionTolerance(o._causticsMotionTolerance),
      _refractionCameraRotation(o._refractionCameraRotation), _refractionCameraApparentEye(o._refractionCameraApparentEye),
      _reflectionEnabled(o._reflectionEnabled), _refractionEnabled(o._refractionEnabled),
      _causticsEnabled(o._causticsEnabled), _causticsFiltering(o._causticsFiltering),
      _causticsFocused(o._causticsFocused),
      _causticsResolution(o._causticsResolution), _photonGridSize(o._photonGridSize),
      _causticsIntensity(o._causticsIntensity), _causticsGather(o._causticsGather),
      _causticsMethod(o._causticsMethod), _causticsSupersampling(o._causticsSupersampling),
      _reflectiveCaustics(o._reflectiveCaustics), _causticsTileSize(o._causticsTileSize),
      _environmentMapEnabled(o._environmentMapEnabled), _environmentMapSize(o._environmentMapSize),
      _underwaterModel(o._underwaterModel), _glowEnabled(o._glowEnabled), _glowIntensity(o._glowIntensity),
      _glowRadius(o._glowRadius), _glowResolution(o._glowResolution), _glowExponent(o._glowExponent),
      _sunDirection(o._sunDirection), _sunColor(o._sunColor), _ambientColor(o._ambientColor),
      _exposure(o._exposure), _toneCurve(o._toneCurve), _revision(0)
{
}

namespace {
// an enum read from a file (or cast from an int) that names no model: the default, said once
template <typename E>
E validEnum(const char* name, E v, E last, E fallback)
{
    if (int(v) >= 0 && int(v) <= int(last)) return v;
    OSG_WARN << "osgWater::WaterSettings: " << name << " = " << int(v) << " is not one of 0.." << int(last)
             << ", using " << int(fallback) << std::endl;
    return fallback;
}
}

void WaterSettings::setWaterModel(WaterModel m) { _waterModel = validEnum("waterModel", m, WATER_PER_CHANNEL, WATER_THESIS); touch(); }
void WaterSettings::setAbsorption(const osg::Vec3& a) { _absorption = clampColor("absorption", a, defaultAbsorption(), 100.0f); touch(); }
void WaterSettings::setScattering(const osg::Vec3& b) { _scattering = clampColor("scattering", b, defaultScattering(), 100.0f); touch(); }
void WaterSettings::setBackscattering(const osg::Vec3& bb) { _backscattering = clampColor("backscattering", bb, defaultBackscattering(), 100.0f); touch(); }
void WaterSettings::setFresnelModel(FresnelModel m) { _fresnelModel = validEnum("fresnelModel", m, FRESNEL_RECIPROCAL, FRESNEL_SCHLICK); touch(); }
void WaterSettings::setRefractionLookup(RefractionLookup l) { _refractionLookup = validEnum("refractionLookup", l, VIRTUAL_VERTICES, ITERATIVE); touch(); }
void WaterSettings::setReflectionLookup(ReflectionLookup l) { _reflectionLookup = validEnum("reflectionLookup", l, REFLECTION_SEARCH, REFLECTION_SEARCH); touch(); }
void WaterSettings::setReflectionPlaneHeight(float m) { _reflectionPlaneHeight = clampOr("reflectionPlaneHeight", m, 0.0f, 10000.0f, 0.0f); touch(); }
void WaterSettings::setRefractionPlaneDepth(float m) { _refractionPlaneDepth = clampOr("refractionPlaneDepth", m, 0.0f, 10000.0f, 0.0f); touch(); }
void WaterSettings::setUnderwaterModel(UnderwaterModel m) { _underwaterModel = validEnum("underwaterModel", m, UNDERWATER_THESIS, UNDERWATER_PHYSICAL); touch(); }
void WaterSettings::setCausticsGather(CausticsGather g) { _causticsGather = validEnum("causticsGather", g, GATHER_CPU, GATHER_AUTO); touch(); }
void WaterSettings::setCausticsMethod(CausticsMethod m) { _causticsMethod = validEnum("causticsMethod", m, CAUSTICS_PROCEDURAL_SCREEN, CAUSTICS_PHOTONS); touch(); }
void WaterSettings::setAirIOR(float v) { _airIOR = clampOr("airIOR", v, 1.0f, 3.0f, 1.0f); touch(); }
void WaterSettings::setWaterIOR(float v) { _waterIOR = clampOr("waterIOR", v, 1.0f, 3.0f, 1.333f); touch(); }
void WaterSettings::setWaterColor(const osg::Vec3& c) { _waterColor = clampColor("waterColor", c, osg::Vec3(0.0f, 0.2f, 0.1f), 1.0f); touch(); }
void WaterSettings::setAttenuation(float k) { _attenuation = clampOr("attenuation", k, 0.0f, 100.0f, 0.5f); touch(); }
void WaterSettings::setFresnelExponent(float q) { _fresnelExponent = clampOr("fresnelExponent", q, 0.1f, 64.0f, 5.0f); touch(); }
void WaterSettings::setFresnelReciprocalPower(float p) { _fresnelReciprocalPower = clampOr("fresnelReciprocalPower", p, 1.0f, 32.0f, 6.62f); touch(); }

namespace {
// each enum's names in its values' order: one table per enum, read both ways
const char* const kFresnelNames[] = { "schlick", "power", "exact", "reciprocal" };
const char* const kRefractionLookupNames[] = { "one-step", "iterative", "plane", "bracketed", "virtual-vertices" };
const char* const kReflectionLookupNames[] = { "offset", "plane", "search" };
const char* const kUnderwaterModelNames[] = { "physical", "thesis" };
const char* const kCausticsGatherNames[] = { "auto", "copy", "texture", "cpu" };
const char* const kCausticsMethodNames[] = { "photons", "mesh", "procedural", "procedural-screen" };
const char* const kToneCurveNames[] = { "clip", "aces" };

// an unknown value reads as the table's first name
template <typename E, size_t N> const char* nameOf(const char* const (&names)[N], E value)
{
    return detail::nameOf(names, value, names[0]);
}
using detail::valueOf;
}

const char* WaterSettings::fresnelModelName(FresnelModel m) { return nameOf(kFresnelNames, m); }
bool WaterSettings::fresnelModelFromName(const std::string& name, FresnelModel& m) { return valueOf(kFresnelNames, name, m); }
const char* WaterSettings::refractionLookupName(RefractionLookup l) { return nameOf(kRefractionLookupNames, l); }
bool WaterSettings::refractionLookupFromName(const std::string& name, RefractionLookup& l)
{
    return valueOf(kRefractionLookupNames, name, l);
}
const char* WaterSettings::reflectionLookupName(ReflectionLookup l) { return nameOf(kReflectionLookupNames, l); }
bool WaterSettings::reflectionLookupFromName(const std::string& name, ReflectionLookup& l)
{
    return valueOf(kReflectionLookupNames, name, l);
}
const char* WaterSettings::underwaterModelName(UnderwaterModel m) { return nameOf(kUnderwaterModelNames, m); }
bool WaterSettings::underwaterModelFromName(const std::string& name, UnderwaterModel& m)
{
    return valueOf(kUnderwaterModelNames, name, m);
}
const char* WaterSettings::causticsGatherName(CausticsGather g) { return nameOf(kCausticsGatherNames, g); }
bool WaterSettings::causticsGatherFromName(const std::string& name, CausticsGather& g)
{
    return valueOf(kCausticsGatherNames, name, g);
}
const char* WaterSettings::causticsMethodName(CausticsMethod m) { return nameOf(kCausticsMethodNames, m); }
bool WaterSettings::causticsMethodFromName(const std::string& name, CausticsMethod& m)
{
    return valueOf(kCausticsMethodNames, name, m);
}
const char* WaterSettings::toneCurveName(ToneCurve c) { return nameOf(kToneCurveNames, c); }
bool WaterSettings::toneCurveFromName(const std::string& name, ToneCurve& c) { return valueOf(kToneCurveNames, name, c); }
std::string WaterSettings::fresnelModelNames() { return detail::joinedNames(kFresnelNames); }
std::string WaterSettings::refractionLookupNames() { return detail::joinedNames(kRefractionLookupNames); }
std::string WaterSettings::reflectionLookupNames() { return detail::joinedNames(kReflectionLookupNames); }
std::string WaterSettings::underwaterModelNames() { return detail::joinedNames(kUnderwaterModelNames); }
std::string WaterSettings::causticsGatherNames() { return detail::joinedNames(kCausticsGatherNames); }
std::string WaterSettings::toneCurveNames() { return detail::joinedNames(kToneCurveNames); }
std::string WaterSettings::causticsMethodNames() { return detail::joinedNames(kCausticsMethodNames); }
void WaterSettings::setReflectionScale(float c) { _reflectionScale = clampOr("reflectionScale", c, 0.0f, 1000.0f, 1.0f); touch(); }
void WaterSettings::setSearchSteps(int n) { _searchSteps = clampInt("searchSteps", n, 1, 8); touch(); }
void WaterSettings::setErrorBudget(float texels) { _errorBudget = clampOr("errorBudget", texels, 1.0f / 64.0f, 16.0f, 0.25f); touch(); }
void WaterSettings::setOneStepScale(float s) { _oneStepScale = clampOr("oneStepScale", s, 0.0f, 100.0f, 1.0f); touch(); }
void WaterSettings::setOneStepMaxDepth(float d) { _oneStepMaxDepth = clampOr("oneStepMaxDepth", d, 0.0f, 1.0e4f, 20.0f); touch(); }
void WaterSettings::setUnderwaterLookupScale(float m) { _underwaterLookupScale = clampOr("underwaterLookupScale", m, 0.0f, 1000.0f, 1.5f); touch(); }
void WaterSettings::setClipOffset(float d) { _clipOffset = clampOr("clipOffset", d, 0.0f, 100.0f, 0.05f); touch(); }
void WaterSettings::setReflectionTextureSize(int s) { _reflectionTextureSize = clampInt("reflectionTextureSize", s, 16, 4096); touch(); }
void WaterSettings::setPassTargetScale(float f)
{
    // 0 selects the fixed sizes; anything else is a fraction of the viewport
    _passTargetScale = f == 0.0f ? 0.0f : clampOr("passTargetScale", f, 0.05f, 2.0f, 0.0f);
    touch();
}
void WaterSettings::setCausticsMotionTolerance(float t)
{
    _causticsMotionTolerance = clampOr("causticsMotionTolerance", t, 0.0f, 16.0f, 0.5f);
    touch();
}
void WaterSettings::setRefractionTextureSize(int s) { _refractionTextureSize = clampInt("refractionTextureSize", s, 16, 4096); touch(); }
void WaterSettings::setCausticsResolution(int s) { _causticsResolution = clampInt("causticsResolution", s, 16, 4096); touch(); }
void WaterSettings::setPhotonGridSize(int s) { _photonGridSize = clampInt("photonGridSize", s, 16, 4096); touch(); }
void WaterSettings::setCausticsTileSize(float m) { _causticsTileSize = clampOr("causticsTileSize", m, 0.0f, 10000.0f, 0.0f); touch(); }
void WaterSettings::setEnvironmentMapSize(int s) { _environmentMapSize = clampInt("environmentMapSize", s, 16, 2048); touch(); }
void WaterSettings::setCausticsIntensity(float v) { _causticsIntensity = clampOr("causticsIntensity", v, 0.0f, 100.0f, 1.0f); touch(); }
void WaterSettings::setGlowIntensity(float v) { _glowIntensity = clampOr("glowIntensity", v, 0.0f, 100.0f, 1.0f); touch(); }
void WaterSettings::setGlowRadius(float r) { _glowRadius = clampOr("glowRadius", r, 0.0f, 32.0f, 3.0f); touch(); }
void WaterSettings::setGlowResolution(float f) { _glowResolution = clampOr("glowResolution", f, 1.0f / 64.0f, 1.0f, 0.25f); touch(); }
void WaterSettings::setGlowExponent(float e) { _glowExponent = clampOr("glowExponent", e, 1.0f, 10000.0f, 200.0f); touch(); }
void WaterSettings::setSunColor(const osg::Vec3& c) { _sunColor = clampColor("sunColor", c, osg::Vec3(1.0f, 1.0f, 0.9f), 100.0f); touch(); }
void WaterSettings::setAmbientColor(const osg::Vec3& c) { _ambientColor = clampColor("ambientColor", c, osg::Vec3(0.35f, 0.38f, 0.45f), 100.0f); touch(); }
void WaterSettings::setExposure(float e) { _exposure = clampOr("exposure", e, 0.0f, 1000.0f, 1.0f); touch(); }
void WaterSettings::setToneCurve(ToneCurve c) { _toneCurve = validEnum("toneCurve", c, TONE_ACES, TONE_CLIP); touch(); }

void WaterSettings::setFovExtension(float nearExt, float farExt, float falloffHeight)
{
    setFovExtensionNear(nearExt);
    setFovExtensionFar(farExt);
    setFovExtensionFalloff(falloffHeight);
}

void WaterSettings::setFovExtensionNear(float v) { _fovExtNear = clampOr("fovExtensionNear", v, 1.0f, 4.0f, 1.5f); touch(); }
void WaterSettings::setFovExtensionFar(float v) { _fovExtFar = clampOr("fovExtensionFar", v, 1.0f, 4.0f, 1.2f); touch(); }
void WaterSettings::setFovExtensionFalloff(float v) { _fovExtFalloff = clampOr("fovExtensionFalloff", v, 0.01f, 1.0e5f, 10.0f); touch(); }

void WaterSettings::setSunDirection(const osg::Vec3& d)
{
    osg::Vec3d n(d); // double: a 1e30 component would overflow the float length
    const bool finite = std::isfinite(n.x()) && std::isfinite(n.y()) && std::isfinite(n.z());
    if (!finite || n.length2() < 1e-24) {
        n = defaultSunDirection();
        OSG_WARN << "osgWater::WaterSettings: sunDirection (" << d << ") is not a direction, using (" << n << ")"
                 << std::endl;
    }
    // a direction already of unit length is kept as it is: normalising again can flip its last bit,
    // and a file written and read back would not be the same (found by the fuzz target)
    if (std::fabs(n.length() - 1.0) > 1e-6) n.normalize();
    _sunDirection = osg::Vec3(n);
    touch();
}

osg::Vec3 WaterSettings::getViewExtinction() const
{
    if (_waterModel == WATER_THESIS) return osg::Vec3(_attenuation, _attenuation, _attenuation);
    return _absorption + _scattering;
}

osg::Vec3 WaterSettings::effectiveBackscattering() const
{
    // backscattering beyond the scattering is not light the water can send back: at most b counts
    return osg::Vec3(std::min(_backscattering.x(), _scattering.x()), std::min(_backscattering.y(), _scattering.y()),
                     std::min(_backscattering.z(), _scattering.z()));
}

osg::Vec3 WaterSettings::getSunExtinction() const
{
    if (_waterModel == WATER_THESIS) return osg::Vec3(_attenuation, _attenuation, _attenuation);
    return _absorption + effectiveBackscattering();
}

osg::Vec3 WaterSettings::getBodyColor() const
{
    if (_waterModel == WATER_THESIS) return _waterColor;
    // the light falling on the water: the sun on a level surface, and the sky
    const osg::Vec3 light = _sunColor * std::max(_sunDirection.z(), 0.0f) + _ambientColor;
    osg::Vec3 r;
    for (int i = 0; i < 3; ++i)
        r[i] = std::min(1.0f, light[i] * optics::deepWaterReflectance(_absorption[i], effectiveBackscattering()[i]));
    return r;
}

float WaterSettings::getNormalReflectance() const
{
    const float r = (_airIOR - _waterIOR) / (_airIOR + _waterIOR);
    return r * r;
}

float WaterSettings::fovExtensionAt(double eyeHeight) const
{
    // exponential falloff: exactly nearExt on the water, e-folding height falloffHeight.
    const double h = std::isfinite(eyeHeight) ? std::fabs(eyeHeight) : 1.0e30;
    const double w = std::exp(-h / _fovExtFalloff);
    return float(_fovExtFar + (_fovExtNear - _fovExtFar) * w);
}
