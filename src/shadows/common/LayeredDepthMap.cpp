#include "shadows/common/LayeredDepthMap.h"

#include "gl/Debug.h"
#include "gl/PassState.h"
#include "gpu/ShaderContract.h"
#include "util/Digest.h"

#include <algorithm>

namespace penumbra::shadows {

void LayeredDepthMap::render(const ShadowFrame& frame, const scene::Light& light, int res,
                             const std::vector<glm::mat4>& viewProj, const std::vector<glm::vec4>& clipPlanes,
                             const std::vector<TexelRect>& readTexels, int readRoom) {
    const int count = std::clamp(static_cast<int>(viewProj.size()), 1, kMaxLayers);
    if (res != resolution_ || count != layers_) {
        texture_ = gl::Texture::create2DArray(GL_DEPTH_COMPONENT32F, res, res, count);
        texture_.setFilter(GL_NEAREST, GL_NEAREST);
        texture_.setDepthCompare(true);
        view_ = gl::Texture::view2D(texture_, GL_DEPTH_COMPONENT32F, 0);
        layerTargets_.clear();
        for (int layer = 0; layer < count; ++layer) {
            gl::Framebuffer target;
            target.attachLayer(GL_DEPTH_ATTACHMENT, texture_, layer);
            target.setNoColor();
            target.checkComplete("layered shadow map, layer " + std::to_string(layer));
            layerTargets_.push_back(std::move(target));
        }
        resolution_ = res;
        layers_ = count;
        holds_.assign(static_cast<std::size_t>(count), 0);
        drawn_.assign(static_cast<std::size_t>(count), TexelRect(0));
    }
    gl::unbindTextureUnits(gpu::kLightingUnits);  // see DepthAndTintMaps::render
    gl::PassState pass = gl::PassState::depthOnly().withPolygonOffset(light.shadow.polygonOffset.x, light.shadow.polygonOffset.y);
    pass.clipDistance0 = !clipPlanes.empty();
    const gl::ScopedPassState state(pass);
    const bool reuse = frame.reuseStillCasters && frame.casterDigest;
    for (int layer = 0; layer < count; ++layer) {
        const auto l = static_cast<std::size_t>(layer);
        const glm::vec4 clipPlane = l < clipPlanes.size() ? clipPlanes[l] : glm::vec4(0, 0, 0, 1);
        // A caster outside the layer's clip volume would be clipped whole (no depth clamp here):
        // culling it per object leaves the map unchanged.
        const bool cropped = l < readTexels.size();
        const TexelRect read = cropped ? readTexels[l] : TexelRect(0, 0, res, res);
        // What drawing the casters that reach `rect` of the layer would write there.
        const auto selection = [&](const TexelRect& rect) {
            return CasterSelection{Casters::Opaque, cropped && !isEmpty(rect) ? cropTo(rect, res) * viewProj[l] : viewProj[l],
                                   frame.slots->sun, Motion::Any, viewProj[l], true};
        };
        const auto keyOf = [&](const TexelRect& rect) {
            return reuse ? util::Digest().add(frame.casterDigest(selection(rect)), viewProj[l], clipPlane, light.shadow.polygonOffset, rect).value()
                         : std::uint64_t{0};
        };
        // Kept while it is unchanged and its reads lie in what was drawn last.
        const std::uint64_t drawnKey = holds_[l] != 0 ? keyOf(drawn_[l]) : 0;
        const bool unchanged = drawnKey != 0 && drawnKey == holds_[l];
        if (unchanged && intersection(read, drawn_[l]) == read) continue;
        // With `readRoom`, drawn with that room around the reads, so that a layer whose box is held
        // while the camera moves (fitCascade's `previous`) is kept until its reads leave it.
        const TexelRect draw = cropped ? grown(read, glm::ivec2(readRoom), res) : read;
        const CasterSelection casters = selection(draw);
        holds_[l] = drawnKey != 0 && draw == drawn_[l] ? drawnKey : keyOf(draw);  // the same rectangle: its key is known
        drawn_[l] = draw;
        if (isEmpty(draw)) continue;  // nothing reads this layer: its stale texels stay unread
        const ScopedScissor scissor(draw, cropped);
        layerTargets_[l].beginDepthPass(res, res);
        casters_.set("uClipPlane", clipPlane);
        frame.drawCasters(casters_, casters);
    }
}

DebugView LayeredDepthMap::debugView(const std::string& label) const {
    return {label, view_.id(), GL_TEXTURE_2D, true, 0};
}

}  // namespace penumbra::shadows
