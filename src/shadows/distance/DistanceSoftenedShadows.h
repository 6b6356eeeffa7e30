#pragma once
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"

namespace penumbra::shadows {

// The "Fresnel effect of shadows" of the small coloured-light engine (seed document 001): three
// fixed 3x3 kernels chosen by the caster-receiver distance.
class DistanceSoftenedShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "distance"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/distance/lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override { maps_.render(frame); }
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override { return maps_.memoryBytes(); }
    std::vector<DebugView> debugViews() const override { return maps_.debugViews(); }

protected:
    std::vector<Parameter> declareParameters() override;

private:
    float nearDistance_ = 0.3f, farDistance_ = 1.5f, spacing_ = 1.5f;
    DepthAndTintMaps maps_;
};

}  // namespace penumbra::shadows
