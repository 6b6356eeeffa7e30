#pragma once
// The scene at one instant, in an Embree 3 BVH, answering "how much of a light's colour gets
// from A to B": the product over every surface crossed of (1 - rho_rgb), rho = (1 - t) * alpha
// (McGuire & Enderton 2011), with alpha textures and alpha-test cut-outs honoured. Knows nothing of GL.
#include "scene/Scene.h"

#include <glm/glm.hpp>
#include <memory>

namespace penumbra::reference {

class RayScene {
public:
    RayScene(const scene::Scene& scene, float time);
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // Transmittance along the segment origin + t*direction, t in (tMin, tMax); direction unit length.
    // Returns 0 as soon as an opaque surface is met. Thread-safe.
    glm::vec3 transmittance(const glm::vec3& origin, const glm::vec3& direction, float tMin, float tMax) const;
    // Distance to the first surface (any material), or +inf.
    float firstHit(const glm::vec3& origin, const glm::vec3& direction) const;
    float sceneRadius() const { return radius_; }
    std::size_t triangleCount() const { return triangles_; }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    float radius_ = 1.0f;
    std::size_t triangles_ = 0;
};

}  // namespace penumbra::reference
