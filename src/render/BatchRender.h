#pragma once
// Headless rendering of a frame sequence: PNG frames + stats.json with per-pass GPU times.
#include "render/Renderer.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace penumbra::render {

struct BatchJob {
    std::filesystem::path scene;  // scene file or bare model
    std::string technique;        // "" = the scene's choice, else "hard"
    int shadowResolution = 0;     // 0 = per light
    int width = 1280, height = 720;
    int frames = 1;
    float startTime = 0.0f;
    float fps = 30.0f;
    bool overlay = false;
    std::filesystem::path outDir = "out";
    std::string eglPlatform = "auto";
    std::vector<std::pair<std::string, float>> parameters;  // technique parameters
    std::string transparency = "sorted-objects";
    int peelLayers = 4;
};

struct BatchResult {
    std::string device;
    int frames = 0;
    PassTimes mean;
    std::size_t shadowMemoryBytes = 0;
    std::filesystem::path statsFile;
};

// Creates its own EGL context. Throws InputError / ShaderError / std::runtime_error.
BatchResult renderBatch(const BatchJob& job);

}  // namespace penumbra::render
