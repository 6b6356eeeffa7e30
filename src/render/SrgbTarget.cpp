#include "render/SrgbTarget.h"

namespace penumbra::render {

namespace {

// Level 0 of the immutable RGBA8 / SRGB8_ALPHA8 2D texture attached as `output`'s colour 0, of at
// least width x height; 0 where there is none (the window, a renderbuffer, another format).
GLuint outputColourTexture(GLuint output, int width, int height) {
    if (output == 0) return 0;
    GLint type = GL_NONE, name = 0, level = -1, layered = GL_TRUE;
    glGetNamedFramebufferAttachmentParameteriv(output, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_TEXTURE) return 0;
    glGetNamedFramebufferAttachmentParameteriv(output, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
    glGetNamedFramebufferAttachmentParameteriv(output, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &level);
    glGetNamedFramebufferAttachmentParameteriv(output, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_LAYERED, &layered);
    const auto texture = static_cast<GLuint>(name);
    GLint target = GL_NONE, immutable = GL_FALSE, format = GL_NONE, w = 0, h = 0;
    glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &target);
    glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &w);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &h);
    const bool usable = level == 0 && layered == GL_FALSE && target == GL_TEXTURE_2D && immutable == GL_TRUE &&
                        (format == GL_RGBA8 || format == GL_SRGB8_ALPHA8) && w >= width && h >= height;
    return usable ? texture : 0;
}

gl::Texture viewOf(GLuint texture, GLenum format, int width, int height) {
    GLuint id = 0;
    glGenTextures(1, &id);  // glTextureView needs a name that was never bound: glGen, not glCreate
    glTextureView(id, GL_TEXTURE_2D, texture, format, 0, 1, 0, 1);
    return gl::Texture::adopt(GL_TEXTURE_2D, id, width, height, 0);
}

}  // namespace

GLuint SrgbTarget::begin(GLuint output, int width, int height, const gl::Texture& depth) {
    const GLuint colour = outputColourTexture(output, width, height);
    intoOutput_ = colour != 0;
    if (intoOutput_) {
        outputView_ = viewOf(colour, GL_SRGB8_ALPHA8, width, height);
        outputBytes_ = viewOf(colour, GL_RGBA8, width, height);
        frame_ = gl::Framebuffer::colourAndDepth(outputView_, depth, "the output seen as sRGB");
        bytesFrame_ = gl::Framebuffer::colourAndDepth(outputBytes_, depth, "the output's bytes");
        return frame_.id();
    }
    outputView_ = {};
    outputBytes_ = {};
    if (own_.width() != width || own_.height() != height) {
        own_ = gl::Texture::create2D(GL_SRGB8_ALPHA8, width, height);
        ownBytes_ = viewOf(own_.id(), GL_RGBA8, width, height);
        ownRead_ = gl::Framebuffer::colourOnly(ownBytes_, -1, "sRGB frame's bytes");
    }
    frame_ = gl::Framebuffer::colourAndDepth(own_, depth, "sRGB frame");  // the renderer may have made `depth` again
    bytesFrame_ = gl::Framebuffer::colourAndDepth(ownBytes_, depth, "sRGB frame's bytes");
    return frame_.id();
}

void SrgbTarget::finish(GLuint output, int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, output);  // as the resolve leaves it: whatever draws next (the UI) draws there
    if (intoOutput_) return;
    glBlitNamedFramebuffer(ownRead_.id(), output, 0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

const gl::Texture& SrgbTarget::opaqueDepthCopy(const gl::Texture& depth) {
    if (depthCopy_.width() != depth.width() || depthCopy_.height() != depth.height()) {
        depthCopy_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, depth.width(), depth.height());
        depthCopy_.setFilter(GL_NEAREST, GL_NEAREST);
    }
    glCopyImageSubData(depth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, depthCopy_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, depth.width(), depth.height(), 1);
    return depthCopy_;
}

}  // namespace penumbra::render
