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

protected:
    std::vector<Parameter> declareParameters() override;

private:
    float nearDistance_ = 0.3f, farDistance_ = 1.5f, spacing_ = 1.5f;
};

}  // namespace penumbra::shadows
