/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_PROCEDURALCAUSTICS
#define OSGWATER_PROCEDURALCAUSTICS 1

#include <osgWater/Export>
#include <glm/glm.hpp>

//! Procedural caustics (Sanchez-Crespo 2003) on the CPU, in double precision: the construction a
//! caustics shader of this kind is to be held to (the frame does not draw them yet). From a bed point, back
//! up along the sun's refracted ray to the water above it, the wave's analytic normal there, the ray
//! refracted back into the air, and the sky's brightness in that direction from a sun-and-halo map.
//! Where the exit ray points at the sun the bed is lit. Aesthetic, not physical (the paper's own
//! words): nothing conserves the light, so it is calibrated to be right on flat water only.
namespace osgWater {

class WaterSurface;

namespace procedural {

//! The sky as the caustics see it: a sun disc of `discRadius` radians at brightness 1, a halo around
//! it falling smoothly to 0 at `haloRadius`, starting at `haloLevel`.
struct SunHalo {
    double discRadius = 0.5 * 0.53 * 3.14159265358979323846 / 180.0;  //!< the sun's disc: 0.53 degrees across
    double haloRadius = 10.0 * 0.5 * 0.53 * 3.14159265358979323846 / 180.0; //!< ten times the disc
    double haloLevel = 0.25;
};

//! The map's brightness `angle` radians from the sun's centre (1 at the centre; 0 beyond the halo).
OSGWATER_EXPORT double sunHalo(double angle, const SunHalo& map = SunHalo());

struct Backtrace {
    bool valid = false;         //!< the sun is up, the bed point is under the water
    glm::dvec3 surface{0.0};    //!< where the backward ray meets the waves
    glm::dvec3 normal{0.0, 0.0, 1.0};
    glm::dvec3 exit{0.0};       //!< the backward ray refracted into the air (zero: total internal reflection)
    double angleToSun = 0.0;    //!< radians between `exit` and the sun (pi under total internal reflection)
    double pathInWater = 0.0;   //!< metres from the surface point to the bed point
};

//! From `bed` (local frame, z up) towards the sun `towardsSun` (unit): up along the direction the
//! sun's light takes through flat water (`vertical`: straight up, the paper's sun overhead) to the
//! waves of `surface` at time t (a few fixed-point steps on the height), the
//! analytic normal there, the ray refracted into the air (n_water / n_air). Invalid with the sun at
//! or below the horizon or the bed point above the waves.
OSGWATER_EXPORT Backtrace backtrace(const glm::dvec3& bed, const glm::dvec3& towardsSun, const WaterSurface& surface,
                                    double t, double nAir, double nWater, bool vertical = false);

//! The caustic light on `bed` in units of the sun's irradiance seen from the sun, as the photon
//! caustics count it: sunHalo(angle) / sunHalo(0), times (1 - F) exp(-k d) with `transmitted` = 1 - F
//! at the sun's angle on flat water and k the extinction per metre along the path in water, so flat
//! water gives the physical (1 - F) exp(-k d) (calibrated). Uncalibrated: the paper's map value alone.
OSGWATER_EXPORT double causticLight(const Backtrace& trace, double transmitted, double extinction, bool calibrated = true,
                                    const SunHalo& map = SunHalo());

} }

#endif
