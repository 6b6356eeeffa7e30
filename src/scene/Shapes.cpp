#include "scene/Shapes.h"

#include <glm/gtc/constants.hpp>

namespace penumbra::scene::shapes {

static Mesh finish(Mesh m, const char* name) {
    m.name = name;
    m.parts.push_back({0, static_cast<std::uint32_t>(m.indices.size()), 0});
    m.computeBounds();
    return m;
}

// One quad: corner + u + v spans it; normal = normalize(cross(u, v)); UVs scale with size.
static void addQuad(Mesh& m, glm::vec3 corner, glm::vec3 u, glm::vec3 v) {
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    const glm::vec3 n = glm::normalize(glm::cross(u, v));
    const float lu = glm::length(u), lv = glm::length(v);
    m.vertices.push_back({corner, n, {0, 0}});
    m.vertices.push_back({corner + u, n, {lu, 0}});
    m.vertices.push_back({corner + u + v, n, {lu, lv}});
    m.vertices.push_back({corner + v, n, {0, lv}});
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

Mesh plane(float sx, float sz) {
    Mesh m;
    // u = +Z, v = +X so that cross(u, v) = +Y.
    addQuad(m, {-sx / 2, 0, -sz / 2}, {0, 0, sz}, {sx, 0, 0});
    return finish(std::move(m), "plane");
}

Mesh box(const glm::vec3& s) {
    Mesh m;
    const glm::vec3 h = s * 0.5f;
    const glm::vec3 X{s.x, 0, 0}, Y{0, s.y, 0}, Z{0, 0, s.z};
    addQuad(m, {h.x, -h.y, -h.z}, Y, Z);      // +X
    addQuad(m, {-h.x, -h.y, -h.z}, Z, Y);     // -X
    addQuad(m, {-h.x, h.y, -h.z}, Z, X);      // +Y
    addQuad(m, {-h.x, -h.y, -h.z}, X, Z);     // -Y
    addQuad(m, {-h.x, -h.y, h.z}, X, Y);      // +Z
    addQuad(m, {-h.x, -h.y, -h.z}, Y, X);     // -Z
    return finish(std::move(m), "box");
}

Mesh sphere(float r, int slices, int stacks) {
    Mesh m;
    for (int i = 0; i <= stacks; ++i) {
        const float v = float(i) / stacks, phi = v * glm::pi<float>();
        for (int j = 0; j <= slices; ++j) {
            const float u = float(j) / slices, theta = j == slices ? 0.0f : u * glm::two_pi<float>();
            // The seam and the poles repeat their positions exactly (sin(2 pi) and sin(pi) are not 0
            // in floats), so that the surface is closed (Mesh::partIsClosed).
            const float ring = i == 0 || i == stacks ? 0.0f : std::sin(phi), height = i == 0 ? 1.0f : i == stacks ? -1.0f : std::cos(phi);
            const glm::vec3 n{ring * std::cos(theta), height, -ring * std::sin(theta)};
            m.vertices.push_back({n * r, n, {u, v}});
        }
    }
    const int row = slices + 1;
    for (int i = 0; i < stacks; ++i)
        for (int j = 0; j < slices; ++j) {
            const std::uint32_t a = i * row + j, b = a + row;
            // Counter-clockwise seen from outside.
            for (std::uint32_t k : {a, b, a + 1, a + 1, b, b + 1}) m.indices.push_back(k);
        }
    return finish(std::move(m), "sphere");
}

}  // namespace penumbra::scene::shapes
