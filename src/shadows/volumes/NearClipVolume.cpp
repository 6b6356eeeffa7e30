#include "shadows/volumes/NearClipVolume.h"

#include <array>
#include <cmath>

namespace penumbra::shadows {

namespace {

// The plane through `a` and `b` that holds `along` (a direction) and faces `inside`.
glm::vec4 planeFacing(const glm::vec3& a, const glm::vec3& b, const glm::vec3& along, const glm::vec3& inside) {
    glm::vec3 n = glm::cross(b - a, along);
    if (glm::dot(n, inside - a) < 0.0f) n = -n;
    return glm::vec4(n, -glm::dot(n, a));
}

}  // namespace

NearClipVolume::NearClipVolume(const glm::mat4& inverseViewProj, const scene::Light& light) {
    std::array<glm::vec3, 4> near;  // the near rectangle's corners, in order round it
    const glm::vec2 ndc[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < 4; ++i) {
        const glm::vec4 w = inverseViewProj * glm::vec4(ndc[i], -1.0f, 1.0f);
        near[static_cast<std::size_t>(i)] = glm::vec3(w) / w.w;
    }
    const glm::vec3 centre = (near[0] + near[1] + near[2] + near[3]) * 0.25f;
    const glm::vec3 normal = glm::cross(near[1] - near[0], near[3] - near[0]);
    const bool directional = light.type == scene::Light::Type::Directional;
    // Towards the light from the rectangle: the sweep's direction at its centre.
    const glm::vec3 toLight = directional ? -light.direction : light.position - centre;
    const float facing = glm::dot(normal, toLight);
    // Edge-on (or a point light in the near plane's plane): the sweep is flat and the planes
    // below would not bound it; take z-fail for everything.
    if (std::abs(facing) <= 1e-6f * glm::length(normal) * glm::length(toLight)) return;
    const glm::vec3 inside = centre + 0.5f * (directional ? toLight : light.position - centre);
    planes_.push_back(planeFacing(near[0], near[1], near[3] - near[0], inside));  // the near plane's
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::vec3& a = near[i];
        const glm::vec3& b = near[(i + 1) % 4];
        // Each side holds the rectangle's edge and the direction to the light from it.
        planes_.push_back(planeFacing(a, b, directional ? toLight : light.position - a, inside));
    }
}

bool NearClipVolume::mayHold(const scene::Bounds& box) const {
    if (box.empty()) return false;
    if (planes_.empty()) return true;
    for (const glm::vec4& plane : planes_) {
        // The box corner farthest along the plane's normal: outside if even it is behind.
        const glm::vec3 n(plane);
        const glm::vec3 far{n.x >= 0.0f ? box.max.x : box.min.x, n.y >= 0.0f ? box.max.y : box.min.y, n.z >= 0.0f ? box.max.z : box.min.z};
        if (glm::dot(n, far) + plane.w < 0.0f) return false;
    }
    return true;
}

}  // namespace penumbra::shadows
