#include "shadows/common/DepthAndTintMaps.h"

#include "gl/Debug.h"
#include "render/Bindings.h"

namespace penumbra::shadows {

using scene::Light;

DepthAndTintMaps::DepthAndTintMaps(bool withTint) : withTint_(withTint) {
    depthProgram_ = gl::Program::build({.vertex = "shaders/passes/shadow_caster.vert",
                                        .fragment = "shaders/passes/shadow_depth.frag"});
    tintProgram_ = gl::Program::build({.vertex = "shaders/passes/shadow_caster.vert",
                                       .fragment = "shaders/passes/shadow_transmit.frag"});
}

std::vector<int> DepthAndTintMaps::slots(const std::vector<Light>& lights) {
    std::vector<int> out;
    int next2D = 0, nextCube = 0;
    for (const auto& l : lights) {
        if (!l.shadow.enabled) { out.push_back(-1); continue; }
        if (l.type == Light::Type::Point)
            out.push_back(nextCube < render::kMaxShadowCube ? nextCube++ : -1);
        else
            out.push_back(next2D < render::kMaxShadow2D ? next2D++ : -1);
    }
    return out;
}

int DepthAndTintMaps::firstShadowedSun(const std::vector<Light>& lights) {
    const std::vector<int> slot = slots(lights);
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (lights[i].type == Light::Type::Directional && slot[i] >= 0) return static_cast<int>(i);
    return -1;
}

void DepthAndTintMaps::ensure(std::size_t i, int res, bool cube) {
    if (maps_.size() <= i) maps_.resize(i + 1);
    LightMaps& m = maps_[i];
    if (m.resolution == res && m.cube == cube && m.depth.id() != 0) return;
    m = LightMaps{};
    m.resolution = res;
    m.cube = cube;
    m.depth = cube ? gl::Texture::createCube(GL_DEPTH_COMPONENT32F, res) : gl::Texture::create2D(GL_DEPTH_COMPONENT32F, res, res);
    // Without tint a 1-texel white map keeps the lookups' "no tint" answer and costs nothing.
    const int tintRes = withTint_ ? res : 1;
    m.tint = cube ? gl::Texture::createCube(GL_RGBA16F, tintRes) : gl::Texture::create2D(GL_RGBA16F, tintRes, tintRes);
    if (!withTint_) {
        const float white[4] = {1, 1, 1, 1};
        glClearTexImage(m.tint.id(), 0, GL_RGBA, GL_FLOAT, white);
    }
    m.depth.setDepthCompare(true);
    for (gl::Texture* t : {&m.depth, &m.tint}) t->setFilter(filter_, filter_);
    for (int f = 0; f < (cube ? 6 : 1); ++f) {
        gl::Framebuffer depthOnly, withTint;
        for (gl::Framebuffer* fb : {&depthOnly, &withTint}) {
            if (cube) fb->attachLayer(GL_DEPTH_ATTACHMENT, m.depth, f);
            else fb->attach(GL_DEPTH_ATTACHMENT, m.depth);
        }
        if (withTint_) {
            if (cube) withTint.attachLayer(GL_COLOR_ATTACHMENT0, m.tint, f);
            else withTint.attach(GL_COLOR_ATTACHMENT0, m.tint);
            withTint.setDrawBuffers({GL_COLOR_ATTACHMENT0});
            withTint.checkComplete("shadow tint map " + std::to_string(res));
        }
        depthOnly.setNoColor();
        depthOnly.checkComplete("shadow depth map " + std::to_string(res));
        m.depthFaces.push_back(std::move(depthOnly));
        m.tintFaces.push_back(std::move(withTint));
    }
}

void DepthAndTintMaps::setFiltering(GLenum filter) {
    filter_ = filter;
    for (auto& m : maps_)
        for (gl::Texture* t : {&m.depth, &m.tint})
            if (t->id()) t->setFilter(filter, filter);
}

void DepthAndTintMaps::render(const ShadowFrame& frame) {
    const auto& lights = *frame.lights;
    const auto& spaces = *frame.lightSpaces;
    slots_ = slots(lights);
    cube_.assign(lights.size(), false);
    const float white[4] = {1, 1, 1, 1};
    const float farDepth = 1.0f;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (slots_[i] < 0) continue;
        const Light& light = lights[i];
        const LightSpace& ls = spaces[i];
        cube_[i] = ls.faceCount == 6;
        ensure(i, ls.resolution, cube_[i]);
        gl::DebugGroup group(("shadow map: " + light.name).c_str());
        // Unbind every texture unit first. Measured on llvmpipe: with the previous frame's lookup
        // textures still bound, every shadow map after the first in a frame costs 7-10x more to
        // rasterise (2048^2, one thread: 145-190 ms instead of 15-20 ms), whatever its order.
        gl::unbindTextureUnits();
        LightMaps& m = maps_[i];
        glViewport(0, 0, ls.resolution, ls.resolution);
        for (int f = 0; f < ls.faceCount; ++f) {
            const auto face = static_cast<std::size_t>(f);
            const glm::mat4& vp = ls.viewProj[face];

            // 1. Opaque casters: depth only, with the light's polygon offset.
            m.depthFaces[face].bind();
            glClearNamedFramebufferfv(m.depthFaces[face].id(), GL_DEPTH, 0, &farDepth);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LESS);
            glDepthMask(GL_TRUE);
            const glm::vec2 po = light.shadow.polygonOffset;
            if (po.x != 0.0f || po.y != 0.0f) {
                glEnable(GL_POLYGON_OFFSET_FILL);
                glPolygonOffset(po.x, po.y);
            }
            depthProgram_.set("uLightViewProj", vp);
            frame.drawCasters(depthProgram_, Casters::Opaque);
            glDisable(GL_POLYGON_OFFSET_FILL);

            if (!withTint_) continue;
            // 2. Translucent casters in front of the opaque depth: multiply transmittance
            //    into rgb, keep the nearest translucent depth in alpha.
            m.tintFaces[face].bind();
            glClearNamedFramebufferfv(m.tintFaces[face].id(), GL_COLOR, 0, white);
            glDepthMask(GL_FALSE);
            glEnable(GL_BLEND);
            glBlendEquationSeparate(GL_FUNC_ADD, GL_MIN);
            glBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ONE, GL_ONE);
            tintProgram_.set("uLightViewProj", vp);
            frame.drawCasters(tintProgram_, Casters::Translucent);
            // Leave the default blend state for whoever draws next.
            glDisable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFunc(GL_ONE, GL_ZERO);
            glDepthMask(GL_TRUE);
        }
    }
}

GLuint DepthAndTintMaps::rawUnit(std::size_t light) const {
    return (cube_[light] ? render::kUnitRawCube : render::kUnitRaw2D) + static_cast<GLuint>(slots_[light]);
}

void DepthAndTintMaps::bind(bool rawDepth) const {
    for (std::size_t i = 0; i < slots_.size() && i < maps_.size(); ++i) {
        if (slots_[i] < 0 || maps_[i].depth.id() == 0) continue;
        const auto slot = static_cast<GLuint>(slots_[i]);
        const GLuint raw = rawUnit(i);
        maps_[i].depth.bind((cube_[i] ? render::kUnitShadowCube : render::kUnitShadow2D) + slot);
        maps_[i].tint.bind((cube_[i] ? render::kUnitTintCube : render::kUnitTint2D) + slot);
        if (rawDepth) {
            maps_[i].depth.bind(raw);
            rawSampler_.bind(raw);
        } else {
            gl::Sampler::unbind(raw);
        }
    }
}

std::size_t DepthAndTintMaps::memoryBytes() const {
    std::size_t total = 0;
    for (const auto& m : maps_) total += m.depth.memoryBytes() + m.tint.memoryBytes();
    return total;
}

std::vector<DebugView> DepthAndTintMaps::debugViews() const {
    std::vector<DebugView> views;
    for (std::size_t i = 0; i < maps_.size(); ++i) {
        if (maps_[i].depth.id() == 0 || maps_[i].cube) continue;
        views.push_back({"light " + std::to_string(i) + " depth", maps_[i].depth.id(), GL_TEXTURE_2D, true, 0});
        views.push_back({"light " + std::to_string(i) + " colour", maps_[i].tint.id(), GL_TEXTURE_2D, false, 0});
    }
    return views;
}

}  // namespace penumbra::shadows
