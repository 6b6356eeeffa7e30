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
    margin_ = powerOfTwoAbove(std::max(0.005f * diagonal, 1e-4f));  // 0.5-1 % of the diagonal
    if (point) return;
    // A sun's volumes end on a plane past the scene's farthest corner along the light, at least.
    const glm::vec3 d(light_);
    float far = -std::numeric_limits<float>::max();
    for (const glm::vec3& corner : sceneBounds.corners()) far = std::max(far, glm::dot(d, corner));
    acrossLight_ = glm::vec4(d, stepAbove(far + margin_, margin_));
}

float VolumeExtent::longestRay(const glm::vec4& plane, const scene::Bounds& casters) const {
    const glm::vec3 n(plane), light(light_);
    float longest = 0.0f;
    for (const glm::vec3& c : casters.corners()) {
        if (light_.w < 0.5f) {  // a sun's rays run along d: to the plane in (w - n.c) / n.d
            longest = std::max(longest, (plane.w - glm::dot(n, c)) / glm::dot(n, light));
        } else {  // a point light's from L through c: at L + s (c - L) on the plane
            const float s = (plane.w - glm::dot(n, light)) / glm::dot(n, c - light);
            longest = std::max(longest, (s - 1.0f) * glm::length(c - light));
        }
    }
    return longest;
}

// A receiver x in the scene's box lies short of every face of the box: n.x <= the face's offset
// < w. A volume may so end on a face pushed out by the margin, if every ray from its caster
// crosses that plane outwards (n.d > 0): the part of the infinite volume short of the plane then
// holds every receiver, its far cap lies on the plane and its sides stay planar quads (each holds
// the light, or runs along a sun's d). Of the faces that qualify, and for a sun the plane across
// the light past the scene's farthest corner, the one the casters' rays reach soonest: for a sun
// from above, the ground's plane just under the ground, where the plane across the light lies deep
// beneath the ground near the caster. A point light with casters on every side of it has none:
// its volumes are pushed a fixed distance (a plane with n = 0). Faces the rays graze are left:
// they would be reached late, and the division would lose precision.
glm::vec4 VolumeExtent::farPlane(const scene::Bounds& casters) const {
    const bool sun = light_.w < 0.5f;
    glm::vec4 best = sun ? acrossLight_ : glm::vec4(0.0f);
    if (extrusion_ <= 0.0f || casters.empty()) return best;
    // A point light's plane must come sooner than its fixed push, so that no ray the plane meets at
    // a grazing angle runs out farther than that (and costs the clipper precision).
    float bestRay = sun ? longestRay(best, casters) : extrusion_;
    const auto corners = casters.corners();
    const glm::vec3 light(light_);
    const float grazing = 1e-3f * glm::length(sceneBounds_.extent());
    for (int i = 0; i < 3; ++i)
        for (const float sign : {1.0f, -1.0f}) {
            glm::vec3 n(0.0f);
            n[i] = sign;
            // Every ray from the casters leaves through this face: the sun's d, or each corner's
            // direction from a point light, points out of it.
            const bool outwards = sun ? glm::dot(n, light) >= 0.1f
                                      : std::all_of(corners.begin(), corners.end(), [&](const glm::vec3& c) { return glm::dot(n, c - light) > grazing; });
            if (!outwards) continue;
            const float side = sign > 0.0f ? sceneBounds_.max[i] : sceneBounds_.min[i];
            const glm::vec4 face(n, stepAbove(sign * side + margin_, margin_));
            const bool castersShort = std::all_of(corners.begin(), corners.end(), [&](const glm::vec3& c) { return glm::dot(n, c) < face.w; });
            const float ray = longestRay(face, casters);
            if (castersShort && ray < bestRay) best = face, bestRay = ray;
        }
    return best;
}

}  // namespace penumbra::shadows
