#include "shadows/pcf/DepthTileBounds.h"

#include "gl/Debug.h"
#include "gl/PassState.h"
#include "gpu/ShaderContract.h"
#include "util/Digest.h"

#include <algorithm>

namespace penumbra::shadows {

namespace {
int tilesOver(int texels) { return (texels + gpu::kDepthTile - 1) / gpu::kDepthTile; }
}  // namespace

void DepthTileBounds::ensure(int tilesAcross) {
    if (tilesAcross == tilesAcross_ && layers_.size() == gpu::kMaxShadow2D) return;
    if (tilesAcross != tilesAcross_) {
        bounds_ = gl::Texture::create2DArray(GL_RGBA32F, tilesAcross, tilesAcross, gpu::kMaxShadow2D);
        bounds_.setFilter(GL_NEAREST, GL_NEAREST);
        tilesAcross_ = tilesAcross;
    }
    layers_.clear();  // every layer is made again
    layers_.resize(gpu::kMaxShadow2D);
    for (int slot = 0; slot < gpu::kMaxShadow2D; ++slot)
        layers_[static_cast<std::size_t>(slot)].target = gl::Framebuffer::colourOnly(bounds_, slot, "depth tile bounds");
}

void DepthTileBounds::update(const DepthAndTintMaps& maps) {
    const ShadowSlots& slots = maps.slots();
    int widest = 0;
    for (std::size_t i = 0; i < slots.size(); ++i)
        if (slots.shadowed(i) && !slots.cube[i]) widest = std::max(widest, maps.maps(i).resolution);
    if (widest == 0) return;
    if (!build_.id())
        build_ = gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = "src/shadows/pcf/tile_bounds.frag"});
    ensure(std::max(tilesOver(widest), tilesAcross_));
    gl::DebugGroup group("depth tile bounds");
    const gl::ScopedPassState state(gl::PassState::fullscreen());
    fullscreenVao_.bind();
    build_.use();
    depthSampler_.bind(0);
    glViewport(0, 0, tilesAcross_, tilesAcross_);
    glEnable(GL_SCISSOR_TEST);
    for (std::size_t i = 0; i < slots.size(); ++i) {
        if (!slots.shadowed(i) || slots.cube[i]) continue;
        const DepthAndTintMaps::LightMaps& map = maps.maps(i);
        Layer& layer = layers_[static_cast<std::size_t>(slots.slot[i])];
        if (layer.light != static_cast<int>(i) || layer.resolution != map.resolution) layer.derived = DerivedTexels{};
        layer.light = static_cast<int>(i);
        layer.resolution = map.resolution;
        const std::uint64_t key = map.stillKeys[0] == 0 ? 0 : util::Digest().add(map.stillKeys[0], map.resolution).value();
        const TexelRect changed = layer.derived.changed(key, map.movingTexels[0], map.resolution);
        if (isEmpty(changed)) continue;
        // Tiles whose texels or border hold a changed texel.
        const TexelRect tiles = coarser(grown(changed, glm::ivec2(gpu::kDepthTileBorder), map.resolution), gpu::kDepthTile,
                                        tilesOver(map.resolution));
        map.depth.bind(0);
        layer.target.bind();
        glScissor(tiles.x, tiles.y, tiles.z - tiles.x, tiles.w - tiles.y);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glDisable(GL_SCISSOR_TEST);
    gl::Sampler::unbind(0);
}

void DepthTileBounds::bind() const {
    if (bounds_.id()) bounds_.bind(gpu::kUnitDepthTiles);
}

}  // namespace penumbra::shadows
