#pragma once
// Frame-level shadow policy, decided once per frame by the renderer and handed to the technique
// in ShadowFrame: which light gets which shadow slot (the per-slot texture units of
// gpu/ShaderContract.h), and which sun the view-dependent techniques (cascades, LiSPSM, PSM)
// take over. Storage helpers and techniques read it; none of them decides it.
#include "scene/Light.h"

#include <vector>

namespace penumbra::shadows {

struct ShadowSlots {
    std::vector<int> slot;  // per light: shadow slot, -1 = no shadow this frame
    std::vector<bool> cube;  // per light: its maps are cube maps (point lights)
    int sun = -1;            // the first shadowed directional light, -1 = none

    // First come, first served: 2D slots (directional, spot, projector) and cube slots (point)
    // up to the contract's limits; lights past them, and lights without shadows, get -1.
    static ShadowSlots assign(const std::vector<scene::Light>& lights);

    std::size_t size() const { return slot.size(); }
    bool shadowed(std::size_t light) const { return light < slot.size() && slot[light] >= 0; }
    // Texture units of light `light`'s maps (its slot within each per-slot range).
    int depthUnit(std::size_t light) const;  // depth with hardware compare
    int tintUnit(std::size_t light) const;   // transmittance of translucent casters
    int rawUnit(std::size_t light) const;    // raw depth, or a technique's own map in its place
    int drawnUnit(std::size_t light) const;  // the farthest translucent layer and entry (DepthAndTintMaps)
};

}  // namespace penumbra::shadows
