#include "render/Offscreen.h"

#include <algorithm>

namespace penumbra::render {

OffscreenTarget::OffscreenTarget(int width, int height)
    : width_(width), height_(height), color_(gl::Texture::create2D(GL_RGBA8, width, height)) {
    fbo_.attach(GL_COLOR_ATTACHMENT0, color_);
    fbo_.setDrawBuffers({GL_COLOR_ATTACHMENT0});
    fbo_.checkComplete("offscreen target");
}

std::vector<std::uint8_t> readFramebufferRgba8(GLuint fbo, int width, int height) {
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    std::vector<std::uint8_t> glOrder(row * static_cast<std::size_t>(height));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glReadnPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(glOrder.size()), glOrder.data());
    std::vector<std::uint8_t> out(glOrder.size());
    for (int y = 0; y < height; ++y)  // GL's first row is the bottom of the picture
        std::copy_n(&glOrder[static_cast<std::size_t>(height - 1 - y) * row], row, &out[static_cast<std::size_t>(y) * row]);
    return out;
}

std::vector<std::uint8_t> OffscreenTarget::readRgba8() const { return readFramebufferRgba8(fbo_.id(), width_, height_); }

}  // namespace penumbra::render
