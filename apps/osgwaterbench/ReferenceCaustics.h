// The direct sun under the water in the reference image, as the photon reference measured it: the
// scene program's sun term below the level is the sun times the caustics' irradiance there (thesis
// ch. 8) and zero in an underwater shadow; here both come from exact machinery, not from the kit's
// passes: the photons traced through the waves (PhotonTracer), and a shadow ray cast along the
// sun's path under a level surface.
#pragma once
#include "PhotonTracer.h"
#include "RayCaster.h"
#include <osg/Matrixd>
#include <glm/vec3.hpp>
#include <functional>

namespace bench {

//! What lights the bed below the water, in the kit's terms (osgWater::CausticsLighting and
//! WaterSettings): the photons' texels over the sun's window, and how the scene program scales them.
struct UnderwaterSun {
    const PhotonImage* photons = nullptr; //!< in the caustics texture's units, over `localToSun`'s window
    osg::Matrixd localToSun;              //!< water-local -> the sun's window, [0,1]^2 across it
    double intensity = 1.0;               //!< CausticsLighting::intensity
    glm::dvec3 channelExtinction{ 0.0 };  //!< per metre of depth, beyond the photons' own (green) fading
    double level = 0.0;                   //!< the water's level
    glm::dvec3 towardsSun{ 0.0, 0.0, 1.0 }; //!< unit, in the air
    double airIOR = 1.0, waterIOR = 1.33;
};

//! The share of the direct sun, per channel, at a scene point: 1 above the level and outside the
//! sun's window (as the scene program: no caustics there), 0 where the scene stands between the
//! point and the level along the sun's refracted path, else intensity times the photons' texels
//! filtered bilinearly (as the GPU filters the caustics texture) times exp(channelExtinction *
//! (height - level)). `scene` is kept by reference.
std::function<glm::dvec3(const glm::dvec3&)> underwaterSunShare(const UnderwaterSun& sun, const RayCaster& scene);

//! The photons' texels at `st` over the window, bilinear with clamping at the edges, texel
//! centres at half-integers (GL_LINEAR, CLAMP_TO_EDGE).
double samplePhotons(const PhotonImage& photons, double s, double t);

}
