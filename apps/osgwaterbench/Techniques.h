// The techniques and settings the benchmark compares: the scene's own settings ("default"), and
// one axis changed at a time (refraction lookup and its steps, camera rotation, texture size,
// Fresnel model, caustics path, glow, underwater model, the surface's mesh and wave model).
#pragma once
#include <osgWater/WaterSettings>
#include <osgWater/WaterSurface>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace bench {

struct Technique {
    std::string name;
    std::function<void(osgWater::WaterSettings&)> apply; //!< applied to a copy of the scene's settings
    //! The surface's mesh layout for this technique; none: the scene's (put back after each)
    std::optional<osgWater::WaterSurface::MeshLayout> mesh;
    //! The surface's wave model (the wind's: its WindWaves); none: the scene's (put back after each)
    std::optional<osgWater::WaterSurface::WaveModel> waves;
};

//! Every technique, "default" first.
std::vector<Technique> allTechniques();
//! Those named in a comma-separated list ("all" or empty: every one); false with the unknown name.
bool selectTechniques(const std::string& list, std::vector<Technique>& out, std::string& error);

//! Labels of settings as they appear in the results.
std::string lookupName(const osgWater::WaterSettings& s);
std::string fresnelName(const osgWater::WaterSettings& s);
std::string causticsName(const osgWater::WaterSettings& s);

}
