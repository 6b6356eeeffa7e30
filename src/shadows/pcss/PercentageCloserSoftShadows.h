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
    float shadowReachTexels() const override { return radiusReachTexels(maxRadius_); }
    // Less where the receivers lie near the light's near plane: the widest penumbra the lookup
    // can estimate there, with every blocker at that plane (penumbraTexels in lookup.glsl).
    void fitToView(const ShadowFrame& frame) override;
    float shadowReachTexelsWithin(int light, const scene::Bounds& region) const override;
    std::uint64_t reachViewsDigest() const override;
    // The search and the filter compare the receiver's own depth at every tap.
    float shadowReachDepth() const override { return 0.0f; }

protected:
    std::vector<Parameter> declareParameters() override;
    // The blocker search and the filter are both clamped to uMaxRadiusTexels (lookup.glsl).
    float tileReachTexels() const override { return maxRadius_; }

private:
    // A radius of `radius` texels, with the lookup's 1 % rounding, and each tap's compare a texel more.
    static float radiusReachTexels(float radius) { return radius * 1.01f + 2.0f; }
    // What shadowReachTexelsWithin needs of a light: fitToView's copy of this frame's.
    struct LightReach {
        bool bounded = false;  // a sun, spot or projector (a cube map's faces are not bounded here)
        bool perspective = false;
        glm::mat4 shadowMatrix{1.0f};  // world -> [0,1]^3: its z the window depth
        float near = 0.0f, far = 1.0f, texelScale = 0.0f, normalOffset = 0.0f;
        float size = 0.0f;  // the lookup's light size: degrees for a sun, world units else
    };
    std::vector<LightReach> lightReach_;

    static constexpr int kMaxTaps = 64;  // a cost bound only
    int blockerSamples_ = 16, filterTaps_ = 32;
    float lightSize_ = 0.3f, sunAngle_ = 2.0f, maxRadius_ = 48.0f;
};

}  // namespace penumbra::shadows
