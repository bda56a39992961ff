#include "optics/Srgb.h"
#include <glm/mat3x3.hpp>
#include <algorithm>
#include <cmath>

using namespace osgWater;

float optics::decodeSrgb(float c)
{
    c = c > 0.0f ? std::min(c, 1.0f) : 0.0f; // NaN too: black
    return c < 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float optics::encodeSrgb(float c)
{
    c = c > 0.0f ? std::min(c, 1.0f) : 0.0f; // NaN too: black
    return c < 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

glm::vec3 optics::decodeSrgb(const glm::vec3& c) { return glm::vec3(decodeSrgb(c.x), decodeSrgb(c.y), decodeSrgb(c.z)); }

glm::vec3 optics::encodeSrgb(const glm::vec3& c) { return glm::vec3(encodeSrgb(c.x), encodeSrgb(c.y), encodeSrgb(c.z)); }

float optics::decodeSrgbFitted(float c)
{
    c = c > 0.0f ? std::min(c, 1.0f) : 0.0f;
    if (c < 0.04045f) return c / 12.92f;
    return 0.00095477318f + c * (0.031784446f + c * (0.52634035f + c * (0.64794601f + c * (-0.28556063f + c * 0.078688271f))));
}

float optics::encodeSrgbFitted(float c)
{
    c = c > 0.0f ? std::min(c, 1.0f) : 0.0f;
    if (c < 0.0031308f) return c * 12.92f;
    const float s1 = std::sqrt(c), s2 = std::sqrt(s1), s3 = std::sqrt(s2);
    return 0.65468427f * s1 + 0.68885027f * s2 - 0.31928944f * s3 - 0.020599216f * c - 0.0037160980f;
}

float optics::toneCurve(float x, WaterSettings::ToneCurve curve)
{
    if (curve != WaterSettings::TONE_ACES) return x;
    x = x > 0.0f ? x : 0.0f; // NaN too: black
    return x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f);
}

glm::vec3 optics::display(const glm::vec3& linear, float exposure, WaterSettings::ToneCurve curve)
{
    const glm::vec3 x = exposure * linear;
    return encodeSrgb(glm::vec3(toneCurve(x.x, curve), toneCurve(x.y, curve), toneCurve(x.z, curve)));
}

namespace {
// sRGB's primaries and D65 white to CIE XYZ (IEC 61966-2-1), by columns
const glm::dmat3 kXyzFromSrgb(0.4124564, 0.2126729, 0.0193339, 0.3575761, 0.7151522, 0.1191920, 0.1804375, 0.0721750, 0.9503041);
}

glm::dvec3 optics::xyzFromLinearSrgb(const glm::dvec3& rgb) { return kXyzFromSrgb * rgb; }

glm::dvec3 optics::linearSrgbFromXyz(const glm::dvec3& xyz)
{
    static const glm::dmat3 srgbFromXyz = glm::inverse(kXyzFromSrgb);
    return srgbFromXyz * xyz;
}

glm::dvec3 optics::xyzFromChromaticity(double x, double y, double luminance)
{
    if (!(y != 0.0)) return glm::dvec3(0.0);
    return glm::dvec3(x / y * luminance, luminance, (1.0 - x - y) / y * luminance);
}
