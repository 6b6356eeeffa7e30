#pragma once
// `penumbra bench`: parses nothing itself (main.cpp does); runs the cases in a headless EGL
// context with a progress bar on a terminal and writes the report (bench/Report.h).
#include "bench/Bench.h"

#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::app {

struct BenchJob {
    std::vector<std::filesystem::path> scenes;  // empty: the built-in scene (unless a suite is given)
    // Empty: the scene's own; {"all"}: every registered one. Each may carry parameters of its own,
    // "vsm:blur_kernel=box:mipmaps=false", so that variants of one technique are measured side by side.
    std::vector<std::string> techniques;
    std::vector<int> shadowResolutions;         // empty: each light's own
    std::vector<std::string> suites;
    std::vector<std::size_t> gridScenes;  // generated grid scenes of about these many triangles
    int rounds = 1;  // the case list measured this many times in turn (bench::roundRatios)
    bench::BenchSettings settings;
    std::filesystem::path outDir = "bench-out";
    std::filesystem::path baseline;
    bool quality = false;  // score each technique against the ray-traced reference too
    int samples = 16;      // reference samples per pixel with --quality
    bool tunedMalloc = true;
    std::string eglPlatform = "auto";
    std::vector<std::string> commandLine;
};

int runBench(const BenchJob& job);

}  // namespace penumbra::app
