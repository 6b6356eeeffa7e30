#pragma once
// CPU side of the std140 LightBlock in shaders/common/lights.glsl.
#include "render/Bindings.h"
#include "scene/Light.h"
#include "shadows/LightSpace.h"

#include <glm/glm.hpp>
#include <vector>

namespace penumbra::render {

struct GpuLight {
    glm::mat4 shadowMatrix;
    glm::vec4 colorType;
    glm::vec4 positionNear;
    glm::vec4 directionFar;
    glm::vec4 cone;
    glm::vec4 shadow;
    glm::vec4 misc;
};

struct LightBlock {
    glm::ivec4 count{0};
    GpuLight lights[kMaxLights];
};
static_assert(sizeof(GpuLight) == 160, "std140 layout of LightData");

// Packs lights (with their light spaces and shadow slots) into the uniform block.
LightBlock packLights(const std::vector<scene::Light>& lights, const std::vector<shadows::LightSpace>& spaces,
                      const std::vector<int>& shadowSlots);

}  // namespace penumbra::render
