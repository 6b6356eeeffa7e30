#include "shadows/volumes/VolumeExtent.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace penumbra::shadows {

namespace {

// Sizes and planes on a ladder of powers of two, so that a scene box that grows or shrinks a
// little (an animated object near its side) leaves them, and the volumes VolumeCache keeps, as
// they were. Rounds up: a volume may always reach farther.
float powerOfTwoAbove(float x) { return x > 0.0f ? std::exp2(std::ceil(std::log2(x))) : 0.0f; }
float stepAbove(float x, float step) { return std::ceil(x / step) * step; }

}  // namespace

VolumeExtent::VolumeExtent(const scene::Light& light, const scene::Bounds& sceneBounds, bool infinite) : sceneBounds_(sceneBounds) {
    const bool point = light.type != scene::Light::Type::Directional;
    light_ = point ? glm::vec4(light.position, 1.0f) : glm::vec4(glm::normalize(light.direction), 0.0f);
    if (infinite || sceneBounds.empty()) return;
    // Past every receiver: the scene's diagonal plus the light's distance to the scene.
    const float diagonal = glm::length(sceneBounds.extent());
    const float lightDistance = point ? glm::length(light.position - sceneBounds.center()) : 0.0f;
    extrusion_ = powerOfTwoAbove(2.0f * (diagonal + lightDistance));
    margin_ = powerOfTwoAbove(0.005f * diagonal);  // 0.5-1 % of the diagonal
    if (point) return;
    // A sun's volumes end on a plane past the scene's farthest corner along the light, at least.
    const glm::vec3 d(light_);
    float far = -std::numeric_limits<float>::max();
    for (const glm::vec3& corner : sceneBounds.corners()) far = std::max(far, glm::dot(d, corner));
    acrossLight_ = glm::vec4(d, stepAbove(far + margin_, margin_));
}

float VolumeExtent::longestRay(const glm::vec4& plane, const scene::Bounds& casters) const {
    const glm::vec3 n(plane), d(light_);
    float longest = 0.0f;
    for (const glm::vec3& c : casters.corners()) longest = std::max(longest, (plane.w - glm::dot(n, c)) / glm::dot(n, d));
    return longest;
}

// A receiver x = p + t d in the scene's box lies short of every face the light leaves the box
// through: n.x <= the face's offset < w. So a volume may end on any such face pushed out by the
// margin, and the caster's rays meet the face they leave through soonest: for a sun from above, the
// ground's plane just under the ground, where the plane across the light lies deep beneath the
// ground near the caster. Every ray stays parallel to d, so each side stays a planar quad whose far
// edge lies on the plane. Faces the light grazes (|d_i| small) are left: the rays would reach them
// late, and the division would lose precision.
glm::vec4 VolumeExtent::farPlane(const scene::Bounds& casters) const {
    if (light_.w > 0.5f || extrusion_ <= 0.0f || casters.empty()) return acrossLight_;
    const glm::vec3 d(light_);
    glm::vec4 best = acrossLight_;
    float bestRay = longestRay(best, casters);
    const auto corners = casters.corners();
    for (int i = 0; i < 3; ++i) {
        if (std::abs(d[i]) < 0.1f) continue;
        glm::vec3 n(0.0f);
        n[i] = d[i] > 0.0f ? 1.0f : -1.0f;
        const float side = d[i] > 0.0f ? sceneBounds_.max[i] : sceneBounds_.min[i];
        const glm::vec4 face(n, stepAbove(n[i] * side + margin_, margin_));
        const bool castersShort = std::all_of(corners.begin(), corners.end(), [&](const glm::vec3& c) { return glm::dot(n, c) < face.w; });
        const float ray = longestRay(face, casters);
        if (castersShort && ray < bestRay) best = face, bestRay = ray;
    }
    return best;
}

}  // namespace penumbra::shadows
