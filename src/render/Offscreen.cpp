#include "render/Offscreen.h"

#include <stb_image_write.h>

#include <algorithm>
#include <stdexcept>

namespace penumbra::render {

OffscreenTarget::OffscreenTarget(int width, int height)
    : width_(width), height_(height), color_(gl::Texture::create2D(GL_RGBA8, width, height)) {
    fbo_.attach(GL_COLOR_ATTACHMENT0, color_);
    fbo_.setDrawBuffers({GL_COLOR_ATTACHMENT0});
    fbo_.checkComplete("offscreen target");
}

std::vector<std::uint8_t> OffscreenTarget::readRgba8() const {
    const std::size_t row = static_cast<std::size_t>(width_) * 4;
    std::vector<std::uint8_t> flipped(row * static_cast<std::size_t>(height_));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(color_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(flipped.size()), flipped.data());
    std::vector<std::uint8_t> out(flipped.size());
    for (int y = 0; y < height_; ++y)  // GL's first row is the bottom of the picture
        std::copy_n(&flipped[static_cast<std::size_t>(height_ - 1 - y) * row], row, &out[static_cast<std::size_t>(y) * row]);
    return out;
}

void writePng(const std::filesystem::path& file, int width, int height, const std::vector<std::uint8_t>& rgba) {
    if (!stbi_write_png(file.string().c_str(), width, height, 4, rgba.data(), width * 4))
        throw std::runtime_error(file.string() + ": cannot write PNG");
}

}  // namespace penumbra::render
