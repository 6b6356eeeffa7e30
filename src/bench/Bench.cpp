#include "bench/Bench.h"

#include "bench/FloorRenderer.h"
#include "gl/Debug.h"
#include "gl/Program.h"
#include "render/Offscreen.h"
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

double millisecondsSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

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

CaseResult runCase(scene::Scene& scene, const BenchCase& c, const BenchSettings& settings,
                   const std::function<void(double)>& progress) {
    gl::resetDebugErrorCount();
    const int warningsBefore = gl::debugWarningCount();
    std::unique_ptr<Engine> engine = makeEngine(scene, c, settings);
    const int w = settings.width, h = settings.height;
    FramePacer pacer;
    std::uint64_t frameNumber = 0;  // the renderer's frame index (timer queries), warm-up included
    // Scene time runs from 0 again when the measurement starts, so that every case measures the
    // same frames of the animation whatever its warm-up took (until stop 55 each case went on
    // from its warm-up's last frame: a faster case measured a later part of the scene).
    std::uint64_t sceneFrame = 0;
    Clock::time_point lastStart{};
    // Renders the next frame; returns the wall time since the previous frame's start (0 for the first).
    const auto step = [&] {
        pacer.wait();
        const Clock::time_point start = Clock::now();
        const double interval = frameNumber > 0 ? std::chrono::duration<double, std::milli>(start - lastStart).count() : 0.0;
        lastStart = start;
        const float t = static_cast<float>(sceneFrame++) * settings.sceneStep;
        engine->frame(t, settings.fixedCamera ? scene.camera : benchCamera(scene, t), w, h);
        pacer.submitted();
        ++frameNumber;
        return interval;
    };

    CaseResult r;
    r.spec = c;
    r.technique = engine->technique();
    r.width = w;
    r.height = h;

    // One measurement: the frames' wall intervals, shadow triangles, and GPU ms per pass.
    const auto measureFrames = [&](std::vector<double>& frameMs, double& triangles,
                                   std::array<std::vector<double>, render::kPassCount>& pass, std::vector<double>& gpuTotal) {
        engine->timer().takeFinished();  // what came before (those still in flight are dropped by frame number below)
        const std::uint64_t firstMeasured = frameNumber;
        sceneFrame = 0;
        frameMs.clear();
        triangles = 0;
        for (auto& p : pass) p.clear();
        gpuTotal.clear();
        const Clock::time_point measureStart = Clock::now();
        for (int i = 0;; ++i) {
            const double interval = step();
            if (i > 0) frameMs.push_back(interval);
            triangles += static_cast<double>(engine->shadowTriangles());
            const double elapsed = millisecondsSince(measureStart);
            // N frames give N intervals: N - 1 between starts, and the last one's start to its end.
            const bool done = settings.frames > 0 ? i + 1 >= settings.frames : (i >= 2 && elapsed >= settings.seconds * 1000.0);
            progress(0.3 + 0.6 * (settings.frames > 0 ? double(i + 1) / settings.frames : std::min(1.0, elapsed / (settings.seconds * 1000.0))));
            if (done) break;
        }
        // The last frame's interval: until it has finished.
        glFinish();
        frameMs.push_back(millisecondsSince(lastStart));
        engine->timer().waitForAll();
        for (const render::FrameTimes& t : engine->timer().takeFinished()) {
            if (t.frame < firstMeasured) continue;
            for (int p = 0; p < render::kPassCount; ++p) pass[static_cast<std::size_t>(p)].push_back(t.gpu[static_cast<render::Pass>(p)]);
            gpuTotal.push_back(t.gpu.totalMs());
        }
    };

    // Warm-up: shaders compile at first draw, a GPU climbs to its working clock.
    const Clock::time_point warmStart = Clock::now();
    std::vector<double> warm;
    const double warmMs = settings.warmupSeconds * 1000.0;
    for (;;) {
        const double interval = step();
        if (frameNumber > 1) warm.push_back(interval);
        const double elapsed = millisecondsSince(warmStart);
        if (frameNumber >= 2 && (warmMs <= 0 || (elapsed >= warmMs && framesSettled(warm)))) {
            r.settled = true;
            break;
        }
        if (frameNumber >= 2 && elapsed >= 3.0 * warmMs) break;
        progress(0.3 * std::min(1.0, elapsed / std::max(1.0, 3.0 * warmMs)));
    }
    r.warmupFrames = static_cast<int>(frameNumber);
    r.warmupSeconds = millisecondsSince(warmStart) / 1000.0;

    // Measurement, from scene time 0 along the same path as the warm-up. A measured frame that
    // links a program (a lighting build that the camera's new view needs first: lighting.frag is
    // specialised to the pixels each light reaches, render/LightingProgram.h) pays for its compile,
    // 450 ms on llvmpipe with a cold shader cache against 50 ms frames: the measurement is taken
    // again over the same frames, now compiled, at most kMostMeasurements times in all.
    constexpr int kMostMeasurements = 3;
    std::vector<double> frameMs;
    double triangles = 0;
    std::array<std::vector<double>, render::kPassCount> pass;
    std::vector<double> gpuTotal;
    for (int attempt = 1;; ++attempt) {
        const std::uint64_t linkedBefore = gl::Program::linkedSoFar();
        measureFrames(frameMs, triangles, pass, gpuTotal);
        r.programsLinkedMeasuring = gl::Program::linkedSoFar() - linkedBefore;
        if (r.programsLinkedMeasuring == 0 || attempt == kMostMeasurements) break;
        ++r.measurementsRepeated;
    }
    for (int p = 0; p < render::kPassCount; ++p) r.passMs[static_cast<std::size_t>(p)] = summarize(pass[static_cast<std::size_t>(p)]);
    r.passSamples = pass;
    r.frameSamples = frameMs;
    r.gpuFrameMs = summarize(gpuTotal);
    r.frameMs = summarize(frameMs);
    const double measured = static_cast<double>(frameMs.size());
    r.shadowTrianglesPerFrame = triangles / measured;
    r.fpsMean = 1000.0 / r.frameMs.mean;
    r.fpsMin = 1000.0 / r.frameMs.max;
    r.fpsMax = 1000.0 / r.frameMs.min;
    r.fpsP95 = 1000.0 / r.frameMs.p95;
    r.shadowMemoryBytes = engine->memoryBytes();
    r.parameters = engine->parameters();

    if (settings.calibrate) {
        // glFinish around every pass: what each pass really takes, against its query.
        engine->timer().setCalibration(true);
        const int n = std::max(3, std::min(settings.frames > 0 ? settings.frames : 8, 8));
        const std::uint64_t first = frameNumber;
        for (int i = 0; i < n; ++i) step();
        glFinish();
        engine->timer().waitForAll();
        std::array<std::vector<double>, render::kPassCount> query, wall;
        for (const render::FrameTimes& t : engine->timer().takeFinished()) {
            if (t.frame < first) continue;
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
        r.finishOverheadMs = engine->timer().finishOverheadMs();
        engine->timer().setCalibration(false);
        r.calibrated = true;
    }

    if (settings.images && c.round == 0) {  // later rounds (--rounds) draw the same pictures
        engine->frame(0.0f, settings.fixedCamera ? scene.camera : benchCamera(scene, 0.0f), w, h);
        r.image = render::readFramebufferRgba8(engine->framebuffer(), w, h);
    }
    r.glErrors = gl::debugErrorCount();
    r.glWarnings = gl::debugWarningCount() - warningsBefore;
    progress(1.0);
    return r;
}

}  // namespace

std::vector<CaseResult> runBench(const std::vector<BenchCase>& cases, const BenchSettings& settings, const Progress& progress) {
    std::vector<CaseResult> results;
    std::optional<scene::Scene> scene;
    std::filesystem::path loaded;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const BenchCase& c = cases[i];
        if (!scene || loaded != c.scene) {
            scene.reset();
            scene = scene::io::loadScene(c.scene);
            loaded = c.scene;
        }
        const auto report = [&](double fraction) {
            if (progress) progress(i, cases.size(), c, fraction);
        };
        report(0.0);
        CaseResult r = runCase(*scene, c, settings, report);
        r.sceneName = scene->source.empty() ? c.scene.stem().string() : scene->source.stem().string();
        r.sceneTriangles = scene->triangleCount();
        for (const auto& l : scene->lights)
            if (l.shadow.enabled) r.resolutions.push_back(c.shadowResolution > 0 ? c.shadowResolution : l.shadow.resolution);
        results.push_back(std::move(r));
    }
    return results;
}

}  // namespace penumbra::bench
