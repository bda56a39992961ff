/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_CLEARSKY
#define OSGWATER_CLEARSKY 1

#include <osgWater/Export>
#include <glm/glm.hpp>

//! A clear sky's light, as Preetham, Shirley and Smits's analytic model gives it (SIGGRAPH 1999):
//! Perez et al.'s all-weather distribution (1993) for the luminance Y and the chromaticities x, y,
//! each scaled to its value at the zenith, whose fits in the sun's zenith angle and the
//! atmosphere's turbidity the paper's appendix gives. In double precision; the shaders mirror it.
namespace osgWater { namespace sky {

//! The five coefficients of Perez's distribution.
struct Perez {
    double a, b, c, d, e;
};

//! Perez's relative value at a view zenith angle theta, gamma from the sun:
//! (1 + a e^(b / cos theta)) (1 + c e^(d gamma) + e cos^2 gamma). At and below the horizon
//! (cos theta <= 0) the first factor is its limit there, 1 (b < 0 for every turbidity).
OSGWATER_EXPORT double perez(const Perez& p, double cosTheta, double gamma);

//! The distribution's coefficients for Y, x and y at a turbidity (Preetham's appendix, linear in it).
struct PerezSet {
    Perez luminance, x, y;
};
OSGWATER_EXPORT PerezSet perezCoefficients(double turbidity);

//! The zenith's luminance (kcd/m^2) and chromaticity (x, y) for the sun at zenith angle sunTheta.
OSGWATER_EXPORT double zenithLuminance(double turbidity, double sunTheta);
OSGWATER_EXPORT glm::dvec2 zenithChromaticity(double turbidity, double sunTheta);

//! The range the fits were made over: turbidity 2 (very clear) to 10 (hazy); 1.7 still gives a sky.
constexpr double MIN_TURBIDITY = 1.7, MAX_TURBIDITY = 10.0;

//! The sky for one sun and turbidity. The sun's direction points toward it, z up; a sun below the
//! horizon is taken on it (the model's fits stop there). Turbidity is clamped to its range.
class OSGWATER_EXPORT ClearSky
{
public:
    ClearSky(const glm::dvec3& towardSun, double turbidity);

    //! The sky's chromaticity and luminance, (x, y, Y in kcd/m^2), seen along `direction` (toward
    //! the sky; need not be unit). At and below the horizon, the horizon's.
    glm::dvec3 xyY(const glm::dvec3& direction) const;
    //! The same light in linear sRGB (D65 white), scaled so that Y is kcd/m^2.
    glm::dvec3 linearSrgb(const glm::dvec3& direction) const;

    //! The zenith's (x, y, Y) over Perez's values there: what Perez's value along a direction is
    //! multiplied by (the shaders' osgWater_SkyZenith).
    glm::dvec3 zenithScale() const { return _zenith / _atZenith; }
    //! Perez's coefficients for its turbidity (the shaders' osgWater_SkyA .. E).
    const PerezSet& perezSet() const { return _perez; }
    double turbidity() const { return _turbidity; }
    const glm::dvec3& towardSun() const { return _sun; }

private:
    glm::dvec3 _sun;
    double _turbidity;
    PerezSet _perez;
    glm::dvec3 _zenith;    // x, y, Y at the zenith
    glm::dvec3 _atZenith;  // Perez's values at the zenith for Y, x, y: the scale's denominators
};

} }

#endif
