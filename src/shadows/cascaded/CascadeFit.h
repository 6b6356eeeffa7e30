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

}  // namespace penumbra::shadows
