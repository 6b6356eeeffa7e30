#pragma once
// Triangles with their neighbours (GL_TRIANGLES_ADJACENCY: 6 indices per triangle, the shared
// edges' opposite vertices between the triangle's own), on positions welded across the normal
// and uv seams that split a mesh's vertices. Pure CPU, no GL.
#include "scene/Mesh.h"

#include <cstdint>
#include <vector>

namespace penumbra::shadows {

// How a set of triangles' edges are shared.
struct EdgeCounts {
    std::size_t boundary = 0;     // triangle sides left without a partner: a hole's or a border's, a fan's odd one, a face's copy
    std::size_t nonManifold = 0;  // more than two triangles
    std::size_t misoriented = 0;  // pairs that run their edge the same way (inconsistent winding)
    // Closed and consistently wound: the volume of the triangles facing the light is the
    // object's. Anything else needs every triangle's volume (both sides).
    bool closed() const { return boundary == 0 && nonManifold == 0 && misoriented == 0; }
    EdgeCounts& operator+=(const EdgeCounts& o);
};

struct AdjacencyMesh {
    std::vector<glm::vec3> positions;  // welded: one per distinct position
    std::vector<std::uint32_t> indices;  // 6 per triangle, in the mesh's triangle order
    // On each edge the triangles paired together (buildAdjacency's `alone`) are paired off,
    // whichever way each runs it, and each is the other's neighbour: the pairing is symmetric,
    // which is what lets the geometry shader's two invocations agree whether the edge is a
    // silhouette. A triangle left without a partner (a border, the odd one of a fan, a copy of
    // its only neighbour) gets its own opposite vertex: a reversed copy of itself, so that edge
    // is always a side of its volume.
    std::vector<EdgeCounts> parts;  // per mesh part: the counts of the triangles it is paired with
    EdgeCounts edges;               // the whole mesh's
    bool closed() const { return edges.closed(); }
};

// `alone`: per part, whether it may be left out of a volume while the others are drawn (glass,
// which tints through the maps instead). Such a part is paired on its own: a triangle whose
// partner is not drawn would leave its volume open. The other parts are paired together, so a
// closed mesh of several materials stays closed.
AdjacencyMesh buildAdjacency(const scene::Mesh& mesh, const std::vector<bool>& alone = {});

}  // namespace penumbra::shadows
