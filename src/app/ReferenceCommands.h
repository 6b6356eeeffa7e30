#pragma once
// `penumbra reference` and `penumbra compare`: run a Comparison headless and write its files.
#include "render/Renderer.h"

#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::app {

struct ReportJob {
    std::filesystem::path scene;
    int width = 1280, height = 720;
    float time = 0.0f;
    int samples = 64;  // per pixel, for area lights
    std::filesystem::path outDir;
    std::string eglPlatform = "auto";
    // compare only: the techniques, and the options they all share (shadow resolution, and
    // parameters applied to every technique that has them).
    std::vector<std::string> techniques;
    render::RenderOptions render;
    int timedFrames = 3;
    int motionFrames = 0;                // > 1: also score a slow pan (Comparison::evaluateMotion)
    float motionPixelsPerFrame = 0.5f;
    bool translucentReceivers = false;  // score the nearest surface, translucent ones too (reference::Surfaces)
    bool behindGlass = false;           // score the surface seen through the nearest translucent one
};

// Writes reference.png, visibility_<i>.png per light and reference.json. Returns exit code.
int runReference(const ReportJob& job);
// Writes reference.png, <technique>.png, <technique>_heat.png, side_by_side.png and
// compare.json, and prints the table. Returns exit code.
int runCompare(const ReportJob& job);

}  // namespace penumbra::app
