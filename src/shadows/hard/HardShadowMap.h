#pragma once
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"

namespace penumbra::shadows {

// Williams 1978: one depth comparison per pixel against the nearest opaque caster, nearest
// texel (so aliasing stays visible), plus the coloured tint of Nápravník 2020 from translucent casters.
class HardShadowMap final : public ShadowTechnique {
public:
    std::string name() const override { return "hard"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/hard/lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override { maps_.render(frame); }
    void bindLookup(const gl::Program&) const override { maps_.bind(); }
    std::size_t memoryBytes() const override { return maps_.memoryBytes(); }
    std::vector<DebugView> debugViews() const override { return maps_.debugViews(); }

private:
    DepthAndTintMaps maps_;
};

}  // namespace penumbra::shadows
