#pragma once
#include "gl/Texture.h"
#include "shadows/common/KernelTechnique.h"
#include "shadows/common/PoissonDisk.h"
#include "shadows/pcf/PcfKernel.h"

namespace penumbra::shadows {

// Fixed-size penumbra: PCF over one of the kernels of pcf/lookup.glsl. The jitter texture is
// built once.
class PercentageCloserFilter final : public KernelTechnique {
public:
    enum class Kernel {
        Grid = gpu::kPcfGrid, Bilinear = gpu::kPcfBilinear, Gaussian = gpu::kPcfGaussian, Poisson = gpu::kPcfPoisson,
        Random = gpu::kPcfRandom, Jitter = gpu::kPcfJitter, Dither = gpu::kPcfDither, Rotated = gpu::kPcfRotated,
        Adaptive = gpu::kPcfAdaptive
    };
    PercentageCloserFilter(std::string name, Kernel kernel, int taps);

    std::string name() const override { return name_; }
    std::filesystem::path lookupShader() const override { return "src/shadows/pcf/lookup.glsl"; }
    std::vector<std::string> lookupDefines() const override;
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override { return KernelTechnique::memoryBytes() + jitter_.memoryBytes(); }
    float shadowReachTexels() const override;
    float shadowReachDepth() const override { return receiverPlane_ ? 0.01f : 0.0f; }  // tapReceiverDepth's clamp

protected:
    std::vector<Parameter> declareParameters() override;
    // lookup.glsl asks tapsAgree() for radius * uTapReach; a radius in world units has no bound in texels.
    float tileReachTexels() const override { return radiusWorld_ > 0.0f ? -1.0f : radiusTexels_ * tapReach(); }

private:
    float tapReach() const;
    std::string name_;
    Kernel kernel_;
    int taps_;
    int kernelSize_ = 3;
    float radiusTexels_ = 1.5f;
    float radiusWorld_ = 0.0f;
    bool receiverPlane_ = true;
    PoissonDisk poisson_;
    gl::Texture jitter_;
};

}  // namespace penumbra::shadows
