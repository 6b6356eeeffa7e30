#include "shadows/volumes/Adjacency.h"

#include <algorithm>
#include <unordered_map>

namespace penumbra::shadows {

EdgeCounts& EdgeCounts::operator+=(const EdgeCounts& o) {
    boundary += o.boundary;
    nonManifold += o.nonManifold;
    misoriented += o.misoriented;
    return *this;
}

AdjacencyMesh buildAdjacency(const scene::Mesh& mesh, const std::vector<bool>& alone) {
    AdjacencyMesh out;
    // The weld Mesh::closedParts judges by: a part closed for the renderer is closed here.
    const std::vector<std::uint32_t> remap = mesh.weldedPositionIds();
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (remap[v] >= out.positions.size()) out.positions.resize(remap[v] + 1);
        out.positions[remap[v]] = mesh.vertices[v].position;
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
    auto from = [&](const Side& s) { return corner(s.triangle, s.edge); };  // where the triangle starts the edge
    auto opposite = [&](const Side& s) { return corner(s.triangle, (s.edge + 2) % 3); };
    auto link = [&](const Side& p, const Side& q) {
        out.indices[6 * p.triangle + 2 * static_cast<std::size_t>(p.edge) + 1] = opposite(q);
        out.indices[6 * q.triangle + 2 * static_cast<std::size_t>(q.edge) + 1] = opposite(p);
    };
    // Any symmetric pairing is right; the best one lets the most sides cancel. So first pair
    // triangles that run the edge opposite ways (consistently wound neighbours), then any two;
    // never a triangle with a copy of itself (the same opposite corner: models made two-sided by
    // duplicating faces, as the street's trash can is), whose sides never cancel.
    auto pairEdge = [&](const std::vector<Side>& sides, EdgeCounts& counts) {
        std::vector<bool> taken(sides.size(), false);
        for (const bool consistentOnly : {true, false})
            for (std::size_t i = 0; i < sides.size(); ++i)
                for (std::size_t j = i + 1; j < sides.size() && !taken[i]; ++j) {
                    const bool consistent = from(sides[i]) != from(sides[j]);
                    if (taken[j] || opposite(sides[i]) == opposite(sides[j]) || (consistentOnly && !consistent)) continue;
                    link(sides[i], sides[j]);
                    taken[i] = taken[j] = true;
                    counts.misoriented += !consistent;
                }
        counts.boundary += static_cast<std::size_t>(std::count(taken.begin(), taken.end(), false));
    };
    using Triangles = std::pair<std::size_t, std::size_t>;  // [first, end)
    auto pairOff = [&](const std::vector<Triangles>& ranges) {
        EdgeCounts counts;
        std::unordered_map<std::uint64_t, std::vector<Side>> edges;  // undirected edge -> its triangles, in mesh order
        for (const auto& [first, end] : ranges)
            for (std::size_t t = first; t < end; ++t)
                for (int k = 0; k < 3 && !degenerate(t); ++k) {
                    const std::uint32_t a = corner(t, k), b = corner(t, (k + 1) % 3);
                    edges[(static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b)].push_back({t, k});
                }
        for (const auto& [key, sides] : edges) {
            counts.nonManifold += sides.size() > 2;
            pairEdge(sides, counts);
        }
        return counts;
    };
    if (mesh.parts.empty()) out.edges = pairOff({{0, triangles}});
    out.parts.resize(mesh.parts.size());
    std::vector<Triangles> together;
    std::vector<std::size_t> members;
    for (std::size_t p = 0; p < mesh.parts.size(); ++p) {
        const Triangles r{mesh.parts[p].firstIndex / 3, std::min<std::size_t>((mesh.parts[p].firstIndex + mesh.parts[p].indexCount) / 3, triangles)};
        if (p < alone.size() && alone[p]) {
            out.parts[p] = pairOff({r});
            out.edges += out.parts[p];
        } else {
            together.push_back(r);
            members.push_back(p);
        }
    }
    const EdgeCounts shared = together.empty() ? EdgeCounts{} : pairOff(together);
    for (const std::size_t p : members) out.parts[p] = shared;
    out.edges += shared;
    return out;
}

}  // namespace penumbra::shadows
