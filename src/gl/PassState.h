#pragma once
// The fixed-function state of one pass, declared whole (after bgfx's per-draw state word): depth,
// colour mask, blending, stencil, polygon offset, clipping, culling. ScopedPassState applies all
// of it when a pass begins and re-applies what was in force before when the pass ends, so no pass
// inherits another's state and none has to promise to "leave the default behind". Every field
// starts at OpenGL's initial value, so a pass names only what it changes.
#include "gl/Object.h"

#include <array>
#include <glm/glm.hpp>
#include <vector>

namespace penumbra::gl {

struct BlendState {
    GLenum equationRgb = GL_FUNC_ADD, equationAlpha = GL_FUNC_ADD;
    GLenum srcRgb = GL_ONE, dstRgb = GL_ZERO, srcAlpha = GL_ONE, dstAlpha = GL_ZERO;

    // The same equation and factors for colour and alpha.
    static BlendState of(GLenum equation, GLenum src, GLenum dst) { return {equation, equation, src, dst, src, dst}; }
};

struct StencilFace {
    GLenum func = GL_ALWAYS;
    GLint ref = 0;
    GLuint mask = 0xffffffffu;
    GLenum stencilFail = GL_KEEP, depthFail = GL_KEEP, depthPass = GL_KEEP;
};

struct PassState {
    bool depthTest = false;
    GLenum depthFunc = GL_LESS;
    bool depthWrite = true;
    bool depthClamp = false;
    glm::bvec4 colorWrite{true};
    bool blend = false;
    BlendState blending;                                    // every draw buffer...
    std::vector<std::pair<GLuint, BlendState>> bufferBlending;  // ...except these
    bool stencilTest = false;
    StencilFace stencilFront, stencilBack;
    bool polygonOffset = false;  // GL_POLYGON_OFFSET_FILL
    float offsetFactor = 0.0f, offsetUnits = 0.0f;
    bool clipDistance0 = false;
    bool cullFace = false;

    // Depth test (GL_LESS) and depth writes, nothing else: shadow maps, camera pre-passes.
    static PassState depthOnly();
    // No depth test, no depth writes: full-screen passes.
    static PassState fullscreen();
    PassState& withBlend(const BlendState& b) { blend = true; blending = b; return *this; }
    PassState& withStencil(const StencilFace& both) { stencilTest = true; stencilFront = stencilBack = both; return *this; }
    PassState& withPolygonOffset(float factor, float units) {
        polygonOffset = factor != 0.0f || units != 0.0f;
        offsetFactor = factor;
        offsetUnits = units;
        return *this;
    }
};

// Sets every field of `state` (a handful of GL calls; passes are few per frame).
void applyPassState(const PassState& state);
// The state last applied through applyPassState / ScopedPassState.
const PassState& currentPassState();

class ScopedPassState {
public:
    explicit ScopedPassState(const PassState& state);
    ~ScopedPassState();
    ScopedPassState(const ScopedPassState&) = delete;
    ScopedPassState& operator=(const ScopedPassState&) = delete;

private:
    PassState previous_;
};

}  // namespace penumbra::gl
