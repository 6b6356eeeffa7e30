#include "platform/GlfwWindow.h"

#include <GLFW/glfw3.h>
#include <cstdlib>
#include <stdexcept>

namespace penumbra::platform {

static std::string g_lastGlfwError;
static void onGlfwError(int code, const char* description) {
    g_lastGlfwError = std::string(description) + " (GLFW error " + std::to_string(code) + ")";
}

bool displayAvailable() {
    const char* x = std::getenv("DISPLAY");
    const char* w = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (w && *w);
}

GlfwWindow::GlfwWindow(int width, int height, const std::string& title, bool debug) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) throw std::runtime_error("cannot initialise GLFW: " + g_lastGlfwError);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string reason = g_lastGlfwError;
        glfwTerminate();
        throw std::runtime_error("cannot create an OpenGL 4.5 core window: " + reason);
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(0);
}

GlfwWindow::~GlfwWindow() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

bool GlfwWindow::shouldClose() const { return glfwWindowShouldClose(window_); }
void GlfwWindow::swapBuffers() { glfwSwapBuffers(window_); }

void GlfwWindow::framebufferSize(int& width, int& height) const {
    glfwGetFramebufferSize(window_, &width, &height);
}

void GlfwWindow::toggleFullscreen() {
    if (glfwGetWindowMonitor(window_)) {
        glfwSetWindowMonitor(window_, nullptr, windowedX_, windowedY_, windowedW_, windowedH_, 0);
        return;
    }
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    if (!monitor) return;
    glfwGetWindowPos(window_, &windowedX_, &windowedY_);
    glfwGetWindowSize(window_, &windowedW_, &windowedH_);
    const GLFWvidmode* mode = glfwGetVideoMode(monitor);
    glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}

}  // namespace penumbra::platform
