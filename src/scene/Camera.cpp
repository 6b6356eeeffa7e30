#include "scene/Camera.h"
#include "scene/Light.h"

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::scene {

glm::mat4 Camera::view() const { return glm::lookAt(position, target, up); }

glm::mat4 Camera::projection(float aspect) const {
    return glm::perspective(glm::radians(fovDeg), aspect, near, far);
}

const char* toString(Camera::Controller c) {
    switch (c) {
        case Camera::Controller::Fly: return "fly";
        case Camera::Controller::Trackball: return "trackball";
        case Camera::Controller::Orbit: return "orbit";
    }
    return "?";
}

const char* toString(Light::Type t) {
    switch (t) {
        case Light::Type::Directional: return "directional";
        case Light::Type::Spot: return "spot";
        case Light::Type::Point: return "point";
        case Light::Type::Projector: return "projector";
    }
    return "?";
}

}  // namespace penumbra::scene
