#pragma once
#include "shadows/ShadowTechnique.h"

namespace penumbra::shadows {

// The baseline: visibility 1 everywhere; measures the cost of everything but shadows.
class NoShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "none"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/none/lookup.glsl"; }
    // Its lookup reads no tint: splitting receivers between two programs would only add draws
    // (measured on llvmpipe, default scene: frame +2-3 ms).
    float tintReachTexels() const override { return -1.0f; }
    void renderMaps(const ShadowFrame&) override {}
    void bindLookup(const gl::Program&) const override {}
    std::size_t memoryBytes() const override { return 0; }
};

}  // namespace penumbra::shadows
