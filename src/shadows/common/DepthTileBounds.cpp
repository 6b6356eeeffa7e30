#include "shadows/common/DepthTileBounds.h"

#include "gl/Debug.h"
#include "gl/PassState.h"
#include "gpu/ShaderContract.h"
#include "util/Digest.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace penumbra::shadows {

namespace {
int tileSide(int level) { return gpu::kDepthTile << level; }
int tilesOver(int texels, int level) { return (texels + tileSide(level) - 1) / tileSide(level); }
int border(int level) { return tileSide(level) - gpu::kDepthTileInset; }
}  // namespace

int DepthTileBounds::levelFor(float reachTexels) {
    const float inset = static_cast<float>(gpu::kDepthTileInset), tile = static_cast<float>(gpu::kDepthTile);
    int level = std::max(0, static_cast<int>(std::ceil(std::log2((reachTexels + 1e-3f + inset) / tile))));
    if (static_cast<float>((gpu::kDepthTile << level) - gpu::kDepthTileInset) < reachTexels + 1e-3f) ++level;  // log2's rounding
    return level;
}

void DepthTileBounds::ensure(int tilesAcross, int layers, int levels) {
    if (tilesAcross == tilesAcross_ && layers == static_cast<int>(layers_.size()) && levels == levels_) return;
    if (tilesAcross != tilesAcross_ || layers != layerCount_ || levels != levels_) {
        // Layers only for the slots in use: a 16384^2 sun alone needs 2048^2 tiles, 85 MiB, not 4 x that.
        levels_ = levels;
        bounds_ = gl::Texture::create2DArray(GL_RGBA32F, tilesAcross, tilesAcross, layers, levels_);
        bounds_.setFilter(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST);
        // Bounds that never agree until a layer is made (and no undefined texels in a readback).
        const float never[4] = {-4.0f, 0.0f, 0.0f, 1.0f};
        for (int level = 0; level < levels_; ++level) glClearTexImage(bounds_.id(), level, GL_RGBA, GL_FLOAT, never);
        tilesAcross_ = tilesAcross;
        layerCount_ = layers;
    }
    layers_.clear();  // every layer is made again
    layers_.resize(static_cast<std::size_t>(layers));
    for (int slot = 0; slot < layers; ++slot)
        for (int level = 0; level < levels_; ++level) {
            Layer& layer = layers_[static_cast<std::size_t>(slot)];
            layer.levelTargets.push_back(gl::Framebuffer::colourOnly(bounds_, slot, "depth tile bounds", level));
            layer.levelViews.push_back(gl::Texture::view2D(bounds_, GL_RGBA32F, slot, level));
        }
}

void DepthTileBounds::update(const DepthAndTintMaps& maps, float reachTexels, bool everyFrame) {
    const ShadowSlots& slots = maps.slots();
    int widest = 0, layers = 0;
    for (std::size_t i = 0; i < slots.size(); ++i)
        if (slots.shadowed(i) && !slots.cube[i]) {
            widest = std::max(widest, maps.maps(i).resolution);
            layers = std::max(layers, slots.slot[i] + 1);
        }
    if (widest == 0) return;
    if (!tiles_.id()) {
        tiles_ = gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = "src/shadows/common/glsl/depth_tiles.frag"});
        merge_ = gl::Program::build(
            {.vertex = "shaders/passes/fullscreen.vert", .fragment = "src/shadows/common/glsl/depth_tiles_merge.frag"});
    }
    const int across = std::max(static_cast<int>(std::bit_ceil(static_cast<unsigned>(tilesOver(widest, 0)))), tilesAcross_);
    // A level the reach never asks for is not made: the lookup reads textureQueryLevels and runs
    // its taps past the last level there is (one more than the reach needs, against rounding).
    const int allLevels = 1 + std::countr_zero(static_cast<unsigned>(across));
    ensure(across, std::max(layers, layerCount_), reachTexels < 0.0f ? allLevels : std::min(allLevels, levelFor(reachTexels) + 2));
    gl::DebugGroup group("depth tile bounds");
    const gl::ScopedPassState state(gl::PassState::fullscreen());
    fullscreenVao_.bind();
    glEnable(GL_SCISSOR_TEST);
    for (std::size_t i = 0; i < slots.size(); ++i) {
        if (!slots.shadowed(i) || slots.cube[i]) continue;
        const DepthAndTintMaps::LightMaps& map = maps.maps(i);
        Layer& layer = layers_[static_cast<std::size_t>(slots.slot[i])];
        if (layer.light != static_cast<int>(i) || layer.resolution != map.resolution) layer.derived = DerivedTexels{};
        layer.light = static_cast<int>(i);
        layer.resolution = map.resolution;
        if (map.stillKeys[0] == 0 && !everyFrame) {  // a map drawn whole every frame: bounds that never agree, once
            neverAgree(layer, slots.slot[i]);
            continue;
        }
        layer.neverAgrees = false;
        const std::uint64_t key = map.stillKeys[0] == 0 ? 0 : util::Digest().add(map.stillKeys[0], map.resolution).value();
        const TexelRect changed = layer.derived.changed(key, map.movingTexels[0], map.resolution);
        if (!isEmpty(changed)) updateLayer(layer, map.depth, changed);
    }
    glDisable(GL_SCISSOR_TEST);
    gl::Sampler::unbind(0);
}

// Bounds of a map that is drawn whole every frame (nothing kept: `--redraw-shadow-maps`) would be
// made whole every frame too, and on llvmpipe that costs more than the taps they let the lookups
// skip: default scene, every map redrawn, four alternated rounds, frame with the bounds ÷ without:
// pcf-poisson16 1.15 (1/0.867), pcss 1.11; the bounds' pass ~10 ms, the taps it saved ~3-4 ms of
// the opaque pass. With the maps kept they are made once and pay: without them pcf-poisson16's
// frame was 1.21x, pcss's 1.17x. So such a layer holds bounds that never agree: the lookups run
// their whole kernels, the same pixels.
void DepthTileBounds::neverAgree(Layer& layer, int slot) {
    layer.derived = DerivedTexels{};  // made whole when the map is kept again
    if (layer.neverAgrees) return;
    const float never[4] = {-4.0f, 0.0f, 0.0f, 1.0f};
    for (int level = 0; level < levels_; ++level) {
        const int size = std::max(1, tilesAcross_ >> level);
        glClearTexSubImage(bounds_.id(), level, 0, 0, slot, size, size, 1, GL_RGBA, GL_FLOAT, never);
    }
    layer.neverAgrees = true;
}

void DepthTileBounds::updateLayer(Layer& layer, const gl::Texture& depth, const TexelRect& changed) {
    const int res = layer.resolution;
    for (int level = 0; level < levels_; ++level) {
        const auto l = static_cast<std::size_t>(level);
        // The tiles whose texels or border hold a changed texel.
        const TexelRect tiles = coarser(grown(changed, glm::ivec2(border(level)), res), tileSide(level), tilesOver(res, level));
        if (level == 0) {
            tiles_.use();
            depthSampler_.bind(0);
            depth.bind(0);
        } else {
            merge_.use();
            gl::Sampler::unbind(0);
            merge_.set("uLevel", level);
            merge_.set("uFinerTiles", tilesOver(res, level - 1));
            layer.levelViews[l - 1].bind(0);
        }
        glViewport(0, 0, std::max(1, tilesAcross_ >> level), std::max(1, tilesAcross_ >> level));
        layer.levelTargets[l].bind();
        glScissor(tiles.x, tiles.y, tiles.z - tiles.x, tiles.w - tiles.y);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
}

std::vector<DebugView> DepthTileBounds::debugViews(const ShadowSlots& slots) const {
    std::vector<DebugView> views;
    if (!bounds_.id()) return views;
    for (std::size_t i = 0; i < slots.size(); ++i)
        if (slots.shadowed(i) && !slots.cube[i])
            views.push_back({"light " + std::to_string(i) + " depth tile bounds (a, g, farthest)", bounds_.id(),
                             GL_TEXTURE_2D_ARRAY, false, slots.slot[i]});
    return views;
}

void DepthTileBounds::bind() const {
    if (bounds_.id()) bounds_.bind(gpu::kUnitDepthTiles);
}

}  // namespace penumbra::shadows
