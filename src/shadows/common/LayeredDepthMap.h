#pragma once
// A depth array with one layer per sub-view of one light (cascades, LiSPSM tiles), sampled by the
// lookup as one sampler2DArrayShadow. Each layer is its own depth pass over the casters that can
// reach it (culled per object against that layer's volume). Measured on llvmpipe, 975k triangles,
// 2048^2: a single pass instancing each triangle into every layer through a geometry shader
// (invocations = 16) cost lispsm 1845 ms and cascaded 2006 ms against hard's 112 ms (issue 15).
// A layer whose volume, clip plane and casters (ShadowFrame::casterDigest, animated ones with
// their current placement) are as in the last frame, and whose texels read lie in those last
// drawn, is kept (ShadowFrame::reuseStillCasters): kept while the camera and what the layer sees
// stand still, or while the camera moves within a held cascade box (fitCascade's `previous`).
// A layer that animated casters reach keeps its still casters' depth in a second array, as the
// plain maps do (DepthAndTintMaps::renderOpaque): each frame the still depth is copied back where
// the animated casters were and are, and they are drawn there, instead of the whole layer.
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "shadows/ShadowTechnique.h"
#include "shadows/common/MapRegion.h"

#include <glm/glm.hpp>
#include <vector>

namespace penumbra::shadows {

class LayeredDepthMap {
public:
    static constexpr int kMaxLayers = 16;

    // Opaque casters of `frame` into layer i through viewProj[i]. clipPlanes (optional, world
    // space, one per layer) keep only the half-space dot(plane, P) >= 0. readTexels (optional,
    // one per layer): the only texels of the layer any lookup reads; the casters are culled to
    // them and drawn scissored to them (an empty one: the layer is not drawn at all). readRoom:
    // texels drawn around them too, for layers whose boxes are held while the camera moves
    // (cascades); a layer is kept while it is unchanged and its reads lie in what it drew last.
    // Without room, a moving camera's reads leave a held layer at once; with room always, layers
    // whose boxes move every frame pay for it every frame (the default orbit at 0.125 s a frame,
    // cascaded's shadow pass 8.7-9.8 -> 11.5-11.9 ms on llvmpipe with 64 texels, boxes refitted).
    // readColumns (optional, one per layer): CasterSelection::cullPlanes around what is read.
    void render(const ShadowFrame& frame, const scene::Light& light, int resolution, const std::vector<glm::mat4>& viewProj,
                const std::vector<glm::vec4>& clipPlanes = {}, const std::vector<TexelRect>& readTexels = {}, int readRoom = 0,
                const std::vector<std::vector<glm::vec4>>& readColumns = {});
    void bind(unsigned unit) const { texture_.bind(unit); }
    bool empty() const { return texture_.id() == 0; }
    int layers() const { return layers_; }
    std::size_t memoryBytes() const { return texture_.memoryBytes() + still_.memoryBytes(); }
    DebugView debugView(const std::string& label) const;  // layer 0

private:
    // Per layer: the caster selection for texels `rect`, and the digest of what it would draw.
    struct LayerPass;
    void renderPlain(const LayerPass& pass, const TexelRect& read, const TexelRect& moving);
    void renderOverStill(const LayerPass& pass, const TexelRect& read, const TexelRect& moving);
    void restoreStill(std::size_t layer, const TexelRect& rect);
    void drawInto(const gl::Framebuffer& target, const LayerPass& pass, const TexelRect& rect, Motion motion, bool clear);

    gl::Texture texture_;
    gl::Texture view_;  // layer 0 as a plain 2D texture for the debug overlay
    std::vector<gl::Framebuffer> layerTargets_;  // one depth-only framebuffer per layer
    std::vector<std::uint64_t> holds_;           // per layer: the digest of what it holds (0: unknown)
    std::vector<TexelRect> drawn_;               // per layer: the texels last drawn (the rest is stale)
    // Layers that animated casters reach: the still casters' depth, what it holds, and where the
    // animated casters were drawn over its copy (empty: the layer is the still depth there too).
    gl::Texture still_;
    std::vector<gl::Framebuffer> stillTargets_;
    std::vector<std::uint64_t> stillHolds_;   // per layer: the digest of what the still array holds
    std::vector<TexelRect> stillDrawn_;       // per layer: the texels of the still array last drawn
    std::vector<std::uint64_t> overStill_;    // per layer: the still casters' digest its texels hold but where movingDrawn_ (0: unknown)
    std::vector<TexelRect> movingDrawn_;
    std::vector<std::uint64_t> viewKeys_;     // per layer: last frame's view (matrix and clip plane)
    int resolution_ = 0, layers_ = 0;
    DepthCasterProgram casters_;
    gl::Program restore_;  // depth_restore.frag, made when first needed
    gl::VertexArray fullscreenVao_;
};

}  // namespace penumbra::shadows
