#pragma once
#include "shadows/common/KernelTechnique.h"
#include "shadows/common/PoissonDisk.h"

namespace penumbra::shadows {

// Variable-size penumbra (Fernando 2005): blocker search, penumbra estimate, variable PCF.
// Light size comes from the scene file (`size`), else from the parameters.
class PercentageCloserSoftShadows final : public KernelTechnique {
public:
    std::string name() const override { return "pcss"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/pcss/lookup.glsl"; }
    void bindLookup(const gl::Program& lighting) const override;

protected:
    std::vector<Parameter> declareParameters() override;

private:
    int blockerSamples_ = 16, filterTaps_ = 32;
    float lightSize_ = 0.3f, sunAngle_ = 2.0f, maxRadius_ = 48.0f;
    PoissonDisk poisson_;
};

}  // namespace penumbra::shadows
