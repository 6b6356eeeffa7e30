#include "shadows/planar/PlanarProjectedShadows.h"

#include "gl/Debug.h"

#include <cmath>

namespace penumbra::shadows {

PlanarProjectedShadows::PlanarProjectedShadows() {
    flattened_ = gl::Program::build({.vertex = "src/shadows/planar/planar.vert", .fragment = "src/shadows/planar/planar.frag"});
}

std::vector<Parameter> PlanarProjectedShadows::parameters() {
    return {{"receiver", &receiverObject_, -1, 1e6f},      {"clip_to_receiver", &clipToReceiver_, 0, 1},
            {"stencil_once", &stencilOnce_, 0, 1},        {"naive", &naive_, 0, 1},
            {"opacity", &opacity_, 0, 1}};
}

void PlanarProjectedShadows::renderMaps(const ShadowFrame& frame) {
    maps_.render(frame);  // coloured tint, and the fallback for glass the pre-pass does not see
    if (!frame.scene || !frame.camera || frame.viewport.x <= 0) return;
    receiver_ = findReceiverPlane(*frame.scene, frame.time, static_cast<int>(std::lround(receiverObject_)));
    gl::DebugGroup group("planar shadows");
    mask_.begin(frame);
    const auto& lights = *frame.lights;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const bool clip = clipToReceiver_ > 0.5f;
        mask_.beginLight(static_cast<int>(i), clip ? 0 : 1);  // without the receiver mask every pixel may take a shadow
        if (!lights[i].shadow.enabled || !receiver_) continue;
        glEnable(GL_STENCIL_TEST);
        glDepthMask(GL_FALSE);
        glEnable(GL_DEPTH_TEST);
        if (clip) {  // stencil 1 where the receiver is the visible surface
            glDepthFunc(GL_LEQUAL);
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glStencilFunc(GL_ALWAYS, 1, 0xff);
            glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
            const gl::Program& surfaces = maps_.depthProgram();  // plain positions; the light's matrix swapped for the camera's
            surfaces.set("uLightViewProj", mask_.viewProj());
            frame.drawSurfaces(surfaces, receiver_->object);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        }
        flattenCasters(frame, lights[i]);
        glDepthMask(GL_TRUE);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ZERO);
    }
}

void PlanarProjectedShadows::flattenCasters(const ShadowFrame& frame, const scene::Light& light) {
    const glm::vec4 L = homogeneousLight(light);
    glm::vec4 plane = receiver_->plane;
    if (glm::dot(plane, L) < 0.0f) plane = -plane;  // the light on the positive side
    if (glm::dot(plane, L) <= 0.0f) return;           // light in the plane: no projection
    // Shadows sit on the receiver: drawn over it (polygon offset towards the camera), hidden by
    // what stands in front. Stencil "equal 1, then increment" lets each pixel darken once.
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.0f, -4.0f);
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, stencilOnce_ > 0.5f ? GL_INCR : GL_KEEP);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);  // visibility *= 1 - opacity
    flattened_.set("uViewProj", mask_.viewProj());
    flattened_.set("uFlatten", planarShadowMatrix(plane, L));
    flattened_.set("uPlane", plane);
    flattened_.set("uLight", L);
    flattened_.set("uNaive", naive_ > 0.5f ? 1 : 0);
    flattened_.set("uOpacity", opacity_);
    flattened_.set("uPlaneEpsilon", 1e-4f * std::sqrt(receiver_->area));
    frame.drawCasters(flattened_, Casters::Opaque);
    glDisable(GL_POLYGON_OFFSET_FILL);
}

void PlanarProjectedShadows::bindLookup(const gl::Program& lighting) const {
    maps_.bind();
    mask_.bind(lighting);
}

}  // namespace penumbra::shadows
