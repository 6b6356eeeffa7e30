#pragma once
// Triangles with their neighbours (GL_TRIANGLES_ADJACENCY: 6 indices per triangle, the shared
// edges' opposite vertices between the triangle's own), on positions welded across the normal
// and uv seams that split a mesh's vertices. Pure CPU, no GL.
#include "scene/Mesh.h"

#include <cstdint>
#include <vector>

namespace penumbra::shadows {

struct AdjacencyMesh {
    std::vector<glm::vec3> positions;  // welded: one per distinct position
    std::vector<std::uint32_t> indices;  // 6 per triangle, in the mesh's triangle order
    // Edges with one triangle (a hole, a border) and with more than two. A boundary edge gets the
    // triangle's own opposite vertex as neighbour: a reversed copy of the triangle, so it is a
    // silhouette whenever the triangle faces the light.
    std::size_t boundaryEdges = 0, nonManifoldEdges = 0;
    bool closed() const { return boundaryEdges == 0 && nonManifoldEdges == 0; }
};

AdjacencyMesh buildAdjacency(const scene::Mesh& mesh);

}  // namespace penumbra::shadows
