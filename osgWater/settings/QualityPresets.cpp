// The quality presets: bundles of the settings that trade speed against error, each a point on
// the frontier osgwaterbench measures (its preset rows in docs/BENCHMARKS.md give their ratios
// and errors). BALANCED is the defaults.
#include <osgWater/WaterSettings>
#include "settings/EnumNames.h"
#include <osg/Notify>

using namespace osgWater;

namespace {

struct SpeedSettings {
    WaterSettings::RefractionLookup lookup;
    WaterSettings::ReflectionLookup reflection;
    int searchSteps;
    float passTargetScale;
    int textureSize; // reflection and refraction, when the scale is 0
    int causticsResolution, photonGrid;
    float causticsMotionTolerance;
    float glowResolution;
    bool operator==(const SpeedSettings& o) const
    {
        return lookup == o.lookup && reflection == o.reflection && searchSteps == o.searchSteps && passTargetScale == o.passTargetScale &&
               textureSize == o.textureSize && causticsResolution == o.causticsResolution &&
               photonGrid == o.photonGrid && causticsMotionTolerance == o.causticsMotionTolerance &&
               glowResolution == o.glowResolution;
    }
};

// QUALITY_FAST, QUALITY_BALANCED, QUALITY_EXACT
const SpeedSettings kPresets[3] = {
    // one-step lookup (SCCG 2008) and the thesis's offset reflection, targets a third of the view,
    // caustics at half the resolution kept two texels
    { WaterSettings::ONE_STEP, WaterSettings::REFLECTION_OFFSET, 3, 0.35f, 512, 128, 256, 2.0f, 0.125f },
    // the defaults: 3-step searches, 512-texel squares, caustics kept half a texel
    { WaterSettings::ITERATIVE, WaterSettings::REFLECTION_SEARCH, 3, 0.0f, 512, 256, 512, 0.5f, 0.25f },
    // 8-step searches, targets of the view's resolution, finer caustics rendered whenever the waves move
    { WaterSettings::ITERATIVE, WaterSettings::REFLECTION_SEARCH, 8, 1.0f, 512, 512, 1024, 0.0f, 0.5f },
};

SpeedSettings speedSettingsOf(const WaterSettings& s)
{
    // one texture size when both agree; otherwise no preset can match
    const int size = s.getReflectionTextureSize() == s.getRefractionTextureSize() ? s.getRefractionTextureSize() : -1;
    return { s.getRefractionLookup(), s.getReflectionLookup(), s.getSearchSteps(), s.getPassTargetScale(), size, s.getCausticsResolution(),
             s.getPhotonGridSize(), s.getCausticsMotionTolerance(), s.getGlowResolution() };
}

}

void WaterSettings::setQuality(Quality q)
{
    if (q == QUALITY_CUSTOM) return; // "as they are": nothing to set
    if (q < QUALITY_FAST || q > QUALITY_EXACT) {
        OSG_WARN << "osgWater::WaterSettings: quality " << int(q)
                 << " is no preset (fast, balanced, exact); the settings are kept" << std::endl;
        return;
    }
    const SpeedSettings& p = kPresets[q];
    setRefractionLookup(p.lookup);
    setReflectionLookup(p.reflection);
    setSearchSteps(p.searchSteps);
    setPassTargetScale(p.passTargetScale);
    setReflectionTextureSize(p.textureSize);
    setRefractionTextureSize(p.textureSize);
    setCausticsResolution(p.causticsResolution);
    setPhotonGridSize(p.photonGrid);
    setCausticsMotionTolerance(p.causticsMotionTolerance);
    setGlowResolution(p.glowResolution);
}

WaterSettings::Quality WaterSettings::getQuality() const
{
    const SpeedSettings mine = speedSettingsOf(*this);
    for (int q = QUALITY_FAST; q <= QUALITY_EXACT; ++q)
        if (mine == kPresets[q]) return Quality(q);
    return QUALITY_CUSTOM;
}

namespace {
// the presets' names in their values' order (QUALITY_CUSTOM, -1, reads as "custom")
const char* const kQualityNames[] = { "fast", "balanced", "exact" };
}

const char* WaterSettings::qualityName(Quality q) { return detail::nameOf(kQualityNames, q, "custom"); }
bool WaterSettings::qualityFromName(const std::string& name, Quality& q) { return detail::valueOf(kQualityNames, name, q); }
std::string WaterSettings::qualityNames() { return detail::joinedNames(kQualityNames); }
