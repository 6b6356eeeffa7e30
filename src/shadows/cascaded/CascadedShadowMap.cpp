#include "shadows/cascaded/CascadedShadowMap.h"

#include "gl/Debug.h"
#include "render/Bindings.h"

#include <algorithm>
#include <cmath>

namespace penumbra::shadows {

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
    const scene::Camera& cam = *frame.camera;
    if (freeze_ < 0.5f || static_cast<int>(fitted_.size()) != count || fittedResolution_ != res) {
        fittedResolution_ = res;
        const float far = maxDistance_ > 0.0f ? std::min(maxDistance_, cam.far) : cam.far;
        splits_ = cascadeSplits(cam.near, far, count, lambda_);
        fitted_.clear();
        for (int c = 0; c < count; ++c)
            fitted_.push_back(fitCascade(sun, cam, frame.aspect, splits_[static_cast<std::size_t>(c)],
                                         splits_[static_cast<std::size_t>(c) + 1], frame.sceneBounds, res, stabilize_ > 0.5f));
        cameraView_ = cam.view();
    }
    gl::DebugGroup group("cascades");
    std::vector<glm::mat4> viewProj;
    for (const auto& c : fitted_) viewProj.push_back(c.viewProj);
    cascades_.render(frame, sun, res, viewProj);
}

void CascadedShadowMap::bindLookup(const gl::Program& lighting) const {
    maps_.bind();
    lighting.set("uCascadeLight", cascades_.empty() ? -1 : light_);
    if (light_ < 0 || cascades_.empty()) return;
    cascades_.bind(render::kUnitLayered);
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
