#pragma once
// Bounds on a 2D shadow map's depth, tile by tile, at every scale: level k has tiles of
// kDepthTile << k texels, each bounding its texels and a border around them (2 texels at level
// 0; at level k, one level-(k-1) tile and its border more: (8 << k) - kDepthTileInset texels)
// with a plane under every depth there, d >= g . c + a (c the texel's centre relative to the
// tile's corner), and the farthest depth. From one fetch a lookup can tell that every tap of
// its kernel returns the same (common/glsl/depth_tiles.glsl, tapsAgree): lit when the plane lies
// behind the highest reference any tap can have, shadowed when the farthest depth lies in front
// of the lowest. A plane and not
// just a minimum, because the receiver most often is the surface in the map: a tilted ground's
// minimum over a tile lies in front of the ground at the receiver, and a min/max pyramid
// (Dmitriev & Uralsky's hierarchical min-max map, GDC 2007) skipped almost nothing on the default
// scene's ground (measured).
//
// Why skip at all on llvmpipe, where an `if` skips nothing (both sides run, masked): a loop ends
// as soon as no lane of its 8-pixel group is left in it (gallivm's lp_exec_endloop), so a kernel
// loop that breaks first thing where the answer is known costs one tap there.
//
// One mipmapped RGBA32F 2D array (mip level k = tile level k), a layer per 2D shadow slot in use, on
// gpu::kUnitDepthTiles; each layer made again only where its map's depth changed (DerivedTexels).
// Cube maps have none.
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Sampler.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "shadows/common/DepthAndTintMaps.h"

#include <vector>

namespace penumbra::shadows {

class DepthTileBounds {
public:
    // Brings each 2D-mapped light's layer up to date with the depth `maps` hold this frame, with
    // the levels a lookup reaching up to `reachTexels` can read (tileAround in depth_tiles.glsl;
    // < 0: every level). Where a kernel reaches a few texels, as PCF's default 1.5-texel radius
    // does, one level serves: measured on llvmpipe, every further level cost a pass of 0.03-0.18 ms
    // per light and frame while anything animated reached the map.
    // `everyFrame`: make them also for maps of which nothing is kept (drawn whole every frame),
    // which otherwise get bounds that never agree (neverAgree).
    void update(const DepthAndTintMaps& maps, float reachTexels = -1.0f, bool everyFrame = false);
    // The finest level whose tiles' border holds every texel within `reachTexels` of a receiver
    // (depth_tiles.glsl's tileAround computes the same).
    static int levelFor(float reachTexels);
    // The maps changed without update(): every layer is made again next time.
    void forget() { layers_.clear(); }
    void bind() const;  // to gpu::kUnitDepthTiles
    // Per 2D-mapped light of `slots`, its layer (every level), for tests and tools: the overlay shows 2D views only.
    std::vector<DebugView> debugViews(const ShadowSlots& slots) const;
    std::size_t memoryBytes() const { return bounds_.memoryBytes(); }

private:
    struct Layer {
        int light = -1, resolution = 0;
        DerivedTexels derived;
        bool neverAgrees = false;  // every level holds bounds that never agree (neverAgree)
        std::vector<gl::Framebuffer> levelTargets;
        std::vector<gl::Texture> levelViews;  // each level alone: the next one's input, no feedback loop
    };
    void ensure(int tilesAcross, int layers, int levels);
    void updateLayer(Layer& layer, const gl::Texture& depth, const TexelRect& changed);
    // Sets layer `slot` to bounds that never agree (once), for a map nothing of which is kept.
    void neverAgree(Layer& layer, int slot);

    gl::Texture bounds_;
    int tilesAcross_ = 0;  // at level 0, a power of two
    int layerCount_ = 0;   // 2D slots 0 .. layerCount_ - 1 (never fewer than once needed)
    int levels_ = 0;       // mip levels of bounds_: as many as the reach needs, at most 1 + log2(tilesAcross_)
    std::vector<Layer> layers_;
    gl::Program tiles_, merge_;
    gl::Sampler depthSampler_{GL_NEAREST, GL_NEAREST};  // depth as values, not comparisons
    gl::VertexArray fullscreenVao_;
};

}  // namespace penumbra::shadows
