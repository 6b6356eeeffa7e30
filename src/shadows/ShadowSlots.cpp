#include "shadows/ShadowSlots.h"

#include "gpu/ShaderContract.h"

namespace penumbra::shadows {

using scene::Light;

ShadowSlots ShadowSlots::assign(const std::vector<Light>& lights) {
    ShadowSlots s;
    int next2D = 0, nextCube = 0;
    for (const auto& l : lights) {
        const bool cube = l.type == Light::Type::Point;
        int slot = -1;
        if (l.shadow.enabled) {
            if (cube && nextCube < gpu::kMaxShadowCube) slot = nextCube++;
            if (!cube && next2D < gpu::kMaxShadow2D) slot = next2D++;
        }
        if (s.sun < 0 && slot >= 0 && l.type == Light::Type::Directional) s.sun = static_cast<int>(s.slot.size());
        s.slot.push_back(slot);
        s.cube.push_back(cube);
    }
    return s;
}

int ShadowSlots::depthUnit(std::size_t light) const {
    return (cube[light] ? gpu::kUnitShadowCube : gpu::kUnitShadow2D) + slot[light];
}
int ShadowSlots::tintUnit(std::size_t light) const {
    return (cube[light] ? gpu::kUnitTintCube : gpu::kUnitTint2D) + slot[light];
}
int ShadowSlots::rawUnit(std::size_t light) const {
    return (cube[light] ? gpu::kUnitRawCube : gpu::kUnitRaw2D) + slot[light];
}
int ShadowSlots::drawnUnit(std::size_t light) const {
    return (cube[light] ? gpu::kUnitDrawnFarthestCube : gpu::kUnitDrawnFarthest2D) + slot[light];
}

}  // namespace penumbra::shadows
