#include "app/BenchCommand.h"

#include "app/MallocTuning.h"
#include "bench/Report.h"
#include "bench/Suites.h"
#include "gl/Debug.h"
#include "platform/EglContext.h"
#include "reference/Comparison.h"
#include "scene/io/SceneFile.h"
#include "util/Log.h"

#include <GitRevision.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <set>
#include <unistd.h>

namespace penumbra::app {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string nowIso() {
    const std::time_t t = std::time(nullptr);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
    return text;
}

std::vector<bench::BenchCase> onePass(const BenchJob& job);

// The case list, once per round (BenchJob::rounds): every case of a round is measured before the
// next round starts, so that the rounds' ratios compare cases measured seconds apart.
std::vector<bench::BenchCase> plan(const BenchJob& job) {
    const std::vector<bench::BenchCase> once = onePass(job);
    std::vector<bench::BenchCase> cases;
    for (int round = 0; round < job.rounds; ++round)
        for (bench::BenchCase c : once) {
            c.round = round;
            cases.push_back(std::move(c));
        }
    return cases;
}

std::vector<bench::BenchCase> onePass(const BenchJob& job) {
    std::vector<bench::BenchCase> cases;
    for (const std::string& suite : job.suites)
        for (bench::BenchCase c : bench::suiteCases(suite, job.outDir / "scenes")) cases.push_back(std::move(c));
    if (!job.suites.empty() && job.scenes.empty() && job.gridScenes.empty() && job.techniques.empty()) return cases;

    std::vector<fs::path> scenes = job.scenes;
    for (std::size_t triangles : job.gridScenes)
        scenes.push_back(bench::writeGridScene(job.outDir / "scenes", "grid_" + std::to_string(triangles), triangles, false));
    if (scenes.empty()) scenes.push_back(scene::io::defaultScenePath());
    std::vector<std::string> techniques = job.techniques;
    if (techniques.size() == 1 && techniques.front() == "all") {
        techniques.clear();
        for (const auto& t : shadows::techniqueRegistry()) techniques.push_back(t.name);
    }
    if (techniques.empty()) techniques.push_back("");  // the scene's own
    std::vector<int> resolutions = job.shadowResolutions;
    if (resolutions.empty()) resolutions.push_back(0);
    for (const fs::path& scene : scenes)
        for (const std::string& spec : techniques) {
            auto [technique, parameters] = shadows::splitTechniqueParameters(spec);
            for (int res : resolutions) cases.push_back({"", scene, technique, res, parameters, ""});
        }
    return cases;
}

// "[#########.........]  3/12  hard 2048 @default  47%" on stderr, rewritten in place.
void drawProgress(std::size_t index, std::size_t count, const bench::BenchCase& c, double fraction) {
    constexpr int width = 24;
    const double total = (static_cast<double>(index) + fraction) / static_cast<double>(count);
    const int filled = static_cast<int>(total * width);
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.resize(width, '.');
    const std::string name = (c.label.empty() ? (c.technique.empty() ? "scene's technique" : c.technique) : c.label) +
                             (c.shadowResolution > 0 && c.label.empty() ? " " + std::to_string(c.shadowResolution) : "") + " @" +
                             c.scene.stem().string();
    std::fprintf(stderr, "\r[%s] %zu/%zu %-44.44s %3d%%", bar.c_str(), index + 1, count, name.c_str(), static_cast<int>(total * 100));
    if (index + 1 == count && fraction >= 1.0) std::fprintf(stderr, "\n");
    std::fflush(stderr);
}

std::optional<bench::Quality> measureQuality(const BenchJob& job, const std::vector<bench::CaseResult>& results) {
    if (!job.quality || results.empty()) return std::nullopt;
    const fs::path scenePath = results.front().spec.scene;
    scene::Scene scene = scene::io::loadScene(scenePath);
    if (scene.lights.empty()) return std::nullopt;
    const int w = job.settings.width, h = job.settings.height;
    reference::Comparison cmp(scene, w, h, 0.0f);
    cmp.setRenderOptions(job.settings.render);
    cmp.traceReference(job.samples, isatty(2));
    bench::Quality q;
    q.sceneName = results.front().sceneName;
    q.width = w;
    q.height = h;
    q.samples = job.samples;
    q.referenceSeconds = cmp.referenceSeconds();
    q.reference = cmp.shade(cmp.referenceVisibility());
    std::set<std::string> done;
    for (const auto& r : results) {
        if (r.spec.scene != scenePath || bench::isFloor(r.technique) ||
            !done.insert(r.technique).second)
            continue;
        const reference::TechniqueScore s = cmp.evaluate(r.technique, r.spec.shadowResolution, 0, r.spec.parameters);
        q.rows.push_back({r.technique, s.rmse, s.wrongShare, s.colourError, s.noise, cmp.shade(s.visibility), cmp.heatMap(s)});
    }
    return q;
}

void printTable(const std::vector<bench::CaseResult>& results) {
    if (!results.empty() && results.front().interleaveFrames > 0)
        std::printf("each scene's cases measured together, in turns of %d frames each (the first two and the last of a turn not counted)\n",
                    results.front().interleaveFrames);
    std::printf("%-30s %-14s %9s %9s %8s %8s %8s %8s %8s %9s %10s %12s\n", "case", "scene", "frame ms", "p95", "FPS", "CPU ms",
                "GPU ms", "shadow", "opaque", "transl.", "memory MiB", "shadow tris");
    for (const auto& r : results) {
        std::printf("%-30.30s %-14.14s %9.2f %9.2f %8.1f %8.2f %8.2f %8.2f %8.2f %9.2f %10.2f %12.0f\n", bench::caseLabel(r).c_str(),
                    r.sceneName.c_str(), r.frameMs.mean, r.frameMs.p95, r.fpsMean, r.cpuFrameMs.median, r.gpuFrameMs.median, r.passMs[0].median,
                    r.passMs[1].median, r.passMs[2].median, static_cast<double>(r.shadowMemoryBytes) / 1048576.0,
                    r.shadowTrianglesPerFrame);
        if (r.measurementsRepeated > 0)
            std::printf("    measured %d times: %s\n", r.measurementsRepeated + 1,
                        r.programsLinkedMeasuring == 0
                            ? "the earlier tries compiled shaders the camera's path needed first, the last one none"
                            : ("every try compiled shaders; the last one " + std::to_string(r.programsLinkedMeasuring) +
                               " program(s), whose compile its times include")
                                  .c_str());
        if (r.glErrors > 0 || r.glWarnings > 0)
            std::printf("    GL errors %d, driver warnings %d while it ran: its times include the driver's checks and their logging\n", r.glErrors,
                        r.glWarnings);
        if (r.calibrated)
            for (int p = 0; p < render::kPassCount; ++p) {
                const auto& cal = r.calibration[static_cast<std::size_t>(p)];
                std::printf("    calibration %-12s query %8.2f ms  glFinish wall %8.2f ms%s\n", render::toString(static_cast<render::Pass>(p)),
                            cal.queryMs, cal.wallMs, cal.flagged ? "  <-- differ by over 10 %" : "");
            }
        for (const auto& [path, ms] : r.subPassMs) std::printf("    sub-pass %-56s glFinish wall %8.2f ms\n", path.c_str(), ms);
    }
}

// One line per case label that ran on three or more scenes: shadow pass = a + b · triangles.
void printScaling(const std::vector<bench::CaseResult>& results) {
    const auto fits = bench::shadowPassScaling(results);
    if (fits.empty()) return;
    std::printf("shadow pass against triangles drawn into the maps (least squares over the scenes):\n");
    for (const auto& f : fits)
        std::printf("  %-30.30s %8.2f ms + %8.2f ms per million triangles   R² %.4f   (%zu scenes, %.0f-%.0f triangles)\n",
                    f.label.c_str(), f.fit.intercept, f.fit.slope * 1e6, f.fit.r2, f.fit.count,
                    *std::min_element(f.triangles.begin(), f.triangles.end()), *std::max_element(f.triangles.begin(), f.triangles.end()));
}

// Each case against the floor of its scene, where the floor ran beside it.
void printFloorRatios(const std::vector<bench::CaseResult>& results) {
    const auto ratios = bench::floorRatios(results);
    if (ratios.empty()) return;
    std::printf("against the floor (same scene, map size and round; frame: wall-clock means; shadow pass: glFinish wall "
                "clocks with --calibrate, else GPU medians, which llvmpipe can misplace):\n");
    for (const auto& q : ratios) {
        std::printf("  %-30.30s @%-14.14s", q.label.c_str(), q.sceneName.c_str());
        if (q.round > 0) std::printf(" round %d", q.round + 1);
        if (!q.frameFloor.empty()) std::printf("  frame %6.2fx %s", q.frame, q.frameFloor.c_str());
        if (q.shadowPass > 0)
            std::printf("  shadow pass %6.2fx %s by %s (%zu shadowed light%s; the floor draws 1)", q.shadowPass, bench::kFloorDepth,
                        q.shadowPassByWall ? "wall" : "query", q.lights, q.lights == 1 ? "" : "s");
        std::printf("\n");
    }
}

// With --rounds: each case's frame against its scene's first case, round by round, and medians.
void printRoundRatios(const std::vector<bench::CaseResult>& results) {
    const auto rows = bench::roundRatios(results);
    if (rows.empty()) return;
    std::printf("in rounds (frame ms of each case, the median over its consecutive frame pairs, ÷ its scene's first case's in the "
                "same round; median over the rounds; with 6 rounds or more, where the median lies with at least 95 %% "
                "confidence, from the rounds' order statistics):\n");
    for (const auto& q : rows) {
        std::printf("  %-30.30s @%-14.14s %8.2f ms  %6.3fx %s  [", q.label.c_str(), q.sceneName.c_str(), q.medianFrameMs, q.medianRatio,
                    q.base.c_str());
        for (std::size_t k = 0; k < q.ratios.size(); ++k) std::printf("%s%.3f", k ? " " : "", q.ratios[k]);
        std::printf("]");
        if (q.ratioInterval.found && (q.ratioInterval.low != 1.0 || q.ratioInterval.high != 1.0))  // not the base itself
            std::printf("  median within %.3f-%.3f (%.1f %%)", q.ratioInterval.low, q.ratioInterval.high, 100.0 * q.ratioInterval.coverage);
        std::printf("\n");
    }
}

}  // namespace

int runBench(const BenchJob& job) {
    const json mallocSettings = configureMalloc(job.tunedMalloc);
    std::optional<json> baseline;
    if (!job.baseline.empty()) {
        std::ifstream in(job.baseline);
        if (!in) throw std::runtime_error(job.baseline.string() + ": cannot read the baseline");
        try {
            baseline = json::parse(in);
        } catch (const json::exception& e) {
            throw std::runtime_error(job.baseline.string() + ": not a bench.json: " + e.what());
        }
        if (!baseline->contains("cases")) throw std::runtime_error(job.baseline.string() + ": not a bench.json (no 'cases')");
    }
    const std::vector<bench::BenchCase> cases = plan(job);
    for (const auto& c : cases)
        if (!fs::exists(c.scene)) throw std::runtime_error(c.scene.string() + ": no such scene or model file");

    auto context = platform::EglContext::create(job.eglPlatform);
    gl::enableDebugOutput();
    bench::BenchContext info;
    info.device = platform::glDeviceDescription();
    info.glVendor = reinterpret_cast<const char*>(glGetString(GL_VENDOR));
    info.eglPlatform = context->platformName();
    info.gitRevision = PENUMBRA_GIT_REVISION;
    info.malloc = mallocSettings;
    info.created = nowIso();
    info.commandLine = job.commandLine;

    std::printf("penumbra bench: %zu case(s) at %dx%d on %s\n", cases.size(), job.settings.width, job.settings.height, info.device.c_str());
    std::fflush(stdout);
    const bool terminal = isatty(2);
    const auto results = bench::runBench(cases, job.settings, terminal ? bench::Progress(drawProgress) : bench::Progress());
    const auto quality = measureQuality(job, results);
    const std::string warning = bench::writeBenchReport(job.outDir, results, job.settings, info, baseline, quality);
    if (!warning.empty()) log::warn("{}", warning);
    printTable(results);
    printScaling(results);
    printFloorRatios(results);
    printRoundRatios(results);
    std::printf("wrote %s/bench.json, bench.csv and report.html\n", job.outDir.string().c_str());
    return 0;
}

}  // namespace penumbra::app
