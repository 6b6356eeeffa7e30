#pragma once
#include "shadows/common/SharedMapTechnique.h"

namespace penumbra::shadows {

// The "Fresnel effect of shadows" of the small coloured-light engine (seed document 001): three
// fixed 3x3 kernels chosen by the caster-receiver distance.
class DistanceSoftenedShadows final : public SharedMapTechnique {
public:
    std::string name() const override { return "distance"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/distance/lookup.glsl"; }
    void bindLookup(const gl::Program& lighting) const override;
    // The 3x3 taps' corners, spacing x sqrt 2 away, and each compare's texels (as hard's). Where
    // every compare passes, each kernel sums to exactly 9 of 9, whichever the distance chose.
    float shadowReachTexels() const override { return spacing_ * 1.4143f + 2.0f; }
    float shadowReachDepth() const override { return 0.0f; }  // the receiver's own depth at every tap

protected:
    std::vector<Parameter> declareParameters() override;

private:
    float nearDistance_ = 0.3f, farDistance_ = 1.5f, spacing_ = 1.5f;
};

}  // namespace penumbra::shadows
