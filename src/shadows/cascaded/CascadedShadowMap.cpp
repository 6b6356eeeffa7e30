#include "shadows/cascaded/CascadedShadowMap.h"

#include "gl/Debug.h"
#include "render/Bindings.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <cmath>

namespace penumbra::shadows {

std::vector<Parameter> CascadedShadowMap::parameters() {
    return {{"cascades", &count_, 1, 8},           {"lambda", &lambda_, 0, 1},
            {"stabilize", &stabilize_, 0, 1},      {"blend", &blend_, 0, 0.5f},
            {"select_by_projection", &select_, 0, 1}, {"debug_tint", &debugTint_, 0, 1},
            {"freeze", &freeze_, 0, 1},            {"max_distance", &maxDistance_, 0, 100000},
            {"sdsm", &sdsm_, 0, 1},                {"draw_frusta", &drawFrusta_, 0, 1}};
}

void CascadedShadowMap::renderMaps(const ShadowFrame& frame) {
    maps_.render(frame);  // other lights, and every light's coloured tint
    const auto& lights = *frame.lights;
    light_ = DepthAndTintMaps::firstShadowedSun(lights);
    if (light_ < 0 || !frame.camera) return;
    const scene::Light& sun = lights[static_cast<std::size_t>(light_)];
    const int count = std::clamp(static_cast<int>(std::lround(count_)), 1, 8);
    const int res = (*frame.lightSpaces)[static_cast<std::size_t>(light_)].resolution;
    const scene::Camera& cam = *frame.camera;
    if (freeze_ < 0.5f || static_cast<int>(fitted_.size()) != count || fittedResolution_ != res) {
        fittedResolution_ = res;
        float near = cam.near, far = maxDistance_ > 0.0f ? std::min(maxDistance_, cam.far) : cam.far;
        if (sdsm_ > 0.5f && frame.drawSurfaces)
            if (const auto bounds = depthBounds_.measure(frame)) {  // SDSM: split only what is visible
                near = std::max(near, bounds->first * 0.99f);
                far = std::max(std::min(far, bounds->second * 1.01f), near * 1.01f);
            }
        splits_ = cascadeSplits(near, far, count, lambda_);
        fitted_.clear();
        slices_.clear();
        for (int c = 0; c < count; ++c) {
            const float a = splits_[static_cast<std::size_t>(c)], b = splits_[static_cast<std::size_t>(c) + 1];
            fitted_.push_back(fitCascade(sun, cam, frame.aspect, a, b, frame.sceneBounds, res, stabilize_ > 0.5f));
            slices_.push_back(frustumCorners(glm::perspective(glm::radians(cam.fovDeg), frame.aspect, a, b) * cam.view()));
        }
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

std::vector<DebugView> CascadedShadowMap::debugViews() const {
    auto views = maps_.debugViews();
    if (!cascades_.empty()) views.insert(views.begin(), cascades_.debugView("cascade 0"));
    return views;
}

static void appendBox(std::vector<DebugLine>& lines, const std::array<glm::vec3, 8>& c, const glm::vec3& color) {
    for (int i = 0; i < 8; ++i)
        for (int bit = 1; bit < 8; bit <<= 1)
            if (!(i & bit)) lines.push_back({c[static_cast<std::size_t>(i)], c[static_cast<std::size_t>(i | bit)], color});
}

// Each cascade's slice of the camera frustum and its light-space box, in the cascade's tint:
// freeze the cascades and fly away to see how they cover the view.
std::vector<DebugLine> CascadedShadowMap::debugLines() const {
    std::vector<DebugLine> lines;
    if (drawFrusta_ < 0.5f) return lines;
    static const glm::vec3 kTints[4] = {{1.0f, 0.3f, 0.3f}, {0.3f, 1.0f, 0.3f}, {0.3f, 0.3f, 1.0f}, {1.0f, 1.0f, 0.3f}};
    for (std::size_t c = 0; c < fitted_.size() && c < slices_.size(); ++c) {
        appendBox(lines, slices_[c], kTints[c % 4]);
        appendBox(lines, frustumCorners(fitted_[c].viewProj), kTints[c % 4] * 0.5f);
    }
    return lines;
}

}  // namespace penumbra::shadows
