#include "shadows/common/ScreenShadowMask.h"

#include "gl/Debug.h"
#include "gl/PassState.h"
#include "gpu/ShaderContract.h"

#include <algorithm>

namespace penumbra::shadows {

ScreenShadowMask::ScreenShadowMask() {
    stencilToMask_ = gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = "src/shadows/common/glsl/shadowed.frag"});
}

void ScreenShadowMask::begin(const ShadowFrame& frame) {
    const int lights = std::max(1, static_cast<int>(frame.lights->size()));
    if (frame.viewport != size_ || lights != layerCount_) {
        size_ = frame.viewport;
        layerCount_ = lights;
        mask_ = gl::Texture::create2DArray(GL_R8, size_.x, size_.y, lights);
        mask_.setFilter(GL_NEAREST, GL_NEAREST);
        const GLint grey[4] = {GL_RED, GL_RED, GL_RED, GL_ONE};  // the overlay shows visibility as grey, not red
        glTextureParameteriv(mask_.id(), GL_TEXTURE_SWIZZLE_RGBA, grey);
        depth_ = gl::Texture::create2D(GL_DEPTH24_STENCIL8, size_.x, size_.y);
        depth_.setFilter(GL_NEAREST, GL_NEAREST);
        layers_.clear();
        for (int i = 0; i < lights; ++i) {
            gl::Framebuffer fb;
            fb.attachLayer(GL_COLOR_ATTACHMENT0, mask_, i);
            fb.attach(GL_DEPTH_STENCIL_ATTACHMENT, depth_);
            fb.setDrawBuffers({GL_COLOR_ATTACHMENT0});
            fb.checkComplete("screen shadow mask");
            layers_.push_back(std::move(fb));
        }
    }
    const scene::Camera& cam = *frame.camera;
    viewProj_ = cam.projection(frame.aspect) * cam.view();
    depthRange_ = {cam.near, cam.far};
    gl::unbindTextureUnits(gpu::kLightingUnits);
    layers_[0].bind();
    glViewport(0, 0, size_.x, size_.y);
    glClearNamedFramebufferfi(layers_[0].id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    gl::PassState prePass = gl::PassState::depthOnly();
    prePass.colorWrite = glm::bvec4(false);
    const gl::ScopedPassState state(prePass);
    depthProgram_.set("uLightViewProj", viewProj_);
    frame.drawSurfaces(depthProgram_, -1);
}

void ScreenShadowMask::beginLight(int light, int stencil) {
    const gl::Framebuffer& fb = layers_[static_cast<std::size_t>(light)];
    fb.bind();
    glViewport(0, 0, size_.x, size_.y);
    const float lit[4] = {1, 1, 1, 1};
    glClearNamedFramebufferfv(fb.id(), GL_COLOR, 0, lit);
    glClearNamedFramebufferiv(fb.id(), GL_STENCIL, 0, &stencil);
}

void ScreenShadowMask::shadowWhereStencilNonZero() {
    const gl::ScopedPassState state(gl::PassState::fullscreen().withStencil({.func = GL_NOTEQUAL, .ref = 0, .mask = 0xff}));
    stencilToMask_.use();
    emptyVao_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void ScreenShadowMask::bind(const gl::Program& lighting) const {
    if (mask_.id() == 0) return;
    mask_.bind(gpu::kUnitScreenShadow);
    depth_.bind(gpu::kUnitScreenDepth);
    lighting.set("uScreenMaskDepthRange", depthRange_);
}

// The array's layers themselves, not 2D texture views of them. On an H100 (driver 580.159.04),
// views made once when the array was allocated read back, in some runs, values this mask never
// holds (neither 0 nor 1), for one layer or the other, while the array itself (sampled by the
// lighting pass, or read directly) and views made just before reading held the right ones.
std::vector<DebugView> ScreenShadowMask::debugViews() const {
    std::vector<DebugView> views;
    for (int i = 0; i < std::min(layerCount_, 2) && mask_.id() != 0; ++i)
        views.push_back({"screen mask, light " + std::to_string(i), mask_.id(), GL_TEXTURE_2D_ARRAY, false, i});
    return views;
}

}  // namespace penumbra::shadows
