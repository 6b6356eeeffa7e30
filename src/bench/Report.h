#pragma once
// What `penumbra bench` leaves in its output folder:
// - bench.json: every setting, the machine, every sample and its summaries;
// - bench.csv: one row per case;
// - report.html: one self-contained page (works offline) with the tables, Chart.js plots
//   (Debian's libjs-chart.js, copied into the page) and a labelled image grid;
// - images/<case>.png.
#include "bench/Bench.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace penumbra::bench {

// Where and how the numbers were taken.
struct BenchContext {
    std::string device;       // GL renderer | version
    std::string glVendor;
    std::string eglPlatform;
    std::string gitRevision;
    nlohmann::json malloc;    // the allocator settings in force (see PLATFORM.md "Timing on llvmpipe")
    std::string created;      // ISO 8601, UTC
    std::vector<std::string> commandLine;
};

// A technique's score against the ray-traced reference (`--quality`).
struct QualityRow {
    std::string technique;
    double rmse = 0, wrongShare = 0, colourError = 0, noise = 0;
    std::vector<std::uint8_t> image, heatMap;  // RGBA8, top row first
};
struct Quality {
    std::string sceneName;
    int width = 0, height = 0, samples = 0;
    double referenceSeconds = 0;
    std::vector<std::uint8_t> reference;
    std::vector<QualityRow> rows;
};

nlohmann::json benchJson(const std::vector<CaseResult>& results, const BenchSettings& settings, const BenchContext& context,
                         const nlohmann::json* baseline);

// Writes bench.json, bench.csv, report.html and images/ into `dir`. `baseline` (an earlier
// bench.json) adds ratios against it, matched by suite, scene, label and resolution.
// Returns a warning ("" if none), e.g. when the chart library is not installed.
std::string writeBenchReport(const std::filesystem::path& dir, const std::vector<CaseResult>& results,
                             const BenchSettings& settings, const BenchContext& context,
                             const std::optional<nlohmann::json>& baseline, const std::optional<Quality>& quality);

// The case's name in tables: its label, else technique (its own parameters, and resolution when set).
std::string caseLabel(const CaseResult& r);

// Shadow-pass time against the triangles drawn into the maps, for each suite and case label that
// ran on at least three scenes drawing different numbers of triangles: one least-squares line
// over its scenes (the speed issue asks for R² ≥ 0.98 from 10k to 1M triangles; see the
// triangle-scaling suite). Labels that draw no map (none) are left out.
struct ScalingFit {
    std::string suite, label;
    std::vector<double> triangles, shadowMs;  // per scene: triangles drawn per frame, shadow pass GPU median
    LineFit fit;                              // shadowMs against triangles
};
std::vector<ScalingFit> shadowPassScaling(const std::vector<CaseResult>& results);

// Each case against the floor run on the same scene at the same map size in the same round (the
// speed issue's "≤ 1.2× the bare program"): its wall-clock frame ÷ floor-unshadowed's when it
// draws no map (none), else ÷ floor-lambert's; its shadow pass ÷ floor-depth's. 0 where that
// floor case did not run. Floor cases themselves get no row. The floor draws the first light's map
// only: `lights` says how many the case drew.
// The shadow pass is the glFinish-bounded wall clock where both cases were calibrated (`bench
// --calibrate`), else the GPU queries' median: on llvmpipe floor-depth's query read 7-8 ms in some
// frames and 14-19 in others of one run (the 98k grid, 2048²), its wall clock 10.6-10.9 ms.
struct FloorRatio {
    std::string label, sceneName;
    std::string frameFloor;  // the floor case the frame is divided by ("" when none ran)
    double frame = 0, shadowPass = 0;
    std::size_t lights = 0;  // shadowed lights of the case
    int round = 0;
    bool shadowPassByWall = false;  // shadowPass from the calibration's wall clocks
};
std::vector<FloorRatio> floorRatios(const std::vector<CaseResult>& results);

// With the case list measured in several rounds in turn (`bench --rounds N`), each case of the
// first round against the first case of its scene (`base`), round by round: the median of its
// frames ÷ the base's in the same round, and the median of those ratios. A machine whose speed
// swings within seconds moves both cases of a round alike, so the ratios hold where single
// frame times do not. Empty with one round.
struct RoundRatio {
    std::string label, sceneName, base;
    std::vector<double> frameMs, ratios;  // per round: the frames' pairedMedian (wall clock), ÷ the base's
    double medianFrameMs = 0, medianRatio = 0;
    MedianInterval ratioInterval;  // of medianRatio, over the rounds (6 or more)
};
std::vector<RoundRatio> roundRatios(const std::vector<CaseResult>& results);

}  // namespace penumbra::bench
