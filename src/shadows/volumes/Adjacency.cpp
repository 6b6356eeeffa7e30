#include "shadows/volumes/Adjacency.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <unordered_map>

namespace penumbra::shadows {

namespace {

struct PositionKey {
    std::array<std::int64_t, 3> cell;
    bool operator==(const PositionKey& o) const { return cell == o.cell; }
};
struct PositionHash {
    std::size_t operator()(const PositionKey& k) const {
        return (static_cast<std::size_t>(k.cell[0]) * 73856093u) ^ (static_cast<std::size_t>(k.cell[1]) * 19349663u) ^
               (static_cast<std::size_t>(k.cell[2]) * 83492791u);
    }
};

// Positions closer than `weld` (a millionth of the mesh) are one: generated seams (sin 2π ≠ 0)
// and exporters' rounding must not open a closed mesh.
PositionKey keyOf(const glm::vec3& p, float weld) {
    PositionKey k{};
    for (int i = 0; i < 3; ++i) k.cell[static_cast<std::size_t>(i)] = static_cast<std::int64_t>(std::llround(p[i] / weld));
    return k;
}

}  // namespace

AdjacencyMesh buildAdjacency(const scene::Mesh& mesh) {
    AdjacencyMesh out;
    std::unordered_map<PositionKey, std::uint32_t, PositionHash> welded;
    std::vector<std::uint32_t> remap(mesh.vertices.size());
    scene::Bounds bounds;
    for (const auto& v : mesh.vertices) bounds.add(v.position);
    const float weld = std::max(1e-6f * glm::length(bounds.extent()), 1e-12f);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const auto [it, inserted] = welded.try_emplace(keyOf(mesh.vertices[v].position, weld), static_cast<std::uint32_t>(out.positions.size()));
        if (inserted) out.positions.push_back(mesh.vertices[v].position);
        remap[v] = it->second;
    }
    const std::size_t triangles = mesh.indices.size() / 3;
    auto corner = [&](std::size_t t, int k) { return remap[mesh.indices[3 * t + static_cast<std::size_t>(k)]]; };
    // Directed edge (a -> b) -> the vertex opposite it in its triangle; several for non-manifold edges.
    std::multimap<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> opposite;
    // Triangles that weld to a line or a point (sphere poles) have no area and no edges.
    auto degenerate = [&](std::size_t t) { return corner(t, 0) == corner(t, 1) || corner(t, 1) == corner(t, 2) || corner(t, 0) == corner(t, 2); };
    for (std::size_t t = 0; t < triangles; ++t)
        for (int k = 0; k < 3 && !degenerate(t); ++k) opposite.emplace(std::make_pair(corner(t, k), corner(t, (k + 1) % 3)), corner(t, (k + 2) % 3));
    out.indices.reserve(triangles * 6);
    for (std::size_t t = 0; t < triangles; ++t)
        for (int k = 0; k < 3; ++k) {
            if (degenerate(t)) {  // kept for the index layout; it never faces the light
                out.indices.push_back(corner(t, k));
                out.indices.push_back(corner(t, k));
                continue;
            }
            const std::uint32_t a = corner(t, k), b = corner(t, (k + 1) % 3), own = corner(t, (k + 2) % 3);
            // A consistently wound neighbour runs the edge the other way (b -> a).
            const auto range = opposite.equal_range({b, a});
            const std::size_t sharing = static_cast<std::size_t>(std::distance(range.first, range.second)) +
                                        opposite.count({a, b}) - 1;  // other triangles on this edge, either way
            std::uint32_t neighbour = own;
            if (range.first != range.second) neighbour = range.first->second;
            if (sharing == 0) ++out.boundaryEdges;
            else if (sharing > 1 || range.first == range.second) ++out.nonManifoldEdges;  // or wound against us
            out.indices.push_back(a);
            out.indices.push_back(neighbour);
        }
    return out;
}

}  // namespace penumbra::shadows
