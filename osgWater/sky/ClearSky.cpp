#include "sky/ClearSky.h"
#include "optics/Srgb.h"
#include <algorithm>
#include <cmath>

using namespace osgWater;

namespace {
const double kPi = 3.14159265358979323846;

double clampTurbidity(double t)
{
    return std::isfinite(t) ? std::clamp(t, sky::MIN_TURBIDITY, sky::MAX_TURBIDITY) : 3.0;
}

// the angle between two unit vectors, exact near 0 and pi too
double angleBetween(const glm::dvec3& a, const glm::dvec3& b)
{
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}
}

double sky::perez(const Perez& p, double cosTheta, double gamma)
{
    const double horizon = cosTheta > 0.0 ? 1.0 + p.a * std::exp(p.b / cosTheta) : 1.0;
    const double cg = std::cos(gamma);
    return horizon * (1.0 + p.c * std::exp(p.d * gamma) + p.e * cg * cg);
}

sky::PerezSet sky::perezCoefficients(double t)
{
    PerezSet s;
    s.luminance = { 0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771, -0.0670 * t + 0.3703 };
    s.x = { -0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989, -0.0033 * t + 0.0452 };
    s.y = { -0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537, -0.0109 * t + 0.0529 };
    return s;
}

double sky::zenithLuminance(double t, double sunTheta)
{
    const double chi = (4.0 / 9.0 - t / 120.0) * (kPi - 2.0 * sunTheta);
    return (4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192;
}

glm::dvec2 sky::zenithChromaticity(double t, double sunTheta)
{
    // each a quadratic in turbidity whose coefficients are cubics in the sun's zenith angle
    const glm::dvec4 s(sunTheta * sunTheta * sunTheta, sunTheta * sunTheta, sunTheta, 1.0);
    const glm::dvec3 tt(t * t, t, 1.0);
    const glm::dvec3 x(glm::dot(s, glm::dvec4(0.00166, -0.00375, 0.00209, 0.0)), glm::dot(s, glm::dvec4(-0.02903, 0.06377, -0.03202, 0.00394)),
                       glm::dot(s, glm::dvec4(0.11693, -0.21196, 0.06052, 0.25886)));
    const glm::dvec3 y(glm::dot(s, glm::dvec4(0.00275, -0.00610, 0.00317, 0.0)), glm::dot(s, glm::dvec4(-0.04214, 0.08970, -0.04153, 0.00516)),
                       glm::dot(s, glm::dvec4(0.15346, -0.26756, 0.06670, 0.26688)));
    return glm::dvec2(glm::dot(tt, x), glm::dot(tt, y));
}

sky::ClearSky::ClearSky(const glm::dvec3& towardSun, double turbidity)
    : _sun(0.0, 0.0, 1.0), _turbidity(clampTurbidity(turbidity))
{
    const double len = glm::length(towardSun);
    if (std::isfinite(len) && len > 1e-12) _sun = towardSun / len;
    if (_sun.z < 0.0) { // below the horizon: on it, toward the same azimuth
        const double flat = std::hypot(_sun.x, _sun.y);
        _sun = flat > 1e-12 ? glm::dvec3(_sun.x / flat, _sun.y / flat, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
    }
    const double sunTheta = std::acos(std::clamp(_sun.z, -1.0, 1.0));
    _perez = perezCoefficients(_turbidity);
    const glm::dvec2 xy = zenithChromaticity(_turbidity, sunTheta);
    _zenith = glm::dvec3(xy, zenithLuminance(_turbidity, sunTheta));
    _atZenith = glm::dvec3(perez(_perez.x, 1.0, sunTheta), perez(_perez.y, 1.0, sunTheta), perez(_perez.luminance, 1.0, sunTheta));
}

glm::dvec3 sky::ClearSky::xyY(const glm::dvec3& direction) const
{
    const double len = glm::length(direction);
    const glm::dvec3 d = std::isfinite(len) && len > 1e-300 ? direction / len : glm::dvec3(0.0, 0.0, 1.0);
    const double gamma = angleBetween(d, _sun);
    return glm::dvec3(_zenith.x * perez(_perez.x, d.z, gamma) / _atZenith.x, _zenith.y * perez(_perez.y, d.z, gamma) / _atZenith.y,
                      _zenith.z * perez(_perez.luminance, d.z, gamma) / _atZenith.z);
}

glm::dvec3 sky::ClearSky::linearSrgb(const glm::dvec3& direction) const
{
    const glm::dvec3 c = xyY(direction);
    return optics::linearSrgbFromXyz(optics::xyzFromChromaticity(c.x, c.y, c.z));
}
