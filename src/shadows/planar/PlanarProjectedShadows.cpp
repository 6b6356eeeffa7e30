#include "shadows/planar/PlanarProjectedShadows.h"

#include "gl/Debug.h"
#include "gl/PassState.h"

#include <cmath>

namespace penumbra::shadows {

PlanarProjectedShadows::PlanarProjectedShadows() {
    flattened_ = gl::Program::build({.vertex = "src/shadows/planar/planar.vert", .fragment = "src/shadows/planar/planar.frag"});
}

std::vector<Parameter> PlanarProjectedShadows::declareParameters() {
    return {Parameter::integer("receiver", receiverObject_, -1, 1000000, "receiver object index; -1: the largest flat object"),
            Parameter::flag("clip_to_receiver", clipToReceiver_, "stencil keeps shadows on the receiver's visible pixels"),
            Parameter::flag("stencil_once", stencilOnce_, "stencil darkens each pixel once where casters overlap"),
            Parameter::flag("naive", naive_, "divide by w first: casters behind the light or under the plane cast too"),
            Parameter::real("opacity", opacity_, 0, 1, "how dark the shadow is")};
}

void PlanarProjectedShadows::renderMaps(const ShadowFrame& frame) {
    maps_.render(frame);  // coloured tint, and the fallback for glass the pre-pass does not see
    if (!frame.scene || !frame.camera || frame.viewport.x <= 0) return;
    receiver_ = findReceiverPlane(*frame.scene, frame.time, receiverObject_);
    gl::DebugGroup group("planar shadows");
    mask_.begin(frame);
    const auto& lights = *frame.lights;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const bool clip = clipToReceiver_;
        mask_.beginLight(static_cast<int>(i), clip ? 0 : 1);  // without the receiver mask every pixel may take a shadow
        if (!lights[i].shadow.enabled || !receiver_) continue;
        if (clip) {  // stencil 1 where the receiver is the visible surface
            gl::PassState marking = gl::PassState::depthOnly().withStencil({.ref = 1, .mask = 0xff, .depthPass = GL_REPLACE});
            marking.depthFunc = GL_LEQUAL;
            marking.depthWrite = false;
            marking.colorWrite = glm::bvec4(false);
            const gl::ScopedPassState state(marking);
            const DepthCasterProgram& surfaces = maps_.depthProgram();  // plain positions; the light's matrix swapped for the camera's
            surfaces.set("uLightViewProj", mask_.viewProj());
            frame.drawSurfaces(surfaces, receiver_->object);
        }
        flattenCasters(frame, static_cast<int>(i));
    }
}

void PlanarProjectedShadows::flattenCasters(const ShadowFrame& frame, int light) {
    const glm::vec4 L = homogeneousLight((*frame.lights)[static_cast<std::size_t>(light)]);
    glm::vec4 plane = receiver_->plane;
    if (glm::dot(plane, L) < 0.0f) plane = -plane;  // the light on the positive side
    if (glm::dot(plane, L) <= 0.0f) return;           // light in the plane: no projection
    // Shadows sit on the receiver: drawn over it (polygon offset towards the camera), hidden by
    // what stands in front. Stencil "equal 1, then increment" lets each pixel darken once; the
    // blend multiplies visibility by 1 - opacity.
    gl::PassState flatten = gl::PassState::depthOnly()
                                .withPolygonOffset(-1.0f, -4.0f)
                                .withStencil({.func = GL_EQUAL, .ref = 1, .mask = 0xff, .depthPass = GLenum(stencilOnce_ ? GL_INCR : GL_KEEP)})
                                .withBlend(gl::BlendState::of(GL_FUNC_ADD, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA));
    flatten.depthFunc = GL_LEQUAL;
    flatten.depthWrite = false;
    const gl::ScopedPassState state(flatten);
    flattened_.set("uViewProj", mask_.viewProj());
    flattened_.set("uFlatten", planarShadowMatrix(plane, L));
    flattened_.set("uPlane", plane);
    flattened_.set("uLight", L);
    flattened_.set("uNaive", naive_ ? 1 : 0);
    flattened_.set("uOpacity", opacity_);
    flattened_.set("uPlaneEpsilon", 1e-4f * std::sqrt(receiver_->area));
    frame.drawCasters(flattened_, {Casters::Opaque, std::nullopt, light});
}

void PlanarProjectedShadows::bindLookup(const gl::Program& lighting) const {
    maps_.bind();
    mask_.bind(lighting);
}

}  // namespace penumbra::shadows
