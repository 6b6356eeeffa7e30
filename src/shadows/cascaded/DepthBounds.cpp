#include "shadows/cascaded/DepthBounds.h"

#include "gl/PassState.h"
#include "gpu/ShaderContract.h"

#include <algorithm>
#include <vector>

namespace penumbra::shadows {

std::optional<std::pair<float, float>> DepthBounds::measure(const ShadowFrame& frame) {
    // A quarter of the pixels is plenty for the bounds and keeps the read-back small.
    const glm::ivec2 size = glm::max(frame.viewport / 2, glm::ivec2(1));
    if (size != size_) {
        size_ = size;
        depth_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, size.x, size.y);
        target_ = gl::Framebuffer();
        target_.attach(GL_DEPTH_ATTACHMENT, depth_);
        target_.setNoColor();
        target_.checkComplete("SDSM depth pre-pass");
    }
    const scene::Camera& cam = *frame.camera;
    gl::unbindTextureUnits(gpu::kLightingUnits);
    {
        const gl::ScopedPassState state(gl::PassState::depthOnly());
        target_.beginDepthPass(size.x, size.y);
        program_.set("uLightViewProj", cam.projection(frame.aspect) * cam.view());
        frame.drawSurfaces(program_, -1);
    }
    std::vector<float> depth(static_cast<std::size_t>(size.x) * size.y);
    glGetTextureImage(depth_.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, static_cast<GLsizei>(depth.size() * sizeof(float)), depth.data());
    float lo = 1.0f, hi = 0.0f;
    for (float d : depth)
        if (d < 1.0f) {
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
    if (lo > hi) return std::nullopt;
    auto distance = [&](float d) {  // window depth -> view distance (perspective)
        const float n = cam.near, f = cam.far;
        return 2.0f * n * f / (f + n - (2.0f * d - 1.0f) * (f - n));
    };
    return std::make_pair(distance(lo), distance(hi));
}

}  // namespace penumbra::shadows
