/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_CAUSTICSMETHOD
#define OSGWATER_CAUSTICSMETHOD 1

#include <osgWater/WaterSettings>

namespace osgWater {

//! How one set of caustics passes makes its caustics this frame: the one place the setting is
//! turned into what runs.
struct CausticsChoice {
    WaterSettings::CausticsMethod gathered; //!< what the gather pass draws into the caustics texture
    bool procedural;                        //!< no photons are traced (the procedural construction)
    bool perPixel;                          //!< made by the scene program at each fragment: no photon
                                            //!< or gather pass runs, only the sun's depth map
};

//! `wanted`: the settings' method; `reflectedPasses`: the sun's reflection's passes (no procedural
//! construction: their photons stay); `tiled`: tileable caustics (the area-ratio mesh's: photon
//! splats would lose the light straddling a tile's edges); `reflectiveRun`: the reflective caustics'
//! passes run this frame too (then the per-pixel variant falls back to the texture, whose passes
//! run anyway).
inline CausticsChoice chooseCaustics(WaterSettings::CausticsMethod wanted, bool reflectedPasses, bool tiled,
                                     bool reflectiveRun)
{
    CausticsChoice c;
    c.gathered = tiled ? WaterSettings::CAUSTICS_AREA_MESH : wanted;
    // the gather's procedural path is the texture-space variant's, which the per-pixel one falls back to
    if (c.gathered == WaterSettings::CAUSTICS_PROCEDURAL_SCREEN) c.gathered = WaterSettings::CAUSTICS_PROCEDURAL;
    if (reflectedPasses && c.gathered == WaterSettings::CAUSTICS_PROCEDURAL) c.gathered = WaterSettings::CAUSTICS_PHOTONS;
    c.procedural = c.gathered == WaterSettings::CAUSTICS_PROCEDURAL;
    c.perPixel = c.procedural && wanted == WaterSettings::CAUSTICS_PROCEDURAL_SCREEN && !reflectiveRun;
    return c;
}

}

#endif
