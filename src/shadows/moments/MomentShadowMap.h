#pragma once
#include "gl/Framebuffer.h"
#include "gl/Sampler.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"

namespace penumbra::shadows {

// VSM, ESM, EVSM (2 and 4 components) and MSM: one class, the warp differs. Moments are made
// from the (opaque-caster) depth map by a full-screen pass, then blurred with a separable
// Gaussian and optionally mip-mapped for trilinear/anisotropic filtering. Coloured tint from
// translucent casters comes from the shared tint map.
class MomentShadowMap final : public ShadowTechnique {
public:
    enum class Warp { Variance = 0, Exponential = 1, ExponentialVariance2 = 2, ExponentialVariance4 = 3, Moments4 = 4 };
    MomentShadowMap(std::string name, Warp warp);

    std::string name() const override { return name_; }
    std::filesystem::path lookupShader() const override { return "src/shadows/moments/lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override;
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override;
    std::vector<DebugView> debugViews() const override;
    std::vector<Parameter> parameters() override;

private:
    struct LightMoments {
        int resolution = 0;
        bool cube = false;
        GLenum format = 0;
        int levels = 1;
        gl::Texture moments, scratch;                  // scratch: 2D, one blur direction
        std::vector<gl::Texture> depthFaces, momentFaces;  // 2D views of each face (cube) or of the map
        std::vector<gl::Framebuffer> momentTargets;    // one per face
        gl::Framebuffer scratchTarget;
        gl::Texture multisampledDepth;  // 4x MSAA depth, re-rendered per face when MSAA is on
        gl::Framebuffer multisampledTarget;
    };
    GLenum format() const;
    void ensure(std::size_t light, const DepthAndTintMaps::LightMaps& depth);
    void convert(std::size_t light, const ShadowFrame& frame);

    std::string name_;
    Warp warp_;
    float blurRadius_ = 2, fp16_ = 0, mipmaps_ = 1, msaa_ = 0, positiveExponent_, negativeExponent_ = 5;
    float minVariance_ = 1e-5f, bleedReduction_, momentBias_ = 3e-5f;
    DepthAndTintMaps maps_;
    std::vector<LightMoments> moments_;
    gl::Program toMoments_, blur_;
    gl::Sampler depthSampler_{GL_NEAREST, GL_NEAREST};  // depth as values, not comparisons
    gl::VertexArray fullscreenVao_;  // attribute-less full-screen passes
};

}  // namespace penumbra::shadows
