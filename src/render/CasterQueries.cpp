#include "render/CasterQueries.h"

#include "util/Digest.h"

namespace penumbra::render {

bool CasterQueries::selected(const Draw& d, const shadows::CasterSelection& selection) const {
    using shadows::Motion;
    return d.castsShadow && d.translucent == (selection.casters == shadows::Casters::Translucent) &&
           (selection.motion == Motion::Any || d.moving == (selection.motion == Motion::Moving)) &&
           !(selection.light >= 0 && (needs_[indexOf(d)].nothing >> selection.light & 1u)) &&
           !(selection.cull && outsideClipVolume(d.worldBounds, *selection.cull)) &&
           !outsideAnyPlane(d.worldBounds, selection.cullPlanes);
}

const NearCasters* CasterQueries::nearOf(const Draw& d, const shadows::CasterSelection& selection) const {
    const auto& near = needs_[indexOf(d)].near;
    const auto light = static_cast<std::size_t>(selection.light);
    if (selection.light < 0 || light >= near.size() || near[light].empty()) return nullptr;
    const bool follows = selection.map && selection.map->followsMovingCasters;
    return near[light].moving.empty() || follows ? &near[light] : nullptr;
}

glm::ivec4 CasterQueries::nearTexels(std::span<const OrientedBox::Corners> boxes, const shadows::CasterSelection& selection) const {
    const float pad = lookupPadTexels(reachTexels_, block_.lights[selection.light]);
    return selection.map->texelsNear(boxes, *selection.lightViewProj, pad);
}

scene::Bounds CasterQueries::bounds(const shadows::CasterSelection& selection) const {
    scene::Bounds all;
    for (const Draw& d : draws_)
        if (selected(d, selection)) all.add(d.worldBounds);
    return all;
}

glm::ivec4 CasterQueries::texels(const shadows::CasterSelection& selection) const {
    using shadows::CasterMap;
    std::vector<OrientedBox::Corners> whole;  // the casters drawn whole
    glm::ivec4 near(0);                       // and the scissors of those drawn near others
    shadows::CasterSelection any = selection;
    any.motion = shadows::Motion::Any;
    for (const Draw& d : draws_) {
        const NearCasters* boxes = nearOf(d, selection);
        if (selected(d, selection)) {
            if (boxes) {
                near = CasterMap::united(near, CasterMap::united(nearTexels(boxes->still, selection), nearTexels(boxes->moving, selection)));
            } else {
                whole.push_back(d.worldBounds.corners());
            }
        } else if (boxes && selection.motion == shadows::Motion::Moving && selected(d, any)) {
            near = CasterMap::united(near, nearTexels(boxes->moving, selection));  // a still ground following them
        }
    }
    return CasterMap::united(near, selection.map->texelsNear(whole, *selection.lightViewProj, 0.0f));
}

std::vector<scene::Bounds> CasterQueries::boxes(const shadows::CasterSelection& selection) const {
    std::vector<scene::Bounds> out;
    for (const Draw& d : draws_)
        if (selected(d, selection)) out.push_back(d.worldBounds);
    return out;
}

std::uint64_t CasterQueries::digest(const shadows::CasterSelection& selection) const {
    util::Digest digest;
    for (const Draw& d : draws_) {
        if (!selected(d, selection)) continue;
        digest.add(d.object, d.mesh, d.part, d.model, d.material->alphaCutoff, d.material->diffuseTexture);
        // A big part's clusters drawn: its column planes may move while the rest holds.
        if (selection.cull && !selection.cullPlanes.empty())
            if (const auto ranges = gpu_.rangesInside(d, *selection.cull, selection.cullPlanes))
                for (const IndexRange& r : *ranges) digest.add(r.firstIndex, r.indexCount);
        // A flat part drawn only near still casters holds what they were when it was drawn.
        const auto& near = needs_[indexOf(d)].near;
        if (selection.light >= 0 && static_cast<std::size_t>(selection.light) < near.size())
            for (const OrientedBox::Corners& box : near[static_cast<std::size_t>(selection.light)].still) digest.add(box);
    }
    return digest.value();
}

}  // namespace penumbra::render
