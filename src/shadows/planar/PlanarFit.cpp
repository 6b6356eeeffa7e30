#include "shadows/planar/PlanarFit.h"

#include <cmath>

namespace penumbra::shadows {

glm::mat4 planarShadowMatrix(const glm::vec4& plane, const glm::vec4& light) {
    const float dot = glm::dot(plane, light);
    glm::mat4 m(0.0f);
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) m[col][row] = (row == col ? dot : 0.0f) - light[row] * plane[col];
    return m;
}

glm::vec4 homogeneousLight(const scene::Light& light) {
    if (light.type == scene::Light::Type::Directional) return glm::vec4(-glm::normalize(light.direction), 0.0f);
    return glm::vec4(light.position, 1.0f);
}

static std::optional<ReceiverPlane> flatObject(const scene::Scene& scene, float time, std::size_t o) {
    const scene::Object& obj = scene.objects[o];
    const scene::Mesh& mesh = scene.meshes[static_cast<std::size_t>(obj.mesh)];
    const glm::mat4 model = obj.transformAt(time);
    ReceiverPlane r;
    r.object = static_cast<int>(o);
    glm::vec3 normal(0.0f), origin(0.0f);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        glm::vec3 p[3];
        for (int k = 0; k < 3; ++k) p[k] = glm::vec3(model * glm::vec4(mesh.vertices[mesh.indices[t + static_cast<std::size_t>(k)]].position, 1.0f));
        const glm::vec3 c = glm::cross(p[1] - p[0], p[2] - p[0]);
        r.area += 0.5f * glm::length(c);
        if (glm::length(c) > glm::length(normal)) {
            normal = c;
            origin = p[0];
        }
    }
    if (r.area <= 0.0f) return std::nullopt;
    normal = glm::normalize(normal);
    const float tolerance = 1e-4f * std::sqrt(r.area);
    for (const auto& v : mesh.vertices)
        if (std::abs(glm::dot(glm::vec3(model * glm::vec4(v.position, 1.0f)) - origin, normal)) > tolerance) return std::nullopt;
    r.plane = glm::vec4(normal, -glm::dot(normal, origin));
    return r;
}

std::optional<ReceiverPlane> findReceiverPlane(const scene::Scene& scene, float time, int object) {
    if (object >= 0)
        return static_cast<std::size_t>(object) < scene.objects.size() ? flatObject(scene, time, static_cast<std::size_t>(object))
                                                                        : std::nullopt;
    std::optional<ReceiverPlane> best;
    for (std::size_t o = 0; o < scene.objects.size(); ++o)
        if (auto r = flatObject(scene, time, o); r && (!best || r->area > best->area)) best = r;
    return best;
}

}  // namespace penumbra::shadows
