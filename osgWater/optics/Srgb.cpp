#include "optics/Srgb.h"
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

glm::vec3 optics::display(const glm::vec3& linear, float exposure) { return encodeSrgb(exposure * linear); }
