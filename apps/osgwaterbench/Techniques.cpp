#include "Techniques.h"
#include <utility>
#include <sstream>

namespace bench {

using osgWater::WaterSettings;

std::vector<Technique> allTechniques()
{
    std::vector<Technique> t;
    t.push_back({ "default", [](WaterSettings&) {} });
    t.push_back({ "one-step", [](WaterSettings& s) { s.setRefractionLookup(WaterSettings::ONE_STEP); } });
    for (int steps = 1; steps <= 8; ++steps)
        t.push_back({ "iterative-" + std::to_string(steps), [steps](WaterSettings& s) {
                         s.setRefractionLookup(WaterSettings::ITERATIVE);
                         s.setSearchSteps(steps);
                     } });
    // the error budget's frontier: each search stopped by the budget alone (eight steps at most);
    // the default is a quarter texel, capped at three steps
    const std::pair<const char*, float> budgets[] = { { "0.0625", 1.0f / 16.0f }, { "0.25", 0.25f }, { "1", 1.0f }, { "4", 4.0f } };
    for (const auto& [name, texels] : budgets)
        t.push_back({ std::string("budget-") + name, [texels = texels](WaterSettings& s) {
                         s.setSearchSteps(8);
                         s.setErrorBudget(texels);
                     } });
    t.push_back({ "refraction-bracketed", [](WaterSettings& s) { s.setRefractionLookup(WaterSettings::BRACKETED); } });
    t.push_back({ "refraction-virtual-vertices", [](WaterSettings& s) { s.setRefractionLookup(WaterSettings::VIRTUAL_VERTICES); } });
    t.push_back({ "refraction-plane", [](WaterSettings& s) { s.setRefractionLookup(WaterSettings::PLANE_OFFSET); } });
    t.push_back({ "reflection-offset", [](WaterSettings& s) { s.setReflectionLookup(WaterSettings::REFLECTION_OFFSET); } });
    t.push_back({ "reflection-plane", [](WaterSettings& s) { s.setReflectionLookup(WaterSettings::REFLECTION_PLANE); } });
    t.push_back({ "mesh-grid", [](WaterSettings&) {}, osgWater::WaterSurface::MESH_GRID });
    // the two wave models side by side, each against the exact reference of its own surface
    t.push_back({ "waves-sum", [](WaterSettings&) {}, std::nullopt, osgWater::WaterSurface::WAVES_SUM });
    t.push_back({ "waves-wind", [](WaterSettings&) {}, std::nullopt, osgWater::WaterSurface::WAVES_WIND });
    t.push_back({ "environment-map", [](WaterSettings& s) { s.setEnvironmentMapEnabled(true); } });
    t.push_back({ "no-rotation", [](WaterSettings& s) { s.setRefractionCameraRotation(false); } });
    t.push_back({ "rotation-thesis", [](WaterSettings& s) { s.setRefractionCameraApparentEye(false); } });
    for (int size : { 256, 1024 })
        t.push_back({ "texture-" + std::to_string(size), [size](WaterSettings& s) {
                         s.setReflectionTextureSize(size);
                         s.setRefractionTextureSize(size);
                     } });
    for (float f : { 0.5f, 1.0f })
        t.push_back({ "view-targets-" + std::string(f == 0.5f ? "0.5" : "1"), [f](WaterSettings& s) { s.setPassTargetScale(f); } });
    t.push_back({ "fresnel-schlick", [](WaterSettings& s) { s.setFresnelModel(WaterSettings::FRESNEL_SCHLICK); } });
    t.push_back({ "fresnel-power", [](WaterSettings& s) { s.setFresnelModel(WaterSettings::FRESNEL_POWER); } });
    t.push_back({ "fresnel-exact", [](WaterSettings& s) { s.setFresnelModel(WaterSettings::FRESNEL_EXACT); } });
    t.push_back({ "fresnel-reciprocal", [](WaterSettings& s) { s.setFresnelModel(WaterSettings::FRESNEL_RECIPROCAL); } });
    t.push_back({ "caustics-off", [](WaterSettings& s) { s.setCausticsEnabled(false); } });
    t.push_back({ "caustics-unfocused", [](WaterSettings& s) { s.setCausticsFocused(false); } });
    const std::pair<const char*, WaterSettings::CausticsGather> gathers[] = {
        { "caustics-cpu", WaterSettings::GATHER_CPU },
        { "caustics-points-copy", WaterSettings::GATHER_POINTS_COPY },
        { "caustics-points-texture", WaterSettings::GATHER_POINTS_TEXTURE } };
    for (const auto& [name, g] : gathers)
        t.push_back({ name, [g = g](WaterSettings& s) {
                         s.setCausticsEnabled(true);
                         s.setCausticsGather(g);
                     } });
    // a quarter of the photons (the lake's: one per caustics texel against its settings' four)
    t.push_back({ "caustics-photons-halved", [](WaterSettings& s) { s.setPhotonGridSize(s.getPhotonGridSize() / 2); } });
    t.push_back({ "caustics-mesh", [](WaterSettings& s) { s.setCausticsMethod(WaterSettings::CAUSTICS_AREA_MESH); } });
    t.push_back({ "caustics-procedural", [](WaterSettings& s) { s.setCausticsMethod(WaterSettings::CAUSTICS_PROCEDURAL); } });
    t.push_back({ "caustics-procedural-screen", [](WaterSettings& s) { s.setCausticsMethod(WaterSettings::CAUSTICS_PROCEDURAL_SCREEN); } });
    t.push_back({ "caustics-mesh-supersampled", [](WaterSettings& s) {
                     s.setCausticsMethod(WaterSettings::CAUSTICS_AREA_MESH);
                     s.setCausticsSupersampling(true);
                 } });
    // the lake's waves do not repeat over 8 m: the row measures the seams and the flat bed together
    t.push_back({ "caustics-tiled", [](WaterSettings& s) { s.setCausticsTileSize(8.0f); } });
    t.push_back({ "caustics-reflective", [](WaterSettings& s) { s.setReflectiveCaustics(true); } });
    t.push_back({ "glow-off", [](WaterSettings& s) { s.setGlowEnabled(false); } });
    t.push_back({ "quality-fast", [](WaterSettings& s) { s.setQuality(WaterSettings::QUALITY_FAST); } });
    t.push_back({ "quality-exact", [](WaterSettings& s) { s.setQuality(WaterSettings::QUALITY_EXACT); } });
    t.push_back({ "underwater-thesis", [](WaterSettings& s) { s.setUnderwaterModel(WaterSettings::UNDERWATER_THESIS); } });
    return t;
}

bool selectTechniques(const std::string& list, std::vector<Technique>& out, std::string& error)
{
    const std::vector<Technique> all = allTechniques();
    out.clear();
    if (list.empty() || list == "all") {
        out = all;
        return true;
    }
    std::istringstream in(list);
    std::string name;
    while (std::getline(in, name, ',')) {
        if (name.empty()) continue;
        bool found = false;
        for (const Technique& t : all)
            if (t.name == name) { out.push_back(t); found = true; }
        if (!found) {
            error = "unknown technique '" + name + "'; known:";
            for (const Technique& t : all) error += " " + t.name;
            return false;
        }
    }
    if (out.empty()) error = "no techniques selected";
    return !out.empty();
}

std::string lookupName(const WaterSettings& s)
{
    return WaterSettings::refractionLookupName(s.getRefractionLookup());
}

std::string fresnelName(const WaterSettings& s) { return WaterSettings::fresnelModelName(s.getFresnelModel()); }

std::string causticsName(const WaterSettings& s)
{
    if (!s.getCausticsEnabled()) return "off";
    std::string gather;
    switch (s.getCausticsGather()) {
    case WaterSettings::GATHER_CPU: gather = "cpu"; break;
    case WaterSettings::GATHER_POINTS_COPY: gather = "points-copy"; break;
    case WaterSettings::GATHER_POINTS_TEXTURE: gather = "points-texture"; break;
    default: gather = "auto"; break;
    }
    // the method and the supersampling, where not the defaults: "mesh-auto", "mesh-auto-2x2"
    if (s.getCausticsMethod() != WaterSettings::CAUSTICS_PHOTONS)
        gather = std::string(WaterSettings::causticsMethodName(s.getCausticsMethod())) + "-" + gather;
    return s.getCausticsSupersampling() ? gather + "-2x2" : gather;
}

}
