#include "shadows/common/LayeredDepthMap.h"

#include "gl/Debug.h"
#include "gl/PassState.h"
#include "gpu/ShaderContract.h"

#include <algorithm>

namespace penumbra::shadows {

LayeredDepthMap::LayeredDepthMap() {
    casters_ = gl::Program::build({.vertex = "src/shadows/common/glsl/layered_caster.vert",
                                   .fragment = "src/shadows/common/glsl/depth.frag",
                                   .geometry = "src/shadows/common/glsl/layered_caster.geom"});
}

void LayeredDepthMap::render(const ShadowFrame& frame, const scene::Light& light, int res,
                             const std::vector<glm::mat4>& viewProj, const std::vector<glm::vec4>& clipPlanes) {
    const int count = std::clamp(static_cast<int>(viewProj.size()), 1, kMaxLayers);
    if (res != resolution_ || count != layers_) {
        texture_ = gl::Texture::create2DArray(GL_DEPTH_COMPONENT32F, res, res, count);
        texture_.setFilter(GL_NEAREST, GL_NEAREST);
        texture_.setDepthCompare(true);
        view_ = gl::Texture::view2D(texture_, GL_DEPTH_COMPONENT32F, 0);
        target_ = gl::Framebuffer();
        target_.attach(GL_DEPTH_ATTACHMENT, texture_);  // layered: the geometry shader picks gl_Layer
        target_.setNoColor();
        target_.checkComplete("layered shadow map");
        resolution_ = res;
        layers_ = count;
    }
    std::vector<glm::vec4> planes(clipPlanes);
    planes.resize(static_cast<std::size_t>(count), glm::vec4(0, 0, 0, 1));  // w = 1: keep everything
    gl::unbindTextureUnits(gpu::kLightingUnits);  // see DepthAndTintMaps::render
    gl::PassState pass = gl::PassState::depthOnly().withPolygonOffset(light.shadow.polygonOffset.x, light.shadow.polygonOffset.y);
    pass.clipDistance0 = true;
    const gl::ScopedPassState state(pass);
    target_.beginDepthPass(res, res);
    glProgramUniformMatrix4fv(casters_.id(), casters_.location("uLayerViewProj[0]"), count, GL_FALSE, &viewProj[0][0][0]);
    glProgramUniform4fv(casters_.id(), casters_.location("uLayerClip[0]"), count, &planes[0].x);
    casters_.set("uLayerCount", count);
    frame.drawCasters(casters_, {Casters::Opaque, std::nullopt, frame.slots->sun});  // culled per layer in the geometry shader
}

DebugView LayeredDepthMap::debugView(const std::string& label) const {
    return {label, view_.id(), GL_TEXTURE_2D, true, 0};
}

}  // namespace penumbra::shadows
