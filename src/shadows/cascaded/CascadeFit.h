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
    // Stabilised: the box's centre and half its side in the view along `direction` (held by the next fit).
    glm::vec2 centre{0.0f};
    float halfSize = 0;
    glm::vec3 direction{0.0f};
};

// One cascade for the camera-frustum slice [splitNear, splitFar]. Stabilised: the box is the
// slice's bounding sphere (independent of camera rotation) with its centre snapped to whole
// texels in light space (independent of sub-texel camera motion), so shadows do not shimmer.
// Unstabilised: the tightest box around the slice (sharper, but it swims as the camera moves).
// Depth always spans every caster in `scene`.
// `previous` (stabilised only; may be null): the same cascade last frame, at the same resolution.
// Its box is kept while it still holds the slice's sphere (to within the texel its centre snaps
// by) and is no larger than a moved one; a moved box leaves kBoxSlack of the radius as room, so
// that a moving camera redraws the cascade every few frames, not every frame (as LightSpace's
// plain sun box). Without it, the tight box.
Cascade fitCascade(const scene::Light& light, const scene::Camera& camera, float aspect, float splitNear,
                   float splitFar, const scene::Bounds& scene, int resolution, bool stabilize,
                   const Cascade* previous = nullptr);

// World planes around the column along the light through `points` (where a cascade's lookups
// read) in its orthographic view `viewProj`: the sides of their convex hull in the map, pushed
// out by `marginTexels` texels of a `resolution`-texel map, each parallel to the light. A caster
// wholly outside one writes no texel within that margin of the points' (CasterSelection::cullPlanes):
// a slice's hull in the map is a narrow trapezoid where its bounding rectangle is not (the 98k
// grid's cascades 1 and 3: 32 and 64 objects in the rectangle, 11 and 21 in the hull). None where
// the hull is degenerate.
std::vector<glm::vec4> columnPlanes(const std::vector<glm::vec3>& points, const glm::mat4& viewProj, int resolution, float marginTexels);

}  // namespace penumbra::shadows
