#pragma once
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"
#include "shadows/common/PoissonDisk.h"

namespace penumbra::shadows {

// Variable-size penumbra (Fernando 2005): blocker search, penumbra estimate, variable PCF.
// Light size comes from the scene file (`size`), else from the parameters.
class PercentageCloserSoftShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "pcss"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/pcss/lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override { maps_.render(frame); }
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override { return maps_.memoryBytes(); }
    std::vector<DebugView> debugViews() const override { return maps_.debugViews(); }

protected:
    std::vector<Parameter> declareParameters() override;

private:
    int blockerSamples_ = 16, filterTaps_ = 32;
    float lightSize_ = 0.3f, sunAngle_ = 2.0f, maxRadius_ = 48.0f;
    PoissonDisk poisson_;
    DepthAndTintMaps maps_;
};

}  // namespace penumbra::shadows
