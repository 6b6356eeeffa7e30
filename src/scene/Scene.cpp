#include "scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::scene {

glm::mat4 Object::transformAt(float time) const {
    const glm::vec3 pos = animation.position.empty() ? position : position + animation.position.sample(time);
    const glm::vec3 rot = animation.rotationDeg.empty() ? rotationDeg : rotationDeg + animation.rotationDeg.sample(time);
    glm::mat4 m = glm::translate(glm::mat4(1.0f), pos);
    // Euler angles in degrees, applied to the model in X, Y, Z order (R = Rz * Ry * Rx).
    m = glm::rotate(m, glm::radians(rot.z), {0, 0, 1});
    m = glm::rotate(m, glm::radians(rot.y), {0, 1, 0});
    m = glm::rotate(m, glm::radians(rot.x), {1, 0, 0});
    return glm::scale(m, scale);
}

const Material& Scene::material(const Object& object, const MeshPart& part) const {
    return materials[static_cast<std::size_t>(object.materialOverride >= 0 ? object.materialOverride : part.material)];
}

Bounds Scene::boundsAt(float time) const {
    Bounds b;
    for (const auto& o : objects) b.add(meshes[static_cast<std::size_t>(o.mesh)].bounds.transformed(o.transformAt(time)));
    return b;
}

std::size_t Scene::triangleCount() const {
    std::size_t n = 0;
    for (const auto& o : objects) n += meshes[static_cast<std::size_t>(o.mesh)].triangleCount();
    return n;
}

bool Scene::animated() const {
    for (const auto& o : objects)
        if (!o.animation.empty()) return true;
    return false;
}

Camera Scene::cameraAt(float time) const {
    Camera c = camera;
    if (!cameraPath.position.empty()) c.position = cameraPath.position.sample(time);
    if (!cameraPath.target.empty()) c.target = cameraPath.target.sample(time);
    if (glm::length(c.position - c.target) <= 1e-6f) c.target = c.position + (camera.target - camera.position);
    return c;
}

}  // namespace penumbra::scene
