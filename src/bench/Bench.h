#pragma once
// `penumbra bench`: frames rendered back to back the way the window draws them (no read-back,
// no file I/O, at most two frames in flight), GPU time per pass from a ring of timer queries
// collected a few frames late, wall-clock frame times, shadow-map memory and triangles drawn,
// per technique x shadow-map resolution x scene. Needs a current GL context.
#include "bench/Statistics.h"
#include "render/FrameTimer.h"
#include "render/Renderer.h"

#include <array>
#include <map>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace penumbra::bench {

// Pseudo-techniques measured beside the real ones: the floor (bench/FloorRenderer.h).
inline constexpr const char* kFloorDepth = "floor-depth";
inline constexpr const char* kFloorLambert = "floor-lambert";
inline constexpr const char* kFloorUnshadowed = "floor-unshadowed";
// All of them, in the order of FloorRenderer::Mode (DepthOnly, Lambert, Unshadowed).
inline constexpr std::array<const char*, 3> kFloors{kFloorDepth, kFloorLambert, kFloorUnshadowed};
// Whether `technique` names one of the floor's pseudo-techniques above.
bool isFloor(const std::string& technique);

struct BenchCase {
    std::string suite;                    // "" outside a named suite
    std::filesystem::path scene;
    std::string technique;                // a registry name or a floor (isFloor)
    int shadowResolution = 0;             // 0: each light's own
    shadows::ParameterValues parameters;  // on top of BenchSettings::render.parameters
    std::string label;                    // what tables call it; technique[, parameters] when empty
    bool redrawShadowMaps = false;        // every map every frame, whatever BenchSettings::render says
    int round = 0;                        // which pass over the case list (BenchJob::rounds), from 0
};

struct BenchSettings {
    int width = 1280, height = 720;
    int frames = 0;        // > 0: measure this many frames...
    double seconds = 2.0;  // ...else frames for this long (at least 3)
    double warmupSeconds = 1.0;  // at least this long, then until frame times settle (cap 3x)
    // Scene seconds per frame, from 0 at the first measured frame: every case sees the same motion.
    float sceneStep = 1.0f / 60.0f;
    bool calibrate = false;  // also check every pass's query against a glFinish wall clock
    bool images = true;      // one picture per case (read back after timing)
    bool fixedCamera = false;  // the scene's camera throughout (peer comparisons), no path or orbit
    // > 0: the cases of one scene and round are measured together, in turns of this many frames
    // each (the first two and the last of each turn not counted); 0: one case after the other.
    int interleaveFrames = 0;
    render::RenderOptions render;  // transparency, parameters common to every case
};

struct PassCalibration {
    double queryMs = 0, wallMs = 0;
    bool flagged = false;  // differ by over 10 % (and over 0.1 ms, the glFinish round trip)
};

struct CaseResult {
    BenchCase spec;
    std::string technique;  // resolved name (a scene's own when spec.technique is "")
    std::string sceneName;
    std::size_t sceneTriangles = 0;
    std::vector<int> resolutions;  // per shadowed light
    std::array<Summary, render::kPassCount> passMs;  // GPU query ms per pass
    Summary gpuFrameMs;                             // sum of the passes
    Summary frameMs;                                // wall clock between frame starts
    // The frame's calls on the thread that makes them: from its start until the engine's frame
    // returns (after the wait for the frame two before it). Above gpuFrameMs on a GPU, the frame is
    // the CPU's; on llvmpipe it also holds the vertex stage and binning, which run on that thread.
    Summary cpuFrameMs;
    double fpsMean = 0, fpsMin = 0, fpsMax = 0, fpsP95 = 0;  // fpsP95: 95 % of frames ran at least this fast
    std::size_t shadowMemoryBytes = 0;
    double shadowTrianglesPerFrame = 0;
    int warmupFrames = 0;
    double warmupSeconds = 0;
    bool settled = false;  // warm-up ended because frame times settled, not at its cap
    // Programs linked during the measured frames (gl::Program::linkedSoFar): each repeat of the
    // measurement follows one that linked some, and this counts those of the one kept (0 unless
    // every try linked one). Interleaved cases share one measurement: these are its, and so are
    // glErrors and glWarnings below.
    std::uint64_t programsLinkedMeasuring = 0;
    int measurementsRepeated = 0;
    int interleaveFrames = 0;  // BenchSettings::interleaveFrames it was measured with
    bool calibrated = false;
    double finishOverheadMs = 0;  // an empty glFinish round trip, subtracted from the wall times
    std::array<PassCalibration, render::kPassCount> calibration;
    // With calibration: each debug group's glFinish-bounded wall ms per frame, by path
    // ("shadow maps/moments/blur"; render/SubPassClock.h), from frames of their own.
    std::map<std::string, double> subPassMs;
    shadows::ParameterValues parameters;  // every parameter of the technique as it ran
    int glErrors = 0;
    int glWarnings = 0;  // driver warnings while the case ran (its frames paid for their callbacks)
    int width = 0, height = 0;
    std::vector<std::uint8_t> image;  // RGBA8, top row first (empty unless settings.images)
    // Every measured sample: wall frame ms, CPU frame ms (the same frames, in order), and GPU ms per pass.
    std::vector<double> frameSamples;
    std::vector<double> cpuSamples;
    std::array<std::vector<double>, render::kPassCount> passSamples;
};

// Called before each case and with the fraction of the current case done.
using Progress = std::function<void(std::size_t caseIndex, std::size_t caseCount, const BenchCase&, double fraction)>;

// Runs the cases in order, loading each scene once for consecutive cases that share it.
// Throws InputError (bad scene), std::invalid_argument (unknown technique or parameter).
std::vector<CaseResult> runBench(const std::vector<BenchCase>& cases, const BenchSettings& settings,
                                 const Progress& progress = {});

// The camera of frame `time`: the scene's camera_path when it has one, else one turn around the
// camera's target every 20 s, starting from the scene's own camera.
scene::Camera benchCamera(const scene::Scene& scene, float time);

}  // namespace penumbra::bench
