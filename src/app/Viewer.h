#pragma once
#include "render/Renderer.h"

#include <filesystem>
#include <string>

namespace penumbra::app {

struct ViewerOptions {
    std::filesystem::path scene;
    render::RenderOptions render;
    int width = 800, height = 600;
    std::string controller;  // "" = the scene's
    bool debugContext = false;
    int exitAfterFrames = 0;  // > 0: quit after that many frames (scripted runs, screenshots)
    std::filesystem::path screenshotDir = ".";
};

// Opens the window and runs until Esc / close. Returns the process exit code.
int runViewer(const ViewerOptions& options);

}  // namespace penumbra::app
