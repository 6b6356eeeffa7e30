#include "render/LightBlock.h"

#include <cmath>

namespace penumbra::render {

using scene::Light;

static_assert(static_cast<int>(Light::Type::Directional) == gpu::kLightDirectional &&
                  static_cast<int>(Light::Type::Spot) == gpu::kLightSpot &&
                  static_cast<int>(Light::Type::Point) == gpu::kLightPoint &&
                  static_cast<int>(Light::Type::Projector) == gpu::kLightProjector,
              "light-type codes of gpu/ShaderContract.h follow scene::Light::Type");

gpu::LightBlock packLights(const std::vector<Light>& lights, const std::vector<shadows::LightSpace>& spaces,
                           const shadows::ShadowSlots& slots) {
    static_assert(scene::kLightLimit == gpu::kMaxLights, "the scene limit is the GPU light block's size");
    gpu::LightBlock block{};
    int projectorSlot = 0;
    const int n = static_cast<int>(std::min<std::size_t>(lights.size(), gpu::kMaxLights));
    block.count.x = n;
    for (int i = 0; i < n; ++i) {
        const auto index = static_cast<std::size_t>(i);
        const Light& l = lights[index];
        const shadows::LightSpace& ls = spaces[index];
        gpu::LightData& g = block.lights[i];
        g.shadowMatrix = ls.shadowMatrix;
        g.colorType = glm::vec4(l.radiance(), static_cast<float>(l.type));
        g.positionNear = glm::vec4(l.position, ls.near);
        g.directionFar = glm::vec4(l.direction, ls.far);
        const float halfAngle = glm::radians(l.angleDeg) * 0.5f;
        // Spot lights fade over the outer 10% of the cone; projectors cut at the frame edge.
        g.cone = glm::vec4(std::cos(halfAngle), std::cos(halfAngle * 0.9f),
                           l.type == Light::Type::Projector && projectorSlot < gpu::kMaxProjectors ? projectorSlot++ : -1,
                           index < slots.size() ? slots.slot[index] : -1);
        g.shadow = glm::vec4(l.shadow.bias, l.shadow.slopeBias, l.shadow.normalOffset, ls.texelScale);
        g.misc = glm::vec4(0.0f, static_cast<float>(ls.resolution), l.size, 0.0f);
    }
    return block;
}

}  // namespace penumbra::render
