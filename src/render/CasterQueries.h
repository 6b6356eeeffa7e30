#pragma once
// The frame's casters as a shadow pass asks for them (shadows::ShadowFrame's callbacks): which of
// the frame's draws a CasterSelection takes, their bounds, boxes and digest, and the texels of the
// selection's map they can write. A flat part that casts only on what it carries (a ground under
// its objects, Renderer::flatCasterNeeds) is left out of a light's maps, or drawn only near the
// casters whose lookups read it.
#include "gpu/ShaderContract.h"
#include "render/GpuScene.h"
#include "render/MeshClusters.h"
#include "render/TintReach.h"
#include "shadows/ShadowTechnique.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace penumbra::render {

// How many texels around a receiver's own a lookup may read in `light`'s map: the technique's
// reach (ShadowTechnique::shadowReachTexels), the normal offset, which moves the lookup that many
// texels besides, and 2 for rounding.
inline float lookupPadTexels(float reach, const gpu::LightData& light) { return reach + light.shadow.z + 2.0f; }

// The boxes of the draws a flat part is drawn near: still ones, and (with a filtered lookup,
// Renderer::FlatCasterReach) moving ones, drawn near only in passes that follow them
// (CasterMap::followsMovingCasters).
struct NearCasters {
    std::vector<OrientedBox::Corners> still, moving;
    bool empty() const { return still.empty() && moving.empty(); }
};

// What a light's maps need of an opaque flat part (no solid) that shadows none of its own
// points, with a technique that bounds its lookup's reach. Its map texels hold what lies
// behind it where it is left out, and every lookup answers as before: receivers' own texels
// count as lit, and no receiver it is not drawn for lies behind it within that reach. A
// filtered lookup (moment maps) reads the part's own texels averaged with its occluders':
// there it also needs the part around the shadows on it.
struct FlatCasterNeed {
    // A bit per light whose maps leave the part out: its shadow footprint on every other draw
    // is empty (as Renderer::addShadowReach pads it), and with a filtered lookup no opaque
    // caster's footprint reaches it.
    std::uint32_t nothing = 0;
    // Per light (empty where the part is drawn whole or not at all): the boxes of the draws
    // its footprint reaches, a ground carrying them, and with a filtered lookup of the opaque
    // casters whose footprint reaches it. The part is drawn only where their lookups read,
    // their texels and the lookup's reach around them (nearTexels, CasterMap::texelsNear).
    std::vector<NearCasters> near;
};

// Answers about one frame's draws; it holds references to its arguments, which must outlive it.
class CasterQueries {
public:
    // `needs`: one per draw; `reachTexels`: the lookup's reach flatCasterNeeds judged by.
    CasterQueries(const std::vector<Draw>& draws, const std::vector<FlatCasterNeed>& needs, const GpuScene& gpu,
                  const gpu::LightBlock& block, float reachTexels)
        : draws_(draws), needs_(needs), gpu_(gpu), block_(block), reachTexels_(reachTexels) {}

    // The frame's draws the answers index into (a pass iterates these, not a copy).
    const std::vector<Draw>& draws() const { return draws_; }
    // Whether the selection takes `d` (one of draws()).
    bool selected(const Draw& d, const shadows::CasterSelection& selection) const;
    // The boxes `d` (a flat part) is drawn near in the selection's light's maps; null: drawn whole.
    // Near moving casters only in passes that redraw wherever they are and were.
    const NearCasters* nearOf(const Draw& d, const shadows::CasterSelection& selection) const;
    // The texels of selection.map a flat part drawn near `boxes` is drawn in (a scissor).
    glm::ivec4 nearTexels(std::span<const OrientedBox::Corners> boxes, const shadows::CasterSelection& selection) const;

    // shadows::ShadowFrame's casterBounds, casterTexels, casterBoxes and casterDigest.
    scene::Bounds bounds(const shadows::CasterSelection& selection) const;
    glm::ivec4 texels(const shadows::CasterSelection& selection) const;
    std::vector<scene::Bounds> boxes(const shadows::CasterSelection& selection) const;
    std::uint64_t digest(const shadows::CasterSelection& selection) const;

private:
    std::size_t indexOf(const Draw& d) const { return static_cast<std::size_t>(&d - draws_.data()); }

    const std::vector<Draw>& draws_;
    const std::vector<FlatCasterNeed>& needs_;
    const GpuScene& gpu_;
    const gpu::LightBlock& block_;
    float reachTexels_;
};

}  // namespace penumbra::render
