#include "scene/CameraController.h"

#include <algorithm>
#include <glm/gtc/constants.hpp>
#include <glm/gtx/rotate_vector.hpp>

namespace penumbra::scene {

CameraController::CameraController(Camera& camera) : camera_(camera) {
    speed = std::max(0.5f, glm::length(camera.target - camera.position) * 0.5f);
}

void CameraController::setMode(Camera::Controller mode) { camera_.controller = mode; }

void CameraController::update(const ControllerInput& in) {
    switch (camera_.controller) {
        case Camera::Controller::Fly: fly(in); break;
        case Camera::Controller::Orbit: orbit(in); break;
        case Camera::Controller::Trackball: trackball(in); break;
    }
}

// First person: mouse turns (yaw about world up, pitch clamped), WASD moves; the target moves along.
void CameraController::fly(const ControllerInput& in) {
    glm::vec3 forward = glm::normalize(camera_.target - camera_.position);
    const glm::vec3 up = glm::normalize(camera_.up);
    const float radPerPixel = 0.004f;
    forward = glm::rotate(forward, -in.dragPixels.x * radPerPixel, up);
    glm::vec3 right = glm::normalize(glm::cross(forward, up));
    const glm::vec3 pitched = glm::rotate(forward, -in.dragPixels.y * radPerPixel, right);
    if (std::abs(glm::dot(pitched, up)) < 0.98f) forward = pitched;
    right = glm::normalize(glm::cross(forward, up));
    const float step = speed * in.dt * (in.fast ? 4.0f : 1.0f);
    const glm::vec3 delta = (right * in.move.x + up * in.move.y + forward * in.move.z) * step;
    camera_.position += delta;
    camera_.target = camera_.position + forward;
}

// Orbit: drag rotates around the target keeping world up; scroll zooms.
void CameraController::orbit(const ControllerInput& in) {
    const glm::vec3 up = glm::normalize(camera_.up);
    glm::vec3 offset = camera_.position - camera_.target;
    float distance = glm::length(offset);
    offset = glm::rotate(offset, -in.dragPixels.x * 0.005f, up);
    const glm::vec3 right = glm::normalize(glm::cross(up, offset));
    const glm::vec3 pitched = glm::rotate(offset, in.dragPixels.y * 0.005f, right);
    if (std::abs(glm::dot(glm::normalize(pitched), up)) < 0.98f) offset = pitched;
    distance *= std::pow(0.9f, in.scroll);
    camera_.position = camera_.target + glm::normalize(offset) * std::max(distance, camera_.near * 2.0f);
    if (glm::length(in.move) > 0) {  // WASD pans the orbit centre
        const glm::vec3 fwd = glm::normalize(glm::vec3(-offset.x, 0.0f, -offset.z) + glm::vec3(1e-6f));
        const glm::vec3 side = glm::normalize(glm::cross(fwd, up));
        const glm::vec3 pan = (side * in.move.x + up * in.move.y + fwd * in.move.z) * speed * in.dt;
        camera_.position += pan;
        camera_.target += pan;
    }
}

// Trackball (Shoemake's arcball): drag rotates the view freely around the target, up included.
void CameraController::trackball(const ControllerInput& in) {
    if (glm::length(in.dragPixels) > 0.0f) {
        const glm::vec3 offset = camera_.position - camera_.target;
        const glm::vec3 forward = glm::normalize(-offset);
        const glm::vec3 right = glm::normalize(glm::cross(forward, camera_.up));
        const glm::vec3 trueUp = glm::cross(right, forward);
        // Screen drag direction as a world axis; rotate about its perpendicular in the view plane.
        const glm::vec3 dragWorld = right * in.dragPixels.x - trueUp * in.dragPixels.y;
        const glm::vec3 axis = glm::normalize(glm::cross(dragWorld, forward));
        const float angle = glm::length(in.dragPixels) / std::max(in.viewport.y, 1.0f) * glm::pi<float>();
        camera_.position = camera_.target + glm::rotate(offset, angle, axis);
        camera_.up = glm::rotate(trueUp, angle, axis);
    }
    const glm::vec3 offset = camera_.position - camera_.target;
    camera_.position = camera_.target + offset * std::pow(0.9f, in.scroll);
}

}  // namespace penumbra::scene
