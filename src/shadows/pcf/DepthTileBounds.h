#pragma once
// Per tile of kDepthTile^2 texels of each 2D shadow map, bounds on the depth of the tile and of a
// border of kDepthTileBorder texels around it: a plane under every texel there, d >= g . c + a
// (c the texel's centre relative to the tile's corner), and the farthest depth. From one fetch a
// PCF lookup can tell that every tap of its kernel returns the same (pcf/lookup.glsl, tapsAgree):
// lit when the plane lies behind the highest reference any tap can have, shadowed when the
// farthest depth lies in front of the lowest. A plane and not a minimum, because the receiver
// most often is the surface in the map: a tilted ground's minimum over a tile lies in front of
// the ground at the receiver, and a min/max pyramid (measured: Dmitriev & Uralsky's hierarchical
// min-max map, GDC 2007) skipped almost nothing on the default scene's ground.
//
// Why skip at all on llvmpipe, where an `if` skips nothing (both sides run, masked): a loop ends
// as soon as no lane of its 8-pixel group is left in it (gallivm's lp_exec_endloop), so a kernel
// loop that breaks first thing where the answer is known costs one tap there.
//
// One RGBA32F 2D array, a layer per 2D shadow slot, on gpu::kUnitDepthTiles; each layer made
// again only where its map's depth changed (DerivedTexels). Cube maps have none.
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
    // Brings each 2D-mapped light's layer up to date with the depth `maps` hold this frame.
    void update(const DepthAndTintMaps& maps);
    // The maps changed without update(): every layer is made again next time.
    void forget() { layers_.clear(); }
    void bind() const;  // to gpu::kUnitDepthTiles
    std::size_t memoryBytes() const { return bounds_.memoryBytes(); }

private:
    struct Layer {
        int light = -1, resolution = 0;
        DerivedTexels derived;
        gl::Framebuffer target;
    };
    void ensure(int tilesAcross);

    gl::Texture bounds_;
    int tilesAcross_ = 0;
    std::vector<Layer> layers_;
    gl::Program build_;
    gl::Sampler depthSampler_{GL_NEAREST, GL_NEAREST};  // depth as values, not comparisons
    gl::VertexArray fullscreenVao_;
};

}  // namespace penumbra::shadows
