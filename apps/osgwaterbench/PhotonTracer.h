// Caustics reference by forward photon tracing (thesis ch. 8, done exactly): photons leave the
// sun's window uniformly (two independent sets of jittered strata), meet the water unless the scene
// stands in their way first (a dry shore, a pier), refract at the water surface by Snell with exact
// Fresnel transmission, lose exp(-k d) on the way to what they hit below, and land in the texel of
// the caustics texture that the scene shader would read at that point. The result is in the
// texture's units: irradiance per area seen from the sun, in units of the sun's irradiance.
#pragma once
#include "Reference.h"
#include <osg/Matrixd>
#include <osg/Image>
#include "frame/SceneLighting.h"
#include <cstddef>
#include <vector>

namespace bench {

struct PhotonSettings {
    size_t photons = 4000000;
    int resolution = 512;         //!< caustics texture size
    double attenuation = 0.0;     //!< k per metre
    Media media;
    bool progress = true;         //!< a progress bar on stderr
};

struct PhotonImage {
    int resolution = 0;
    size_t photons = 0;           //!< photons traced
    std::vector<float> value;     //!< resolution^2, row 0 at v = 0
    //! The same estimate from each half of the photons alone (two independent sets of strata over
    //! the whole window): value is their mean, and their difference measures its noise.
    std::vector<float> half[2];
};

//! localToSun: the water's local frame -> the sun camera's texture space [0,1]^3 (the matrix the
//! scene shader uses); towardsSun: unit vector to the sun, local frame.
PhotonImage tracePhotons(const RayCaster& scene, const WaterCaster& water, const osgWater::WaterSurface& surface,
                         double t, const osg::Matrixd& localToSun, const osg::Vec3d& towardsSun,
                         const PhotonSettings& settings);

//! Tileable caustics brought into the reference's texels: for each texel of the sun's window
//! (`lighting.localToSun`, `resolution` per side), what the scene shader reads from the repeating
//! tile (RGBA float, `lighting.localToTile`) at the bed point under it: the first scene hit below
//! the water `level` along the straight sun ray (0 where there is none), faded by that point's depth
//! as the scene program fades it (the green channel). RGBA float, value in red.
osg::ref_ptr<osg::Image> tileSeenFromTheSun(const osg::Image* tile, const RayCaster& scene,
                                            const osgWater::CausticsLighting& lighting, const osg::Vec3d& towardsSun,
                                            double level, int resolution);

}
