#include "app/RenderCommand.h"

#include "app/MallocTuning.h"
#include "util/OutputFiles.h"
#include "gl/Debug.h"
#include "gl/Object.h"
#include "platform/EglContext.h"
#include "app/RenderOptionsCli.h"
#include "render/Offscreen.h"
#include "render/RegionView.h"
#include "render/SplitView.h"
#include "scene/io/SceneFile.h"
#include "util/DataPaths.h"
#include "util/Log.h"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <malloc.h>
#include <unistd.h>
#include <cstdio>
#include <string_view>
#include <nlohmann/json.hpp>

namespace penumbra::app {

// How the frame's opaque draws met coloured shadows (render/TintReach.h): drawn with the whole
// lookup, with none (no translucent caster's shadow reaches them), with the behind-layers build
// (behind every layer that may reach them), or split on the screen; and how many translucent draws
// met none but their own layers (ShadowTechnique::ownLayersBuild), whole or split; how many pieces
// of draws left out a projector or spot light that cannot reach them (RenderOptions::
// lightOnlyWhereReached), and of opaque draws without the lookup of a light whose shadow cannot
// fall on them (shadowOnlyWhereCast); how many footprints and reaches it worked out rather than kept from the
// last frame; and the CPU milliseconds the choice took.
static nlohmann::json tintShadingJson(const render::Renderer::TintShading& t) {
    return {{"whole_draws", t.whole},
            {"untinted_draws", t.untinted},
            {"behind_layers_draws", t.behindLayers},
            {"split_draws", t.split},
            {"tinted_rectangles", t.tintedRects},
            {"untinted_rectangles", t.untintedRects},
            {"behind_layers_rectangles", t.behindLayersRects},
            {"translucent_untinted_draws", t.translucentUntinted},
            {"translucent_behind_layers_draws", t.translucentBehindLayers},
            {"translucent_split_draws", t.translucentSplit},
            {"unlit_pieces", t.unlitPieces},
            {"unshadowed_pieces", t.unshadowedPieces},
            {"footprints_made", t.footprintsMade},
            {"cpu_ms", t.cpuMs}};
}

using render::PassTimes;

namespace fs = std::filesystem;

namespace {

// Resident memory after handing glibc's free heap back to the system, so that the soak record
// follows live memory rather than how much freed memory the allocator happens to keep.
long residentKiB() {
    ::malloc_trim(0);
    std::ifstream statm("/proc/self/statm");
    long pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * (::sysconf(_SC_PAGESIZE) / 1024);
}

// Memory in use from malloc (the driver's included), as mallinfo2 counts it: the main arena and
// mmapped chunks, not other threads' arenas. Unlike resident memory, it does not depend on which
// freed pages the allocator and the kernel happen to keep.
// `mmappedKiB` is the part in mmapped chunks: big blocks, such as textures' storage under llvmpipe.
struct HeapInUse {
    long kib, mmappedKiB;
};
HeapInUse heapInUse() {
    const struct mallinfo2 m = ::mallinfo2();
    return {static_cast<long>((m.uordblks + m.hblkhd) / 1024), static_cast<long>(m.hblkhd / 1024)};
}

// With rasteriser threads, llvmpipe releases a scene's references to textures only when it reuses
// that scene for a later flush, so a deleted technique's maps can stay allocated for a while that
// depends on thread timing (tests/cli/soak.cmake has the measurements). Rasterising on the calling
// thread (LP_NUM_THREADS=0), memory follows what is live.
void hintAtLlvmpipeThreads() {
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const char* threads = std::getenv("LP_NUM_THREADS");
    const bool llvmpipe = renderer && std::string_view(renderer).find("llvmpipe") != std::string_view::npos;
    if (llvmpipe && !(threads && std::string_view(threads) == "0"))
        log::info("soak on llvmpipe with rasteriser threads: its memory figures include deleted maps the driver has not "
                  "released yet; set LP_NUM_THREADS=0 to read live memory");
}

int drainGlErrors() {
    int n = 0;
    while (glGetError() != GL_NO_ERROR && n < 1000) ++n;
    return n;
}

// The soak's cycle of output sizes and shadow-map resolutions: the job's size, a quarter of it,
// a 1x1 frame and an odd, narrow one, against maps of 512, 256, 1024 and 2048 texels.
struct SizeStep {
    int width, height, shadowResolution;
};
std::vector<SizeStep> sizeCycle(const BatchJob& job) {
    return {{job.width, job.height, 512},
            {std::max(1, job.width / 2), std::max(1, job.height / 2), 256},
            {1, 1, 1024},
            {std::max(1, job.width * 3 / 4 + 1), std::max(1, job.height / 3 + 1), 2048}};
}

}  // namespace

BatchResult renderBatch(const BatchJob& job) {
    const nlohmann::json mallocSettings = configureMalloc(job.tunedMalloc);
    scene::Scene scene = scene::io::loadScene(job.scene);
    if (job.width <= 0 || job.height <= 0 || job.width > 16384 || job.height > 16384)
        throw std::invalid_argument("--size must be within 1x1..16384x16384");
    auto context = platform::EglContext::create(job.eglPlatform);
    gl::enableDebugOutput();

    render::RenderOptions options = job.render;
    options.strictParameters = true;
    // One renderer, two side by side, or one per region of the scene; `renderer` is the only,
    // the left or the base one (stats, soak).
    std::unique_ptr<render::Renderer> single;
    std::unique_ptr<render::SplitView> split;
    std::unique_ptr<render::RegionView> regions;
    if (!job.split.empty()) {
        split = std::make_unique<render::SplitView>(scene, options, splitSideOptions(options, job.split));
        split->setDivider(job.splitAt);
    } else if (render::drawsByRegion(options, scene)) {
        regions = std::make_unique<render::RegionView>(scene, options);
    } else {
        single = std::make_unique<render::Renderer>(scene, options);
    }
    render::Renderer& renderer = split ? split->left() : regions ? regions->base() : *single;
    const auto draw = [&](float t, int w, int h, GLuint fb) {
        if (split) split->render(t, scene.cameraAt(t), w, h, fb);
        else if (regions) regions->render(t, scene.cameraAt(t), w, h, fb);
        else renderer.render(t, scene.cameraAt(t), w, h, fb);
    };
    auto target = std::make_unique<render::OffscreenTarget>(job.width, job.height);
    int width = job.width, height = job.height;
    const auto& registry = shadows::techniqueRegistry();
    const auto sizes = sizeCycle(job);
    std::size_t techniqueIndex = 0, sizeIndex = 0;
    util::createOutputDirectory(job.outDir);

    // One untimed warm-up frame: llvmpipe compiles shaders at first draw, and its first timer
    // query of a context reads garbage.
    draw(job.startTime, job.width, job.height, target->framebuffer());

    BatchResult result;
    auto sample = [&](int frame) {
        glFinish();
        const long resident = residentKiB();  // trims the heap first
        const HeapInUse heap = heapInUse();
        result.soak.push_back({frame, renderer.technique().name(), width, height, renderer.options().shadowResolution, resident,
                               heap.kib, heap.mmappedKiB, gl::liveObjectCount(), renderer.shadowMemoryBytes(), drainGlErrors()});
    };
    const bool soaking = job.cycleTechniquesEvery > 0 || job.cycleSizesEvery > 0;
    if (soaking) {
        hintAtLlvmpipeThreads();
        sample(0);
    }
    result.device = platform::glDeviceDescription();
    nlohmann::json frames = nlohmann::json::array();
    for (int i = 0; i < job.frames; ++i) {
        bool changed = false;
        if (job.cycleTechniquesEvery > 0 && i > 0 && i % job.cycleTechniquesEvery == 0) {
            techniqueIndex = (techniqueIndex + 1) % registry.size();
            renderer.setTechnique(registry[techniqueIndex].name);
            if (split) split->right().setTechnique(registry[(techniqueIndex + 1) % registry.size()].name);
            changed = true;
        }
        if (job.cycleSizesEvery > 0 && i > 0 && i % job.cycleSizesEvery == 0) {
            const SizeStep& s = sizes[++sizeIndex % sizes.size()];
            width = s.width;
            height = s.height;
            renderer.options().shadowResolution = s.shadowResolution;
            if (split) split->right().options().shadowResolution = s.shadowResolution;
            target = std::make_unique<render::OffscreenTarget>(width, height);
            changed = true;
        }
        if (changed) sample(i);
        const float t = job.startTime + static_cast<float>(i) / job.fps;
        const auto cpuStart = std::chrono::steady_clock::now();
        draw(t, width, height, target->framebuffer());  // along camera_path, if any
        const bool png = job.pngEvery > 0 && i % job.pngEvery == 0;
        const std::vector<std::uint8_t> pixels = png ? target->readRgba8() : std::vector<std::uint8_t>{};
        const double cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - cpuStart).count();
        if (png) {
            char name[32];
            std::snprintf(name, sizeof name, "frame_%04d.png", i);
            util::writePng(job.outDir / name, width, height, pixels);
        }
        const PassTimes p = regions ? regions->waitForTimes() : renderer.waitForTimes();  // a PNG's read-back has synchronised already
        const auto& triangles = renderer.shadowTriangles();
        if (result.shadowTriangles.size() < triangles.size()) result.shadowTriangles.resize(triangles.size());
        for (std::size_t l = 0; l < triangles.size(); ++l)
            result.shadowTriangles[l] += static_cast<double>(triangles[l]) / job.frames;
        frames.push_back({{"index", i}, {"time", t}, {"shadow_ms", p.shadowMs}, {"opaque_ms", p.opaqueMs},
                          {"translucent_ms", p.translucentMs}, {"post_ms", p.postMs}, {"total_ms", p.totalMs()},
                          {"cpu_ms_with_readback", cpuMs}, {"tint_shading", tintShadingJson(renderer.tintShading())}});
        result.mean.shadowMs += p.shadowMs / job.frames;
        result.mean.opaqueMs += p.opaqueMs / job.frames;
        result.mean.translucentMs += p.translucentMs / job.frames;
        result.mean.postMs += p.postMs / job.frames;
    }
    result.frames = job.frames;
    if (soaking) sample(job.frames);
    result.shadowMemoryBytes = regions ? regions->shadowMemoryBytes() : renderer.shadowMemoryBytes();

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
        {"malloc", mallocSettings},
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
    if (split)
        stats["split"] = {{"left", split->left().technique().name()}, {"right", split->right().technique().name()},
                          {"divider_column", split->dividerColumn(job.width)}};
    if (regions) {
        nlohmann::json list = nlohmann::json::array();
        for (std::size_t r = 0; r < scene.regions.size(); ++r) {
            render::Renderer& region = regions->region(r);
            list.push_back({{"name", scene.regions[r].name}, {"technique", region.technique().name()},
                            {"shadow_resolution", region.options().shadowResolution}});
        }
        stats["regions"] = list;
    }
    if (soaking) {
        nlohmann::json soak = nlohmann::json::array();
        for (const SoakSample& s : result.soak)
            soak.push_back({{"frame", s.frame}, {"technique", s.technique}, {"width", s.width}, {"height", s.height},
                            {"shadow_resolution", s.shadowResolution}, {"rss_kib", s.rssKiB}, {"heap_kib", s.heapKiB},
                            {"heap_mmapped_kib", s.mmappedKiB}, {"gl_objects", s.glObjects},
                            {"shadow_memory_bytes", s.shadowMemoryBytes}, {"gl_errors", s.glErrors}});
        stats["soak"] = soak;
    }
    result.statsFile = job.outDir / "stats.json";
    util::writeJson(result.statsFile, stats);
    return result;
}

}  // namespace penumbra::app
