#include "render/PlaceholderTextures.h"

#include "gpu/ShaderContract.h"

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
}

void PlaceholderTextures::bindAll() const {
    // Units from kUnitDualDepth up belong to the camera-transparency passes, which bind them.
    for (int unit = 0; unit < gpu::kUnitDualDepth; ++unit) white2D_.bind(static_cast<GLuint>(unit));
    for (int slot = 0; slot < gpu::kMaxShadow2D; ++slot) {
        depth2D_.bind(static_cast<GLuint>(gpu::kUnitShadow2D + slot));
        white2D_.bind(static_cast<GLuint>(gpu::kUnitDrawnFarthest2D + slot));
    }
    for (int slot = 0; slot < gpu::kMaxShadowCube; ++slot) {
        depthCube_.bind(static_cast<GLuint>(gpu::kUnitShadowCube + slot));
        whiteCube_.bind(static_cast<GLuint>(gpu::kUnitTintCube + slot));
        whiteCube_.bind(static_cast<GLuint>(gpu::kUnitRawCube + slot));
        whiteCube_.bind(static_cast<GLuint>(gpu::kUnitDrawnFarthestCube + slot));
    }
    depthArray_.bind(gpu::kUnitLayered);
    whiteArray_.bind(gpu::kUnitScreenShadow);
    whiteArray_.bind(gpu::kUnitDepthTiles);
    white3D_.bind(gpu::kUnitJitter);
    white2D_.bind(gpu::kUnitBehindDepth);
}

}  // namespace penumbra::render
