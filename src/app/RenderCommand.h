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
    bool tunedMalloc = true;  // app/MallocTuning.h
    // Soak runs (issue 12): every N frames the next technique of the registry (0: never), every
    // M frames the next output size and shadow-map resolution (0: never); a PNG every K frames.
    int cycleTechniquesEvery = 0;
    int cycleSizesEvery = 0;
    int pngEvery = 1;
    // Split view (issue 13): "TECHNIQUE[:name=value,...]" renders the columns right of the divider
    // with that technique and parameters, the left ones with `render`; "" = no split.
    std::string split;
    float splitAt = 0.5f;  // share of the width left of the divider
};

// One row of the soak record, taken at every technique or size change and at the end.
struct SoakSample {
    int frame = 0;
    std::string technique;
    int width = 0, height = 0, shadowResolution = 0;
    long rssKiB = 0;
    long heapKiB = 0;  // KiB in use from glibc's malloc (mallinfo2: the main arena and mmapped chunks)
    long mmappedKiB = 0;  // of heapKiB, the mmapped chunks: big blocks such as textures' storage under llvmpipe
    long glObjects = 0;
    std::size_t shadowMemoryBytes = 0;
    int glErrors = 0;
};

struct BatchResult {
    std::string device;
    int frames = 0;
    render::PassTimes mean;
    std::size_t shadowMemoryBytes = 0;
    std::vector<double> shadowTriangles;  // per light: mean triangles drawn into its shadow maps per frame
    std::filesystem::path statsFile;
    std::vector<SoakSample> soak;
};

// Creates its own EGL context. Throws InputError / ShaderError / std::runtime_error.
BatchResult renderBatch(const BatchJob& job);

}  // namespace penumbra::app
