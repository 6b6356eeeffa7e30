#include "scene/Mesh.h"

#include <cstring>
#include <unordered_map>

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

bool Mesh::partIsClosed(std::size_t part) const {
    if (part >= parts.size()) return false;
    const MeshPart& p = parts[part];
    if (p.indexCount < 12 || p.firstIndex + static_cast<std::size_t>(p.indexCount) > indices.size()) return false;
    // Welded ids: one per distinct position (a box's faces, a sphere's seam and poles repeat them).
    struct PositionHash {
        std::size_t operator()(const glm::vec3& v) const {
            const glm::vec3 w = v + glm::vec3(0.0f);  // -0 + 0 = +0: equal positions, equal bits
            std::uint32_t bits[3];
            std::memcpy(bits, &w, sizeof bits);
            return (static_cast<std::size_t>(bits[0]) * 73856093u) ^ (static_cast<std::size_t>(bits[1]) * 19349663u) ^
                   (static_cast<std::size_t>(bits[2]) * 83492791u);
        }
    };
    std::unordered_map<glm::vec3, std::uint32_t, PositionHash> welded;
    std::unordered_map<std::uint64_t, int> edges;  // directed edge (from << 32 | to) -> times run
    double volume = 0.0;
    for (std::uint32_t t = 0; t + 2 < p.indexCount; t += 3) {
        std::uint32_t id[3];
        glm::dvec3 q[3];
        for (int k = 0; k < 3; ++k) {
            const glm::vec3& v = vertices.at(indices[p.firstIndex + t + static_cast<std::uint32_t>(k)]).position;
            id[k] = welded.try_emplace(v, static_cast<std::uint32_t>(welded.size())).first->second;
            q[k] = glm::dvec3(v);
        }
        if (id[0] == id[1] || id[1] == id[2] || id[2] == id[0]) continue;
        for (int k = 0; k < 3; ++k) ++edges[static_cast<std::uint64_t>(id[k]) << 32 | id[(k + 1) % 3]];
        volume += glm::dot(q[0], glm::cross(q[1], q[2])) / 6.0;
    }
    for (const auto& [edge, count] : edges) {
        const auto reverse = edges.find(edge << 32 | edge >> 32);
        if (count != 1 || reverse == edges.end() || reverse->second != 1) return false;
    }
    return !edges.empty() && volume > 0.0;
}

}  // namespace penumbra::scene
