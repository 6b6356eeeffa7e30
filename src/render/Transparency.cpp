#include "render/Transparency.h"

#include "gl/PassState.h"
#include "gpu/ShaderContract.h"
#include "render/LightingProgram.h"

namespace penumbra::render {

namespace {
constexpr int kStochasticSamples = 4;  // llvmpipe's maximum
}  // namespace

const char* toString(TransparencyMode mode) {
    switch (mode) {
        case TransparencyMode::SortedObjects: return "sorted-objects";
        case TransparencyMode::SortedTriangles: return "sorted-triangles";
        case TransparencyMode::DepthPeeling: return "depth-peeling";
        case TransparencyMode::DualDepthPeeling: return "dual-depth-peeling";
        case TransparencyMode::WeightedBlended: return "weighted";
        case TransparencyMode::Stochastic: return "stochastic";
    }
    return "?";
}

OrderIndependentTransparency::OrderIndependentTransparency(const std::filesystem::path& lookup,
                                                           std::vector<std::string> lightLayout)
    : lookup_(lookup), lightLayout_(std::move(lightLayout)),
      resolve_(gl::Program::build({.vertex = "shaders/passes/fullscreen.vert",
                                   .fragment = "shaders/passes/transparency_resolve.frag"})) {}

const gl::Program& OrderIndependentTransparency::variant(const std::string& define) {
    auto found = variants_.find(define);
    if (found != variants_.end()) return found->second;
    std::vector<std::string> defines = lightLayout_;
    defines.push_back(define);
    defines.emplace_back("MATERIAL_TRANSLUCENT 1");  // every variant shades translucent surfaces (LightingPrograms)
    return variants_.emplace(define, buildLightingProgram(lookup_, defines)).first->second;
}

void OrderIndependentTransparency::ensure(int w, int h, int layers) {
    if (w == width_ && h == height_ && layers == layers_) return;
    width_ = w;
    height_ = h;
    layers_ = layers;
    accum_ = gl::Texture::create2D(GL_RGBA32F, w, h);
    transmit_ = gl::Texture::create2D(GL_RGBA16F, w, h);
    depthCopy_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, w, h);
    weightedFbo_ = gl::Framebuffer();
    weightedFbo_.attach(GL_COLOR_ATTACHMENT0, accum_);
    weightedFbo_.attach(GL_COLOR_ATTACHMENT1, transmit_);
    weightedFbo_.attach(GL_DEPTH_ATTACHMENT, depthCopy_);
    weightedFbo_.setDrawBuffers({GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1});
    weightedFbo_.checkComplete("weighted blended OIT");
    stochasticDepth_ = gl::Texture::create2DMultisample(GL_DEPTH_COMPONENT32F, w, h, kStochasticSamples);
    stochasticFbo_ = gl::Framebuffer();
    stochasticFbo_.attach(GL_DEPTH_ATTACHMENT, stochasticDepth_);
    stochasticFbo_.setNoColor();
    stochasticFbo_.checkComplete("stochastic transparency depth");
    layerColour_ = gl::Texture::create2DArray(GL_RGBA16F, w, h, layers);
    layerTransmit_ = gl::Texture::create2DArray(GL_RGBA16F, w, h, layers);
    for (auto& d : peelDepth_) {
        d = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, w, h);
        d.setFilter(GL_NEAREST, GL_NEAREST);
    }
    backColour_ = gl::Texture::create2DArray(GL_RGBA16F, w, h, layers);
    backTransmit_ = gl::Texture::create2DArray(GL_RGBA16F, w, h, layers);
    for (auto& d : dualDepth_) d = gl::Texture::create2D(GL_RG32F, w, h);
    dualInitFbo_ = gl::Framebuffer();
    dualInitFbo_.attach(GL_COLOR_ATTACHMENT0, dualDepth_[0]);
    dualInitFbo_.setDrawBuffers({GL_COLOR_ATTACHMENT0});
    dualInitFbo_.checkComplete("dual depth peeling bounds");
    dualFbos_.clear();
    for (int k = 0; k < layers; ++k) {  // at most `layers` passes are ever used
        gl::Framebuffer fb;
        fb.attach(GL_COLOR_ATTACHMENT0, dualDepth_[(k + 1) % 2]);
        fb.attachLayer(GL_COLOR_ATTACHMENT1, layerColour_, k);
        fb.attachLayer(GL_COLOR_ATTACHMENT2, layerTransmit_, k);
        fb.attachLayer(GL_COLOR_ATTACHMENT3, backColour_, k);
        fb.attachLayer(GL_COLOR_ATTACHMENT4, backTransmit_, k);
        fb.setDrawBuffers({GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3,
                           GL_COLOR_ATTACHMENT4});
        fb.checkComplete("dual depth peeling pass");
        dualFbos_.push_back(std::move(fb));
    }
    peelFbos_.clear();
    for (int i = 0; i < layers; ++i) {
        gl::Framebuffer fb;
        fb.attachLayer(GL_COLOR_ATTACHMENT0, layerColour_, i);
        fb.attachLayer(GL_COLOR_ATTACHMENT1, layerTransmit_, i);
        fb.attach(GL_DEPTH_ATTACHMENT, peelDepth_[i % 2]);
        fb.setDrawBuffers({GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1});
        fb.checkComplete("depth peeling layer");
        peelFbos_.push_back(std::move(fb));
    }
}

void OrderIndependentTransparency::render(TransparencyMode mode, int layers, const GpuScene& gpu,
                                          const std::vector<Draw>& draws, const Prepare& prepare,
                                          const gl::Framebuffer& hdr, const gl::Texture& opaqueDepth, int w, int h) {
    layers = std::max(1, layers);
    ensure(w, h, layers);
    if (mode == TransparencyMode::WeightedBlended) {
        weighted(gpu, draws, prepare, opaqueDepth, variant("TRANSLUCENT_WEIGHTED"));
        composite(0, 0, hdr, w, h);
    } else if (mode == TransparencyMode::Stochastic) {
        stochasticDepth(gpu, draws, prepare, opaqueDepth);
        stochasticDepth_.bind(gpu::kUnitStochasticDepth);
        opaqueDepth.bind(gpu::kUnitOpaqueDepth);
        weighted(gpu, draws, prepare, opaqueDepth, variant("TRANSLUCENT_STOCHASTIC_ACCUM"));  // same targets, visibility weights
        glBindTextureUnit(gpu::kUnitStochasticDepth, 0);
        glBindTextureUnit(gpu::kUnitOpaqueDepth, 0);
        composite(0, 0, hdr, w, h);
    } else if (mode == TransparencyMode::DualDepthPeeling) {
        const int passes = (layers + 1) / 2;
        dualPeel(passes, gpu, draws, prepare, opaqueDepth);
        composite(2, passes, hdr, w, h);
    } else {
        peel(layers, gpu, draws, prepare, opaqueDepth);
        composite(1, layers, hdr, w, h);
    }
}

void OrderIndependentTransparency::stochasticDepth(const GpuScene& gpu, const std::vector<Draw>& draws,
                                                   const Prepare& prepare, const gl::Texture& opaqueDepth) {
    stochasticFbo_.bind();
    const float farDepth = 1.0f;
    glClearNamedFramebufferfv(stochasticFbo_.id(), GL_DEPTH, 0, &farDepth);
    const gl::ScopedPassState state(gl::PassState::depthOnly());
    const gl::Program& program = variant("TRANSLUCENT_STOCHASTIC_DEPTH");
    prepare(program);
    opaqueDepth.bind(gpu::kUnitOpaqueDepth);
    for (const Draw& d : draws)
        if (d.translucent && d.visible) gpu.draw(d, program);
}

void OrderIndependentTransparency::weighted(const GpuScene& gpu, const std::vector<Draw>& draws, const Prepare& prepare,
                                            const gl::Texture& opaqueDepth, const gl::Program& program) {
    // The opaque depth, copied so that translucent fragments behind opaque ones are rejected.
    glCopyImageSubData(opaqueDepth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, depthCopy_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, width_,
                       height_, 1);
    weightedFbo_.bind();
    const float zero[4] = {0, 0, 0, 0}, one[4] = {1, 1, 1, 1};
    glClearNamedFramebufferfv(weightedFbo_.id(), GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(weightedFbo_.id(), GL_COLOR, 1, one);
    gl::PassState state = gl::PassState::depthOnly().withBlend(gl::BlendState::of(GL_FUNC_ADD, GL_ONE, GL_ONE));  // Σ C w, Σ a w
    state.bufferBlending = {{1, gl::BlendState::of(GL_FUNC_ADD, GL_ZERO, GL_SRC_COLOR)}};  // Π T, per channel
    state.depthWrite = false;
    const gl::ScopedPassState scope(state);
    prepare(program);
    for (const Draw& d : draws)
        if (d.translucent && d.visible) gpu.draw(d, program);
}

void OrderIndependentTransparency::peel(int layers, const GpuScene& gpu, const std::vector<Draw>& draws,
                                        const Prepare& prepare, const gl::Texture& opaqueDepth) {
    const gl::Program& program = variant("TRANSLUCENT_PEEL");
    prepare(program);
    opaqueDepth.bind(gpu::kUnitOpaqueDepth);
    const float black[4] = {0, 0, 0, 0}, white[4] = {1, 1, 1, 1}, nearDepth = 0.0f, farDepth = 1.0f;
    // "Previous layer" of the first pass: depth 0, so every fragment is behind it.
    glClearTexImage(peelDepth_[1].id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &nearDepth);
    const gl::ScopedPassState state(gl::PassState::depthOnly());
    for (int i = 0; i < layers; ++i) {
        const gl::Framebuffer& fb = peelFbos_[static_cast<std::size_t>(i)];
        fb.bind();
        glClearNamedFramebufferfv(fb.id(), GL_COLOR, 0, black);
        glClearNamedFramebufferfv(fb.id(), GL_COLOR, 1, white);
        glClearNamedFramebufferfv(fb.id(), GL_DEPTH, 0, &farDepth);
        peelDepth_[(i + 1) % 2].bind(gpu::kUnitPeelDepth);  // the layer before this one
        for (const Draw& d : draws)
            if (d.translucent && d.visible) gpu.draw(d, program);
    }
    glBindTextureUnit(gpu::kUnitPeelDepth, 0);
    glBindTextureUnit(gpu::kUnitOpaqueDepth, 0);
}

void OrderIndependentTransparency::dualPeel(int passes, const GpuScene& gpu, const std::vector<Draw>& draws,
                                            const Prepare& prepare, const gl::Texture& opaqueDepth) {
    const gl::Program& program = variant("TRANSLUCENT_DUAL_PEEL");
    prepare(program);
    opaqueDepth.bind(gpu::kUnitOpaqueDepth);
    // Bounds and colours keep the largest value (MAX), transmittances the smallest (MIN, draw
    // buffers 2 and 4 of the peeling passes): every fragment writes neutral values except into
    // the one layer it belongs to.
    gl::PassState state = gl::PassState::fullscreen().withBlend(gl::BlendState::of(GL_MAX, GL_ONE, GL_ONE));
    state.bufferBlending = {{2, gl::BlendState::of(GL_MIN, GL_ONE, GL_ONE)}, {4, gl::BlendState::of(GL_MIN, GL_ONE, GL_ONE)}};
    const gl::ScopedPassState scope(state);
    const float outside[4] = {-1, -1, 0, 0}, everything[4] = {0, 1, 0, 0}, black[4] = {0, 0, 0, 0},
                white[4] = {1, 1, 1, 1};
    auto drawAll = [&] {
        for (const Draw& d : draws)
            if (d.translucent && d.visible) gpu.draw(d, program);
    };
    // Initial bounds: every translucent fragment lies within (0, 1); MAX gives (-nearest, farthest).
    glClearTexImage(dualDepth_[1].id(), 0, GL_RG, GL_FLOAT, everything);
    dualInitFbo_.bind();
    glClearNamedFramebufferfv(dualInitFbo_.id(), GL_COLOR, 0, outside);
    dualDepth_[1].bind(gpu::kUnitDualDepth);
    drawAll();
    for (int k = 0; k < passes; ++k) {
        const gl::Framebuffer& fb = dualFbos_[static_cast<std::size_t>(k)];
        fb.bind();
        glClearNamedFramebufferfv(fb.id(), GL_COLOR, 0, outside);
        glClearNamedFramebufferfv(fb.id(), GL_COLOR, 1, black);
        glClearNamedFramebufferfv(fb.id(), GL_COLOR, 2, white);
        glClearNamedFramebufferfv(fb.id(), GL_COLOR, 3, black);
        glClearNamedFramebufferfv(fb.id(), GL_COLOR, 4, white);
        dualDepth_[k % 2].bind(gpu::kUnitDualDepth);
        drawAll();
    }
    glBindTextureUnit(gpu::kUnitDualDepth, 0);
    glBindTextureUnit(gpu::kUnitOpaqueDepth, 0);
}

void OrderIndependentTransparency::composite(int mode, int layers, const gl::Framebuffer& hdr, int w, int h) {
    hdr.bind();
    glViewport(0, 0, w, h);
    const gl::ScopedPassState state(gl::PassState::fullscreen().withBlend(overTransmittance()));
    resolve_.set("uMode", mode);
    resolve_.set("uLayers", layers);
    accum_.bind(0);
    transmit_.bind(1);
    layerColour_.bind(2);
    layerTransmit_.bind(3);
    backColour_.bind(4);
    backTransmit_.bind(5);
    resolve_.use();
    fullscreen_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace penumbra::render
