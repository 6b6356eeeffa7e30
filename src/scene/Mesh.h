#pragma once
#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::scene {

struct Bounds {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};
    bool empty() const { return min.x > max.x; }
    void add(const glm::vec3& p) { min = glm::min(min, p); max = glm::max(max, p); }
    void add(const Bounds& b) { if (!b.empty()) { add(b.min); add(b.max); } }
    glm::vec3 center() const { return (min + max) * 0.5f; }
    glm::vec3 extent() const { return max - min; }
    // Corner i of 8: bit 0 picks max.x, bit 1 max.y, bit 2 max.z (frustumCorners' order).
    glm::vec3 corner(int i) const { return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z}; }
    std::array<glm::vec3, 8> corners() const {
        std::array<glm::vec3, 8> c{};
        for (int i = 0; i < 8; ++i) c[static_cast<std::size_t>(i)] = corner(i);
        return c;
    }
    Bounds transformed(const glm::mat4& m) const;
};

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec2 uv;
};

// Triangles sharing one material.
struct MeshPart {
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    int material = 0;  // index into Scene::materials
};

struct Mesh {
    std::string name;
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<MeshPart> parts;
    Bounds bounds;

    std::size_t triangleCount() const { return indices.size() / 3; }
    void computeBounds();
    // Per part, whether its triangles bound a solid: vertices welded by position, every edge
    // shared by exactly two triangles that run it in opposite directions, wound counter-clockwise
    // seen from outside (positive volume). Degenerate triangles are left out. Sorts, no hashing:
    // O(n log n) in vertices and triangles, once for all parts.
    std::vector<bool> closedParts() const;
    bool partIsClosed(std::size_t part) const;  // closedParts()[part]: for one look
    // Per vertex, an id shared by every vertex at the same position, bit for bit (-0 as +0), ids
    // numbered from 0 without gaps: the weld that sees through the normal and uv seams that split
    // a mesh's vertices, for closedParts and for the shadow volumes' adjacency alike. No tolerance:
    // GL draws a crack between positions one ulp apart, and a tolerance also welds distinct
    // vertices (on scenes/park.json a grid of a millionth of the mesh gave the trash can 31 edges
    // shared by three triangles in a part the exact weld finds closed).
    std::vector<std::uint32_t> weldedPositionIds() const;
    // Whether a part's every vertex lies on or behind the plane of each of its triangles (their
    // counter-clockwise side is the front), to 1e-4 of the part's size: a flat part, or the
    // surface of a convex solid when the part is also closed. A ray then crosses at most two of
    // its surfaces. Parts of more than `mostTriangles` triangles are not checked (false):
    // O(triangles x vertices).
    bool partIsConvex(std::size_t part, std::size_t mostTriangles = 4096) const;
    bool partIsFlat(std::size_t part) const;  // every vertex of the part on the plane of its first proper triangle
    // That plane (unit normal, offset) of a flat part; none for a part that is not flat.
    std::optional<glm::vec4> partPlane(std::size_t part) const;
    // Whether every vertex normal of the part is its triangle's own normal (within 1e-5 in each
    // component; degenerate triangles left out): flat shading, so a point's N.L has its face's
    // sign. Smooth normals (a sphere's) can light a facet turned from the light.
    bool partHasFaceNormals(std::size_t part) const;
};

}  // namespace penumbra::scene
