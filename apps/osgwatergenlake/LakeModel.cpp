#include "LakeModel.h"
#include <algorithm>
#include <cmath>

namespace lake {

float height(float x, float y)
{
    // slightly oval basin, radius ~42 m at the waterline
    const float r = std::sqrt(x * x + 1.15f * y * y);
    const float t = std::min(std::max((r - 14.0f) / 34.0f, 0.0f), 1.0f);
    const float s = t * t * (3.0f - 2.0f * t);
    const float rolling = 0.6f * std::sin(0.11f * x + 0.4f) * std::cos(0.09f * y) * s;
    const float bedRipple = 0.25f * std::sin(0.5f * x) * std::sin(0.37f * y) * (1.0f - s);
    return -kDeepest + (kDeepest + kRimHeight) * s + rolling + bedRipple;
}

}
