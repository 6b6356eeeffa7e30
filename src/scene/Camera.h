#pragma once
#include <glm/glm.hpp>

namespace penumbra::scene {

struct Camera {
    enum class Controller { Fly, Trackball, Orbit };
    glm::vec3 position{0.0f, 2.0f, 6.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovDeg = 50.0f;  // vertical
    float near = 0.1f;
    float far = 100.0f;
    Controller controller = Controller::Fly;

    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
};

const char* toString(Camera::Controller c);

}  // namespace penumbra::scene
