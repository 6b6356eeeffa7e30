#include "shadows/cssm/ColoredStochasticShadowMap.h"

#include "gl/Debug.h"
#include "render/Bindings.h"
#include "shadows/pcf/PercentageCloserFilter.h"

#include <algorithm>
#include <cmath>

namespace penumbra::shadows {

ColoredStochasticShadowMap::ColoredStochasticShadowMap(Variant variant)
    : variant_(variant), fp16_(variant == Variant::Rgb ? 1.0f : 0.0f), poisson_(poissonDisk(32)) {
    copy_ = gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = "shaders/passes/cssm_copy.frag"});
    casters_ = gl::Program::build({.vertex = "shaders/passes/shadow_caster.vert", .fragment = "shaders/passes/cssm_caster.frag"});
}

std::vector<Parameter> ColoredStochasticShadowMap::parameters() {
    return {{"filter", &filter_, 0, 4},  // 0 pcf9, 1 poisson16, 2 poisson20, 3 random30, 4 cross13
            {"radius_texels", &radiusTexels_, 0.0f, 8.0f},  // 0: automatic (distinct texels per tap)
            {"rng", &generator_, 0, 1},  // 0 PCG hash, 1 fract(sin)
            {"fp16", &fp16_, 0, 1}};
}

void ColoredStochasticShadowMap::ensure(std::size_t i, const DepthAndTintMaps::LightMaps& depth) {
    if (maps_.size() <= i) maps_.resize(i + 1);
    LightMap& m = maps_[i];
    const GLenum format = fp16_ > 0.5f ? GL_RGBA16F : GL_RGBA32F;
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
    casters_.set("uRandomGenerator", generator_ > 0.5f ? 1 : 0);
    casters_.set("uFrameSeed", static_cast<int>(frame.frameIndex));
    for (std::size_t i = 0; i < depth_.lightCount(); ++i) {
        if (depth_.slot(i) < 0) continue;
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
            // 2. Opaque depth into every channel (1 = white where nothing opaque is).
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_BLEND);
            copy_.use();
            depthSampler_.bind(0);
            m.depthFaces[f].bind(0);
            fullscreenVao_.bind();
            glDrawArrays(GL_TRIANGLES, 0, 3);
            gl::Sampler::unbind(0);
            // 3. Translucent casters in front of the opaque depth, MIN-blended per channel.
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LESS);
            glDepthMask(GL_FALSE);
            glEnable(GL_BLEND);
            glBlendEquation(GL_MIN);
            casters_.set("uLightViewProj", ls.viewProj[f]);
            if (variant_ == Variant::Rgb) {
                casters_.set("uChannel", -1);
                frame.drawCasters(casters_, Casters::Translucent);
            } else {
                for (int c = 0; c < 3; ++c) {  // one map per wavelength
                    glColorMask(c == 0, c == 1, c == 2, GL_FALSE);
                    casters_.set("uChannel", c);
                    frame.drawCasters(casters_, Casters::Translucent);
                }
                glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            }
            glBlendEquation(GL_FUNC_ADD);
            glDisable(GL_BLEND);
            glDepthMask(GL_TRUE);
        }
    }
}

void ColoredStochasticShadowMap::bindLookup(const gl::Program& lighting) const {
    depth_.bind();
    for (std::size_t i = 0; i < depth_.lightCount() && i < maps_.size(); ++i) {
        if (depth_.slot(i) < 0 || !maps_[i].colour.id()) continue;
        maps_[i].colour.bind(depth_.rawUnit(i));
    }
    lighting.set("uFilter", std::clamp(static_cast<int>(std::lround(filter_)), 0, 4));
    lighting.set("uRadiusTexels", radiusTexels_);
    lighting.set("uStorageEpsilon", fp16_ > 0.5f ? 1.0f / 1024.0f : 0.0f);
    glProgramUniform2fv(lighting.id(), lighting.location("uPoisson[0]"), static_cast<GLsizei>(poisson_.size()), &poisson_[0].x);
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
