#include "gl/PassState.h"

namespace penumbra::gl {

namespace {
PassState g_current;  // GL's initial state until the first pass

void enable(GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); }

void applyStencil(GLenum face, const StencilFace& s) {
    glStencilFuncSeparate(face, s.func, s.ref, s.mask);
    glStencilOpSeparate(face, s.stencilFail, s.depthFail, s.depthPass);
}
}  // namespace

PassState PassState::depthOnly() {
    PassState s;
    s.depthTest = true;
    return s;
}

PassState PassState::fullscreen() {
    PassState s;
    s.depthWrite = false;
    return s;
}

void applyPassState(const PassState& s) {
    enable(GL_DEPTH_TEST, s.depthTest);
    glDepthFunc(s.depthFunc);
    glDepthMask(s.depthWrite ? GL_TRUE : GL_FALSE);
    enable(GL_DEPTH_CLAMP, s.depthClamp);
    glColorMask(s.colorWrite.r, s.colorWrite.g, s.colorWrite.b, s.colorWrite.a);
    enable(GL_BLEND, s.blend);
    const BlendState& b = s.blending;
    glBlendEquationSeparate(b.equationRgb, b.equationAlpha);
    glBlendFuncSeparate(b.srcRgb, b.dstRgb, b.srcAlpha, b.dstAlpha);
    for (const auto& [buffer, o] : s.bufferBlending) {
        glBlendEquationSeparatei(buffer, o.equationRgb, o.equationAlpha);
        glBlendFuncSeparatei(buffer, o.srcRgb, o.dstRgb, o.srcAlpha, o.dstAlpha);
    }
    enable(GL_STENCIL_TEST, s.stencilTest);
    applyStencil(GL_FRONT, s.stencilFront);
    applyStencil(GL_BACK, s.stencilBack);
    enable(GL_POLYGON_OFFSET_FILL, s.polygonOffset);
    glPolygonOffset(s.offsetFactor, s.offsetUnits);
    enable(GL_CLIP_DISTANCE0, s.clipDistance0);
    enable(GL_CULL_FACE, s.cullFace);
    g_current = s;
}

const PassState& currentPassState() { return g_current; }

ScopedPassState::ScopedPassState(const PassState& state) : previous_(g_current) { applyPassState(state); }
ScopedPassState::~ScopedPassState() { applyPassState(previous_); }

}  // namespace penumbra::gl
