#include "shadows/cssm/ColoredStochasticShadowMap.h"

#include "gl/Debug.h"
#include "gl/PassState.h"
#include "gpu/ShaderContract.h"

#include <algorithm>
#include <cmath>

namespace penumbra::shadows {

ColoredStochasticShadowMap::ColoredStochasticShadowMap(Variant variant)
    : variant_(variant), fp16_(variant == Variant::Rgb) {
    copy_ = gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = "src/shadows/cssm/copy.frag"});
    casters_ = gl::Program::build({.vertex = "src/shadows/common/glsl/caster.vert", .fragment = "src/shadows/cssm/caster.frag"});
}

std::vector<Parameter> ColoredStochasticShadowMap::declareParameters() {
    // Labels in the order of CssmFilter.h and of the kRandom* codes.
    return {Parameter::choice("filter", filter_, {"pcf9", "poisson16", "poisson20", "random30", "cross13", "box16", "box64"},
                              "reconstruction filter of the lookup: the thesis's (Mátl 2013 §5.3), or a 4x4 / 8x8 texel box "
                              "matched to the stratified xi"),
            Parameter::choice("xi", xi_, {"white", "stratified"},
                              "how casters draw xi: independent per fragment, or stratified: every threshold stratum once per 4x4 (8x8) tile"),
            Parameter::flag("separate_opaque", separateOpaque_,
                            "opaque occlusion from the depth map (a hard test), the coloured map for translucent layers "
                            "only; off: the thesis's combined map"),
            Parameter::real("radius_texels", radiusTexels_, 0.0f, 8.0f,
                            "Poisson / random filter radius; 0: automatic, so that taps land on distinct texels"),
            Parameter::choice("rng", generator_, {"pcg", "sin-fract"}, "per-fragment random number generator"),
            Parameter::flag("fp16", fp16_, "RGBA16F colour map (else RGBA32F)")};
}

void ColoredStochasticShadowMap::ensure(std::size_t i, const DepthAndTintMaps::LightMaps& depth) {
    if (maps_.size() <= i) maps_.resize(i + 1);
    LightMap& m = maps_[i];
    const GLenum format = fp16_ ? GL_RGBA16F : GL_RGBA32F;
    if (m.resolution == depth.resolution && m.cube == depth.cube && m.format == format) return;
    m = LightMap{};
    m.resolution = depth.resolution;
    m.cube = depth.cube;
    m.format = format;
    const int res = depth.resolution;
    m.colour = m.cube ? gl::Texture::createCube(format, res) : gl::Texture::create2D(format, res, res);
    m.colour.setFilter(GL_NEAREST, GL_NEAREST);  // stochastic texels must not be averaged by the sampler
    for (int f = 0; f < (m.cube ? 6 : 1); ++f) {
        m.depthFaces.push_back(gl::Texture::view2D(depth.depth, GL_DEPTH_COMPONENT32F, f));
        gl::Framebuffer fb;
        if (m.cube) {
            fb.attachLayer(GL_COLOR_ATTACHMENT0, m.colour, f);
            fb.attachLayer(GL_DEPTH_ATTACHMENT, depth.depth, f);
        } else {
            fb.attach(GL_COLOR_ATTACHMENT0, m.colour);
            fb.attach(GL_DEPTH_ATTACHMENT, depth.depth);
        }
        fb.setDrawBuffers({GL_COLOR_ATTACHMENT0});
        fb.checkComplete("coloured stochastic shadow map");
        m.targets.push_back(std::move(fb));
    }
}

void ColoredStochasticShadowMap::renderMaps(const ShadowFrame& frame) {
    depth_.render(frame);  // 1. opaque casters' depth
    gl::DebugGroup group(name().c_str());
    casters_.set("uRandomGenerator", generator_);
    casters_.set("uXi", xi_);
    casters_.set("uDitherBits", filter_ == gpu::kCssmBox64 ? 3 : 2);  // the dither period matches the box
    casters_.set("uFrameSeed", static_cast<int>(frame.frameIndex));
    // 2. Opaque depth copied into every channel; 3. translucent casters in front of the opaque
    // depth (tested, not written), MIN-blended per channel.
    const gl::PassState copyPass = gl::PassState::fullscreen();
    gl::PassState casterPass = gl::PassState::depthOnly().withBlend(gl::BlendState::of(GL_MIN, GL_ONE, GL_ONE));
    casterPass.depthWrite = false;
    for (std::size_t i = 0; i < depth_.slots().size(); ++i) {
        if (!depth_.slots().shadowed(i)) continue;
        ensure(i, depth_.maps(i));
        LightMap& m = maps_[i];
        const LightSpace& ls = (*frame.lightSpaces)[i];
        for (const gl::Program* p : {&copy_, &casters_}) {
            p->set("uPerspective", ls.perspective ? 1 : 0);
            p->set("uNear", ls.near);
            p->set("uFar", ls.far);
        }
        glViewport(0, 0, m.resolution, m.resolution);
        for (std::size_t f = 0; f < m.targets.size(); ++f) {
            m.targets[f].bind();
            if (separateOpaque_) {  // translucent layers only: start from "nothing occludes"
                const float white[4] = {1, 1, 1, 1};
                glClearNamedFramebufferfv(m.targets[f].id(), GL_COLOR, 0, white);
            } else {  // 1 (white) where nothing opaque is
                const gl::ScopedPassState state(copyPass);
                copy_.use();
                depthSampler_.bind(0);
                m.depthFaces[f].bind(0);
                fullscreenVao_.bind();
                glDrawArrays(GL_TRIANGLES, 0, 3);
                gl::Sampler::unbind(0);
            }
            casters_.set("uLightViewProj", ls.viewProj[f]);
            if (variant_ == Variant::Rgb) {
                const gl::ScopedPassState state(casterPass);
                casters_.set("uChannel", -1);
                frame.drawCasters(casters_, {Casters::Translucent, ls.viewProj[f], static_cast<int>(i)});
                continue;
            }
            for (int c = 0; c < 3; ++c) {  // one map per wavelength
                gl::PassState channelPass = casterPass;
                channelPass.colorWrite = glm::bvec4(c == 0, c == 1, c == 2, c == 0);
                const gl::ScopedPassState state(channelPass);
                casters_.set("uChannel", c);
                frame.drawCasters(casters_, {Casters::Translucent, ls.viewProj[f], static_cast<int>(i)});
            }
        }
    }
}

void ColoredStochasticShadowMap::bindLookup(const gl::Program& lighting) const {
    depth_.bind();
    for (std::size_t i = 0; i < depth_.slots().size() && i < maps_.size(); ++i) {
        if (!depth_.slots().shadowed(i) || !maps_[i].colour.id()) continue;
        maps_[i].colour.bind(static_cast<GLuint>(depth_.slots().rawUnit(i)));
    }
    lighting.set("uFilter", filter_);
    lighting.set("uSeparateOpaque", separateOpaque_ ? 1 : 0);
    lighting.set("uRadiusTexels", radiusTexels_);
    lighting.set("uStorageEpsilon", fp16_ ? 1.0f / 1024.0f : 0.0f);
    poisson_.upload(lighting);
}

std::size_t ColoredStochasticShadowMap::memoryBytes() const {
    std::size_t total = depth_.memoryBytes();
    for (const auto& m : maps_) total += m.colour.memoryBytes();
    return total;
}

std::vector<DebugView> ColoredStochasticShadowMap::debugViews() const {
    std::vector<DebugView> views;
    for (std::size_t i = 0; i < maps_.size(); ++i) {
        if (!maps_[i].colour.id() || maps_[i].cube) continue;
        views.push_back({"light " + std::to_string(i) + " opaque depth", depth_.maps(i).depth.id(), GL_TEXTURE_2D, true, 0});
        views.push_back({"light " + std::to_string(i) + " CSSM", maps_[i].colour.id(), GL_TEXTURE_2D, false, 0});
    }
    return views;
}

}  // namespace penumbra::shadows
