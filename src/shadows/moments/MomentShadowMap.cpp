#include "shadows/moments/MomentShadowMap.h"

#include "gl/Debug.h"
#include "gl/PassState.h"
#include "gpu/ShaderContract.h"
#include "util/Digest.h"

#include <algorithm>
#include <cmath>

namespace penumbra::shadows {

MomentShadowMap::MomentShadowMap(std::string name, Warp warp)
    : name_(std::move(name)), warp_(warp),
      // ESM stores one exponential: c = 80 keeps e^{c} within fp32 for x in [-1, 1].
      // EVSM stores the square too, so c+ = 40 (e^{80} < 3.4e38).
      positiveExponent_(warp == Warp::Exponential ? 80.0f : 40.0f),
      bleedReduction_(warp == Warp::Variance ? 0.2f : 0.0f) {
    buildPrograms();
}

// blur_radius is in texels of the light's map resolution (sigma = radius / 2 of them): at half
// resolution the kernel spans half as many moment texels.
int MomentShadowMap::gaussianTaps(int radius, bool halfResolution) {
    return static_cast<int>(std::ceil(static_cast<float>(radius) / (halfResolution ? 2.0f : 1.0f)));
}

bool MomentShadowMap::boxKernel(int radius, bool halfResolution, int kernel) {
    return radius > 0 && (kernel == kBlurBox || (kernel == kBlurAuto && gaussianTaps(radius, halfResolution) == 1));
}

bool MomentShadowMap::boxFromDepth() const {
    const bool msaa = std::get<4>(built_), compute = std::get<5>(built_);
    return boxBlur() && !msaa && !compute;
}

glm::vec2 MomentShadowMap::farFirstOrder() const {
    if (warp_ == Warp::Moments4) return {1.0f, 0.0f};  // t at the far plane
    const glm::vec4 far = farMoments();  // x or e^{c+ x} or p first, n third
    return {far.x, warp_ == Warp::ExponentialVariance4 ? far.z : 0.0f};
}

// The warp, the blur radius and the downsampling are compiled in (caster_moments.frag,
// moments.frag, blur.frag, blur_bilinear.frag): rebuilt when a parameter changes them.
void MomentShadowMap::buildPrograms() {
    built_ = programKey();  // boxFromDepth() reads it
    const bool box = boxKernel(blurRadius_, halfResolution_, blurKernel_);
    const int taps = box ? 1 : gaussianTaps(blurRadius_, halfResolution_);
    const float sigma = std::max(0.5f * static_cast<float>(blurRadius_) / (halfResolution_ ? 2.0f : 1.0f), 0.5f);
    // blur_mips.comp's kernel on each axis over texels p - 1, p, p + 1: blur_box.frag's box (its
    // raster shifted half a texel), or the radius-1 Gaussian's taps, as blur_bilinear.frag weighs them.
    const float g = std::exp(-1.0f / (2.0f * sigma * sigma)), w = g / (1.0f + 2.0f * g);
    blurWeights_ = box ? glm::vec3(0.0f, 0.5f, 0.5f) : glm::vec3(w, 1.0f - 2.0f * w, w);
    std::vector<std::string> defines = lookupDefines();
    defines.push_back("BLUR_RADIUS " + std::to_string(taps));
    defines.push_back("BLUR_SIGMA " + std::to_string(sigma));
    defines.push_back(std::string("MOMENT_DOWNSAMPLE ") + (halfResolution_ ? "1" : "0"));
    toMoments_ = gl::Program::build(
        {.vertex = "shaders/passes/fullscreen.vert", .fragment = "src/shadows/moments/moments.frag", .defines = defines});
    // The box in one bilinear fetch; the Gaussian of radius 1 in one pass of four, larger ones in two
    // separable passes (see update).
    const char* blur = box && boxFromDepth() ? "src/shadows/moments/blur_box_first_order.frag"
                       : box              ? "src/shadows/moments/blur_box.frag"
                       : taps == 1 ? "src/shadows/moments/blur_bilinear.frag"
                                   : "src/shadows/moments/blur.frag";
    const auto blurFor = [&](const char* perspective) {
        std::vector<std::string> d = defines;
        if (boxFromDepth()) d.push_back(std::string("LIGHT_PERSPECTIVE ") + perspective);
        return gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = blur, .defines = d});
    };
    blur_ = blurFor("0");
    perspectiveBlur_ = boxFromDepth() ? blurFor("1") : gl::Program{};
    layeredMips_ = epoxy_has_gl_extension("GL_ARB_shader_viewport_layer_array");
    downsample_ = gl::Program::build({.vertex = "src/shadows/moments/downsample.vert",
                                      .fragment = "src/shadows/moments/downsample.frag",
                                      .defines = {std::string("LAYERED ") + (layeredMips_ ? "1" : "0")}});
    const gl::ProgramDesc caster{.vertex = "src/shadows/common/glsl/caster.vert",
                                 .fragment = "src/shadows/moments/caster_moments.frag",
                                 .defines = defines};
    gl::ProgramDesc alphaTested = caster;
    alphaTested.defines.emplace_back("ALPHA_TEST 1");
    casterMoments_.emplace(caster, alphaTested, false);
    blurTaps_ = taps;
}

std::vector<std::string> MomentShadowMap::lookupDefines() const {
    return {"MOMENT_WARP " + std::to_string(static_cast<int>(warp_)), std::string("MOMENTS_QUANTIZED ") + (quantized() ? "1" : "0")};
}

std::vector<Parameter> MomentShadowMap::declareParameters() {
    std::vector<Parameter> p{
        Parameter::integer("blur_radius", blurRadius_, 0, 16,
                           "pre-filter radius in texels of the light's resolution (a Gaussian of sigma = radius / 2, at "
                           "least half a moment texel); 0: no pre-filter"),
        Parameter::choice("blur_kernel", blurKernel_, {"auto", "gaussian", "box"},
                          "auto: the box where the Gaussian would span one moment texel each side (blur_radius 1-2 at half "
                          "resolution, the default), else the Gaussian; gaussian: the Gaussian blur_radius says (at the "
                          "default three taps across, in four bilinear fetches); box: a 2 x 2 box of moment texels in one "
                          "bilinear fetch whatever the radius (variance 1/4 texel^2 a side, sigma 1/2's; on llvmpipe the "
                          "default scene's frame 0.87x with every map redrawn; against the reference wrong pixels within "
                          "+0.02 points of the Gaussian's, RMSE within +-0.001)"),
        Parameter::flag("fp16", fp16_, "half-float moments (RG16F / RGBA16F) instead of 32-bit; exponential warps then at most c = 10 (esm) or 5.54 (evsm), what half floats hold"),
        Parameter::flag("mipmaps", mipmaps_, "trilinear mipmaps of the moments"),
        Parameter::integer("max_lod", maxLod_, 0, 16,
                           "the coarsest mip level made and read (4: 64^2 of the default 1024^2 moments); it bounds how "
                           "far a lookup reads, so that a ground is drawn, blurred and mip-mapped only around the shadows "
                           "on it, but for msm (the default scene against every level: vsm and evsm4 the same pixels, msm 1 pixel apart)"),
        Parameter::integer("anisotropy", anisotropy_, 1, 16, "anisotropic filtering of the mipmapped moments"),
        Parameter::flag("compute_blur", computeBlur_,
                        "the radius-1 Gaussian (blur_radius 1-2 at half resolution) or the box, and mip levels 1-4, in one "
                        "compute pass with the moments in shared memory (blur_mips.comp) instead of a blur pass and a pass "
                        "per level; the same moments. For GPUs: on llvmpipe its shadow pass is 7x the fragment passes' "
                        "(shared memory is slow there)"),
        Parameter::flag("msaa", msaa_,
                        "moments averaged over a 4x multisampled depth map at the light's resolution (smoother "
                        "silhouettes at several times the cost; without it the casters' moments are drawn directly)"),
        Parameter::flag("half_resolution", halfResolution_,
                        "moments at half the light's map resolution (the same error against the reference on the "
                        "default scene at a quarter of the texels to draw, blur and mipmap)")};
    if (warp_ == Warp::Variance || warp_ == Warp::ExponentialVariance2 || warp_ == Warp::ExponentialVariance4) {
        p.push_back(Parameter::real("min_variance", minVariance_, 0.0f, 1e-2f, "variance floor against acne"));
        p.push_back(Parameter::real("bleed_reduction", bleedReduction_, 0.0f, 0.95f,
                                    "light-bleeding reduction: p_max mapped by linstep(amount, 1) (Lauritzen)"));
    }
    if (warp_ != Warp::Variance && warp_ != Warp::Moments4)
        p.push_back(Parameter::real("exponent", positiveExponent_, 1.0f, 88.0f, "positive warp exponent c+"));
    if (warp_ == Warp::ExponentialVariance4)
        p.push_back(Parameter::real("negative_exponent", negativeExponent_, 1.0f, 40.0f, "negative warp exponent c-"));
    if (warp_ == Warp::Moments4) {
        p.push_back(Parameter::real("moment_bias", momentBias_, 0.0f, 1e-2f, "moment bias alpha (Peters & Klein)"));
        p.push_back(Parameter::flag("quantized", quantized_,
                                    "64 bits a texel: the four moments through Peters & Klein's optimized quantization "
                                    "(2015, section 4.3) into RGBA16 instead of RGBA32F (fp16 then has no effect)"));
    }
    return p;
}

GLenum MomentShadowMap::format() const {
    const bool half = fp16_;
    switch (warp_) {
        case Warp::Variance: return half ? GL_RG16F : GL_RG32F;
        case Warp::Exponential: return half ? GL_R16F : GL_R32F;
        case Warp::ExponentialVariance2: return half ? GL_RG16F : GL_RG32F;
        default: return quantized() ? GL_RGBA16 : half ? GL_RGBA16F : GL_RGBA32F;
    }
}

// Half floats hold at most 65504 = e^11.09. ESM stores e^{c x} and EVSM e^{2 c x} (the square),
// x in [-1, 1], so with fp16 c is at most 10 and 5.54 (MJP's "Shadows" sample uses 5.54 for 16-bit
// EVSM too). Unclamped (c = 80 and 40), the default scene's score (320 x 180) with fp16 was 0.50 RMSE, 28 %
// wrong (esm) and 0.34 / 13 % (evsm2, evsm4), against 0.057 / 1.2 % and 0.052 / 1.2 % in fp32.
glm::vec2 MomentShadowMap::exponents() const {
    if (!fp16_) return {positiveExponent_, negativeExponent_};
    const float most = warp_ == Warp::Exponential ? 10.0f : 5.54f;
    return {std::min(positiveExponent_, most), std::min(negativeExponent_, most)};
}

void MomentShadowMap::ensure(std::size_t i, const DepthAndTintMaps::LightMaps& depth) {
    if (moments_.size() <= i) moments_.resize(i + 1);
    LightMoments& m = moments_[i];
    const int res = halfResolution_ ? std::max(1, depth.resolution / 2) : depth.resolution;
    const int levels = mipmaps_ ? std::min(1 + static_cast<int>(std::log2(res)), maxLod_ + 1) : 1;
    const bool msaa = msaa_;
    if (m.resolution == res && m.depthResolution == depth.resolution && m.cube == depth.cube && m.format == format() &&
        m.rawMoments == !boxFromDepth() && m.levels == levels && (m.multisampledDepth.id() != 0) == msaa)
        return;
    m = LightMoments{};
    m.resolution = res;
    m.depthResolution = depth.resolution;
    m.cube = depth.cube;
    m.format = format();
    m.rawMoments = !boxFromDepth();
    m.levels = levels;
    if (m.cube) {
        GLuint id = 0;
        glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &id);
        glTextureStorage2D(id, levels, m.format, res, res);
        std::size_t bytes = 0;
        for (int l = 0, s = res; l < levels; ++l, s = std::max(1, s / 2)) bytes += 6u * gl::bytesPerTexel(m.format) * s * s;
        m.moments = gl::Texture::adopt(GL_TEXTURE_CUBE_MAP, id, res, res, bytes);
    } else {
        m.moments = gl::Texture::create2D(m.format, res, res, levels);
    }
    m.moments.setFilter(levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
    m.moments.setWrap(GL_CLAMP_TO_EDGE);
    m.rasterDepth = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, res, res);
    if (m.rawMoments) {
        m.raw = gl::Texture::create2D(m.format, res, res);
        m.raw.setFilter(GL_LINEAR, GL_LINEAR);  // blur_bilinear.frag
        m.raw.setWrap(GL_CLAMP_TO_EDGE);
        m.rawTarget = gl::Framebuffer::colourAndDepth(m.raw, m.rasterDepth, "unblurred moments");
    } else {  // blur_box_first_order.frag gathers the depths, clamped to the edges
        m.rasterDepth.setFilter(GL_NEAREST, GL_NEAREST);
        m.rasterDepth.setWrap(GL_CLAMP_TO_EDGE);
        m.depthTarget.attach(GL_DEPTH_ATTACHMENT, m.rasterDepth);
        m.depthTarget.setNoColor();
        m.depthTarget.checkComplete("moment raster depth");
    }
    if (msaa) {  // llvmpipe offers at most 4 samples
        m.multisampledDepth = gl::Texture::create2DMultisample(GL_DEPTH_COMPONENT32F, depth.resolution, depth.resolution, 4);
        m.multisampledTarget.attach(GL_DEPTH_ATTACHMENT, m.multisampledDepth);
        m.multisampledTarget.setNoColor();
        m.multisampledTarget.checkComplete("multisampled moment depth");
    }
    const int faces = m.cube ? 6 : 1;
    m.levelTargets.resize(static_cast<std::size_t>(faces));
    m.levelViews.resize(static_cast<std::size_t>(faces));
    for (int f = 0; f < faces; ++f) {
        for (int level = 0; level < levels; ++level) {
            const auto face = static_cast<std::size_t>(f);
            m.levelTargets[face].push_back(gl::Framebuffer::colourOnly(m.moments, m.cube ? f : -1, "moment map", level));
            m.levelViews[face].push_back(gl::Texture::view2D(m.moments, m.format, f, level));
        }
        // Level 0 takes the casters' raster without a blur: the moments' depth buffer goes with it.
        m.levelTargets[static_cast<std::size_t>(f)][0].attach(GL_DEPTH_ATTACHMENT, m.rasterDepth);
        m.levelTargets[static_cast<std::size_t>(f)][0].checkComplete("moment map with its depth buffer");
    }
    for (int level = 0; level < levels; ++level) {
        m.levelLayersTargets.push_back(gl::Framebuffer::colourOnly(m.moments, -1, "moment map level", level));
        m.levelLayers.push_back(gl::Texture::viewLayers(m.moments, m.format, faces, level));
        m.levelLayers.back().setFilter(GL_LINEAR, GL_LINEAR);  // downsample.frag's fetch
        m.levelLayers.back().setWrap(GL_CLAMP_TO_EDGE);
    }
    m.derived.assign(static_cast<std::size_t>(faces), DerivedTexels{});
    m.holds.assign(static_cast<std::size_t>(faces), {});
    for (auto& levelsOfFace : m.holds)  // unknown yet
        for (int level = 0; level < levels; ++level) levelsOfFace.push_back({0, 0, std::max(1, res >> level), std::max(1, res >> level)});
}

// Level texels `rect` made again, of which `reached` may hold other than the far plane: what
// LightMoments::holds says of the level after (a rectangle around both where `rect` leaves some
// of what it held before).
static void nowHolds(TexelRect& holds, const TexelRect& rect, const TexelRect& reached) {
    const bool remade = isEmpty(holds) || intersection(holds, rect) == holds;
    holds = remade ? reached : unite(holds, reached);
}

// In moment texels: the blur spreads a raw texel over its taps and one more (the box's half-texel
// shift, the Gaussian's bilinear fetches); a texel of mip level L averages 2^L x 2^L of level 0,
// and a bilinear fetch there reads texels up to 1.5 of its own from the point it samples.
float MomentShadowMap::filterReachTexels() const {
    // Not MSM's: its bound is not monotonic in the moments as Chebyshev's and the exponential
    // warps' are, so a ground's own texels read as the far plane's do not light it exactly
    // (CullingTest's scene: visibility up to 0.033 apart under a sun; on a 40 m ground 0.018-0.177
    // at twice this reach, up to 0.05 at four times: docs/measurements.md, stop 74).
    if (warp_ == Warp::Moments4 || (mipmaps_ && anisotropy_ > 1)) return -1.0f;
    const int taps = boxKernel(blurRadius_, halfResolution_, blurKernel_) ? 1 : gaussianTaps(blurRadius_, halfResolution_);
    const float blur = blurRadius_ > 0 ? static_cast<float>(taps) + 1.0f : 0.5f;
    const float fetch = 1.5f * std::exp2(static_cast<float>(mipmaps_ ? maxLod_ : 0));
    return (blur + fetch) * (halfResolution_ ? 2.0f : 1.0f);
}

// moments.glsl's uniforms, on a program or a caster program pair.
template <class Program>
static void setMomentUniforms(const Program& program, const LightSpace& space, glm::vec2 exponents) {
    program.set("uPerspective", space.perspective ? 1 : 0);
    program.set("uNear", space.near);
    program.set("uFar", space.far);
    program.set("uExponents", exponents);
}

TexelRect MomentShadowMap::changedTexels(std::size_t i, std::size_t face, const ShadowFrame& frame) {
    LightMoments& m = moments_[i];
    const LightSpace& space = (*frame.lightSpaces)[i];
    const glm::mat4& vp = space.viewProj[face];
    const int light = static_cast<int>(i);
    // MSAA draws its own depth every frame; the rest is what the moments are a function of: the
    // still casters, the light's transform and depth range, the offset, the warp and the blur.
    const bool reuse = frame.reuseStillCasters && frame.casterDigest && m.multisampledDepth.id() == 0;
    const std::uint64_t key = !reuse ? 0
                                     : util::Digest()
                                           .add(frame.casterDigest({Casters::Opaque, vp, light, Motion::Still}), vp,
                                                (*frame.lights)[i].shadow.polygonOffset, exponents(), space.near, space.far,
                                                space.perspective, blurRadius_, blurKernel_, computeBlur_)
                                           .value();
    const TexelRect moving = frame.casterTexels(casterSelection(frame, i, face, TexelRect(0, 0, m.resolution, m.resolution), Motion::Moving));
    return m.derived[face].changed(key, moving, m.resolution);
}

glm::vec4 MomentShadowMap::farMoments() const {
    const glm::vec2 c = exponents();
    switch (warp_) {
        case Warp::Variance: return {1.0f, 1.0f, 0.0f, 0.0f};
        case Warp::Exponential: return {std::exp(c.x), 0.0f, 0.0f, 0.0f};
        case Warp::ExponentialVariance2:
        case Warp::ExponentialVariance4: {
            const float p = std::exp(c.x), n = -std::exp(-c.y);
            return {p, p * p, n, n * n};
        }
        case Warp::Moments4:
            return quantized() ? gpu::kMomentsQuantize * glm::vec4(1.0f) + gpu::kMomentsQuantizeOffset : glm::vec4(1.0f);
    }
    return glm::vec4(1.0f);
}

void MomentShadowMap::rasterMoments(std::size_t i, std::size_t face, const gl::Framebuffer& target, const TexelRect& texels,
                                    const ShadowFrame& frame) {
    const LightMoments& m = moments_[i];
    const LightSpace& space = (*frame.lightSpaces)[i];
    const glm::vec2 po = (*frame.lights)[i].shadow.polygonOffset;
    // The slope-scaled offset is per texel of slope: a map n times coarser takes 1/n of the
    // factor for the same offset in depth as the light's depth map.
    const float coarser = static_cast<float>(m.depthResolution) / static_cast<float>(m.resolution);
    const gl::ScopedPassState state(gl::PassState::depthOnly().withPolygonOffset(po.x / coarser, po.y));
    target.bind();
    glViewport(0, 0, m.resolution, m.resolution);
    glScissor(texels.x, texels.y, texels.z - texels.x, texels.w - texels.y);
    const float farDepth = 1.0f;
    glClearNamedFramebufferfv(target.id(), GL_DEPTH, 0, &farDepth);
    if (&target == &m.depthTarget) {  // depth alone, whose fragment stage is empty: the box takes the moments
        frame.drawCasters(maps_.depthProgram(), casterSelection(frame, i, face, texels, Motion::Any));
        return;
    }
    const glm::vec4 none = farMoments();
    glClearNamedFramebufferfv(target.id(), GL_COLOR, 0, &none.x);
    setMomentUniforms(*casterMoments_, space, exponents());
    frame.drawCasters(*casterMoments_, casterSelection(frame, i, face, texels, Motion::Any));
}

CasterSelection MomentShadowMap::casterSelection(const ShadowFrame& frame, std::size_t i, std::size_t face, const TexelRect& texels,
                                                 Motion motion) const {
    const LightMoments& m = moments_[i];
    const glm::mat4& vp = (*frame.lightSpaces)[i].viewProj[face];
    glm::mat4 shifted = vp;
    if (boxBlur()) {  // blur_box.frag's box is centred on texel p + 1/2: sample the casters half a texel off
        const float half = 1.0f / static_cast<float>(m.resolution);
        shifted = glm::mat4(1.0f);
        shifted[3][0] = half;
        shifted[3][1] = half;
        shifted = shifted * vp;
    }
    // Culled to the rectangle: a kept map redoes only the texels the animated casters changed,
    // with a ground's ring around them where it follows them (default scene, maps kept: vsm's pass
    // 0.49 -> 1.02 ms; redrawn 15.0 -> 9.8 ms).
    const float perLightTexel = static_cast<float>(m.resolution) / static_cast<float>(m.depthResolution);
    return {Casters::Opaque, cropTo(texels, m.resolution) * shifted, static_cast<int>(i), motion, shifted, true,
            CasterMap{m.resolution, texels, true, perLightTexel, true}};
}

void MomentShadowMap::convertMultisampled(std::size_t i, std::size_t face, const gl::Framebuffer& target, const TexelRect& texels,
                                          const ShadowFrame& frame) {
    LightMoments& m = moments_[i];
    const LightSpace& space = (*frame.lightSpaces)[i];
    const scene::Light& light = (*frame.lights)[i];
    {  // the opaque casters again, into the 4x multisampled depth map of this face
        const gl::ScopedPassState state(
            gl::PassState::depthOnly().withPolygonOffset(light.shadow.polygonOffset.x, light.shadow.polygonOffset.y));
        glDisable(GL_SCISSOR_TEST);
        glViewport(0, 0, m.depthResolution, m.depthResolution);
        m.multisampledTarget.bind();
        const float farDepth = 1.0f;
        glClearNamedFramebufferfv(m.multisampledTarget.id(), GL_DEPTH, 0, &farDepth);
        frame.drawCasters(maps_.depthProgram(), {Casters::Opaque, space.viewProj[face], static_cast<int>(i), Motion::Any, space.viewProj[face], true});
    }
    const gl::ScopedPassState state(gl::PassState::fullscreen());
    glEnable(GL_SCISSOR_TEST);
    glViewport(0, 0, m.resolution, m.resolution);
    fullscreenVao_.bind();
    setMomentUniforms(toMoments_, space, exponents());
    toMoments_.use();
    m.multisampledDepth.bind(1);
    target.bind();
    glScissor(texels.x, texels.y, texels.z - texels.x, texels.w - texels.y);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

// The GLSL image format qualifier of the moments' internal formats.
static const char* imageFormatQualifier(GLenum format) {
    switch (format) {
        case GL_R32F: return "r32f";
        case GL_RG32F: return "rg32f";
        case GL_R16F: return "r16f";
        case GL_RG16F: return "rg16f";
        case GL_RGBA16F: return "rgba16f";
        case GL_RGBA16: return "rgba16";
        default: return "rgba32f";
    }
}

int MomentShadowMap::blurAndMipInCompute(std::size_t i, std::size_t face, const std::vector<TexelRect>& reached) {
    constexpr int kTile = 16, kMostLevels = 5;  // blur_mips.comp's tile, and level 0 with the four beneath it
    LightMoments& m = moments_[i];
    if (blurMipsFormat_ != m.format) {
        blurMips_ = gl::Program::build({.compute = "src/shadows/moments/blur_mips.comp",
                                        .defines = {std::string("MOMENT_IMAGE_FORMAT ") + imageFormatQualifier(m.format)}});
        blurMipsFormat_ = m.format;
    }
    const int made = std::min(m.levels, kMostLevels);
    blurMips_.set("uWeights", blurWeights_);
    blurMips_.set("uLevels", made);
    for (int l = 0; l < kMostLevels; ++l) {
        const auto level = static_cast<std::size_t>(std::min(l, made - 1));  // units past `made` are never written
        glBindImageTexture(static_cast<GLuint>(l), m.levelViews[face][level].id(), 0, GL_FALSE, 0,
                           l == 0 ? GL_READ_WRITE : GL_WRITE_ONLY, m.format);
        const std::string name = "uLevelRect[" + std::to_string(l) + "]";
        blurMips_.set(name.c_str(), l < made ? reached[static_cast<std::size_t>(l)] : TexelRect(0));
    }
    const TexelRect& r = reached[0];
    const glm::ivec2 origin = glm::ivec2(r.x, r.y) / kTile * kTile;
    const glm::ivec2 groups = (glm::ivec2(r.z, r.w) - origin + (kTile - 1)) / kTile;
    blurMips_.set("uTileOrigin", origin);
    m.raw.bind(0);
    blurMips_.use();
    glDispatchCompute(static_cast<GLuint>(groups.x), static_cast<GLuint>(groups.y), 1);
    // The levels are sampled next (the fragment levels below, the lookup), level 0 loaded again by
    // the next frame's dispatch.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    glBindImageTextures(0, kMostLevels, nullptr);
    return made;
}

MomentShadowMap::FaceLevels MomentShadowMap::update(std::size_t i, std::size_t face, const TexelRect& changed,
                                                    const ShadowFrame& frame) {
    LightMoments& m = moments_[i];
    // `changed`: moment texels whose unblurred moments changed. The blur spreads that by its taps:
    // in one pass (radius 1, blur_bilinear.frag) by as much in x and y; in two, the y pass reads
    // the x-blurred texels as far again above and below, the x pass the unblurred ones as far
    // again left and right.
    const bool onePass = blurTaps_ == 1;
    const auto readBy = [&](const TexelRect& r) {  // the unblurred texels the blur of `r` reads
        return onePass ? grown(r, glm::ivec2(1), m.resolution)
                       : grown(grown(r, glm::ivec2(0, blurTaps_), m.resolution), glm::ivec2(blurTaps_, 0), m.resolution);
    };
    const TexelRect blurred = grown(changed, glm::ivec2(blurTaps_), m.resolution);
    const TexelRect xBlurred = grown(blurred, glm::ivec2(0, blurTaps_), m.resolution);
    // Where no caster can have written, even through the blur, every level holds the moments of
    // the far plane: blurred and mip-mapped only where a caster reaches, cleared where it no
    // longer does (a point light's cube face that looks at the sky costs two clears once).
    const TexelRect cast = frame.casterTexels(casterSelection(frame, i, face, TexelRect(0, 0, m.resolution, m.resolution), Motion::Any));
    const TexelRect reached = intersection(blurred, grown(cast, glm::ivec2(blurTaps_ + 1), m.resolution));
    glEnable(GL_SCISSOR_TEST);
    std::optional<gl::DebugGroup> part(std::in_place, "raster");
    // The unblurred moments only where the blur reads them (none where no caster reaches).
    const TexelRect drawn = blurTaps_ > 0 ? intersection(readBy(blurred), readBy(reached)) : blurred;
    const gl::Framebuffer& rasterTarget = !m.rawMoments ? m.depthTarget : blurTaps_ > 0 ? m.rawTarget : m.levelTargets[face][0];
    if (!isEmpty(drawn) && m.multisampledDepth.id() != 0)
        convertMultisampled(i, face, rasterTarget, drawn, frame);
    else if (!isEmpty(drawn))
        rasterMoments(i, face, rasterTarget, drawn, frame);
    const glm::vec4 far = farMoments();
    const auto scissor = [](const TexelRect& r) { glScissor(r.x, r.y, r.z - r.x, r.w - r.y); };
    // Level `level`'s texels of `all` outside `drawn` to the far plane's moments, where they may
    // hold others (LightMoments::holds).
    const auto clearOutside = [&](std::size_t level, const TexelRect& all, const TexelRect& drawn) {
        const TexelRect stale = intersection(all, m.holds[face][level]);
        const TexelRect in = intersection(drawn, stale);
        const GLuint target = m.levelTargets[face][level].id();
        if (isEmpty(in)) {
            clearColourIn(target, stale, far);
        } else {  // the strips of `stale` below, above, left and right of `in`
            clearColourIn(target, {stale.x, stale.y, stale.z, in.y}, far);
            clearColourIn(target, {stale.x, in.w, stale.z, stale.w}, far);
            clearColourIn(target, {stale.x, in.y, in.x, in.w}, far);
            clearColourIn(target, {in.z, in.y, stale.z, in.w}, far);
        }
        glEnable(GL_SCISSOR_TEST);  // clearColourIn's scope ends it
    };
    FaceLevels levels{{blurred}, {reached}, 1};
    for (int l = 1; l < m.levels; ++l) {
        const int size = std::max(1, m.resolution >> l);
        levels.rect.push_back(coarser(levels.rect.back(), 2, size));
        levels.reached.push_back(intersection(levels.rect.back(), coarser(levels.reached.back(), 2, size)));
    }
    part.reset();
    part.emplace("blur");
    const gl::ScopedPassState state(gl::PassState::fullscreen());
    glViewport(0, 0, m.resolution, m.resolution);
    fullscreenVao_.bind();
    if (blurTaps_ > 0) clearOutside(0, blurred, reached);
    if (blurTaps_ > 0 && !isEmpty(reached) && computeBlur_ && onePass) {
        levels.made = blurAndMipInCompute(i, face, levels.reached);
        for (int l = 1; l < levels.made; ++l) {  // the rest of the rectangle of each level it made
            const auto level = static_cast<std::size_t>(l);
            clearOutside(level, levels.rect[level], levels.reached[level]);
        }
    } else if (blurTaps_ > 0 && !isEmpty(reached)) {
        const LightSpace& space = (*frame.lightSpaces)[i];
        const gl::Program& blur = !m.rawMoments && space.perspective ? perspectiveBlur_ : blur_;
        blur.use();
        if (onePass) {  // raw (or the raster's depth) -> map, x and y at once
            m.levelTargets[face][0].bind();
            if (m.rawMoments) {
                m.raw.bind(0);
            } else {
                m.rasterDepth.bind(0);
                setMomentUniforms(blur, space, exponents());
                blur.set("uFarFirstOrder", farFirstOrder());
            }
            scissor(reached);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        } else {  // separable Gaussian: raw -> scratch (x), scratch -> map (y)
            if (m.scratch.id() == 0) {  // only radii over 1 need it
                m.scratch = gl::Texture::create2D(m.format, m.resolution, m.resolution);
                m.scratchTarget = gl::Framebuffer::colourOnly(m.scratch, -1, "moment blur scratch");
            }
            m.scratchTarget.bind();
            blur_.set("uDirection", glm::ivec2(1, 0));
            m.raw.bind(0);
            scissor(intersection(xBlurred, grown(reached, glm::ivec2(0, blurTaps_), m.resolution)));
            glDrawArrays(GL_TRIANGLES, 0, 3);
            m.levelTargets[face][0].bind();
            blur_.set("uDirection", glm::ivec2(0, 1));
            m.scratch.bind(0);
            scissor(reached);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
    }
    glDisable(GL_SCISSOR_TEST);
    for (int l = 0; l < levels.made; ++l) {
        const auto level = static_cast<std::size_t>(l);
        nowHolds(m.holds[face][level], levels.rect[level], levels.reached[level]);
    }
    return levels;
}

void MomentShadowMap::makeMipLevels(std::size_t i, const std::vector<FaceLevels>& faces) {
    const gl::DebugGroup group("mip levels");
    LightMoments& m = moments_[i];
    const int faceCount = static_cast<int>(faces.size());
    const gl::ScopedPassState state(gl::PassState::fullscreen());
    glDisable(GL_SCISSOR_TEST);  // each face's quad covers its rectangle alone
    fullscreenVao_.bind();
    downsample_.use();
    downsample_.set("uFar", farMoments());
    for (int l = 1; l < m.levels; ++l) {
        const auto level = static_cast<std::size_t>(l);
        bool any = false;
        for (int f = 0; f < faceCount; ++f) {
            const FaceLevels& face = faces[static_cast<std::size_t>(f)];
            const bool redo = l >= face.made;  // a face left as it was has made every level
            // What casters reach, and what of the rest may not hold the far plane's moments yet.
            TexelRect& holds = m.holds[static_cast<std::size_t>(f)][level];
            const TexelRect quad = redo ? unite(face.reached[level], intersection(face.rect[level], holds)) : TexelRect(0);
            if (redo) nowHolds(holds, face.rect[level], face.reached[level]);
            any = any || !isEmpty(quad);
            const std::string at = "[" + std::to_string(f) + "]";
            downsample_.set(("uRects" + at).c_str(), quad);
            downsample_.set(("uReached" + at).c_str(), redo ? face.reached[level] : TexelRect(0));
        }
        if (!any) continue;
        const int size = std::max(1, m.resolution >> l);
        glViewport(0, 0, size, size);
        downsample_.set("uLevelSize", glm::vec2(static_cast<float>(size)));
        m.levelLayers[level - 1].bind(0);
        if (layeredMips_) {
            m.levelLayersTargets[level].bind();
            downsample_.set("uFirstFace", 0);
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, faceCount);
        } else {
            for (int f = 0; f < faceCount; ++f) {
                m.levelTargets[static_cast<std::size_t>(f)][level].bind();
                downsample_.set("uFirstFace", f);
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, 1);
            }
        }
    }
}

void MomentShadowMap::renderMaps(const ShadowFrame& frame) {
    if (built_ != programKey()) buildPrograms();
    maps_.render(frame, DepthAndTintMaps::kEveryLight);  // the moments do not read the depth: the tint's test alone
    gl::DebugGroup group("moments");
    for (std::size_t i = 0; i < maps_.slots().size(); ++i) {
        if (!maps_.slots().shadowed(i)) continue;
        ensure(i, maps_.maps(i));
        LightMoments& m = moments_[i];
        std::vector<FaceLevels> faces(m.levelTargets.size(), FaceLevels{{}, {}, m.levels});  // unchanged: nothing to redo
        for (std::size_t f = 0; f < m.levelTargets.size(); ++f) {
            const TexelRect changed = changedTexels(i, f, frame);
            if (!isEmpty(changed)) faces[f] = update(i, f, changed, frame);
        }
        makeMipLevels(i, faces);
        if (m.levels > 1) glTextureParameterf(m.moments.id(), GL_TEXTURE_MAX_ANISOTROPY, static_cast<float>(anisotropy_));
    }
}

void MomentShadowMap::bindLookup(const gl::Program& lighting) const {
    maps_.bind();
    for (std::size_t i = 0; i < maps_.slots().size() && i < moments_.size(); ++i) {
        if (!maps_.slots().shadowed(i) || !moments_[i].moments.id()) continue;
        moments_[i].moments.bind(static_cast<GLuint>(maps_.slots().rawUnit(i)));
    }
    lighting.set("uExponents", exponents());
    lighting.set("uMinVariance", minVariance_);
    lighting.set("uBleedReduction", bleedReduction_);
    lighting.set("uMomentBias", momentBias_);
}

std::size_t MomentShadowMap::memoryBytes() const {
    std::size_t total = maps_.memoryBytes();
    for (const auto& m : moments_)
        total += m.moments.memoryBytes() + m.raw.memoryBytes() + m.scratch.memoryBytes() + m.rasterDepth.memoryBytes() +
                 m.multisampledDepth.memoryBytes();
    return total;
}

std::vector<DebugView> MomentShadowMap::debugViews() const {
    std::vector<DebugView> views = maps_.debugViews();
    for (std::size_t i = 0; i < moments_.size(); ++i)
        if (moments_[i].moments.id() && !moments_[i].cube)
            views.push_back({"light " + std::to_string(i) + " moments", moments_[i].moments.id(), GL_TEXTURE_2D, false, 0});
    return views;
}

}  // namespace penumbra::shadows
