#pragma once
#include "shadows/common/KernelTechnique.h"

namespace penumbra::shadows {

// Variable-size penumbra (Fernando 2005): blocker search, penumbra estimate, variable PCF.
// Light size comes from the scene file (`size`), else from the parameters. Both kernels are Vogel
// spirals computed in the shader, so the tap counts are not bound to a table's size.
class PercentageCloserSoftShadows final : public KernelTechnique {
public:
    std::string name() const override { return "pcss"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/pcss/lookup.glsl"; }
    void bindLookup(const gl::Program& lighting) const override;
    // The search and the filter reach no farther than their radius cap (with the lookup's 1 %
    // rounding), and each tap's compare a texel more.
    float shadowReachTexels() const override { return maxRadius_ * 1.01f + 2.0f; }
    // The search and the filter compare the receiver's own depth at every tap.
    float shadowReachDepth() const override { return 0.0f; }

protected:
    std::vector<Parameter> declareParameters() override;
    // The blocker search and the filter are both clamped to uMaxRadiusTexels (lookup.glsl).
    float tileReachTexels() const override { return maxRadius_; }

private:
    static constexpr int kMaxTaps = 64;  // a cost bound only
    int blockerSamples_ = 16, filterTaps_ = 32;
    float lightSize_ = 0.3f, sunAngle_ = 2.0f, maxRadius_ = 48.0f;
};

}  // namespace penumbra::shadows
