#pragma once
// `penumbra render`: a frame sequence rendered headless (EGL) into PNG frames + stats.json with
// per-pass GPU times.
#include "render/Renderer.h"

#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::app {

struct BatchJob {
    std::filesystem::path scene;  // scene file or bare model
    render::RenderOptions render;
    int width = 1280, height = 720;
    int frames = 1;
    float startTime = 0.0f;
    float fps = 30.0f;
    std::filesystem::path outDir = "out";
    std::string eglPlatform = "auto";
};

struct BatchResult {
    std::string device;
    int frames = 0;
    render::PassTimes mean;
    std::size_t shadowMemoryBytes = 0;
    std::vector<double> shadowTriangles;  // per light: mean triangles drawn into its shadow maps per frame
    std::filesystem::path statsFile;
};

// Creates its own EGL context. Throws InputError / ShaderError / std::runtime_error.
BatchResult renderBatch(const BatchJob& job);

}  // namespace penumbra::app
