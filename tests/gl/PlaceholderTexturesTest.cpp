// The lighting passes bind render::PlaceholderTextures once per pass, in two glBindTextures calls
// from a table: every unit the lighting shader declares must then hold a texture its sampler type
// accepts (a depth texture with comparison for the shadow samplers: NVIDIA reports texture 0 or a
// colour texture there, every frame), and the camera-transparency units between the two ranges
// must keep what their passes bound.
#include "GlTestSupport.h"

#include "gl/Texture.h"
#include "gpu/ShaderContract.h"
#include "render/PlaceholderTextures.h"

#include <string>

namespace penumbra::test {
namespace {

enum class Kind { Colour, Depth };

struct Bound {
    GLuint texture = 0;
    Kind kind = Kind::Colour;
    bool compares = false;
};

// What unit `unit` holds on `binding` (GL_TEXTURE_BINDING_2D, ..._CUBE_MAP, ...), and of what kind.
Bound boundAt(int unit, GLenum binding) {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    GLint id = 0;
    glGetIntegerv(binding, &id);
    glActiveTexture(GL_TEXTURE0);
    Bound b;
    b.texture = static_cast<GLuint>(id);
    if (b.texture == 0) return b;
    GLint depthBits = 0, mode = GL_NONE;
    glGetTextureLevelParameteriv(b.texture, 0, GL_TEXTURE_DEPTH_SIZE, &depthBits);
    glGetTextureParameteriv(b.texture, GL_TEXTURE_COMPARE_MODE, &mode);
    b.kind = depthBits > 0 ? Kind::Depth : Kind::Colour;
    b.compares = mode == GL_COMPARE_REF_TO_TEXTURE;
    return b;
}

void expectShadowSampler(int unit, GLenum binding) {
    const Bound b = boundAt(unit, binding);
    EXPECT_NE(b.texture, 0u) << "unit " << unit;
    EXPECT_EQ(b.kind, Kind::Depth) << "unit " << unit;
    EXPECT_TRUE(b.compares) << "unit " << unit;
}

void expectColour(int unit, GLenum binding) {
    const Bound b = boundAt(unit, binding);
    EXPECT_NE(b.texture, 0u) << "unit " << unit;
    EXPECT_EQ(b.kind, Kind::Colour) << "unit " << unit;
}

TEST(PlaceholderTextures, EveryLightingUnitHoldsWhatItsSamplerAcceptsAndTransparencyUnitsAreLeft) {
    const gl::Texture marker = gl::Texture::create2D(GL_RG16F, 1, 1);
    for (int unit = gpu::kUnitDualDepth; unit <= gpu::kUnitOpaqueDepth; ++unit) marker.bind(static_cast<GLuint>(unit));
    glBindTextures(0, gpu::kUnitDualDepth, nullptr);
    glBindTextures(gpu::kUnitDrawnFarthest2D, gpu::kUnitBehindDepth + 1 - gpu::kUnitDrawnFarthest2D, nullptr);

    const render::PlaceholderTextures placeholders;
    placeholders.bindAll();

    for (int slot = 0; slot < gpu::kMaxShadow2D; ++slot) {
        expectShadowSampler(gpu::kUnitShadow2D + slot, GL_TEXTURE_BINDING_2D);
        expectColour(gpu::kUnitTint2D + slot, GL_TEXTURE_BINDING_2D);
        expectColour(gpu::kUnitRaw2D + slot, GL_TEXTURE_BINDING_2D);
        expectColour(gpu::kUnitDrawnFarthest2D + slot, GL_TEXTURE_BINDING_2D);
    }
    for (int slot = 0; slot < gpu::kMaxShadowCube; ++slot) {
        expectShadowSampler(gpu::kUnitShadowCube + slot, GL_TEXTURE_BINDING_CUBE_MAP);
        expectColour(gpu::kUnitTintCube + slot, GL_TEXTURE_BINDING_CUBE_MAP);
        expectColour(gpu::kUnitRawCube + slot, GL_TEXTURE_BINDING_CUBE_MAP);
        expectColour(gpu::kUnitDrawnFarthestCube + slot, GL_TEXTURE_BINDING_CUBE_MAP);
    }
    expectShadowSampler(gpu::kUnitLayered, GL_TEXTURE_BINDING_2D_ARRAY);
    expectColour(gpu::kUnitScreenShadow, GL_TEXTURE_BINDING_2D_ARRAY);
    expectColour(gpu::kUnitDepthTiles, GL_TEXTURE_BINDING_2D_ARRAY);
    expectColour(gpu::kUnitJitter, GL_TEXTURE_BINDING_3D);
    for (int unit : {gpu::kUnitDiffuse, gpu::kUnitProjector, gpu::kUnitProjector + gpu::kMaxProjectors - 1,
                     gpu::kUnitScreenDepth, gpu::kUnitBehindDepth})
        expectColour(unit, GL_TEXTURE_BINDING_2D);
    for (int unit = gpu::kUnitDualDepth; unit <= gpu::kUnitOpaqueDepth; ++unit)
        EXPECT_EQ(boundAt(unit, GL_TEXTURE_BINDING_2D).texture, marker.id()) << "transparency unit " << unit;

    glBindTextures(0, gpu::kUnitBehindDepth + 1, nullptr);
}

}  // namespace
}  // namespace penumbra::test
