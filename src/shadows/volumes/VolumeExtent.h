#pragma once
// How far a light's shadow volumes reach: the uniforms of volume.geom's `extruded()`, worked out
// per light and caster. Pure CPU, no GL.
#include "scene/Light.h"
#include "scene/Mesh.h"

#include <glm/glm.hpp>

namespace penumbra::shadows {

class VolumeExtent {
public:
    // `sceneBounds`: every receiver. `infinite`: volumes reach infinity (w = 0).
    VolumeExtent(const scene::Light& light, const scene::Bounds& sceneBounds, bool infinite);

    glm::vec4 light() const { return light_; }  // uLight: (position, 1), or (direction light travels, 0)
    float extrusion() const { return extrusion_; }  // uExtrusion: how far a point light pushes a vertex; 0: to infinity
    // uFarPlane: the plane (n, w) on which the volume of the casters inside `casterBounds` ends,
    // every ray from them crossing it outwards. Every point of the scene that their rays reach
    // lies on its near side (n.x < w). Of the planes just past the scene box's faces (and for a
    // sun, the plane across the light past the scene's farthest corner), the one the casters' rays
    // reach soonest; (0, 0, 0, 0) for a point light that has casters on every side: its volumes
    // are then pushed uExtrusion.
    glm::vec4 farPlane(const scene::Bounds& casterBounds) const;
    // How far the longest ray from a corner of `casterBounds` runs to `plane`, away from the light.
    float longestRay(const glm::vec4& plane, const scene::Bounds& casterBounds) const;

private:
    scene::Bounds sceneBounds_;
    glm::vec4 light_;
    float margin_ = 0.0f;  // past the farthest receiver, so that the dark cap never lies on one
    float extrusion_ = 0.0f;
    glm::vec4 acrossLight_{0.0f};  // a sun's plane across the light past the whole scene
};

}  // namespace penumbra::shadows
