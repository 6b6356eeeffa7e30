#include "shadows/volumes/Adjacency.h"

#include <algorithm>
#include <array>
#include <cmath>
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

EdgeCounts& EdgeCounts::operator+=(const EdgeCounts& o) {
    boundary += o.boundary;
    nonManifold += o.nonManifold;
    misoriented += o.misoriented;
    return *this;
}

EdgeCounts AdjacencyMesh::total() const {
    EdgeCounts sum;
    for (const auto& p : parts) sum += p;
    return sum;
}

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
    // Triangles that weld to a line or a point (sphere poles) have no area and no edges.
    auto degenerate = [&](std::size_t t) { return corner(t, 0) == corner(t, 1) || corner(t, 1) == corner(t, 2) || corner(t, 0) == corner(t, 2); };
    // Each triangle's edge k starts the 6-index group's slot 2k; slot 2k + 1 is the neighbour's
    // opposite vertex, the triangle's own until a partner is found.
    out.indices.resize(triangles * 6);
    for (std::size_t t = 0; t < triangles; ++t)  // degenerate ones keep their slots; the shader skips them
        for (int k = 0; k < 3; ++k) {
            out.indices[6 * t + 2 * static_cast<std::size_t>(k)] = corner(t, k);
            out.indices[6 * t + 2 * static_cast<std::size_t>(k) + 1] = corner(t, (k + 2) % 3);
        }
    struct Side {
        std::size_t triangle;
        int edge;
    };
    auto pairOff = [&](std::size_t first, std::size_t end) {
        EdgeCounts counts;
        std::unordered_map<std::uint64_t, std::vector<Side>> edges;  // undirected edge -> its triangles, in mesh order
        for (std::size_t t = first; t < end; ++t)
            for (int k = 0; k < 3 && !degenerate(t); ++k) {
                const std::uint32_t a = corner(t, k), b = corner(t, (k + 1) % 3);
                edges[(static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b)].push_back({t, k});
            }
        for (const auto& [key, sides] : edges) {
            counts.boundary += sides.size() == 1;
            counts.nonManifold += sides.size() > 2;
            for (std::size_t i = 0; i + 1 < sides.size(); i += 2) {
                const Side p = sides[i], q = sides[i + 1];
                out.indices[6 * p.triangle + 2 * static_cast<std::size_t>(p.edge) + 1] = corner(q.triangle, (q.edge + 2) % 3);
                out.indices[6 * q.triangle + 2 * static_cast<std::size_t>(q.edge) + 1] = corner(p.triangle, (p.edge + 2) % 3);
                counts.misoriented += sides.size() == 2 && corner(p.triangle, p.edge) == corner(q.triangle, q.edge);
            }
        }
        return counts;
    };
    if (mesh.parts.empty()) out.parts.push_back(pairOff(0, triangles));
    for (const auto& part : mesh.parts)
        out.parts.push_back(pairOff(part.firstIndex / 3, std::min<std::size_t>((part.firstIndex + part.indexCount) / 3, triangles)));
    return out;
}

}  // namespace penumbra::shadows
