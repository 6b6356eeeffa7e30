#include "app/ReferenceCommands.h"

#include "util/OutputFiles.h"
#include "gl/Debug.h"
#include "platform/EglContext.h"
#include "reference/Comparison.h"
#include "render/Offscreen.h"
#include "shadows/ShadowTechnique.h"
#include "scene/io/SceneFile.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>
#include <tuple>

namespace penumbra::app {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace reference;

namespace {

struct Session {
    std::unique_ptr<platform::EglContext> context;
    scene::Scene scene;
};

Session open(const ReportJob& job) {
    if (job.width <= 0 || job.height <= 0) throw std::invalid_argument("--size must be positive");
    if (job.samples < 1) throw std::invalid_argument("--samples must be at least 1");
    Session s{nullptr, scene::io::loadScene(job.scene)};
    if (s.scene.lights.empty())
        throw std::invalid_argument(job.scene.string() + ": the scene has no lights: there are no shadows to compare");
    s.context = platform::EglContext::create(job.eglPlatform);
    gl::enableDebugOutput();
    util::createOutputDirectory(job.outDir);
    return s;
}

std::string safeName(std::string s) {
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
    return s;
}

reference::Surfaces surfacesOf(const ReportJob& job) {
    if (job.behindGlass) return reference::Surfaces::BehindGlass;
    return job.translucentReceivers ? reference::Surfaces::Nearest : reference::Surfaces::NearestOpaque;
}

// compare.json's "surfaces".
const char* surfacesName(reference::Surfaces surfaces) {
    switch (surfaces) {
    case reference::Surfaces::Nearest: return "nearest";
    case reference::Surfaces::BehindGlass: return "behind glass";
    case reference::Surfaces::NearestOpaque: break;
    }
    return "nearest opaque";
}

// --behind-glass on a view without glass scores nothing: said, so that zeros are not read as exact.
void warnIfNothingBehindGlass(const ReportJob& job, const Comparison& cmp, const char* command) {
    const std::vector<bool>& covered = cmp.surfaces().covered;
    if (job.behindGlass && std::none_of(covered.begin(), covered.end(), [](bool c) { return c; }))
        std::fprintf(stderr, "penumbra %s: --behind-glass: no pixel's nearest surface is translucent in this view; nothing is scored\n",
                     command);
}

}  // namespace

int runReference(const ReportJob& job) {
    Session s = open(job);
    Comparison cmp(s.scene, job.width, job.height, job.time, surfacesOf(job));
    warnIfNothingBehindGlass(job, cmp, "reference");
    cmp.traceReference(job.samples, true);
    util::writePng(job.outDir / "reference.png", job.width, job.height, cmp.shade(cmp.referenceVisibility()));
    json lights = json::array();
    for (std::size_t l = 0; l < s.scene.lights.size(); ++l) {
        const std::string file = "visibility_" + std::to_string(l) + "_" + safeName(s.scene.lights[l].name) + ".png";
        util::writePng(job.outDir / file, job.width, job.height,
                         encodeLinear(cmp.referenceVisibility()[l], job.width, job.height));
        lights.push_back({{"name", s.scene.lights[l].name}, {"visibility", file}, {"size", s.scene.lights[l].size}});
    }
    const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    util::writeJson(job.outDir / "reference.json",
              {{"scene", job.scene.string()}, {"width", job.width}, {"height", job.height}, {"time", job.time},
               {"samples", job.samples}, {"threads", threads}, {"triangles", s.scene.triangleCount()},
               {"seconds", cmp.referenceSeconds()}, {"lights", lights}});
    std::printf("reference: %dx%d, %zu triangles, %d samples for area lights, %u threads: %.2f s\n", job.width,
                job.height, s.scene.triangleCount(), job.samples, threads, cmp.referenceSeconds());
    std::printf("wrote %s/reference.png, visibility_*.png, reference.json\n", job.outDir.string().c_str());
    return 0;
}

namespace {

// One entry of compare's --techniques: "TECHNIQUE[:name=value...]", its own parameters over --param's.
struct CompareVariant {
    std::string label, technique;
    shadows::ParameterValues own, parameters;
};

std::vector<CompareVariant> compareVariants(const ReportJob& job) {
    std::vector<CompareVariant> variants;
    for (const std::string& spec : job.techniques) {
        CompareVariant v{spec, {}, {}, job.render.parameters};
        try {
            std::tie(v.technique, v.own) = shadows::splitTechniqueParameters(spec);
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("--techniques: '" + spec + "': expected TECHNIQUE[:name=value...] (" + e.what() + ")");
        }
        if (!shadows::isKnownTechnique(v.technique))
            throw std::invalid_argument("unknown shadow technique '" + v.technique + "'; known: " + shadows::knownTechniqueNames());
        v.parameters.insert(v.parameters.end(), v.own.begin(), v.own.end());  // applied in order: its own win
        variants.push_back(std::move(v));
    }
    if (variants.empty()) throw std::invalid_argument("--techniques names no technique");
    return variants;
}

// A variant's own parameters must be its technique's (a misspelt one would score the plain
// technique under the variant's label); each of --param's must be some compared technique's, and
// applies where it fits, and each technique that has it must take its value (every variant is
// made whenever --param names any: two techniques may share a name with different ranges or
// choices, as radius_texels does). Needs a GL context: a technique builds its programs when made. Before the
// reference is traced, so as to fail early.
void checkParameters(const std::vector<CompareVariant>& variants, const shadows::ParameterValues& common) {
    std::vector<std::string> unmatched;  // --param's names no technique has yet
    for (const auto& [name, value] : common) unmatched.push_back(name);
    for (const CompareVariant& v : variants) {
        if (v.own.empty() && common.empty()) continue;
        const auto technique = shadows::createTechnique(v.technique);
        std::string known;
        for (const auto& parameter : technique->parameters()) {
            known += (known.empty() ? "" : ", ") + parameter.name;
            std::erase(unmatched, parameter.name);
        }
        shadows::applyParameters(technique->parameters(), common);  // a value it does not take throws here
        const std::vector<std::string> unknown = shadows::applyParameters(technique->parameters(), v.own);
        if (!unknown.empty())
            throw std::invalid_argument("--techniques: '" + v.label + "': " + v.technique + " has no parameter '" + unknown.front() +
                                        "'; its parameters: " + (known.empty() ? "none" : known));
    }
    if (!unmatched.empty())
        throw std::invalid_argument("--param " + unmatched.front() + ": no technique compared has that parameter (`penumbra techniques --verbose` lists them)");
}

}  // namespace

int runCompare(const ReportJob& job) {
    const std::vector<CompareVariant> variants = compareVariants(job);
    Session s = open(job);
    checkParameters(variants, job.render.parameters);
    Comparison cmp(s.scene, job.width, job.height, job.time, surfacesOf(job));
    warnIfNothingBehindGlass(job, cmp, "compare");
    cmp.setRenderOptions(job.render);
    cmp.traceReference(job.samples, true);
    const auto referenceImage = cmp.shade(cmp.referenceVisibility());
    util::writePng(job.outDir / "reference.png", job.width, job.height, referenceImage);

    std::vector<std::vector<std::uint8_t>> shaded, heat;
    json rows = json::array();
    const bool motion = job.motionFrames > 1;
    int labelWidth = 14;
    for (const CompareVariant& v : variants) labelWidth = std::max(labelWidth, static_cast<int>(v.label.size()));
    std::printf("\n%-*s %9s %9s %11s %9s %10s %10s %10s%s\n", labelWidth, "technique", "RMSE", "wrong %", "colour err",
                "noise", "shadow ms", "frame ms", "MiB", motion ? "  temporal  crawl %" : "");
    for (const CompareVariant& v : variants) {
        const TechniqueScore sc = cmp.evaluate(v.technique, job.render.shadowResolution, job.timedFrames, v.parameters);
        shaded.push_back(cmp.shade(sc.visibility));
        heat.push_back(cmp.heatMap(sc));
        const std::string file = safeName(v.label);  // a plain technique's name as it is
        util::writePng(job.outDir / (file + ".png"), job.width, job.height, shaded.back());
        util::writePng(job.outDir / (file + "_heat.png"), job.width, job.height, heat.back());
        const double mib = static_cast<double>(sc.memoryBytes) / (1024.0 * 1024.0);
        std::printf("%-*s %9.4f %9.3f %11.4f %9.4f %10.2f %10.2f %10.2f", labelWidth, v.label.c_str(), sc.rmse, 100.0 * sc.wrongShare,
                    sc.colourError, sc.noise, sc.shadowMs, sc.totalMs, mib);
        json moving = nullptr;
        if (motion) {
            const MotionScore m = cmp.evaluateMotion(v.technique, job.render.shadowResolution, job.motionFrames,
                                                     job.motionPixelsPerFrame, v.parameters);
            std::printf(" %9.4f %8.3f", m.temporalError, 100.0 * m.crawlShare);
            moving = {{"frames", m.frames}, {"pixels_per_frame", job.motionPixelsPerFrame},
                      {"temporal_error", m.temporalError}, {"crawl_share", m.crawlShare}, {"compared", m.pixels}};
        }
        std::printf("\n");
        json own = json::object();
        for (const auto& [name, value] : v.own) own[name] = value;
        rows.push_back({{"technique", v.technique}, {"label", v.label}, {"parameters", own}, {"rmse", sc.rmse}, {"wrong_pixel_share", sc.wrongShare},
                        {"colour_error", sc.colourError}, {"noise", sc.noise}, {"compared_pixels", sc.pixels},
                        {"coloured_pixels", sc.colouredPixels}, {"shadow_ms", sc.shadowMs}, {"frame_ms", sc.totalMs},
                        {"memory_bytes", sc.memoryBytes}, {"image", file + ".png"}, {"heat_map", file + "_heat.png"},
                        {"motion", moving}});
    }
    // Side by side: cells of (image over heat map) at half size, five to a row; the reference's
    // cell holds the reference image over a blank.
    const int tw = job.width / 2, th = job.height / 2;
    std::vector<std::vector<std::uint8_t>> cells;
    auto cell = [&](const std::vector<std::uint8_t>& top, const std::vector<std::uint8_t>& bottom) {
        std::vector<std::uint8_t> c = halve(top, job.width, job.height);
        const auto b = halve(bottom, job.width, job.height);
        c.insert(c.end(), b.begin(), b.end());
        cells.push_back(std::move(c));
    };
    cell(referenceImage, std::vector<std::uint8_t>(referenceImage.size(), 255));
    for (std::size_t k = 0; k < shaded.size(); ++k) cell(shaded[k], heat[k]);
    std::vector<const std::vector<std::uint8_t>*> tiles;
    for (const auto& c : cells) tiles.push_back(&c);
    int mw = 0, mh = 0;
    const auto sideBySide = montage(tiles, tw, 2 * th, std::min<int>(5, static_cast<int>(cells.size())), mw, mh);
    util::writePng(job.outDir / "side_by_side.png", mw, mh, sideBySide);

    util::writeJson(job.outDir / "compare.json",
              {{"device", platform::glDeviceDescription()}, {"scene", job.scene.string()}, {"width", job.width},
               {"height", job.height}, {"time", job.time}, {"samples", job.samples},
               {"shadow_resolution", job.render.shadowResolution}, {"reference_seconds", cmp.referenceSeconds()},
               {"wrong_threshold", VisibilityError::kWrongThreshold},
               {"surfaces", surfacesName(surfacesOf(job))},
               {"techniques", rows}});
    std::printf("\nreference %.2f s; errors are of light visibility on pixels each light reaches; wrong = off by > %.1f\n",
                cmp.referenceSeconds(), VisibilityError::kWrongThreshold);
    std::printf("wrote %s/{compare.json, reference.png, side_by_side.png, <technique>.png, <technique>_heat.png}\n",
                job.outDir.string().c_str());
    return 0;
}

}  // namespace penumbra::app
