#include "shadows/common/LayeredDepthMap.h"

#include "gl/Debug.h"
#include "gl/PassState.h"
#include "gpu/ShaderContract.h"
#include "util/Digest.h"

#include <algorithm>
#include <utility>

namespace penumbra::shadows {

// One layer's pass: what drawing the casters that reach `rect` of it would write there, and its digest.
struct LayeredDepthMap::LayerPass {
    const ShadowFrame& frame;
    const scene::Light& light;
    glm::mat4 viewProj;
    glm::vec4 clipPlane;
    std::size_t layer;
    int res;
    bool cropped, reuse;
    int room;
    bool animated;  // the scene animates casters: layers track what their still casters drew
    const std::vector<glm::vec4>* column;  // cull planes around what is read, or none

    // `scissored`: the pass draws `rect` under its scissor (else the whole layer, no scissor).
    CasterSelection selection(const TexelRect& rect, Motion motion, bool scissored = false) const {
        return {Casters::Opaque, cropped && !isEmpty(rect) ? cropTo(rect, res) * viewProj : viewProj, frame.slots->sun, motion, viewProj,
                true, CasterMap{res, scissored ? rect : TexelRect(0, 0, res, res), scissored}, column ? *column : std::vector<glm::vec4>{}};
    }
    std::uint64_t keyOf(const TexelRect& rect, Motion motion) const {
        return reuse ? util::Digest().add(frame.casterDigest(selection(rect, motion)), viewProj, clipPlane, light.shadow.polygonOffset, rect, motion).value()
                     : std::uint64_t{0};
    }
    // With `room`, drawn with that room around the reads, so that a layer whose box is held while the
    // camera moves (fitCascade's `previous`) is kept until its reads leave it.
    TexelRect drawnFor(const TexelRect& read) const { return cropped ? grown(read, glm::ivec2(room), res) : read; }
};

namespace {
bool holds(const TexelRect& outer, const TexelRect& inner) { return intersection(inner, outer) == inner; }

// A depth-only framebuffer on each layer of `array`.
std::vector<gl::Framebuffer> depthTargets(const gl::Texture& array, int layers, const std::string& what) {
    std::vector<gl::Framebuffer> targets;
    for (int layer = 0; layer < layers; ++layer) {
        gl::Framebuffer target;
        target.attachLayer(GL_DEPTH_ATTACHMENT, array, layer);
        target.setNoColor();
        target.checkComplete(what + ", layer " + std::to_string(layer));
        targets.push_back(std::move(target));
    }
    return targets;
}
}  // namespace

void LayeredDepthMap::render(const ShadowFrame& frame, const scene::Light& light, int res,
                             const std::vector<glm::mat4>& viewProj, const std::vector<glm::vec4>& clipPlanes,
                             const std::vector<TexelRect>& readTexels, int readRoom, const std::vector<std::vector<glm::vec4>>& readColumns) {
    const int count = std::clamp(static_cast<int>(viewProj.size()), 1, kMaxLayers);
    if (res != resolution_ || count != layers_) {
        texture_ = gl::Texture::create2DArray(GL_DEPTH_COMPONENT32F, res, res, count);
        texture_.setFilter(GL_NEAREST, GL_NEAREST);
        texture_.setDepthCompare(true);
        view_ = gl::Texture::view2D(texture_, GL_DEPTH_COMPONENT32F, 0);
        layerTargets_ = depthTargets(texture_, count, "layered shadow map");
        resolution_ = res;
        layers_ = count;
        holds_.assign(static_cast<std::size_t>(count), 0);
        drawn_.assign(static_cast<std::size_t>(count), TexelRect(0));
        still_ = gl::Texture();
        stillTargets_.clear();
        stillHolds_.assign(static_cast<std::size_t>(count), 0);
        stillDrawn_.assign(static_cast<std::size_t>(count), TexelRect(0));
        overStill_.assign(static_cast<std::size_t>(count), 0);
        viewKeys_.assign(static_cast<std::size_t>(count), 0);
        movingDrawn_.assign(static_cast<std::size_t>(count), TexelRect(0));
    }
    gl::unbindTextureUnits(gpu::kLightingUnits);  // see DepthAndTintMaps::render
    gl::PassState state = gl::PassState::depthOnly().withPolygonOffset(light.shadow.polygonOffset.x, light.shadow.polygonOffset.y);
    state.clipDistance0 = !clipPlanes.empty();
    const gl::ScopedPassState scoped(state);
    const bool reuse = frame.reuseStillCasters && frame.casterDigest;
    const bool animated = reuse && frame.scene && frame.scene->animated();
    for (int layer = 0; layer < count; ++layer) {
        const auto l = static_cast<std::size_t>(layer);
        // A caster outside the layer's clip volume would be clipped whole (no depth clamp here):
        // culling it per object leaves the map unchanged.
        const bool cropped = l < readTexels.size();
        const LayerPass pass{frame, light, viewProj[l], l < clipPlanes.size() ? clipPlanes[l] : glm::vec4(0, 0, 0, 1), l, res, cropped, reuse,
                             readRoom, animated, l < readColumns.size() ? &readColumns[l] : nullptr};
        const TexelRect read = cropped ? readTexels[l] : TexelRect(0, 0, res, res);
        // Where animated casters that reach the layer can write.
        const TexelRect moving =
            animated ? texelRect(frame.casterBounds(pass.selection(TexelRect(0), Motion::Moving)), viewProj[l], res) : TexelRect(0);
        // A layer whose view moved this frame is drawn whole: its still depth would have to be drawn
        // too, which a layer that moves in most frames (a warp following a fast camera) would pay in
        // each (lispsm on the default orbit at 0.125 s a frame: shadow pass 6.7-7.2 -> 7.6-7.8 ms on
        // llvmpipe). From the next frame it holds, it is drawn over its still depth.
        const std::uint64_t viewKey = util::Digest().add(viewProj[l], pass.clipPlane).value();
        const bool viewHeld = std::exchange(viewKeys_[l], viewKey) == viewKey;
        if ((isEmpty(moving) && isEmpty(movingDrawn_[l])) || !viewHeld) renderPlain(pass, read, moving);
        else renderOverStill(pass, read, moving);
    }
}

// Kept while it is unchanged and its reads lie in what was drawn last; else drawn whole.
void LayeredDepthMap::renderPlain(const LayerPass& pass, const TexelRect& read, const TexelRect& moving) {
    const std::size_t l = pass.layer;
    const std::uint64_t drawnKey = holds_[l] != 0 ? pass.keyOf(drawn_[l], Motion::Any) : 0;
    if (drawnKey != 0 && drawnKey == holds_[l] && holds(drawn_[l], read)) return;
    const TexelRect draw = pass.drawnFor(read);
    holds_[l] = drawnKey != 0 && draw == drawn_[l] ? drawnKey : pass.keyOf(draw, Motion::Any);  // the same rectangle: its key is known
    drawn_[l] = draw;
    drawInto(layerTargets_[l], pass, draw, Motion::Any, true);
    // What it holds: its still casters' depth but where the animated ones were drawn, so that a
    // still depth drawn next frame for the same view needs copying back only there.
    movingDrawn_[l] = intersection(moving, draw);
    overStill_[l] = pass.animated ? pass.keyOf(draw, Motion::Still) : 0;
}

// The still casters' depth, kept while they are unchanged and the reads lie in what it holds, copied
// back where the animated casters were last frame and are now, and the animated casters drawn there.
void LayeredDepthMap::renderOverStill(const LayerPass& pass, const TexelRect& read, const TexelRect& moving) {
    const std::size_t l = pass.layer;
    if (still_.id() == 0) {
        still_ = gl::Texture::create2DArray(GL_DEPTH_COMPONENT32F, resolution_, resolution_, layers_);
        still_.setFilter(GL_NEAREST, GL_NEAREST);  // one level: complete for texelFetch
        stillTargets_ = depthTargets(still_, layers_, "layered shadow map's still casters");
    }
    const std::uint64_t stillKey = stillHolds_[l] != 0 ? pass.keyOf(stillDrawn_[l], Motion::Still) : 0;
    const bool stillKept = stillKey != 0 && stillKey == stillHolds_[l] && holds(stillDrawn_[l], read);
    if (!stillKept) {
        const TexelRect draw = pass.drawnFor(read);
        stillHolds_[l] = pass.keyOf(draw, Motion::Still);
        stillDrawn_[l] = draw;
        drawInto(stillTargets_[l], pass, draw, Motion::Still, true);
    }
    // The layer differs from the still depth only where last frame's animated casters were drawn,
    // if it was copied from this still depth; else it is copied whole.
    const bool fromThisStill = overStill_[l] == stillHolds_[l] && drawn_[l] == stillDrawn_[l];
    const TexelRect restore = fromThisStill ? intersection(unite(movingDrawn_[l], moving), stillDrawn_[l]) : stillDrawn_[l];
    restoreStill(l, restore);
    drawn_[l] = stillDrawn_[l];
    const TexelRect movingDraw = intersection(moving, drawn_[l]);
    if (!isEmpty(movingDraw)) drawInto(layerTargets_[l], pass, movingDraw, Motion::Moving, false);
    movingDrawn_[l] = movingDraw;
    overStill_[l] = stillHolds_[l];
    // With nothing animated drawn in it, the layer is the still depth: kept as a plain layer too.
    holds_[l] = isEmpty(movingDraw) ? pass.keyOf(drawn_[l], Motion::Any) : 0;
}

// The still depth copied into layer `l` over `rect`: a large rectangle by glCopyImageSubData, a
// memcpy on llvmpipe, which waits there for every queued draw touching either array; a small one
// (the animated casters' texels) by a draw, queued as any other. Measured on llvmpipe (default
// scene, lispsm, fixed camera): the copy 0.72-0.75 ms of shadow pass, the draw 0.32-0.66, and
// the opaque pass after the copy 1-3 ms dearer; a whole 2048^2 layer by the draw 6.4-6.7 ms.
void LayeredDepthMap::restoreStill(std::size_t l, const TexelRect& rect) {
    if (isEmpty(rect)) return;
    const auto width = rect.z - rect.x, height = rect.w - rect.y;
    if (static_cast<long>(width) * height * 16 > static_cast<long>(resolution_) * resolution_) {
        const auto z = static_cast<GLint>(l);
        glCopyImageSubData(still_.id(), GL_TEXTURE_2D_ARRAY, 0, rect.x, rect.y, z, texture_.id(), GL_TEXTURE_2D_ARRAY, 0, rect.x, rect.y, z,
                           width, height, 1);
        return;
    }
    if (restore_.id() == 0)
        restore_ = gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = "src/shadows/common/glsl/depth_restore.frag"});
    gl::PassState copy = gl::PassState::depthOnly();
    copy.depthFunc = GL_ALWAYS;
    const gl::ScopedPassState state(copy);
    const ScopedScissor scissor(rect);
    layerTargets_[l].bind();
    glViewport(0, 0, resolution_, resolution_);
    restore_.use();
    restore_.set("uLayer", static_cast<int>(l));
    still_.bind(0);
    fullscreenVao_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindTextureUnit(0, 0);
}

// The casters of `pass` that reach `rect` (moving as `motion`) into `target`, scissored to `rect`
// when the layer is cropped or over others' depth (`clear` false: drawn over what is there).
void LayeredDepthMap::drawInto(const gl::Framebuffer& target, const LayerPass& pass, const TexelRect& rect, Motion motion, bool clear) {
    if (isEmpty(rect)) return;  // nothing reads there: its stale texels stay unread
    const bool scissored = pass.cropped || !clear;
    const ScopedScissor scissor(rect, scissored);
    if (clear) target.beginDepthPass(pass.res, pass.res);
    else {
        target.bind();
        glViewport(0, 0, pass.res, pass.res);
    }
    casters_.set("uClipPlane", pass.clipPlane);
    pass.frame.drawCasters(casters_, pass.selection(rect, motion, scissored));
}

DebugView LayeredDepthMap::debugView(const std::string& label) const {
    return {label, view_.id(), GL_TEXTURE_2D, true, 0};
}

}  // namespace penumbra::shadows
