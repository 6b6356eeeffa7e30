#pragma once
// The sRGB transfer function (IEC 61966-2-1) of linear values, clamped to [0, 1].
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace penumbra::util {

inline float linearToSrgb(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// Each channel of a linear colour.
inline glm::vec3 linearToSrgb(const glm::vec3& linear) {
    return {linearToSrgb(linear.r), linearToSrgb(linear.g), linearToSrgb(linear.b)};
}

}  // namespace penumbra::util
