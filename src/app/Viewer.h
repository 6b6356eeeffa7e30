#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace penumbra::app {

struct ViewerOptions {
    std::filesystem::path scene;
    std::string technique;
    int shadowResolution = 0;
    int width = 800, height = 600;
    std::string controller;  // "" = the scene's
    bool debugContext = false;
    int exitAfterFrames = 0;  // > 0: quit after that many frames (scripted runs, screenshots)
    std::filesystem::path screenshotDir = ".";
    std::vector<std::pair<std::string, float>> parameters;
    std::string transparency = "sorted-objects";
};

// Opens the window and runs until Esc / close. Returns the process exit code.
int runViewer(const ViewerOptions& options);

}  // namespace penumbra::app
