#pragma once
// The sRGB transfer function (IEC 61966-2-1) of one linear channel value, clamped to [0, 1].
#include <algorithm>
#include <cmath>

namespace penumbra::util {

inline float linearToSrgb(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace penumbra::util
