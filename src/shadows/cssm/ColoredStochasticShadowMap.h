#pragma once
#include "gl/Framebuffer.h"
#include "gl/Sampler.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"
#include "shadows/common/PoissonDisk.h"
#include "shadows/cssm/CssmFilter.h"

#include <glm/glm.hpp>

namespace penumbra::shadows {

// Colored Stochastic Shadow Maps (McGuire & Enderton 2011; Mátl 2013 ch. 4-5). Per light: the
// opaque casters' depth, copied (linearised) into the channels of a colour map; translucent
// casters then write their depth per channel with probability ρ_λ = (1 - t_λ) α under MIN
// blending. Layers multiply naturally: light passes a texel only if no layer stopped it, so two
// green panes give t², which the thesis (sorting whole objects) could not.
//   cssm2: one translucent pass, one ξ per fragment, RGBA16F (the thesis's RGB16F + alpha).
//   cssm1: one translucent pass per channel with independent ξ, RGBA32F ("one depth map per
//          wavelength", packed into the channels of one texture).
class ColoredStochasticShadowMap final : public ShadowTechnique {
public:
    enum class Variant { PerChannel = 1, Rgb = 2 };
    explicit ColoredStochasticShadowMap(Variant variant);

    std::string name() const override { return variant_ == Variant::Rgb ? "cssm2" : "cssm1"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/cssm/lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override;
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override;
    std::vector<DebugView> debugViews() const override;

protected:
    std::vector<Parameter> declareParameters() override;

private:
    struct LightMap {
        int resolution = 0;
        bool cube = false;
        GLenum format = 0;
        gl::Texture colour;
        std::vector<gl::Texture> depthFaces;    // 2D views of the depth map's faces (copy input)
        std::vector<gl::Framebuffer> targets;   // colour face + the depth map face (depth test)
    };
    void ensure(std::size_t light, const DepthAndTintMaps::LightMaps& depth);

    Variant variant_;
    int filter_ = gpu::kCssmBox16, generator_ = gpu::kRandomPcg, xi_ = gpu::kXiStratified;
    float radiusTexels_ = 0.0f;
    bool fp16_, separateOpaque_ = true;
    PoissonDisk poisson_;
    DepthAndTintMaps depth_{/*withTint=*/false};
    std::vector<LightMap> maps_;
    gl::Program copy_, casters_;
    gl::Sampler depthSampler_{GL_NEAREST, GL_NEAREST};  // depth as values, not comparisons
    gl::VertexArray fullscreenVao_;
};

}  // namespace penumbra::shadows
