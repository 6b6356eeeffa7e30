#include "scene/Mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numeric>
#include <optional>
#include <vector>

namespace penumbra::scene {

Bounds Bounds::transformed(const glm::mat4& m) const {
    Bounds out;
    if (empty()) return out;
    for (int i = 0; i < 8; ++i) out.add(glm::vec3(m * glm::vec4(corner(i), 1.0f)));
    return out;
}

void Mesh::computeBounds() {
    bounds = Bounds{};
    for (const auto& v : vertices) bounds.add(v.position);
}

// The vertices sorted by their position's bits, -0 taken as +0 (a box's faces, a sphere's seam
// and poles repeat positions).
std::vector<std::uint32_t> Mesh::weldedPositionIds() const {
    using Key = std::array<std::uint32_t, 3>;
    const auto key = [&](std::uint32_t i) {
        const glm::vec3 w = vertices[i].position + glm::vec3(0.0f);  // -0 + 0 = +0: equal positions, equal bits
        Key bits;
        std::memcpy(bits.data(), &w, sizeof bits);
        return bits;
    };
    std::vector<std::uint32_t> order(vertices.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    std::vector<std::uint32_t> ids(vertices.size());
    std::uint32_t id = 0;
    for (std::size_t k = 0; k < order.size(); ++k) {
        if (k > 0 && key(order[k]) != key(order[k - 1])) ++id;
        ids[order[k]] = id;
    }
    return ids;
}

// Whether the triangles of `p` bound a solid, given the vertices' welded ids.
static bool bindsSolid(const Mesh& mesh, const MeshPart& p, const std::vector<std::uint32_t>& welded) {
    if (p.indexCount < 12 || p.firstIndex + static_cast<std::size_t>(p.indexCount) > mesh.indices.size()) return false;
    // Directed edges (from << 32 | to): a closed surface wound one way runs each edge once and
    // its reverse once, so the sorted edges, reversed and sorted again, are the same list.
    std::vector<std::uint64_t> edges;
    edges.reserve(p.indexCount);
    double volume = 0.0;
    for (std::uint32_t t = 0; t + 2 < p.indexCount; t += 3) {
        std::uint32_t id[3];
        glm::dvec3 q[3];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t index = mesh.indices[p.firstIndex + t + static_cast<std::uint32_t>(k)];
            if (index >= welded.size()) return false;
            id[k] = welded[index];
            q[k] = glm::dvec3(mesh.vertices[index].position);
        }
        if (id[0] == id[1] || id[1] == id[2] || id[2] == id[0]) continue;  // degenerate
        for (int k = 0; k < 3; ++k) edges.push_back(static_cast<std::uint64_t>(id[k]) << 32 | id[(k + 1) % 3]);
        volume += glm::dot(q[0], glm::cross(q[1], q[2])) / 6.0;
    }
    std::sort(edges.begin(), edges.end());
    if (edges.empty() || std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return false;  // an edge run twice
    std::vector<std::uint64_t> reversed(edges.size());
    std::transform(edges.begin(), edges.end(), reversed.begin(), [](std::uint64_t e) { return e << 32 | e >> 32; });
    std::sort(reversed.begin(), reversed.end());
    return reversed == edges && volume > 0.0;
}

std::vector<bool> Mesh::closedParts() const {
    const std::vector<std::uint32_t> welded = weldedPositionIds();
    std::vector<bool> closed(parts.size());
    for (std::size_t p = 0; p < parts.size(); ++p) closed[p] = bindsSolid(*this, parts[p], welded);
    return closed;
}

bool Mesh::partIsClosed(std::size_t part) const { return part < parts.size() && closedParts()[part]; }

namespace {

constexpr float kPlaneTolerance = 1e-4f;  // of a part's size

// A triangle's plane (unit normal, offset), none for a degenerate one.
std::optional<glm::vec4> planeOf(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    if (length <= 1e-12f) return std::nullopt;
    return glm::vec4(n / length, -glm::dot(n / length, a));
}

// The part's vertices (each once), its triangles' planes (degenerate ones left out) and the
// tolerance of kPlaneTolerance of its size.
struct PartPlanes {
    std::vector<glm::vec3> points;
    std::vector<glm::vec4> planes;
    float tolerance = 0.0f;
};
PartPlanes planesOf(const Mesh& mesh, const MeshPart& part) {
    PartPlanes p;
    std::vector<std::uint32_t> used(mesh.indices.begin() + part.firstIndex, mesh.indices.begin() + part.firstIndex + part.indexCount);
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    Bounds box;
    for (std::uint32_t v : used) {
        p.points.push_back(mesh.vertices[v].position);
        box.add(mesh.vertices[v].position);
    }
    p.tolerance = kPlaneTolerance * glm::length(box.extent());
    for (std::uint32_t i = part.firstIndex; i + 2 < part.firstIndex + part.indexCount; i += 3)
        if (const auto plane = planeOf(mesh.vertices[mesh.indices[i]].position, mesh.vertices[mesh.indices[i + 1]].position,
                                       mesh.vertices[mesh.indices[i + 2]].position))
            p.planes.push_back(*plane);
    return p;
}

}  // namespace

bool Mesh::partIsConvex(std::size_t part, std::size_t mostTriangles) const {
    if (part >= parts.size() || parts[part].indexCount / 3 > mostTriangles) return false;
    const PartPlanes p = planesOf(*this, parts[part]);
    for (const glm::vec4& plane : p.planes)
        for (const glm::vec3& q : p.points)
            if (glm::dot(glm::vec3(plane), q) + plane.w > p.tolerance) return false;
    return !p.planes.empty();
}

// Straight over the indices, stopping at the first vertex off the plane: no sorted copy of the
// indices and no plane per triangle, which only partIsConvex needs.
bool Mesh::partIsFlat(std::size_t part) const { return partPlane(part).has_value(); }

std::optional<glm::vec4> Mesh::partPlane(std::size_t part) const {
    if (part >= parts.size()) return std::nullopt;
    const MeshPart& mp = parts[part];
    const auto at = [&](std::uint32_t i) { return vertices[indices[i]].position; };
    std::optional<glm::vec4> plane;
    for (std::uint32_t i = mp.firstIndex; i + 2 < mp.firstIndex + mp.indexCount && !plane; i += 3)
        plane = planeOf(at(i), at(i + 1), at(i + 2));
    if (!plane) return std::nullopt;
    Bounds box;
    for (std::uint32_t i = mp.firstIndex; i < mp.firstIndex + mp.indexCount; ++i) box.add(at(i));
    const float tolerance = kPlaneTolerance * glm::length(box.extent());
    for (std::uint32_t i = mp.firstIndex; i < mp.firstIndex + mp.indexCount; ++i)
        if (std::abs(glm::dot(glm::vec3(*plane), at(i)) + plane->w) > tolerance) return std::nullopt;
    return plane;
}

bool Mesh::partHasFaceNormals(std::size_t part) const {
    if (part >= parts.size()) return false;
    const MeshPart& mp = parts[part];
    bool any = false;
    for (std::uint32_t i = mp.firstIndex; i + 2 < mp.firstIndex + mp.indexCount; i += 3) {
        const Vertex *a = &vertices[indices[i]], *b = &vertices[indices[i + 1]], *c = &vertices[indices[i + 2]];
        const auto plane = planeOf(a->position, b->position, c->position);
        if (!plane) continue;
        const glm::vec3 n(*plane);
        for (const Vertex* v : {a, b, c})
            if (glm::any(glm::greaterThan(glm::abs(v->normal - n), glm::vec3(1e-5f)))) return false;
        any = true;
    }
    return any;
}

}  // namespace penumbra::scene
