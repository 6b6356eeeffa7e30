#pragma once
// Ray-traced light visibility at given surface points (the rasteriser's G-buffer), per light:
// one any-surface ray for point-like lights, N stratified samples over the light's extent
// for area lights (`size`: diameter in world units; for directional lights the angular
// diameter in degrees). Coloured: transmittance through every translucent layer.
#include "reference/RayScene.h"
#include "scene/Light.h"

#include <functional>
#include <glm/glm.hpp>
#include <vector>

namespace penumbra::reference {

// Per-pixel surface samples, row 0 = bottom (GL order).
struct SurfacePoints {
    int width = 0, height = 0;
    std::vector<glm::vec3> position;
    std::vector<glm::vec3> normal;  // unit, facing the camera
    std::vector<bool> covered;      // false: background
};

using Progress = std::function<void(double fraction)>;

// Visibility (RGB transmittance, 1 = unblocked) of `light` at every covered point; 0 elsewhere.
// Uses every hardware thread; `progress` is called from one worker now and then.
std::vector<glm::vec3> traceVisibility(const RayScene& rays, const scene::Light& light, const SurfacePoints& points,
                                       int samples, const Progress& progress = {});

// One point's visibility (exposed for tests).
glm::vec3 visibilityAt(const RayScene& rays, const scene::Light& light, const glm::vec3& position,
                       const glm::vec3& normal, int samples, std::uint32_t seed);

// A progress reporter: a bar redrawn in place on a terminal, plain lines every 10% otherwise.
Progress consoleProgress(const std::string& label);

}  // namespace penumbra::reference
