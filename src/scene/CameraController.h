#pragma once
// The three camera manipulators of OSG that Plachý 2012 §3.3-3.4 used: first-person fly,
// trackball and orbit. Pure math on scene::Camera; the window front-end feeds them input.
#include "scene/Camera.h"

namespace penumbra::scene {

struct ControllerInput {
    glm::vec3 move{0.0f};       // fly: right, up, forward in [-1,1]
    glm::vec2 dragPixels{0.0f}; // mouse drag this frame
    float scroll = 0.0f;
    float dt = 0.0f;
    glm::vec2 viewport{800, 600};
    bool fast = false;
};

class CameraController {
public:
    explicit CameraController(Camera& camera);
    void setMode(Camera::Controller mode);
    Camera::Controller mode() const { return camera_.controller; }
    void update(const ControllerInput& input);
    float speed = 3.0f;  // fly speed, world units per second

private:
    void fly(const ControllerInput& in);
    void orbit(const ControllerInput& in);
    void trackball(const ControllerInput& in);
    Camera& camera_;
};

}  // namespace penumbra::scene
