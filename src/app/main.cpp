// penumbra command line: parses arguments and calls the core. No GL calls here.
#include "app/BenchCommand.h"
#include "app/MallocTuning.h"
#include "bench/Suites.h"
#include "app/ReferenceCommands.h"
#include "app/RenderCommand.h"
#include "app/RenderOptionsCli.h"
#include "app/SeedLaunch.h"
#include "app/TechniqueList.h"
#include "app/Viewer.h"
#include "platform/GlfwWindow.h"
#include "scene/io/SceneFile.h"
#include "util/Log.h"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <unistd.h>

using namespace penumbra;

namespace {

int runRender(const app::BatchJob& job) {
    std::cout << "penumbra: rendering " << job.frames << " frame(s) of " << job.scene.string() << " at " << job.width
              << "x" << job.height << " (headless)\n";
    const app::BatchResult r = app::renderBatch(job);
    std::printf("device: %s\n", r.device.c_str());
    std::printf("mean GPU ms per frame over %d frame(s): shadow %.2f | opaque %.2f | translucent %.2f | post %.2f | total %.2f\n",
                r.frames, r.mean.shadowMs, r.mean.opaqueMs, r.mean.translucentMs, r.mean.postMs, r.mean.totalMs());
    std::printf("shadow-map memory: %.2f MiB\n", static_cast<double>(r.shadowMemoryBytes) / (1024.0 * 1024.0));
    std::printf("triangles drawn into shadow maps per frame, per light:");
    for (double t : r.shadowTriangles) std::printf(" %.0f", t);
    std::printf("\n");
    if (job.pngEvery > 0)
        std::printf("wrote %s/frame_0000.png .. (every %d) and %s\n", job.outDir.string().c_str(), job.pngEvery,
                    r.statsFile.string().c_str());
    else
        std::printf("wrote %s (no PNG: --png-every 0)\n", r.statsFile.string().c_str());
    if (!r.soak.empty()) {
        long maxRss = 0, maxHeap = 0, maxObjects = 0;
        int errors = 0;
        for (const auto& s : r.soak) {
            maxRss = std::max(maxRss, s.rssKiB);
            maxHeap = std::max(maxHeap, s.heapKiB);
            maxObjects = std::max(maxObjects, s.glObjects);
            errors += s.glErrors;
        }
        const auto& first = r.soak.front();
        const auto& last = r.soak.back();
        std::printf("soak over %d frames, %zu samples: RSS first %.1f / last %.1f / max %.1f MiB; malloc'd first %.1f / last %.1f / "
                    "max %.1f MiB; live GL objects first %ld / last %ld / max %ld; GL errors %d\n",
                    r.frames, r.soak.size(), first.rssKiB / 1024.0, last.rssKiB / 1024.0, maxRss / 1024.0,
                    first.heapKiB / 1024.0, last.heapKiB / 1024.0, maxHeap / 1024.0, first.glObjects,
                    last.glObjects, maxObjects, errors);
    }
    return 0;
}

std::filesystem::path sceneOrDefault(const std::filesystem::path& scene) {
    return scene.empty() ? scene::io::defaultScenePath() : scene;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App cli{"penumbra: a real-time renderer whose subject is shadows"};
    cli.require_subcommand(0, 1);

    auto* view = cli.add_subcommand("view", "open a window and fly through a scene");
    app::ViewerOptions viewer;
    app::addSceneAndSize(*view, viewer.scene, viewer.width, viewer.height, "800x600");
    app::addRenderOptions(*view, viewer.render);
    view->add_option("--split", viewer.split, "start in split view: the right side with TECHNIQUE[:name=value,...] (v toggles, x swaps, drag the divider)");
    view->add_flag("--reference", viewer.referenceMode, "start in reference mode: the ray-traced frame, traced in the background (r)");
    view->add_flag("--heat-map", viewer.heatMap, "with --reference: show |technique - reference| (g)");
    view->add_option("--drop", viewer.drop, "scripted: deliver FILE on the first frame as if dropped on the window");
    view->add_option("--choose", viewer.choose, "scripted: choose TECHNIQUE in the panel on the first frame, as a click would")->check(app::checkTechniqueName);
    view->add_option("--controller", viewer.controller, "fly | trackball | orbit")->check(CLI::IsMember({"fly", "trackball", "orbit"}));
    view->add_option("--exit-after", viewer.exitAfterFrames, "quit after N frames (scripted runs)");
    view->add_flag("--gl-debug", viewer.debugContext, "debug GL context with KHR_debug messages");
    app::SeedChoices viewSeed, renderSeed;
    app::addSeedChoices(*view, viewSeed);
    app::addMallocOption(*view, viewer.tunedMalloc);
    view->add_flag("--storm", viewer.resizeStorm, "robustness drill: minimise, restore, 1x1, 8192x8192 and technique switches, every frame");

    auto* rend = cli.add_subcommand("render", "render frames headless (EGL) to PNG + stats.json");
    app::BatchJob job;
    app::addSceneAndSize(*rend, job.scene, job.width, job.height, "1280x720");
    app::addRenderOptions(*rend, job.render);
    rend->add_option("--frames", job.frames, "number of frames")->check(CLI::Range(1, 100000));
    rend->add_option("--time", job.startTime, "scene time of the first frame, seconds");
    rend->add_option("--fps", job.fps, "frames per second of scene time")->check(CLI::PositiveNumber);
    rend->add_option("--out", job.outDir, "output directory (default ./out)");
    rend->add_option("--cycle-techniques", job.cycleTechniquesEvery, "soak: switch to the next technique every N frames")
        ->check(CLI::NonNegativeNumber);
    rend->add_option("--cycle-sizes", job.cycleSizesEvery, "soak: change output size and shadow-map resolution every N frames")
        ->check(CLI::NonNegativeNumber);
    rend->add_option("--png-every", job.pngEvery, "write every Nth frame as PNG (default 1; 0: none)")->check(CLI::NonNegativeNumber);
    rend->add_option("--split", job.split, "split view: the columns right of the divider with TECHNIQUE[:name=value,...]");
    rend->add_option("--split-at", job.splitAt, "split view: share of the width left of the divider (default 0.5)")->check(CLI::Range(0.0f, 1.0f));
    app::addEglPlatform(*rend, job.eglPlatform);
    app::addMallocOption(*rend, job.tunedMalloc);
    app::addSeedChoices(*rend, renderSeed);
    std::string renderController;  // -m on render: accepted for batch files that also open windows

    auto* menu = cli.add_subcommand("menu", "seed 002's text menu: scene, technique, camera manipulator (and LiSPSM's tiles), then the window");
    bool menuPrintOnly = false;
    menu->add_flag("--print", menuPrintOnly, "print the chosen options and the equal command line instead of opening the window");
    menu->add_option("--exit-after", viewer.exitAfterFrames, "quit after N frames (scripted runs)");

    app::ReportJob report;
    std::string techniqueList;
    auto* ref = cli.add_subcommand("reference", "ray-trace the ground truth of a frame (Embree, all cores)");
    auto* cmp = cli.add_subcommand("compare", "score shadow techniques against the ray-traced reference");
    for (CLI::App* sub : {ref, cmp}) {
        app::addSceneAndSize(*sub, report.scene, report.width, report.height, "1280x720");
        sub->add_option("--time", report.time, "scene time of the frame, seconds");
        sub->add_option("--samples", report.samples, "samples per pixel for area lights (default 64)")->check(CLI::Range(1, 65536));
        app::addEglPlatform(*sub, report.eglPlatform);
        auto* nearest = sub->add_flag("--translucent-receivers", report.translucentReceivers,
                                      "score the nearest surface, translucent ones too (default: the nearest opaque surface)");
        sub->add_flag("--behind-glass", report.behindGlass,
                      "score the surface seen through the nearest one, where that one is translucent (a glass box's far "
                      "side, the floor under a pane); other pixels are left out")
            ->excludes(nearest);
    }
    ref->add_option("--out", report.outDir, "output directory (default ./reference)");
    cmp->add_option("--out", report.outDir, "output directory (default ./compare)");
    cmp->add_option("--techniques", techniqueList,
                    "comma-separated techniques (default: all); each may name parameters of its own over --param's, "
                    "technique:name=value[:name=value...], to score variants side by side, e.g. msm,msm:mipmaps=false");
    app::addRenderOptions(*cmp, report.render, {.technique = false, .overlay = false, .transparency = false});
    cmp->add_option("--timed-frames", report.timedFrames, "frames timed per technique (default 3)")->check(CLI::Range(1, 1000));
    cmp->add_option("--motion-frames", report.motionFrames,
                    "also pan the camera over N frames at a fixed scene time and score shadows' frame-to-frame change (0: off)")
        ->check(CLI::Range(0, 1000));
    cmp->add_option("--motion-speed", report.motionPixelsPerFrame, "the pan's speed at the camera target, pixels per frame (default 0.5)")
        ->check(CLI::Range(0.0f, 1000.0f));

    auto* benchCmd = cli.add_subcommand("bench", "measure speed and memory: frames back to back, report in bench.json, bench.csv, report.html");
    app::BenchJob bench;
    for (int i = 0; i < argc; ++i) bench.commandLine.emplace_back(argv[i]);
    benchCmd->add_option("scenes", bench.scenes, "scene or model files (default: the built-in scene)");
    benchCmd->add_option_function<std::string>(
        "--techniques",
        [&bench](const std::string& list) {
            std::stringstream in(list);
            for (std::string spec; std::getline(in, spec, ',');) {
                if (spec.empty()) continue;
                std::string name;
                try {
                    name = shadows::splitTechniqueParameters(spec).first;
                } catch (const std::invalid_argument& e) {
                    throw CLI::ValidationError("--techniques", "'" + spec + "': expected name:parameter=value[:parameter=value...] (" +
                                                                   e.what() + ")");
                }
                if (name != "all" && !bench::isFloor(name) && !shadows::isKnownTechnique(name)) {
                    std::string known = "all, " + shadows::knownTechniqueNames();
                    for (const char* floor : bench::kFloors) known += std::string(", ") + floor;
                    throw CLI::ValidationError("--techniques", "unknown shadow technique '" + name + "'; known: " + known);
                }
                bench.techniques.push_back(spec);
            }
        },
        "comma-separated techniques, or all (default: the scene's own); each may name parameters of its own, "
        "technique:name=value[:name=value...], e.g. vsm,vsm:blur_kernel=gaussian");
    benchCmd->add_option_function<std::string>(
        "--shadow-res",
        [&bench](const std::string& list) {
            std::stringstream in(list);
            for (std::string n; std::getline(in, n, ',');) {
                char* end = nullptr;
                const long v = std::strtol(n.c_str(), &end, 10);
                if (n.empty() || *end || v < 16 || v > 16384)
                    throw CLI::ValidationError("--shadow-res", "expected sizes within 16..16384 like 256,1024,4096, got '" + n + "'");
                bench.shadowResolutions.push_back(static_cast<int>(v));
            }
        },
        "comma-separated shadow-map resolutions (default: each light's own)");
    benchCmd->add_option("--suite", bench.suites, "named suite(s): " + bench::suiteList())->check(CLI::IsMember(bench::suiteNames()));
    app::addSize(*benchCmd, bench.settings.width, bench.settings.height, "1280x720");
    auto* seconds = benchCmd->add_option("--seconds", bench.settings.seconds, "measure each case this long (default 2)")
                        ->check(CLI::PositiveNumber);
    benchCmd->add_option("--frames", bench.settings.frames, "measure each case this many frames instead")
        ->check(CLI::Range(1, 1000000))->excludes(seconds);
    benchCmd->add_option("--rounds", bench.rounds,
                         "measure the whole case list this many times in turn and print each case's frame against its "
                         "scene's first case, round by round, with the median (default 1; ratios that hold on a machine "
                         "whose speed swings within seconds)")
        ->check(CLI::Range(1, 100));
    benchCmd->add_option("--warmup-seconds", bench.settings.warmupSeconds, "warm up at least this long, then until frame times settle (default 1)")
        ->check(CLI::Range(0.0, 600.0));
    benchCmd->add_option("--out", bench.outDir, "output folder (default ./bench-out)");
    benchCmd->add_option("--baseline", bench.baseline, "an earlier bench.json: adds ratios against it")->check(CLI::ExistingFile);
    benchCmd->add_option("--grid-scene", bench.gridScenes,
                         "also a generated scene (ground, 10x10 spheres and tori) of about N triangles, written to OUT/scenes (repeatable)")
        ->check(CLI::Range(std::size_t(1000), std::size_t(50000000)));
    benchCmd->add_option("--scene-step", bench.settings.sceneStep,
                         "scene seconds per frame, from 0 at each case's first measured frame (default 1/60); with --frames N "
                         "every case measures the same N frames, e.g. --frames 64 --scene-step 0.125: the default scene's "
                         "whole 8 s animation")
        ->check(CLI::Range(0.0f, 60.0f));
    benchCmd->add_option("--interleave", bench.settings.interleaveFrames,
                         "measure the cases of each scene together, in turns of N frames each (N >= 5; the first two "
                         "and the last frame of a turn are not counted), so that a machine whose speed swings slows "
                         "them alike; every case of the scene is held in memory at once (default 0: one after another)")
        ->check(CLI::Range(5, 1000));
    benchCmd->add_flag("--fixed-camera", bench.settings.fixedCamera, "keep the scene's camera (no camera_path, no orbit): for peer comparisons");
    benchCmd->add_flag("--calibrate", bench.settings.calibrate, "check every pass's timer query against a glFinish wall clock");
    benchCmd->add_flag("--quality", bench.quality, "add compare's metrics and heat maps (ray-traced reference of the first scene)");
    benchCmd->add_option("--samples", bench.samples, "reference samples per pixel for --quality (default 16)")->check(CLI::Range(1, 4096));
    benchCmd->add_flag("!--no-images", bench.settings.images, "no picture per case");
    app::addMallocOption(*benchCmd, bench.tunedMalloc);
    app::addRenderOptions(*benchCmd, bench.settings.render, {.technique = false, .shadowResolution = false, .overlay = false});
    app::addEglPlatform(*benchCmd, bench.eglPlatform);

    auto* techniques = cli.add_subcommand("techniques", "list the shadow techniques");
    bool verbose = false;
    techniques->add_flag("--verbose", verbose, "with every parameter: kind, range, default and help (needs an EGL context)");

    // The seed's -sc -sh -m -cw -ch become long options CLI11 can parse (app/SeedLaunch.h).
    const std::vector<std::string> args = app::expandSeedFlags(argc, argv);
    std::vector<const char*> argPointers;
    for (const auto& a : args) argPointers.push_back(a.c_str());
    try {
        cli.parse(static_cast<int>(argPointers.size()), argPointers.data());
    } catch (const CLI::ParseError& e) {
        return cli.exit(e);
    }

    try {
        if (*techniques) return app::printTechniques(verbose);
        if (*benchCmd) return app::runBench(bench);
        if (*ref || *cmp) {
            report.scene = sceneOrDefault(report.scene);
            if (report.outDir.empty()) report.outDir = *ref ? "reference" : "compare";
            if (*ref) return app::runReference(report);
            std::stringstream list(techniqueList);
            for (std::string name; std::getline(list, name, ',');)
                if (!name.empty()) report.techniques.push_back(name);
            if (techniqueList.empty())
                for (const auto& t : shadows::techniqueRegistry()) report.techniques.push_back(t.name);
            return app::runCompare(report);
        }
        // Seed 002: with no arguments on a terminal with a display, its menu asks what to open.
        const bool bareOnTerminal = argc == 1 && ::isatty(0) && platform::displayAvailable();
        if (*menu || bareOnTerminal) {
            const app::SeedChoices choices = app::askSeedMenu(std::cin, std::cout);
            app::applySeedChoices(choices, viewer.scene, viewer.render, viewer.controller);
            std::cout << "same as: " << app::seedCommandLine(choices) << "\n";
            if (menuPrintOnly) {
                std::cout << "scene " << viewer.scene.string() << "\ntechnique "
                          << (viewer.render.technique.empty() ? "(the scene's regions)" : viewer.render.technique) << "\n";
                for (const auto& [name, value] : viewer.render.parameters) std::cout << "--param " << name << "=" << value << "\n";
                std::cout << "controller " << viewer.controller << "\n";
                return 0;
            }
            viewer.scene = sceneOrDefault(viewer.scene);
            return app::runViewer(viewer);
        }
        if (*view || (!*rend && platform::displayAvailable())) {
            app::applySeedChoices(viewSeed, viewer.scene, viewer.render, viewer.controller);
            viewer.scene = sceneOrDefault(viewer.scene);
            return app::runViewer(viewer);
        }
        if (!*rend) {
            std::cout << "penumbra: no display found; rendering the default scene headless instead\n";
            job.frames = 3;
        }
        app::applySeedChoices(renderSeed, job.scene, job.render, renderController);
        job.scene = sceneOrDefault(job.scene);
        return runRender(job);
    } catch (const std::exception& e) {
        log::error("{}", e.what());
        return 1;
    }
}
