#include "bench/Bench.h"

#include "bench/FloorRenderer.h"
#include "gl/Debug.h"
#include "gl/Program.h"
#include "render/Offscreen.h"
#include "render/SubPassClock.h"
#include "scene/io/SceneFile.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <memory>
#include <optional>

namespace penumbra::bench {

using Clock = std::chrono::steady_clock;

scene::Camera benchCamera(const scene::Scene& scene, float time) {
    if (!scene.cameraPath.empty()) return scene.cameraAt(time);
    scene::Camera c = scene.camera;
    const glm::vec3 offset = c.position - c.target;
    const float angle = glm::two_pi<float>() * time / 20.0f;
    const float cs = std::cos(angle), sn = std::sin(angle);
    c.position = c.target + glm::vec3(cs * offset.x + sn * offset.z, offset.y, -sn * offset.x + cs * offset.z);
    return c;
}

namespace {

// What the loop drives: the real renderer, or the floor.
class Engine {
public:
    virtual ~Engine() = default;
    virtual void frame(float time, const scene::Camera& camera, int width, int height) = 0;
    virtual render::FrameTimer& timer() = 0;
    virtual std::size_t memoryBytes() const = 0;
    virtual std::size_t shadowTriangles() const = 0;
    virtual GLuint framebuffer() const = 0;
    virtual std::string technique() const = 0;
    virtual shadows::ParameterValues parameters() = 0;
};

class RendererEngine final : public Engine {
public:
    RendererEngine(scene::Scene& scene, const render::RenderOptions& options, int width, int height)
        : renderer_(scene, options), target_(width, height) {}
    void frame(float time, const scene::Camera& camera, int width, int height) override {
        renderer_.render(time, camera, width, height, target_.framebuffer());
    }
    render::FrameTimer& timer() override { return renderer_.frameTimer(); }
    std::size_t memoryBytes() const override { return renderer_.shadowMemoryBytes(); }
    std::size_t shadowTriangles() const override {
        std::size_t n = 0;
        for (std::size_t t : renderer_.shadowTriangles()) n += t;
        return n;
    }
    GLuint framebuffer() const override { return target_.framebuffer(); }
    std::string technique() const override { return renderer_.technique().name(); }
    shadows::ParameterValues parameters() override {
        shadows::ParameterValues out;
        for (const auto& p : renderer_.technique().parameters()) out.emplace_back(p.name, p.text());
        return out;
    }

private:
    render::Renderer renderer_;
    render::OffscreenTarget target_;
};

class FloorEngine final : public Engine {
public:
    FloorEngine(const scene::Scene& scene, FloorRenderer::Mode mode, int resolution, std::string name)
        : floor_(scene, mode, resolution), name_(std::move(name)), resolution_(resolution) {}
    void frame(float time, const scene::Camera& camera, int width, int height) override { floor_.render(time, camera, width, height); }
    render::FrameTimer& timer() override { return floor_.timer(); }
    std::size_t memoryBytes() const override { return floor_.shadowMemoryBytes(); }
    std::size_t shadowTriangles() const override { return floor_.trianglesPerFrame(); }
    GLuint framebuffer() const override { return floor_.framebuffer(); }
    std::string technique() const override { return name_; }
    shadows::ParameterValues parameters() override { return {{"resolution", std::to_string(resolution_)}}; }

private:
    FloorRenderer floor_;
    std::string name_;
    int resolution_;
};

// At most two frames in flight, like a double-buffered swap chain: frame i waits for frame i-2.
class FramePacer {
public:
    ~FramePacer() {
        for (GLsync& f : fences_)
            if (f) glDeleteSync(f);
    }
    void wait() {
        GLsync& f = fences_[next_];
        if (!f) return;
        glClientWaitSync(f, GL_SYNC_FLUSH_COMMANDS_BIT, GLuint64(60) * 1000000000ull);
        glDeleteSync(f);
        f = nullptr;
    }
    void submitted() {
        fences_[next_] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
        next_ = (next_ + 1) % fences_.size();
    }

private:
    std::array<GLsync, 2> fences_{};
    std::size_t next_ = 0;
};

double millisecondsBetween(Clock::time_point from, Clock::time_point to) { return std::chrono::duration<double, std::milli>(to - from).count(); }
double millisecondsSince(Clock::time_point t) { return millisecondsBetween(t, Clock::now()); }

}  // namespace

bool isFloor(const std::string& technique) { return std::find(kFloors.begin(), kFloors.end(), technique) != kFloors.end(); }

namespace {

std::unique_ptr<Engine> makeEngine(scene::Scene& scene, const BenchCase& c, const BenchSettings& settings) {
    if (isFloor(c.technique)) {
        const int res = c.shadowResolution > 0 ? c.shadowResolution : (scene.lights.empty() ? 2048 : scene.lights.front().shadow.resolution);
        const auto mode = static_cast<FloorRenderer::Mode>(std::find(kFloors.begin(), kFloors.end(), c.technique) - kFloors.begin());
        return std::make_unique<FloorEngine>(scene, mode, res, c.technique);
    }
    render::RenderOptions options = settings.render;
    options.technique = c.technique;
    options.shadowResolution = c.shadowResolution;
    options.strictParameters = true;
    if (c.redrawShadowMaps) options.reuseStillCasters = false;
    for (const auto& p : c.parameters) options.parameters.push_back(p);
    return std::make_unique<RendererEngine>(scene, options, settings.width, settings.height);
}

// One case's engine, with its own frame counters: the renderer's frame index (timer queries),
// warm-up included, and the scene frame, from 0 again when the measurement starts, so that every
// case measures the same frames of the animation whatever its warm-up took (until stop 55 each case
// went on from its warm-up's last frame: a faster case measured a later part of the scene).
struct CaseRun {
    CaseRun(scene::Scene& s, const BenchCase& c, const BenchSettings& st, FramePacer& p)
        : scene(s), settings(st), pacer(p), engine(makeEngine(s, c, st)) {
        r.spec = c;
        r.technique = engine->technique();
        r.width = st.width;
        r.height = st.height;
    }
    // Renders the next frame (waiting first for the frame two before it, any case's); returns when it started.
    Clock::time_point step() {
        pacer.wait();
        const Clock::time_point start = Clock::now();
        const float t = static_cast<float>(sceneFrame++) * settings.sceneStep;
        engine->frame(t, settings.fixedCamera ? scene.camera : benchCamera(scene, t), settings.width, settings.height);
        lastCpuMs = millisecondsSince(start);
        pacer.submitted();
        ++frameNumber;
        return start;
    }
    // The GPU ms per pass of the frames `kept` accepts, among those finished since the last call.
    void takeTimes(const std::function<bool(std::uint64_t)>& kept) {
        engine->timer().waitForAll();
        for (const render::FrameTimes& t : engine->timer().takeFinished()) {
            if (!kept(t.frame)) continue;
            for (int p = 0; p < render::kPassCount; ++p) pass[static_cast<std::size_t>(p)].push_back(t.gpu[static_cast<render::Pass>(p)]);
            gpuTotal.push_back(t.gpu.totalMs());
        }
    }
    void clearSamples() {
        engine->timer().takeFinished();  // what came before (those still in flight are dropped by frame number)
        sceneFrame = 0;
        frameMs.clear();
        triangles = 0;
        cpuMs.clear();
        for (auto& p : pass) p.clear();
        gpuTotal.clear();
    }

    scene::Scene& scene;
    const BenchSettings& settings;
    FramePacer& pacer;
    std::unique_ptr<Engine> engine;
    std::uint64_t frameNumber = 0, sceneFrame = 0;
    CaseResult r;
    // The measurement's samples: wall ms per frame, CPU ms per frame, shadow triangles, GPU ms per pass and in all.
    std::vector<double> frameMs, cpuMs;
    double lastCpuMs = 0;  // step()'s frame: CaseResult::cpuFrameMs
    double triangles = 0;
    std::array<std::vector<double>, render::kPassCount> pass;
    std::vector<double> gpuTotal;
};

// Warm-up: shaders compile at first draw, a GPU climbs to its working clock.
void warmUp(CaseRun& run, const std::function<void(double)>& progress) {
    const Clock::time_point warmStart = Clock::now();
    std::vector<double> warm;
    const double warmMs = run.settings.warmupSeconds * 1000.0;
    Clock::time_point last{};
    for (;;) {
        const Clock::time_point start = run.step();
        if (run.frameNumber > 1) warm.push_back(millisecondsBetween(last, start));
        last = start;
        const double elapsed = millisecondsSince(warmStart);
        if (run.frameNumber >= 2 && (warmMs <= 0 || (elapsed >= warmMs && framesSettled(warm)))) {
            run.r.settled = true;
            break;
        }
        if (run.frameNumber >= 2 && elapsed >= 3.0 * warmMs) break;
        progress(0.3 * std::min(1.0, elapsed / std::max(1.0, 3.0 * warmMs)));
    }
    run.r.warmupFrames = static_cast<int>(run.frameNumber);
    run.r.warmupSeconds = millisecondsSince(warmStart) / 1000.0;
}

// One measurement of a case alone: the wall interval between frame starts (the last frame's: to
// its end), shadow triangles, and GPU ms per pass.
void measureAlone(CaseRun& run, const std::function<void(double)>& progress) {
    const BenchSettings& settings = run.settings;
    run.clearSamples();
    const std::uint64_t firstMeasured = run.frameNumber;
    const Clock::time_point measureStart = Clock::now();
    Clock::time_point last{};
    for (int i = 0;; ++i) {
        const Clock::time_point start = run.step();
        if (i > 0) run.frameMs.push_back(millisecondsBetween(last, start));
        last = start;
        run.cpuMs.push_back(run.lastCpuMs);
        run.triangles += static_cast<double>(run.engine->shadowTriangles());
        const double elapsed = millisecondsSince(measureStart);
        // N frames give N intervals: N - 1 between starts, and the last one's start to its end.
        const bool done = settings.frames > 0 ? i + 1 >= settings.frames : (i >= 2 && elapsed >= settings.seconds * 1000.0);
        progress(0.3 + 0.6 * (settings.frames > 0 ? double(i + 1) / settings.frames : std::min(1.0, elapsed / (settings.seconds * 1000.0))));
        if (done) break;
    }
    glFinish();
    run.frameMs.push_back(millisecondsSince(last));
    run.takeTimes([&](std::uint64_t frame) { return frame >= firstMeasured; });
}

// One measurement of several cases of one scene in turns of settings.interleaveFrames frames each,
// round robin, so that a machine whose speed swings within seconds slows them alike. A turn's
// first kTurnSkip frames share the pipeline (two frames in flight) with the case before, and its
// last frame's interval would end at the next case's start: the frames in between are measured,
// wall interval and GPU time alike. Each case measures settings.frames intervals, or turns until
// settings.seconds per case have passed (at least three turns each).
constexpr int kTurnSkip = 2;
void measureInterleaved(std::vector<std::unique_ptr<CaseRun>>& runs, const BenchSettings& settings,
                        const std::function<void(double)>& progress) {
    const int turn = settings.interleaveFrames;
    std::vector<std::vector<std::uint64_t>> measured(runs.size());  // frame numbers, per case
    for (auto& run : runs) run->clearSamples();
    const Clock::time_point measureStart = Clock::now();
    const double targetMs = settings.seconds * 1000.0 * static_cast<double>(runs.size());
    for (int turns = 1;; ++turns) {
        for (std::size_t k = 0; k < runs.size(); ++k) {
            CaseRun& run = *runs[k];
            std::vector<Clock::time_point> starts;
            std::vector<std::size_t> kept;  // frames of the turn measured
            for (int f = 0; f < turn; ++f) {
                starts.push_back(run.step());
                const bool wanted = settings.frames <= 0 || run.frameMs.size() + kept.size() < static_cast<std::size_t>(settings.frames);
                if (f < kTurnSkip || f + 1 == turn || !wanted) continue;
                kept.push_back(static_cast<std::size_t>(f));
                measured[k].push_back(run.frameNumber - 1);
                run.cpuMs.push_back(run.lastCpuMs);
                run.triangles += static_cast<double>(run.engine->shadowTriangles());
            }
            for (std::size_t f : kept) run.frameMs.push_back(millisecondsBetween(starts[f], starts[f + 1]));
        }
        const double elapsed = millisecondsSince(measureStart);
        bool done = true;
        for (const auto& run : runs)
            done = done && (settings.frames > 0 ? run->frameMs.size() >= static_cast<std::size_t>(settings.frames) : turns >= 3);
        if (settings.frames <= 0) done = done && elapsed >= targetMs;
        progress(0.3 + 0.6 * (settings.frames > 0 ? 1.0 : std::min(1.0, elapsed / targetMs)));
        if (done) break;
    }
    glFinish();
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const std::vector<std::uint64_t>& frames = measured[k];
        runs[k]->takeTimes([&](std::uint64_t frame) { return std::binary_search(frames.begin(), frames.end(), frame); });
    }
}

// A measured frame that links a program (a lighting build that the camera's new view needs
// first: lighting.frag is specialised to the pixels each light reaches, render/LightingProgram.h)
// pays for its compile, 450 ms on llvmpipe with a cold shader cache against 50 ms frames: the
// measurement is taken again over the same frames, now compiled, at most kMostMeasurements times
// in all.
constexpr int kMostMeasurements = 3;
template <class Measure>
void measureUntilCompiled(const std::vector<CaseRun*>& runs, Measure&& measure) {
    for (int attempt = 1;; ++attempt) {
        const std::uint64_t linkedBefore = gl::Program::linkedSoFar();
        measure();
        const std::uint64_t linked = gl::Program::linkedSoFar() - linkedBefore;
        for (CaseRun* run : runs) run->r.programsLinkedMeasuring = linked;
        if (linked == 0 || attempt == kMostMeasurements) break;
        for (CaseRun* run : runs) ++run->r.measurementsRepeated;
    }
}

// Frames a case is drawn for each of calibrate's and the sub-passes' measures: 3 to 8.
int calibrationFrames(const BenchSettings& settings) { return std::max(3, std::min(settings.frames > 0 ? settings.frames : 8, 8)); }

// Each pass's query against a glFinish wall clock (settings.calibrate), over a few frames of every
// case of the group taken in turn, one frame each: a machine that slows within the group moves all
// its cases alike. (Taken case after case, two of three rounds on the 98k grid had slowed midway,
// floor-depth's wall reading 15.4 and 16.3 ms against 10.9 in the third: stop 74.)
void calibrate(const std::vector<CaseRun*>& runs) {
    if (runs.empty()) return;
    const BenchSettings& settings = runs.front()->settings;
    const int n = calibrationFrames(settings);
    std::vector<std::uint64_t> first;
    for (CaseRun* run : runs) {
        run->engine->timer().setCalibration(true);
        first.push_back(run->frameNumber);
    }
    for (int i = 0; i < n; ++i)
        for (CaseRun* run : runs) run->step();
    glFinish();
    for (std::size_t k = 0; k < runs.size(); ++k) {
        CaseResult& r = runs[k]->r;
        render::FrameTimer& timer = runs[k]->engine->timer();
        timer.waitForAll();
        std::array<std::vector<double>, render::kPassCount> query, wall;
        for (const render::FrameTimes& t : timer.takeFinished()) {
            if (t.frame < first[k]) continue;
            for (int p = 0; p < render::kPassCount; ++p) {
                query[static_cast<std::size_t>(p)].push_back(t.gpu[static_cast<render::Pass>(p)]);
                wall[static_cast<std::size_t>(p)].push_back(t.wall[static_cast<render::Pass>(p)]);
            }
        }
        for (std::size_t p = 0; p < render::kPassCount; ++p) {
            PassCalibration& cal = r.calibration[p];
            cal.queryMs = summarize(query[p]).median;
            cal.wallMs = summarize(wall[p]).median;
            const double diff = std::abs(cal.queryMs - cal.wallMs);
            cal.flagged = diff > 0.1 * std::max(cal.queryMs, cal.wallMs) && diff > 0.1;
        }
        r.finishOverheadMs = timer.finishOverheadMs();
        timer.setCalibration(false);
        r.calibrated = true;
    }
}

// The measurement's summaries, then (settings.calibrate, after calibrate) the passes' parts, and
// the case's picture.
void finish(CaseRun& run) {
    CaseResult& r = run.r;
    const BenchSettings& settings = run.settings;
    for (int p = 0; p < render::kPassCount; ++p) r.passMs[static_cast<std::size_t>(p)] = summarize(run.pass[static_cast<std::size_t>(p)]);
    r.passSamples = run.pass;
    r.frameSamples = run.frameMs;
    r.cpuSamples = run.cpuMs;
    r.gpuFrameMs = summarize(run.gpuTotal);
    r.frameMs = summarize(run.frameMs);
    r.cpuFrameMs = summarize(run.cpuMs);
    r.shadowTrianglesPerFrame = run.triangles / static_cast<double>(run.frameMs.size());
    r.fpsMean = 1000.0 / r.frameMs.mean;
    r.fpsMin = 1000.0 / r.frameMs.max;
    r.fpsMax = 1000.0 / r.frameMs.min;
    r.fpsP95 = 1000.0 / r.frameMs.p95;
    r.shadowMemoryBytes = run.engine->memoryBytes();
    r.parameters = run.engine->parameters();
    r.interleaveFrames = settings.interleaveFrames;

    Engine& engine = *run.engine;
    if (settings.calibrate) {  // the passes' parts, in frames of their own: their glFinish calls would weigh on calibrate's
        const int n = calibrationFrames(settings);
        render::SubPassClock clock(r.finishOverheadMs);
        for (int i = 0; i < n; ++i) run.step();
        r.subPassMs = clock.perFrame(n);
    }

    if (settings.images && r.spec.round == 0) {  // later rounds (--rounds) draw the same pictures
        engine.frame(0.0f, settings.fixedCamera ? run.scene.camera : benchCamera(run.scene, 0.0f), r.width, r.height);
        r.image = render::readFramebufferRgba8(engine.framebuffer(), r.width, r.height);
    }
}

// The cases of one scene and round that measure together (with settings.interleaveFrames, in turns:
// measureInterleaved), or one case alone (measureAlone). Each is warmed up alone first. GL errors
// and warnings are the group's, given to each of its cases.
std::vector<CaseResult> runGroup(scene::Scene& scene, const std::vector<BenchCase>& cases, const BenchSettings& settings,
                                 const std::function<void(std::size_t, double)>& progress) {
    gl::resetDebugErrorCount();
    const int warningsBefore = gl::debugWarningCount();
    FramePacer pacer;
    std::vector<std::unique_ptr<CaseRun>> runs;
    std::vector<CaseRun*> all;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        runs.push_back(std::make_unique<CaseRun>(scene, cases[i], settings, pacer));
        all.push_back(runs.back().get());
        warmUp(*runs.back(), [&](double f) { progress(i, f); });
    }
    const auto measured = [&](double f) { progress(0, f); };
    measureUntilCompiled(all, [&] {
        if (settings.interleaveFrames > 0) measureInterleaved(runs, settings, measured);
        else measureAlone(*runs.front(), measured);  // runBench groups one case then
    });
    std::vector<CaseResult> results;
    if (settings.calibrate) calibrate(all);
    for (auto& run : runs) finish(*run);
    for (std::size_t i = 0; i < runs.size(); ++i) {
        runs[i]->r.glErrors = gl::debugErrorCount();
        runs[i]->r.glWarnings = gl::debugWarningCount() - warningsBefore;
        progress(i, 1.0);
        results.push_back(std::move(runs[i]->r));
    }
    return results;
}

}  // namespace

std::vector<CaseResult> runBench(const std::vector<BenchCase>& cases, const BenchSettings& settings, const Progress& progress) {
    std::vector<CaseResult> results;
    std::optional<scene::Scene> scene;
    std::filesystem::path loaded;
    for (std::size_t i = 0; i < cases.size();) {
        const BenchCase& c = cases[i];
        if (!scene || loaded != c.scene) {
            scene.reset();
            scene = scene::io::loadScene(c.scene);
            loaded = c.scene;
        }
        // With interleaving, the consecutive cases of this scene and round measure together.
        std::size_t end = i + 1;
        if (settings.interleaveFrames > 0)
            while (end < cases.size() && cases[end].scene == c.scene && cases[end].round == c.round) ++end;
        const auto report = [&](std::size_t k, double fraction) {
            if (progress) progress(i + k, cases.size(), cases[i + k], fraction);
        };
        std::vector<CaseResult> group = runGroup(
            *scene, std::vector<BenchCase>(cases.begin() + static_cast<std::ptrdiff_t>(i), cases.begin() + static_cast<std::ptrdiff_t>(end)),
            settings, report);
        for (CaseResult& r : group) {
            r.sceneName = scene->source.empty() ? c.scene.stem().string() : scene->source.stem().string();
            r.sceneTriangles = scene->triangleCount();
            for (const auto& l : scene->lights)
                if (l.shadow.enabled) r.resolutions.push_back(r.spec.shadowResolution > 0 ? r.spec.shadowResolution : l.shadow.resolution);
            results.push_back(std::move(r));
        }
        i = end;
    }
    return results;
}

}  // namespace penumbra::bench
