#include "app/RenderCommand.h"

#include "util/OutputFiles.h"
#include "gl/Debug.h"
#include "platform/EglContext.h"
#include "render/Offscreen.h"
#include "scene/io/SceneFile.h"
#include "util/DataPaths.h"
#include "util/Log.h"

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace penumbra::app {

using render::PassTimes;

namespace fs = std::filesystem;

BatchResult renderBatch(const BatchJob& job) {
    scene::Scene scene = scene::io::loadScene(job.scene);
    if (job.width <= 0 || job.height <= 0 || job.width > 16384 || job.height > 16384)
        throw std::invalid_argument("--size must be within 1x1..16384x16384");
    auto context = platform::EglContext::create(job.eglPlatform);
    gl::enableDebugOutput();

    render::RenderOptions options = job.render;
    options.strictParameters = true;
    render::Renderer renderer(scene, options);
    render::OffscreenTarget target(job.width, job.height);
    util::createOutputDirectory(job.outDir);

    // One untimed warm-up frame: llvmpipe compiles shaders at first draw, and its first timer
    // query of a context reads garbage.
    renderer.render(job.startTime, scene.cameraAt(job.startTime), job.width, job.height, target.framebuffer());

    BatchResult result;
    result.device = platform::glDeviceDescription();
    nlohmann::json frames = nlohmann::json::array();
    for (int i = 0; i < job.frames; ++i) {
        const float t = job.startTime + static_cast<float>(i) / job.fps;
        const auto cpuStart = std::chrono::steady_clock::now();
        renderer.render(t, scene.cameraAt(t), job.width, job.height, target.framebuffer());  // along camera_path, if any
        const std::vector<std::uint8_t> pixels = target.readRgba8();
        const double cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpuStart).count();
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04d.png", i);
        util::writePng(job.outDir / name, job.width, job.height, pixels);
        const PassTimes& p = renderer.waitForTimes();  // the read-back has synchronised anyway
        const auto& triangles = renderer.shadowTriangles();
        if (result.shadowTriangles.size() < triangles.size()) result.shadowTriangles.resize(triangles.size());
        for (std::size_t l = 0; l < triangles.size(); ++l)
            result.shadowTriangles[l] += static_cast<double>(triangles[l]) / job.frames;
        frames.push_back({{"index", i}, {"time", t}, {"shadow_ms", p.shadowMs}, {"opaque_ms", p.opaqueMs},
                          {"translucent_ms", p.translucentMs}, {"post_ms", p.postMs}, {"total_ms", p.totalMs()},
                          {"cpu_ms_with_readback", cpuMs}});
        result.mean.shadowMs += p.shadowMs / job.frames;
        result.mean.opaqueMs += p.opaqueMs / job.frames;
        result.mean.translucentMs += p.translucentMs / job.frames;
        result.mean.postMs += p.postMs / job.frames;
    }
    result.frames = job.frames;
    result.shadowMemoryBytes = renderer.shadowMemoryBytes();

    nlohmann::json lights = nlohmann::json::array();
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const auto& l = scene.lights[i];
        lights.push_back({{"name", l.name}, {"type", scene::toString(l.type)},
                          {"shadow_resolution", renderer.effectiveResolution(l)}, {"shadows", l.shadow.enabled},
                          {"shadow_triangles_per_frame", i < result.shadowTriangles.size() ? result.shadowTriangles[i] : 0.0}});
    }
    nlohmann::json stats = {
        {"device", result.device},
        {"egl_platform", context->platformName()},
        {"data_dir", paths::dataRoot().string()},
        {"scene", job.scene.string()},
        {"technique", renderer.technique().name()},
        {"transparency", render::toString(job.render.transparency)},
        {"parameters", [&] {
             nlohmann::json p = nlohmann::json::object();
             for (const auto& param : renderer.technique().parameters()) p[param.name] = param.number();
             return p;
         }()},
        {"width", job.width},
        {"height", job.height},
        {"triangles", scene.triangleCount()},
        {"lights", lights},
        {"shadow_memory_bytes", result.shadowMemoryBytes},
        {"gl_errors", gl::debugErrorCount()},
        {"gl_warnings", gl::debugWarningCount()},
        {"warmup_frames", 1},
        {"mean_ms", {{"shadow", result.mean.shadowMs}, {"opaque", result.mean.opaqueMs},
                     {"translucent", result.mean.translucentMs}, {"post", result.mean.postMs},
                     {"total", result.mean.totalMs()}}},
        {"frames", frames},
    };
    result.statsFile = job.outDir / "stats.json";
    util::writeJson(result.statsFile, stats);
    return result;
}

}  // namespace penumbra::app
