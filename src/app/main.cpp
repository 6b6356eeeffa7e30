// penumbra command line: parses arguments and calls the core. No GL calls here.
#include "app/Viewer.h"
#include "platform/GlfwWindow.h"
#include "reference/Report.h"
#include "render/BatchRender.h"
#include "scene/io/SceneFile.h"
#include "shadows/ShadowTechnique.h"
#include "util/Log.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <sstream>

using namespace penumbra;

namespace {

void parseSize(const std::string& text, int& w, int& h) {
    if (std::sscanf(text.c_str(), "%dx%d", &w, &h) != 2 || w <= 0 || h <= 0)
        throw CLI::ValidationError("--size", "expected WxH, e.g. 1280x720, got '" + text + "'");
}

int runRender(render::BatchJob job) {
    std::cout << "penumbra: rendering " << job.frames << " frame(s) of " << job.scene.string() << " at " << job.width
              << "x" << job.height << " (headless)\n";
    const render::BatchResult r = render::renderBatch(job);
    std::printf("device: %s\n", r.device.c_str());
    std::printf("mean GPU ms per frame over %d frame(s): shadow %.2f | opaque %.2f | translucent %.2f | post %.2f | total %.2f\n",
                r.frames, r.mean.shadowMs, r.mean.opaqueMs, r.mean.translucentMs, r.mean.postMs, r.mean.totalMs());
    std::printf("shadow-map memory: %.2f MiB\n", static_cast<double>(r.shadowMemoryBytes) / (1024.0 * 1024.0));
    std::printf("wrote %s/frame_0000.png .. and %s\n", job.outDir.string().c_str(), r.statsFile.string().c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App cli{"penumbra: a real-time renderer whose subject is shadows"};
    cli.require_subcommand(0, 1);

    std::string scenePath;
    std::string technique;
    int shadowRes = 0;
    std::string size;
    std::vector<std::string> paramTexts;

    auto* view = cli.add_subcommand("view", "open a window and fly through a scene");
    app::ViewerOptions viewOpts;
    view->add_option("scene", scenePath, "scene file (.json) or model file; default: the built-in scene");
    view->add_option("--technique", technique, "shadow technique (see `penumbra techniques`)");
    view->add_option("--shadow-res", shadowRes, "shadow-map resolution for every light")->check(CLI::Range(16, 16384));
    view->add_option("--size", size, "window size WxH (default 800x600)");
    view->add_option("--controller", viewOpts.controller, "fly | trackball | orbit")
        ->check(CLI::IsMember({"fly", "trackball", "orbit"}));
    view->add_option("--exit-after", viewOpts.exitAfterFrames, "quit after N frames (scripted runs)");
    view->add_flag("--gl-debug", viewOpts.debugContext, "debug GL context with KHR_debug messages");
    view->add_option("--param", paramTexts, "technique parameter name=value (repeatable)");
    view->add_option("--transparency", viewOpts.transparency, "sorted-objects | sorted-triangles | depth-peeling | dual-depth-peeling | weighted | stochastic")
        ->check(CLI::IsMember({"sorted-objects", "sorted-triangles", "depth-peeling", "dual-depth-peeling", "weighted", "stochastic"}));

    auto* rend = cli.add_subcommand("render", "render frames headless (EGL) to PNG + stats.json");
    render::BatchJob job;
    rend->add_option("scene", scenePath, "scene file (.json) or model file; default: the built-in scene");
    rend->add_option("--technique", technique, "shadow technique (see `penumbra techniques`)");
    rend->add_option("--shadow-res", shadowRes, "shadow-map resolution for every light")->check(CLI::Range(16, 16384));
    rend->add_option("--size", size, "image size WxH (default 1280x720)");
    rend->add_option("--frames", job.frames, "number of frames")->check(CLI::Range(1, 100000));
    rend->add_option("--time", job.startTime, "scene time of the first frame, seconds");
    rend->add_option("--fps", job.fps, "frames per second of scene time")->check(CLI::PositiveNumber);
    rend->add_option("--out", job.outDir, "output directory (default ./out)");
    rend->add_flag("--overlay", job.overlay, "draw the light-space debug maps over the frame");
    rend->add_option("--param", paramTexts, "technique parameter name=value (repeatable)");
    rend->add_option("--transparency", job.transparency, "sorted-objects | sorted-triangles | depth-peeling | dual-depth-peeling | weighted | stochastic")
        ->check(CLI::IsMember({"sorted-objects", "sorted-triangles", "depth-peeling", "dual-depth-peeling", "weighted", "stochastic"}));
    rend->add_option("--peel-layers", job.peelLayers, "layers kept by (dual) depth peeling (default 4)")->check(CLI::Range(1, 32));
    rend->add_option("--egl-platform", job.eglPlatform, "auto | surfaceless | device")
        ->check(CLI::IsMember({"auto", "surfaceless", "device"}));

    reference::ReportJob report;
    std::string techniqueList;
    auto* ref = cli.add_subcommand("reference", "ray-trace the ground truth of a frame (Embree, all cores)");
    auto* cmp = cli.add_subcommand("compare", "score shadow techniques against the ray-traced reference");
    for (CLI::App* sub : {ref, cmp}) {
        sub->add_option("scene", scenePath, "scene file (.json) or model file; default: the built-in scene");
        sub->add_option("--size", size, "image size WxH (default 1280x720)");
        sub->add_option("--time", report.time, "scene time of the frame, seconds");
        sub->add_option("--samples", report.samples, "samples per pixel for area lights (default 64)")
            ->check(CLI::Range(1, 65536));
        sub->add_option("--egl-platform", report.eglPlatform, "auto | surfaceless | device")
            ->check(CLI::IsMember({"auto", "surfaceless", "device"}));
    }
    ref->add_option("--out", report.outDir, "output directory (default ./reference)");
    cmp->add_option("--out", report.outDir, "output directory (default ./compare)");
    cmp->add_option("--techniques", techniqueList, "comma-separated technique names (default: all)");
    cmp->add_option("--shadow-res", report.shadowResolution, "shadow-map resolution for every light")
        ->check(CLI::Range(16, 16384));
    cmp->add_option("--param", paramTexts, "parameter name=value for every technique that has it (repeatable)");
    cmp->add_option("--timed-frames", report.timedFrames, "frames timed per technique (default 3)")
        ->check(CLI::Range(1, 1000));

    auto* techniques = cli.add_subcommand("techniques", "list the shadow techniques");

    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return cli.exit(e);
    }

    try {
        const std::filesystem::path scene = scenePath.empty() ? scene::io::defaultScenePath() : std::filesystem::path(scenePath);
        if (!technique.empty() && !shadows::isKnownTechnique(technique))  // fail early, before any GL work
            throw std::invalid_argument("unknown shadow technique '" + technique + "'; known: " + shadows::knownTechniqueNames());
        if (*techniques) {
            for (const auto& t : shadows::techniqueRegistry()) std::printf("%-10s %s\n", t.name.c_str(), t.description.c_str());
            return 0;
        }
        std::vector<std::pair<std::string, float>> params;
        for (const auto& text : paramTexts) params.push_back(shadows::parseParameter(text));
        viewOpts.parameters = job.parameters = report.parameters = params;
        if (*ref || *cmp) {
            report.scene = scene;
            if (!size.empty()) parseSize(size, report.width, report.height);
            if (report.outDir.empty()) report.outDir = *ref ? "reference" : "compare";
            if (*ref) return reference::runReference(report);
            std::stringstream list(techniqueList);
            for (std::string name; std::getline(list, name, ',');)
                if (!name.empty()) report.techniques.push_back(name);
            if (techniqueList.empty())
                for (const auto& t : shadows::techniqueRegistry()) report.techniques.push_back(t.name);
            return reference::runCompare(report);
        }
        const bool wantView = *view || (!*rend && platform::displayAvailable());
        if (wantView) {
            viewOpts.scene = scene;
            viewOpts.technique = technique;
            viewOpts.shadowResolution = shadowRes;
            if (!size.empty()) parseSize(size, viewOpts.width, viewOpts.height);
            return app::runViewer(viewOpts);
        }
        if (!*rend) std::cout << "penumbra: no display found; rendering the default scene headless instead\n";
        job.scene = scene;
        job.technique = technique;
        job.shadowResolution = shadowRes;
        if (!size.empty()) parseSize(size, job.width, job.height);
        if (!*rend) job.frames = 3;
        return runRender(job);
    } catch (const CLI::ValidationError& e) {
        log::error("{}", e.what());
        return 2;
    } catch (const std::exception& e) {
        log::error("{}", e.what());
        return 1;
    }
}
