#include "render/PlaceholderTextures.h"

#include "gpu/ShaderContract.h"

#include <algorithm>

namespace penumbra::render {

namespace {
gl::Texture filled(gl::Texture texture, GLenum format, GLenum type, const void* value) {
    glClearTexImage(texture.id(), 0, format, type, value);
    return texture;
}
gl::Texture depth(gl::Texture texture) {
    const float one = 1.0f;  // "nothing occludes"
    texture = filled(std::move(texture), GL_DEPTH_COMPONENT, GL_FLOAT, &one);
    texture.setDepthCompare(true);
    return texture;
}
const float kWhite[4] = {1, 1, 1, 1};
}  // namespace

PlaceholderTextures::PlaceholderTextures()
    : depth2D_(depth(gl::Texture::create2D(GL_DEPTH_COMPONENT32F, 1, 1))),
      depthCube_(depth(gl::Texture::createCube(GL_DEPTH_COMPONENT32F, 1))),
      depthArray_(depth(gl::Texture::create2DArray(GL_DEPTH_COMPONENT32F, 1, 1, 1))),
      white2D_(filled(gl::Texture::create2D(GL_RGBA8, 1, 1), GL_RGBA, GL_FLOAT, kWhite)),
      whiteCube_(filled(gl::Texture::createCube(GL_RGBA8, 1), GL_RGBA, GL_FLOAT, kWhite)),
      whiteArray_(filled(gl::Texture::create2DArray(GL_RGBA8, 1, 1, 1), GL_RGBA, GL_FLOAT, kWhite)) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &id);
    glTextureStorage3D(id, 1, GL_RGBA8, 1, 1, 1);
    white3D_ = filled(gl::Texture::adopt(GL_TEXTURE_3D, id, 1, 1, 4), GL_RGBA, GL_FLOAT, kWhite);
    std::array<GLuint, gpu::kUnitBehindDepth + 1> unit{};
    unit.fill(white2D_.id());
    for (int slot = 0; slot < gpu::kMaxShadow2D; ++slot) unit[gpu::kUnitShadow2D + slot] = depth2D_.id();
    for (int slot = 0; slot < gpu::kMaxShadowCube; ++slot) {
        unit[gpu::kUnitShadowCube + slot] = depthCube_.id();
        for (int first : {gpu::kUnitTintCube, gpu::kUnitRawCube, gpu::kUnitDrawnFarthestCube}) unit[first + slot] = whiteCube_.id();
    }
    unit[gpu::kUnitLayered] = depthArray_.id();
    unit[gpu::kUnitScreenShadow] = whiteArray_.id();
    unit[gpu::kUnitDepthTiles] = whiteArray_.id();
    unit[gpu::kUnitJitter] = white3D_.id();
    std::copy_n(unit.begin(), low_.size(), low_.begin());
    std::copy_n(unit.begin() + gpu::kUnitDrawnFarthest2D, high_.size(), high_.begin());
}

void PlaceholderTextures::bindAll() const {
    // Units from kUnitDualDepth to kUnitOpaqueDepth belong to the camera-transparency passes,
    // which bind them.
    glBindTextures(0, static_cast<GLsizei>(low_.size()), low_.data());
    glBindTextures(gpu::kUnitDrawnFarthest2D, static_cast<GLsizei>(high_.size()), high_.data());
}

}  // namespace penumbra::render
