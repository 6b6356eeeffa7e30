#pragma once
#include "shadows/ShadowTechnique.h"

namespace penumbra::shadows {

// The baseline: visibility 1 everywhere; measures the cost of everything but shadows.
class NoShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "none"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/none/lookup.glsl"; }
    void renderMaps(const ShadowFrame&) override {}
    void bindLookup(const gl::Program&) const override {}
    std::size_t memoryBytes() const override { return 0; }
};

}  // namespace penumbra::shadows
