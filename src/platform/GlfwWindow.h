#pragma once
// A GLFW window with a 4.5 core context (GLX under X11/Xvfb).
#include <string>

struct GLFWwindow;

namespace penumbra::platform {

class GlfwWindow {
public:
    // Throws std::runtime_error when there is no display or no 4.5 core context.
    GlfwWindow(int width, int height, const std::string& title, bool debug);
    ~GlfwWindow();
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool shouldClose() const;
    void swapBuffers();
    void toggleFullscreen();
    // Framebuffer size in pixels; 0x0 while minimised.
    void framebufferSize(int& width, int& height) const;

private:
    GLFWwindow* window_ = nullptr;
    int windowedX_ = 0, windowedY_ = 0, windowedW_ = 0, windowedH_ = 0;
};

// True when GLFW can reach a display (X11 DISPLAY or Wayland), checked without opening one.
bool displayAvailable();

}  // namespace penumbra::platform
