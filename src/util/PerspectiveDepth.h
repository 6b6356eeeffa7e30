#pragma once
// The depth mapping of a GL perspective projection (glm::perspective, glDepthRange(0, 1)) between
// view depth z in [n, f] and window depth w in [0, 1]: w(z) = f/(f-n) - fn/((f-n) z), and its
// inverse z(w) = fn / (f - w (f-n)). Lights' reach bounds step along it (TintReach, pcss).
#include <limits>

namespace penumbra::util {

inline float perspectiveWindowDepth(float near, float far, float viewDepth) {
    return far / (far - near) - far * near / ((far - near) * viewDepth);
}

// Infinite at and past w = f/(f-n), where the view depth would be at infinity or behind the eye.
inline float perspectiveViewDepth(float near, float far, float windowDepth) {
    const float rest = far - windowDepth * (far - near);
    return rest > 0.0f ? far * near / rest : std::numeric_limits<float>::infinity();
}

}  // namespace penumbra::util
