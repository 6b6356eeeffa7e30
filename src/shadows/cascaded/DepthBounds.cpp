#include "shadows/cascaded/DepthBounds.h"

#include "gl/PassState.h"
#include "gpu/ShaderContract.h"

#include <array>
#include <cstdint>

namespace penumbra::shadows {

std::pair<float, float> DepthBounds::reduce(glm::ivec2 size) {
    if (!reduce_.id()) {
        reduce_ = gl::Program::build({.compute = "src/shadows/cascaded/depth_bounds.comp"});
        bounds_ = gl::Buffer(2 * sizeof(std::uint32_t), nullptr);
    }
    const std::array<float, 2> cleared{1.0f, 0.0f};  // nearest, farthest: empty until a texel is covered
    bounds_.update(0, sizeof(cleared), cleared.data());
    bounds_.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    glBindTextureUnit(0, depth_.id());
    reduce_.use();
    constexpr int kGroup = 8 * 16;  // depth_bounds.comp's texels per group on each axis
    glDispatchCompute(static_cast<GLuint>((size.x + kGroup - 1) / kGroup), static_cast<GLuint>((size.y + kGroup - 1) / kGroup), 1);
    glBindTextureUnit(0, 0);
    glUseProgram(0);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);  // the shader's atomics, before the read below
    std::array<float, 2> read{};
    glGetNamedBufferSubData(bounds_.id(), 0, sizeof(read), read.data());
    return {read[0], read[1]};
}

std::optional<std::pair<float, float>> DepthBounds::measure(const ShadowFrame& frame) {
    // A quarter of the pixels is plenty for the bounds and keeps the pre-pass cheap.
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
    const auto [lo, hi] = reduce(size);
    if (lo > hi) return std::nullopt;
    auto distance = [&](float d) {  // window depth -> view distance (perspective)
        const float n = cam.near, f = cam.far;
        return 2.0f * n * f / (f + n - (2.0f * d - 1.0f) * (f - n));
    };
    return std::make_pair(distance(lo), distance(hi));
}

}  // namespace penumbra::shadows
