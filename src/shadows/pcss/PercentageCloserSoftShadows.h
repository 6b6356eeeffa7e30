#pragma once
#include "shadows/common/SharedMapTechnique.h"
#include "shadows/common/DepthTileBounds.h"
#include "shadows/common/PoissonDisk.h"

namespace penumbra::shadows {

// Variable-size penumbra (Fernando 2005): blocker search, penumbra estimate, variable PCF.
// Light size comes from the scene file (`size`), else from the parameters.
class PercentageCloserSoftShadows final : public SharedMapTechnique {
public:
    std::string name() const override { return "pcss"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/pcss/lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override;
    void bindLookup(const gl::Program& lighting) const override;
    std::vector<DebugView> debugViews() const override {
        std::vector<DebugView> views = maps_.debugViews(), bounds = tileBounds_.debugViews(maps_.slots());
        views.insert(views.end(), bounds.begin(), bounds.end());
        return views;
    }
    std::size_t memoryBytes() const override { return maps_.memoryBytes() + tileBounds_.memoryBytes(); }

protected:
    std::vector<Parameter> declareParameters() override;

private:
    int blockerSamples_ = 16, filterTaps_ = 32;
    float lightSize_ = 0.3f, sunAngle_ = 2.0f, maxRadius_ = 48.0f;
    bool skipAgreeing_ = true;
    PoissonDisk poisson_;
    DepthTileBounds tileBounds_;  // with skipAgreeing_
};

}  // namespace penumbra::shadows
