#pragma once
#include "gl/Object.h"

#include <cstddef>

namespace penumbra::gl {

// A texture with immutable storage. Created through the named constructors, which say
// what the texture is for; memoryBytes() feeds the per-technique memory statistics.
class Texture {
public:
    Texture() = default;
    static Texture create2D(GLenum internalFormat, int width, int height, int levels = 1);
    static Texture create2DArray(GLenum internalFormat, int width, int height, int layers, int levels = 1);
    static Texture createCube(GLenum internalFormat, int size, int levels = 1);
    static Texture create2DMultisample(GLenum internalFormat, int width, int height, int samples);
    // A 2D view of one layer (cube face) and one mip level of `source`, for passes that read or
    // write one face, or read one level while writing the next (no feedback loop: the view holds
    // only the level it reads).
    static Texture view2D(const Texture& source, GLenum format, int layer, int level = 0);
    // A 2D-array view of `layers` layers (cube faces) of one mip level of `source`, for passes that
    // read every face of a level at once.
    static Texture viewLayers(const Texture& source, GLenum format, int layers, int level);
    // Takes ownership of a texture made elsewhere (3D textures, views).
    static Texture adopt(GLenum target, GLuint id, int width, int height, std::size_t bytes);

    GLuint id() const { return object_.id(); }
    GLenum target() const { return target_; }
    int width() const { return width_; }
    int height() const { return height_; }
    std::size_t memoryBytes() const { return bytes_; }

    void bind(GLuint unit) const { glBindTextureUnit(unit, id()); }
    void setFilter(GLenum minFilter, GLenum magFilter);
    void setWrap(GLenum wrap);
    void setBorderColor(float r, float g, float b, float a);
    // Hardware depth comparison (sampler*Shadow): GL_LEQUAL of reference vs stored depth.
    void setDepthCompare(bool enabled);

private:
    Texture(GLenum target, GLuint id, int w, int h, std::size_t bytes);
    Object<detail::deleteTexture> object_;
    GLenum target_ = 0;
    int width_ = 0, height_ = 0;
    std::size_t bytes_ = 0;
};

// Unbinds the first `units` texture units, and the current program, which may sample them. llvmpipe
// rasterises into a texture several times slower while last frame's textures stay bound for
// sampling, so shadow passes start with this. NVIDIA's driver checks the current program against
// the bound textures at the next clear too (a lighting program left current by a frame drawn
// straight into sRGB, whose shadow samplers then met unbound units: "Program undefined behavior"
// warnings on an H200).
void unbindTextureUnits(GLsizei units);

// Bytes per texel of the internal formats this project uses (for memory statistics).
std::size_t bytesPerTexel(GLenum internalFormat);

}  // namespace penumbra::gl
