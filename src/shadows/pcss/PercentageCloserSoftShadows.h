#pragma once
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"

#include <glm/glm.hpp>

namespace penumbra::shadows {

// Variable-size penumbra (Fernando 2005): blocker search, penumbra estimate, variable PCF.
// Light size comes from the scene file (`size`), else from the parameters.
class PercentageCloserSoftShadows final : public ShadowTechnique {
public:
    PercentageCloserSoftShadows();
    std::string name() const override { return "pcss"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/pcss/lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override { maps_.render(frame); }
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override { return maps_.memoryBytes(); }
    std::vector<DebugView> debugViews() const override { return maps_.debugViews(); }
    std::vector<Parameter> parameters() override;

private:
    float blockerSamples_ = 16, filterTaps_ = 32, lightSize_ = 0.3f, sunAngle_ = 2.0f, maxRadius_ = 48.0f;
    std::vector<glm::vec2> poisson_;
    DepthAndTintMaps maps_;
};

// Seed 001: three fixed 3x3 kernels chosen by caster-receiver distance.
class DistanceSoftenedShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "distance"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/distance/lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override { maps_.render(frame); }
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override { return maps_.memoryBytes(); }
    std::vector<DebugView> debugViews() const override { return maps_.debugViews(); }
    std::vector<Parameter> parameters() override;

private:
    float nearDistance_ = 0.3f, farDistance_ = 1.5f, spacing_ = 1.5f;
    DepthAndTintMaps maps_;
};

}  // namespace penumbra::shadows
