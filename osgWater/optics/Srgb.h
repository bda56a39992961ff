/* osgWater - natural water for OpenSceneGraph */
#ifndef OSGWATER_SRGB
#define OSGWATER_SRGB 1

#include <osgWater/Export>
#include <osgWater/WaterSettings>
#include <glm/glm.hpp>

//! CPU mirror of shaders/srgb.glsl: the sRGB curve (IEC 61966-2-1) between display values, as files
//! and the view hold them, and the linear light every sum of the kit is made in.
namespace osgWater { namespace optics {

//! A display value in [0, 1] (clamped) as linear light.
OSGWATER_EXPORT float decodeSrgb(float c);
OSGWATER_EXPORT glm::vec3 decodeSrgb(const glm::vec3& c);
//! Linear light (clamped to [0, 1]) as a display value.
OSGWATER_EXPORT float encodeSrgb(float c);
OSGWATER_EXPORT glm::vec3 encodeSrgb(const glm::vec3& c);
//! Exposed light through the tone curve (owToneCurve): what the encoding then clamps to [0, 1].
OSGWATER_EXPORT float toneCurve(float exposed, WaterSettings::ToneCurve curve);
//! What the view shows for linear light: exposed, through the tone curve, then encoded (owDisplay).
OSGWATER_EXPORT glm::vec3 display(const glm::vec3& linear, float exposure,
                                  WaterSettings::ToneCurve curve = WaterSettings::TONE_CLIP);

//! CIE XYZ of linear sRGB (its primaries and D65 white, IEC 61966-2-1), and back: the inverse of
//! the same matrix.
OSGWATER_EXPORT glm::dvec3 xyzFromLinearSrgb(const glm::dvec3& rgb);
OSGWATER_EXPORT glm::dvec3 linearSrgbFromXyz(const glm::dvec3& xyz);
//! CIE XYZ of a chromaticity (x, y) at luminance Y; black where y is 0.
OSGWATER_EXPORT glm::dvec3 xyzFromChromaticity(double x, double y, double luminance);

//! The shader's curves line by line (owDecodeSrgb, owEncodeSrgb): the power pieces fitted, a quintic
//! and a series in roots, each within 0.05/255 of the exact curve in display values.
OSGWATER_EXPORT float decodeSrgbFitted(float c);
OSGWATER_EXPORT float encodeSrgbFitted(float c);

} }

#endif
