#pragma once
#include "gl/Framebuffer.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"
#include "shadows/common/MapRegion.h"
#include "shadows/moments/MomentWarp.h"

#include <optional>
#include <tuple>

namespace penumbra::shadows {

// VSM, ESM, EVSM (2 and 4 components) and MSM: one class, the warp differs. The opaque casters are
// drawn straight into a map of the moments' resolution with its own depth buffer: depth alone for
// the default 2 x 2 box, whose pass takes the moments of the four depths it gathers
// (blur_box_first_order.frag); their moments for a Gaussian (caster_moments.frag; with MSAA,
// converted from a multisampled depth map instead). Then blurred, and optionally mip-mapped for
// trilinear/anisotropic filtering. Coloured tint from translucent casters comes from the shared
// tint map, whose opaque depth is drawn only under the translucent casters, as its depth test
// (DepthAndTintMaps::kEveryLight): nothing here reads it.
// While the still casters and the light stay put, only the rectangle the animated casters cover
// now or covered last frame is drawn, blurred and mip-mapped again, widened by the blur's reach.
// A ground is drawn (but for MSM) only within the lookup's reach of the shadows on it and what it
// shadows (filterReachTexels), and the moments are made only where casters reach: elsewhere the
// map keeps the far plane's moments, cleared once (LightMoments::holds).
class MomentShadowMap final : public ShadowTechnique {
public:
    enum class Warp {
        Variance = gpu::kWarpVariance, Exponential = gpu::kWarpExponential,
        ExponentialVariance2 = gpu::kWarpExponentialVariance2, ExponentialVariance4 = gpu::kWarpExponentialVariance4,
        Moments4 = gpu::kWarpMoments4
    };
    MomentShadowMap(std::string name, Warp warp);

    std::string name() const override { return name_; }
    std::filesystem::path lookupShader() const override { return "src/shadows/moments/lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override;
    std::vector<std::string> lookupDefines() const override;
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override;
    // The blur's reach, then the mip levels' (at most max_lod) and the bilinear fetch's, in moment
    // texels, times the light's texels per moment texel; not bounded with anisotropy, whose
    // footprint grows past the level's; none for MSM (see the definition).
    float filterReachTexels() const override;
    std::vector<DebugView> debugViews() const override;

protected:
    std::vector<Parameter> declareParameters() override;

private:
    struct LightMoments {
        int resolution = 0;       // of the moments
        int depthResolution = 0;  // of the depth map they come from
        bool cube = false;
        GLenum format = 0;
        bool rawMoments = false;  // whether `raw` is made (not with boxFromDepth)
        int levels = 1;
        gl::Texture moments;
        // 2D: the unblurred moments of one face (but with boxFromDepth, whose box reads rasterDepth),
        // and those blurred along x (made for radii over 1)
        gl::Texture raw, scratch;
        // Per face, per mip level: a render target (level 0's with rasterDepth), and a view of the
        // level alone (compute_blur's images).
        std::vector<std::vector<gl::Framebuffer>> levelTargets;
        std::vector<std::vector<gl::Texture>> levelViews;
        // Per mip level: every face at once, as a render target (layered for a cube map) and a
        // 2D-array view (the next level's input).
        std::vector<gl::Framebuffer> levelLayersTargets;
        std::vector<gl::Texture> levelLayers;
        std::vector<DerivedTexels> derived;  // per face: what the moments were made from
        // Per face, per level: the texels that may hold other than the far plane's moments, which
        // the texels outside hold; those a remake leaves outside what casters reach are cleared.
        std::vector<std::vector<TexelRect>> holds;
        gl::Framebuffer rawTarget, scratchTarget;  // rawTarget: raw with rasterDepth
        gl::Texture rasterDepth;  // the casters' own raster (not with MSAA), at the moments' resolution
        gl::Framebuffer depthTarget;  // rasterDepth alone: boxFromDepth's raster
        gl::Texture multisampledDepth;  // 4x MSAA depth, re-rendered per face when MSAA is on
        gl::Framebuffer multisampledTarget;
    };
    GLenum format() const;
    // c+ and c- as the maps store them: the parameters, within what half floats hold with fp16.
    glm::vec2 exponents() const;
    void ensure(std::size_t light, const DepthAndTintMaps::LightMaps& depth);
    // The moment texels of face `face` that must be made again this frame (all of them when
    // nothing was kept).
    TexelRect changedTexels(std::size_t light, std::size_t face, const ShadowFrame& frame);
    // Per mip level of one face: the texels made again, and those of them a caster reaches; and
    // how many levels (from 0) are made already.
    struct FaceLevels {
        std::vector<TexelRect> rect, reached;
        int made = 0;
    };
    // Makes the moments of `texels` of face `face` again: level 0, and with compute_blur levels 1-4.
    // Returns what the mip levels below must redo.
    FaceLevels update(std::size_t light, std::size_t face, const TexelRect& texels, const ShadowFrame& frame);
    // Makes each mip level below those made of every face in one draw (downsample.vert).
    void makeMipLevels(std::size_t light, const std::vector<FaceLevels>& faces);
    void buildPrograms();
    // The moments where no caster is (depth 1), as moments.glsl's momentsOf(1) gives them.
    glm::vec4 farMoments() const;
    // The opaque casters of face `face` whose moments the raster draws inside `texels`, through
    // its view (shifted half a texel for the box), a ground only near its shadows.
    CasterSelection casterSelection(const ShadowFrame& frame, std::size_t light, std::size_t face, const TexelRect& texels,
                                    Motion motion) const;
    // Draws the opaque casters' moments into `target` (a raster framebuffer), inside `texels`.
    void rasterMoments(std::size_t light, std::size_t face, const gl::Framebuffer& target, const TexelRect& texels,
                       const ShadowFrame& frame);
    // blur_mips.comp: level 0 blurred from raw inside reached[0], and levels 1-4 inside reached[1-4]
    // from it, in one dispatch. Returns how many levels it made (at most 5).
    int blurAndMipInCompute(std::size_t light, std::size_t face, const std::vector<TexelRect>& reached);
    // Converts face `face`'s 4x multisampled depth into `target`'s moments, inside `texels`.
    void convertMultisampled(std::size_t light, std::size_t face, const gl::Framebuffer& target, const TexelRect& texels,
                             const ShadowFrame& frame);

    std::string name_;
    Warp warp_;
    int blurRadius_ = 2;
    bool fp16_ = false, mipmaps_ = true, msaa_ = false, halfResolution_ = true, computeBlur_ = false;
    enum BlurKernel { kBlurAuto = 0, kBlurGaussian = 1, kBlurBox = 2 };
    int blurKernel_ = kBlurAuto;
    // Whether blur_box.frag serves `radius` at that resolution with that kernel: asked for, or
    // `auto` where the Gaussian spans one moment texel each side (sigma 1/2 texel, the box's variance).
    static bool boxKernel(int radius, bool halfResolution, int kernel);
    // The Gaussian's taps each side, in moment texels, for a blur_radius at that resolution.
    static int gaussianTaps(int radius, bool halfResolution);
    // MSM's moments through the optimized quantization into RGBA16 (MomentWarp.h).
    bool quantized_ = true;
    bool quantized() const { return warp_ == Warp::Moments4 && quantized_; }
    // What the programs are compiled for: the blur radius, half resolution, kernel, quantization,
    // MSAA and the compute blur.
    using ProgramKey = std::tuple<int, bool, int, bool, bool, bool>;
    ProgramKey programKey() const { return {blurRadius_, halfResolution_, blurKernel_, quantized(), msaa_, computeBlur_}; }
    ProgramKey built_{-1, false, -1, false, false, false};  // programKey() when last built
    // Built with blur_box.frag: the moments' raster is shifted by half a texel.
    bool boxBlur() const { return boxKernel(std::get<0>(built_), std::get<1>(built_), std::get<2>(built_)); }
    // The box from the casters' depth alone: the raster draws depth only (DepthAndTintMaps'
    // depth program), and the box's pass takes the first-order values of the four depths it gathers
    // (VSM's x, ESM's e^{c x}, EVSM's (p, n), MSM's t) to their moments (blur_box_first_order.frag).
    // Built for the box without MSAA or the compute blur, which read or write every moment.
    bool boxFromDepth() const;
    // The first-order values where no caster is (depth 1), as the CPU's farMoments raises them:
    // blur_box_first_order.frag's uFarFirstOrder.
    glm::vec2 farFirstOrder() const;
    // The coarsest mip level made, and so read: it bounds how far a lookup reads
    // (filterReachTexels), so that a ground is drawn, blurred and mip-mapped only around the
    // shadows on it.
    int maxLod_ = 4;
    int anisotropy_ = 1;  // of the mipmapped moments; 16x doubled the lookup on llvmpipe (50 -> 100 ms)
    float positiveExponent_, negativeExponent_ = 5;
    float minVariance_ = 1e-5f, bleedReduction_, momentBias_ = 3e-5f;
    DepthAndTintMaps maps_;
    std::vector<LightMoments> moments_;
    gl::Program toMoments_, blur_, downsample_;  // toMoments_: MSAA's conversion
    // With boxFromDepth, blur_ takes an orthographic light's depth as it is, and this one
    // linearises a perspective light's (moments.glsl's LIGHT_PERSPECTIVE): llvmpipe would run the
    // division of every gathered depth under a uniform branch too (msm's box 4.8 -> 6.5 ms).
    gl::Program perspectiveBlur_;
    // downsample_ writes gl_Layer from its vertex shader (GL_ARB_shader_viewport_layer_array): one
    // draw per level for all six faces of a cube; without it, one per face.
    bool layeredMips_ = false;
    gl::Program blurMips_;  // blur_mips.comp, for the moments' format blurMipsFormat_ (built when first used)
    GLenum blurMipsFormat_ = 0;
    std::optional<CasterProgramPair> casterMoments_;
    int blurTaps_ = 0;  // taps each side, in moment texels (the programs' BLUR_RADIUS)
    glm::vec3 blurWeights_{0.0f};  // blur_mips.comp's kernel on each axis, of the programs' radius-1 kernel
    gl::VertexArray fullscreenVao_;  // attribute-less full-screen passes
};

}  // namespace penumbra::shadows
