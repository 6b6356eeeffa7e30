#pragma once
#include "gl/Texture.h"
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"

#include <glm/glm.hpp>
#include <vector>

namespace penumbra::shadows {

// Fixed-size penumbra: PCF over one of the kernels of shaders' pcf/lookup.glsl. Poisson points
// come from Bridson's algorithm at start-up; the jitter texture is built once.
class PercentageCloserFilter final : public ShadowTechnique {
public:
    enum class Kernel { Grid = 0, Bilinear, Gaussian, Poisson, Random, Jitter, Dither, Rotated, Adaptive };
    PercentageCloserFilter(std::string name, Kernel kernel, int taps);

    std::string name() const override { return name_; }
    std::filesystem::path lookupShader() const override { return "src/shadows/pcf/lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override { maps_.render(frame); }
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override { return maps_.memoryBytes() + jitter_.memoryBytes(); }
    std::vector<DebugView> debugViews() const override { return maps_.debugViews(); }
    std::vector<Parameter> parameters() override;

private:
    std::string name_;
    Kernel kernel_;
    float taps_;
    float kernelSize_ = 3.0f;
    float radiusTexels_ = 1.5f;
    float radiusWorld_ = 0.0f;
    float receiverPlane_ = 1.0f;
    std::vector<glm::vec2> poisson_;
    gl::Texture jitter_;
    DepthAndTintMaps maps_;
};

// `count` points in the unit disk at least `minDistance` apart, by Bridson's fast Poisson-disk
// sampling (SIGGRAPH 2007 sketch); the radius shrinks until `count` points fit. Deterministic.
std::vector<glm::vec2> poissonDisk(int count, std::uint32_t seed = 1);

}  // namespace penumbra::shadows
