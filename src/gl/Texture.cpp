#include "gl/Texture.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace penumbra::gl {

std::size_t bytesPerTexel(GLenum f) {
    switch (f) {
        case GL_R8: return 1;
        case GL_RG8: case GL_R16F: case GL_DEPTH_COMPONENT16: return 2;
        case GL_RGB8: case GL_SRGB8: return 3;
        case GL_RGBA8: case GL_SRGB8_ALPHA8: case GL_RG16F: case GL_R32F:
        case GL_DEPTH_COMPONENT24: case GL_DEPTH_COMPONENT32F: case GL_DEPTH24_STENCIL8: return 4;
        case GL_RGB16F: return 6;
        case GL_RGBA16F: case GL_RGBA16: case GL_RG32F: case GL_DEPTH32F_STENCIL8: return 8;
        case GL_RGB32F: return 12;
        case GL_RGBA32F: return 16;
        default: throw std::logic_error("bytesPerTexel: unknown format " + std::to_string(f));
    }
}

static std::size_t mipChainBytes(std::size_t base, int w, int h, int levels) {
    std::size_t total = 0;
    for (int i = 0; i < levels; ++i) {
        total += base * static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
    }
    return total;
}

Texture::Texture(GLenum target, GLuint id, int w, int h, std::size_t bytes)
    : object_(id), target_(target), width_(w), height_(h), bytes_(bytes) {}

Texture Texture::create2D(GLenum fmt, int w, int h, int levels) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    glTextureStorage2D(id, levels, fmt, w, h);
    Texture t(GL_TEXTURE_2D, id, w, h, mipChainBytes(bytesPerTexel(fmt), w, h, levels));
    t.setFilter(levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR, GL_LINEAR);
    t.setWrap(GL_CLAMP_TO_EDGE);
    return t;
}

Texture Texture::create2DArray(GLenum fmt, int w, int h, int layers, int levels) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
    glTextureStorage3D(id, levels, fmt, w, h, layers);
    Texture t(GL_TEXTURE_2D_ARRAY, id, w, h,
              mipChainBytes(bytesPerTexel(fmt), w, h, levels) * static_cast<std::size_t>(layers));
    t.setFilter(GL_LINEAR, GL_LINEAR);
    t.setWrap(GL_CLAMP_TO_EDGE);
    return t;
}

Texture Texture::createCube(GLenum fmt, int size, int levels) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &id);
    glTextureStorage2D(id, levels, fmt, size, size);
    Texture t(GL_TEXTURE_CUBE_MAP, id, size, size, mipChainBytes(bytesPerTexel(fmt), size, size, levels) * 6u);
    t.setFilter(GL_LINEAR, GL_LINEAR);
    t.setWrap(GL_CLAMP_TO_EDGE);
    return t;
}

Texture Texture::create2DMultisample(GLenum fmt, int w, int h, int samples) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &id);
    glTextureStorage2DMultisample(id, samples, fmt, w, h, GL_TRUE);
    return Texture(GL_TEXTURE_2D_MULTISAMPLE, id, w, h,
                   bytesPerTexel(fmt) * static_cast<std::size_t>(w) * h * samples);
}

void unbindTextureUnits(GLsizei units) {
    glBindTextures(0, units, nullptr);
    glUseProgram(0);
}

Texture Texture::view2D(const Texture& source, GLenum format, int layer, int level) {
    GLuint id = 0;
    glGenTextures(1, &id);  // glTextureView needs a name that was never bound: glGen, not glCreate
    glTextureView(id, GL_TEXTURE_2D, source.id(), format, static_cast<GLuint>(level), 1, static_cast<GLuint>(layer), 1);
    const int width = std::max(1, source.width() >> level), height = std::max(1, source.height() >> level);
    return Texture(GL_TEXTURE_2D, id, width, height, 0);
}

Texture Texture::viewLayers(const Texture& source, GLenum format, int layers, int level) {
    GLuint id = 0;
    glGenTextures(1, &id);
    glTextureView(id, GL_TEXTURE_2D_ARRAY, source.id(), format, static_cast<GLuint>(level), 1, 0, static_cast<GLuint>(layers));
    const int width = std::max(1, source.width() >> level), height = std::max(1, source.height() >> level);
    return Texture(GL_TEXTURE_2D_ARRAY, id, width, height, 0);
}

Texture Texture::adopt(GLenum target, GLuint id, int w, int h, std::size_t bytes) { return Texture(target, id, w, h, bytes); }

void Texture::setFilter(GLenum minFilter, GLenum magFilter) {
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
}

void Texture::setWrap(GLenum wrap) {
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_R, static_cast<GLint>(wrap));
}

void Texture::setBorderColor(float r, float g, float b, float a) {
    const float c[4] = {r, g, b, a};
    glTextureParameterfv(id(), GL_TEXTURE_BORDER_COLOR, c);
}

void Texture::setDepthCompare(bool enabled) {
    glTextureParameteri(id(), GL_TEXTURE_COMPARE_MODE, enabled ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
    glTextureParameteri(id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

}  // namespace penumbra::gl
