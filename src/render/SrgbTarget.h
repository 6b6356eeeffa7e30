#pragma once
// The frame shaded straight into 8-bit sRGB (RenderOptions::floatTarget false): the opaque pass
// writes the bytes, its shader encoding sRGB itself (bytesFramebuffer); the passes that blend
// write linear colour, which GL encodes on the way in and blends in linear (GL_FRAMEBUFFER_SRGB);
// the lighting shader applies the fog (FOG_IN_SHADING), and no resolve pass reads the frame again.
// Measured on llvmpipe (default scene, 1280x720, bench): the resolve pass was 15-16 ms of `none`'s
// 60-62 ms frame.
#include "gl/Framebuffer.h"
#include "gl/Texture.h"

namespace penumbra::render {

class SrgbTarget {
public:
    // The framebuffer this frame shades into, with `depth` as its depth: the output's own colour
    // texture, seen as sRGB through a view, where the output's colour attachment 0 is level 0 of
    // an immutable RGBA8 or SRGB8_ALPHA8 2D texture of at least width x height (an offscreen
    // target); else a texture of its own, which finish() copies into the output (the window).
    // The view is made again every frame: a name the output deleted may come back for another
    // texture, so a view kept by name could keep drawing into storage nobody reads.
    GLuint begin(GLuint output, int width, int height, const gl::Texture& depth);
    // The same colour and depth as begin()'s framebuffer, the colour seen as plain RGBA8: for a
    // pass that writes each pixel without blending and encodes sRGB in its shader
    // (ENCODE_SRGB_IN_SHADER, Renderer::withOutputDefines). llvmpipe's own sRGB store cost
    // 2.1-2.2 ms of the 98k grid's 13.6-14 ms opaque pass (none, 1280x720); the shader's encode
    // saves 1.3 ms of it (stop 66). Blending passes stay on begin()'s framebuffer: they must blend
    // in linear.
    GLuint bytesFramebuffer() const { return bytesFrame_.id(); }
    // Copies the frame into the output where begin() could not shade into it; the bytes as they
    // are (an RGBA8 view of the sRGB texture: no driver decodes or encodes them on the way).
    // Leaves the output bound, as the resolve pass does.
    void finish(GLuint output, int width, int height);
    // A copy of `depth` as the opaque passes left it, for the translucent surfaces' fog: they are
    // depth-tested against `depth` itself, which they may not also sample.
    const gl::Texture& opaqueDepthCopy(const gl::Texture& depth);
    // Whether the last begin() shades into the output itself (tests).
    bool intoOutput() const { return intoOutput_; }

private:
    bool intoOutput_ = false;
    gl::Texture outputView_, outputBytes_;  // this frame's sRGB and RGBA8 views of the output's colour
    gl::Framebuffer frame_;       // what begin() returned
    gl::Framebuffer bytesFrame_;  // bytesFramebuffer()
    gl::Texture own_, ownBytes_;  // SRGB8_ALPHA8, and an RGBA8 view of it to copy from
    gl::Framebuffer ownRead_;
    gl::Texture depthCopy_;
};

}  // namespace penumbra::render
