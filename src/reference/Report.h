#pragma once
// `penumbra reference` and `penumbra compare`: run a Comparison headless and write its files.
#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::reference {

struct ReportJob {
    std::filesystem::path scene;
    int width = 1280, height = 720;
    float time = 0.0f;
    int samples = 64;  // per pixel, for area lights
    std::filesystem::path outDir;
    std::string eglPlatform = "auto";
    // compare only:
    std::vector<std::string> techniques;
    int shadowResolution = 0;
    int timedFrames = 3;
    std::vector<std::pair<std::string, float>> parameters;  // applied to every technique that has them
};

// Writes reference.png, visibility_<i>.png per light and reference.json. Returns exit code.
int runReference(const ReportJob& job);
// Writes reference.png, <technique>.png, <technique>_heat.png, side_by_side.png and
// compare.json, and prints the table. Returns exit code.
int runCompare(const ReportJob& job);

}  // namespace penumbra::reference
