// Private to the library: the clamping the setters share. NaN takes the setting's default; any other
// value outside [lo, hi] is clamped; either way one warning naming the setting and the value used.
#pragma once
#include <osg/Notify>
#include <algorithm>
#include <cmath>

namespace osgWater {
namespace detail {

template <typename T> inline T clampTo(const char* owner, const char* name, T v, T lo, T hi, T fallback)
{
    if (std::isnan(v)) {
        OSG_WARN << owner << ": " << name << " is NaN, using " << fallback << std::endl;
        return fallback;
    }
    if (v < lo || v > hi) {
        const T c = std::min(std::max(v, lo), hi);
        OSG_WARN << owner << ": " << name << " = " << v << " out of [" << lo << ", " << hi << "], clamped to " << c
                 << std::endl;
        return c;
    }
    return v;
}

inline float clampOr(const char* owner, const char* name, float v, float lo, float hi, float fallback)
{
    return clampTo<float>(owner, name, v, lo, hi, fallback);
}

inline int clampInt(const char* owner, const char* name, int v, int lo, int hi)
{
    if (v < lo || v > hi) {
        const int c = std::min(std::max(v, lo), hi);
        OSG_WARN << owner << ": " << name << " = " << v << " out of [" << lo << ", " << hi << "], clamped to " << c
                 << std::endl;
        return c;
    }
    return v;
}

}
}
