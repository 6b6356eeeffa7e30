#pragma once
// Per-light visibility in screen space, for techniques that shadow what the camera sees rather
// than what a light sees (shadow volumes, planar projected shadows): a camera depth + stencil
// pre-pass, and an R8 array with one layer per light (1 lit, 0 shadowed) that the lookup reads
// at gl_FragCoord. Fragments that are not the pre-pass surface (glass in front of it) fall back
// to the shadow-map lookup (see screen_mask.glsl).
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "shadows/ShadowTechnique.h"

namespace penumbra::shadows {

class ScreenShadowMask {
public:
    ScreenShadowMask();
    // Allocates for the frame's size and lights, and draws the camera depth pre-pass (stencil 0).
    void begin(const ShadowFrame& frame);
    // Targets layer `light`: colour cleared to 1 (lit), stencil to `stencil`; depth kept.
    void beginLight(int light, int stencil = 0);
    // Writes 0 into the current layer wherever the stencil is not 0 (the stencil test decides).
    void shadowWhereStencilNonZero();
    void bind(const gl::Program& lighting) const;
    std::size_t memoryBytes() const { return mask_.memoryBytes() + depth_.memoryBytes(); }
    std::vector<DebugView> debugViews() const;
    glm::mat4 viewProj() const { return viewProj_; }

private:
    gl::Texture mask_, depth_;
    std::vector<gl::Framebuffer> layers_;
    glm::ivec2 size_{0};
    int layerCount_ = 0;
    glm::mat4 viewProj_{1.0f};
    glm::vec2 depthRange_{0.1f, 100.0f};
    DepthCasterProgram depthProgram_;
    gl::Program stencilToMask_;
    gl::VertexArray emptyVao_;
};

}  // namespace penumbra::shadows
