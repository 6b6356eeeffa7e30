#pragma once
// An RGBA8 colour target for headless frames, and reading a framebuffer back.
#include "gl/Framebuffer.h"
#include "gl/Texture.h"

#include <cstdint>
#include <vector>

namespace penumbra::render {

class OffscreenTarget {
public:
    OffscreenTarget(int width, int height);
    GLuint framebuffer() const { return fbo_.id(); }
    int width() const { return width_; }
    int height() const { return height_; }
    // RGBA8 pixels, top row first (image order).
    std::vector<std::uint8_t> readRgba8() const;

private:
    int width_, height_;
    gl::Texture color_;
    gl::Framebuffer fbo_;
};

// RGBA8 pixels of framebuffer `fbo` (0: the window), top row first (image order).
std::vector<std::uint8_t> readFramebufferRgba8(GLuint fbo, int width, int height);

}  // namespace penumbra::render
