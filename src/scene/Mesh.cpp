#include "scene/Mesh.h"

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

}  // namespace penumbra::scene
