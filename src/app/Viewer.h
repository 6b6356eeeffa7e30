#pragma once
#include "render/Renderer.h"

#include <filesystem>
#include <vector>
#include <string>

namespace penumbra::app {

struct ViewerOptions {
    std::filesystem::path scene;
    render::RenderOptions render;
    int width = 800, height = 600;
    std::string controller;  // "" = the scene's
    bool debugContext = false;
    bool tunedMalloc = true;  // app/MallocTuning.h
    int exitAfterFrames = 0;  // > 0: quit after that many frames (scripted runs, screenshots)
    // Robustness drill (issue 12): every frame the next of minimise, restore, 1x1, 8192x8192,
    // 800x600 and a switch to the next technique (exitAfterFrames counts drawn frames only).
    bool resizeStorm = false;
    std::filesystem::path screenshotDir = ".";
    // Split view: "TECHNIQUE[:name=value,...]" for the right side at start ("" = off; `v` toggles).
    std::string split;
    // Start in reference mode (as if r were pressed on the first frame), with the heat map (g)
    // when `heatMap`; --exit-after then counts its last frame only once the reference is ready.
    bool referenceMode = false, heatMap = false;
    // Scripted drops: these files arrive on the first frame as if dropped on the window.
    std::vector<std::filesystem::path> drop;
    // Scripted choice: this technique is chosen in the panel on the first frame ("" = none).
    std::string choose;
};

// Opens the window and runs until Esc / close. Returns the process exit code.
int runViewer(const ViewerOptions& options);

}  // namespace penumbra::app
