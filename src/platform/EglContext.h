#pragma once
// Headless OpenGL 4.5 core through EGL: Mesa's surfaceless platform, or the device platform
// (EGL_EXT_platform_device) that NVIDIA's driver offers. Rendering goes to FBOs.
#include <memory>
#include <string>

namespace penumbra::platform {

class EglContext {
public:
    // `platform`: "auto" (surfaceless, then device), "surfaceless" or "device".
    // Throws std::runtime_error with the reason when no 4.5 core context can be created.
    static std::unique_ptr<EglContext> create(const std::string& platform = "auto", bool debug = false);
    ~EglContext();
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    const std::string& platformName() const { return platform_; }

private:
    EglContext() = default;
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string platform_;
};

// "llvmpipe (LLVM 15.0.6, 256 bits) | 4.5 (Core Profile) Mesa 22.3.6": for stats and reports.
std::string glDeviceDescription();

}  // namespace penumbra::platform
