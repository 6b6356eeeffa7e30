#pragma once
// Parallel-split / cascaded shadow maps (Zhang et al. 2006), the geometry: where the splits go
// and how each cascade's orthographic box is fitted. Pure math, no GL.
#include "scene/Camera.h"
#include "scene/Light.h"
#include "scene/Mesh.h"

#include <glm/glm.hpp>
#include <vector>

namespace penumbra::shadows {

// count + 1 distances from `near` to `far`: C_i = λ C_i^log + (1 - λ) C_i^uni with
// C_i^log = n (f/n)^(i/m) and C_i^uni = n + (f - n) i / m.
std::vector<float> cascadeSplits(float near, float far, int count, float lambda);

struct Cascade {
    glm::mat4 viewProj{1.0f};      // world -> clip
    glm::mat4 shadowMatrix{1.0f};  // world -> [0,1]^3
    float splitNear = 0, splitFar = 0;
    float texelWorld = 0;          // world size of one shadow texel
    float depthNear = 0, depthFar = 1;
};

// One cascade for the camera-frustum slice [splitNear, splitFar]. Stabilised: the box is the
// slice's bounding sphere (independent of camera rotation) with its centre snapped to whole
// texels in light space (independent of sub-texel camera motion), so shadows do not shimmer.
// Unstabilised: the tightest box around the slice (sharper, but it swims as the camera moves).
// Depth always spans every caster in `scene`.
Cascade fitCascade(const scene::Light& light, const scene::Camera& camera, float aspect, float splitNear,
                   float splitFar, const scene::Bounds& scene, int resolution, bool stabilize);

// The points where the convex frustum of `viewProj` (world -> clip, e.g. one cascade's camera
// slice) and `box` meet: each one's edges clipped to the other. Every vertex of the intersection
// lies on an edge of one of the two (it is where three faces meet, two of them of the same
// solid), so these points span it; none when the two do not meet.
std::vector<glm::vec3> frustumInsideBox(const glm::mat4& viewProj, const scene::Bounds& box);

}  // namespace penumbra::shadows
