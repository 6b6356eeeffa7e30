#pragma once
#include "shadows/common/SharedMapTechnique.h"

namespace penumbra::shadows {

// Williams 1978: one depth comparison per pixel against the nearest opaque caster, nearest
// texel (so aliasing stays visible), plus the coloured tint of Nápravník 2020 from translucent casters.
class HardShadowMap final : public SharedMapTechnique {
public:
    std::string name() const override { return "hard"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/hard/lookup.glsl"; }
    // The texel the comparison reads, and the tint's.
    float shadowReachTexels() const override { return kPlainCompareReachTexels; }
    float shadowReachDepth() const override { return 0.0f; }  // its own depth, compared at one texel
    void bindLookup(const gl::Program&) const override { maps_.bind(); }
};

}  // namespace penumbra::shadows
