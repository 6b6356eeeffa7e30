#pragma once
// Planar projected shadows (Blinn 1988, "Me and my (fake) shadow"), the geometry: the 4x4 matrix
// that flattens everything onto a plane along the light's rays, and finding the receiver plane.
#include "scene/Light.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>
#include <optional>

namespace penumbra::shadows {

// Plane (n, d): dot(n, x) + d = 0. Light: (position, 1) for point-like lights, or (direction
// towards the light, 0) for the sun. M = (P·L) I - L Pᵀ: P·(M X) = 0 for every X, and M X lies
// on the line through X and the light. For a point light, X farther from the plane than the
// light gets w < 0: the "caster behind the light" the GPU's clipper removes, unless the
// projection is divided by w first (the naive version, which casts an anti-shadow).
glm::mat4 planarShadowMatrix(const glm::vec4& plane, const glm::vec4& light);

// The light as a homogeneous point for planarShadowMatrix.
glm::vec4 homogeneousLight(const scene::Light& light);

struct ReceiverPlane {
    int object = -1;
    glm::vec4 plane{0.0f, 1.0f, 0.0f, 0.0f};
    float area = 0.0f;
};

// Object `object`'s plane when its mesh is flat at `time` (nullopt otherwise); with object < 0,
// the flat object of largest area (the ground).
std::optional<ReceiverPlane> findReceiverPlane(const scene::Scene& scene, float time, int object = -1);

}  // namespace penumbra::shadows
