#include "shadows/cascaded/CascadedShadowMap.h"

#include "gl/Debug.h"
#include "render/Bindings.h"

#include <algorithm>
#include <cmath>

namespace penumbra::shadows {

CascadedShadowMap::CascadedShadowMap() {
    casters_ = gl::Program::build({.vertex = "src/shadows/cascaded/caster.vert",
                                   .fragment = "shaders/passes/shadow_depth.frag",
                                   .geometry = "src/shadows/cascaded/caster.geom"});
}

std::vector<Parameter> CascadedShadowMap::parameters() {
    return {{"cascades", &count_, 1, 8},           {"lambda", &lambda_, 0, 1},
            {"stabilize", &stabilize_, 0, 1},      {"blend", &blend_, 0, 0.5f},
            {"select_by_projection", &select_, 0, 1}, {"debug_tint", &debugTint_, 0, 1},
            {"freeze", &freeze_, 0, 1},            {"max_distance", &maxDistance_, 0, 100000}};
}

void CascadedShadowMap::renderMaps(const ShadowFrame& frame) {
    maps_.render(frame);  // other lights, and every light's coloured tint
    const auto& lights = *frame.lights;
    const std::vector<int> slots = DepthAndTintMaps::slots(lights);
    light_ = -1;
    for (std::size_t i = 0; i < lights.size(); ++i)
        if (lights[i].type == scene::Light::Type::Directional && slots[i] >= 0) {
            light_ = static_cast<int>(i);
            break;
        }
    if (light_ < 0 || !frame.camera) return;
    const scene::Light& sun = lights[static_cast<std::size_t>(light_)];
    const int count = std::clamp(static_cast<int>(std::lround(count_)), 1, 8);
    const int res = (*frame.lightSpaces)[static_cast<std::size_t>(light_)].resolution;
    if (res != resolution_ || count != layers_) {
        cascades_ = gl::Texture::create2DArray(GL_DEPTH_COMPONENT32F, res, res, count);
        cascades_.setFilter(GL_NEAREST, GL_NEAREST);
        cascades_.setDepthCompare(true);
        target_ = gl::Framebuffer();
        target_.attach(GL_DEPTH_ATTACHMENT, cascades_);  // layered: the geometry shader picks gl_Layer
        target_.setNoColor();
        target_.checkComplete("cascaded shadow map");
        resolution_ = res;
        layers_ = count;
        fitted_.clear();
    }
    const scene::Camera& cam = *frame.camera;
    if (freeze_ < 0.5f || static_cast<int>(fitted_.size()) != count) {
        const float far = maxDistance_ > 0.0f ? std::min(maxDistance_, cam.far) : cam.far;
        splits_ = cascadeSplits(cam.near, far, count, lambda_);
        fitted_.clear();
        for (int c = 0; c < count; ++c)
            fitted_.push_back(fitCascade(sun, cam, frame.aspect, splits_[static_cast<std::size_t>(c)],
                                         splits_[static_cast<std::size_t>(c) + 1], frame.sceneBounds, res, stabilize_ > 0.5f));
        cameraView_ = cam.view();
    }
    gl::DebugGroup group("cascades");
    gl::unbindTextureUnits();  // see DepthAndTintMaps::render
    target_.bind();
    glViewport(0, 0, res, res);
    const float farDepth = 1.0f;
    glClearNamedFramebufferfv(target_.id(), GL_DEPTH, 0, &farDepth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(sun.shadow.polygonOffset.x, sun.shadow.polygonOffset.y);
    std::vector<glm::mat4> viewProj;
    for (const auto& c : fitted_) viewProj.push_back(c.viewProj);
    glProgramUniformMatrix4fv(casters_.id(), casters_.location("uCascadeViewProj[0]"), count, GL_FALSE, &viewProj[0][0][0]);
    casters_.set("uCascadeCount", count);
    frame.drawCasters(casters_, Casters::Opaque);
    glDisable(GL_POLYGON_OFFSET_FILL);
}

void CascadedShadowMap::bindLookup(const gl::Program& lighting) const {
    maps_.bind();
    lighting.set("uCascadeLight", cascades_.id() ? light_ : -1);
    if (light_ < 0 || !cascades_.id()) return;
    cascades_.bind(render::kUnitCascades);
    const int count = static_cast<int>(fitted_.size());
    lighting.set("uCascadeCount", count);
    glProgramUniform1fv(lighting.id(), lighting.location("uCascadeSplits[0]"), count + 1, splits_.data());
    std::vector<glm::mat4> matrices;
    std::vector<glm::vec3> texels;
    for (const auto& c : fitted_) {
        matrices.push_back(c.shadowMatrix);
        texels.push_back({c.texelWorld, c.depthFar - c.depthNear, 0.0f});
    }
    glProgramUniformMatrix4fv(lighting.id(), lighting.location("uCascadeMatrix[0]"), count, GL_FALSE, &matrices[0][0][0]);
    glProgramUniform3fv(lighting.id(), lighting.location("uCascadeTexel[0]"), count, &texels[0].x);
    lighting.set("uCascadeCameraView", cameraView_);
    lighting.set("uCascadeBlend", blend_);
    lighting.set("uCascadeSelect", select_ > 0.5f ? 1 : 0);
    lighting.set("uCascadeDebug", debugTint_ > 0.5f ? 1 : 0);
}

std::vector<DebugView> CascadedShadowMap::debugViews() const { return maps_.debugViews(); }

}  // namespace penumbra::shadows
