#include "bench/Report.h"

#include "util/DataPaths.h"
#include "util/OutputFiles.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace penumbra::bench {

using nlohmann::json;
namespace fs = std::filesystem;

std::string caseLabel(const CaseResult& r) {
    if (!r.spec.label.empty()) return r.spec.label;
    std::string label = r.technique;
    for (const auto& [name, value] : r.spec.parameters) label += " " + name + "=" + value;
    return r.spec.shadowResolution > 0 ? label + " " + std::to_string(r.spec.shadowResolution) : label;
}

// The median GPU time of a case's shadow pass.
static double shadowPassMs(const CaseResult& r) { return r.passMs[static_cast<std::size_t>(render::Pass::Shadow)].median; }

std::vector<ScalingFit> shadowPassScaling(const std::vector<CaseResult>& results) {
    std::vector<ScalingFit> fits;
    for (const CaseResult& r : results) {
        const std::string label = caseLabel(r);
        auto it = std::find_if(fits.begin(), fits.end(), [&](const ScalingFit& f) { return f.suite == r.spec.suite && f.label == label; });
        if (it == fits.end()) it = fits.insert(fits.end(), ScalingFit{r.spec.suite, label, {}, {}, {}});
        it->triangles.push_back(r.shadowTrianglesPerFrame);
        it->shadowMs.push_back(shadowPassMs(r));
    }
    std::erase_if(fits, [](const ScalingFit& f) {
        std::vector<double> distinct = f.triangles;
        std::sort(distinct.begin(), distinct.end());
        distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
        return distinct.size() < 3 || distinct.back() <= 0;
    });
    for (ScalingFit& f : fits) f.fit = fitLine(f.triangles, f.shadowMs);
    return fits;
}

std::vector<FloorRatio> floorRatios(const std::vector<CaseResult>& results) {
    // The floor of the case's own round: with --rounds, round 1's floor would divide every round.
    const auto floorCase = [&](const CaseResult& r, const char* floor) -> const CaseResult* {
        for (const CaseResult& f : results)
            if (f.technique == floor && f.spec.scene == r.spec.scene && f.spec.shadowResolution == r.spec.shadowResolution &&
                f.spec.round == r.spec.round)
                return &f;
        return nullptr;
    };
    const auto shadowWallMs = [](const CaseResult& r) { return r.calibration[static_cast<std::size_t>(render::Pass::Shadow)].wallMs; };
    std::vector<FloorRatio> ratios;
    for (const CaseResult& r : results) {
        if (isFloor(r.technique)) continue;
        FloorRatio q{caseLabel(r), r.sceneName, "", 0, 0, r.resolutions.size(), r.spec.round};
        const bool mapless = r.shadowMemoryBytes == 0;
        if (const CaseResult* f = floorCase(r, mapless ? kFloorUnshadowed : kFloorLambert); f && f->frameMs.mean > 0) {
            q.frameFloor = f->technique;
            q.frame = r.frameMs.mean / f->frameMs.mean;
        }
        if (const CaseResult* f = floorCase(r, kFloorDepth); f && !mapless && r.calibrated && f->calibrated && shadowWallMs(*f) > 0) {
            q.shadowPass = shadowWallMs(r) / shadowWallMs(*f);
            q.shadowPassByWall = true;
        } else if (f && !mapless && shadowPassMs(*f) > 0) {
            q.shadowPass = shadowPassMs(r) / shadowPassMs(*f);
        }
        if (!q.frameFloor.empty() || q.shadowPass > 0) ratios.push_back(q);
    }
    return ratios;
}

std::vector<RoundRatio> roundRatios(const std::vector<CaseResult>& results) {
    const int rounds = results.empty() ? 0 : results.back().spec.round + 1;
    if (rounds < 2) return {};
    const auto sameCase = [](const CaseResult& a, const CaseResult& b) {
        return a.spec.scene == b.spec.scene && a.spec.suite == b.spec.suite && caseLabel(a) == caseLabel(b) &&
               a.spec.shadowResolution == b.spec.shadowResolution;
    };
    // Round k holds the first round's list again (plan() repeats it): case i of round k is results[k * perRound + i].
    const std::size_t perRound = results.size() / static_cast<std::size_t>(rounds);
    if (perRound * static_cast<std::size_t>(rounds) != results.size()) return {};
    std::vector<RoundRatio> rows;
    for (std::size_t i = 0; i < perRound; ++i) {
        const CaseResult& r = results[i];
        std::size_t baseIndex = 0;
        while (results[baseIndex].spec.scene != r.spec.scene) ++baseIndex;
        RoundRatio row{caseLabel(r), r.sceneName, caseLabel(results[baseIndex]), {}, {}, 0, 0};
        for (int k = 0; k < rounds; ++k) {
            const CaseResult& c = results[static_cast<std::size_t>(k) * perRound + i];
            const CaseResult& base = results[static_cast<std::size_t>(k) * perRound + baseIndex];
            if (!sameCase(c, r) || !sameCase(base, results[baseIndex])) return {};  // not a repeated list
            const double frame = pairedMedian(c.frameSamples), baseFrame = pairedMedian(base.frameSamples);
            row.frameMs.push_back(frame);
            row.ratios.push_back(baseFrame > 0 ? frame / baseFrame : 0.0);
        }
        row.medianFrameMs = summarize(row.frameMs).median;
        row.medianRatio = summarize(row.ratios).median;
        row.ratioInterval = medianInterval(row.ratios);
        rows.push_back(std::move(row));
    }
    return rows;
}

static json roundRatiosJson(const std::vector<CaseResult>& results) {
    json rows = json::array();
    for (const RoundRatio& q : roundRatios(results))
        rows.push_back({{"label", q.label}, {"scene_name", q.sceneName}, {"base", q.base}, {"frame_ms_median_per_round", q.frameMs},
                        {"ratio_to_base_per_round", q.ratios}, {"frame_ms_median", q.medianFrameMs}, {"ratio_to_base_median", q.medianRatio},
                        {"ratio_to_base_median_interval",
                         q.ratioInterval.found ? json{{"low", q.ratioInterval.low}, {"high", q.ratioInterval.high},
                                                      {"coverage", q.ratioInterval.coverage}}
                                               : json(nullptr)}});
    return rows;
}

static json floorRatiosJson(const std::vector<CaseResult>& results) {
    json rows = json::array();
    for (const FloorRatio& q : floorRatios(results))
        rows.push_back({{"label", q.label}, {"scene_name", q.sceneName}, {"frame_floor", q.frameFloor}, {"frame_ratio", q.frame},
                        {"shadow_pass_ratio_to_floor_depth", q.shadowPass},
                        {"shadow_pass_measure", q.shadowPassByWall ? "glFinish wall" : "GPU query median"}, {"round", q.round},
                        {"shadowed_lights", q.lights}});
    return rows;
}

static json scalingJson(const std::vector<CaseResult>& results) {
    json fits = json::array();
    for (const ScalingFit& f : shadowPassScaling(results)) {
        json points = json::array();
        for (std::size_t i = 0; i < f.triangles.size(); ++i) points.push_back({{"triangles", f.triangles[i]}, {"shadow_ms", f.shadowMs[i]}});
        fits.push_back({{"suite", f.suite}, {"label", f.label}, {"points", points},
                        {"slope_ms_per_million_triangles", f.fit.slope * 1e6}, {"intercept_ms", f.fit.intercept}, {"r2", f.fit.r2}});
    }
    return fits;
}

static json summaryJson(const Summary& s) {
    return {{"count", s.count}, {"min", s.min}, {"max", s.max}, {"mean", s.mean}, {"median", s.median}, {"p95", s.p95}};
}

static std::string imageName(std::size_t index, const CaseResult& r) {
    std::string name = std::to_string(index) + "_" + r.sceneName + "_" + caseLabel(r);
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
    return "images/" + name + ".png";
}

// The baseline case with the same suite, scene, label and resolution, if any.
static const json* findBaseline(const json& baseline, const json& c) {
    if (!baseline.contains("cases")) return nullptr;
    for (const json& old : baseline["cases"])
        if (old.value("suite", "") == c["suite"] && old.value("scene_name", "") == c["scene_name"] &&
            old.value("label", "") == c["label"] && old.value("shadow_resolution", -1) == c["shadow_resolution"])
            return &old;
    return nullptr;
}

json benchJson(const std::vector<CaseResult>& results, const BenchSettings& settings, const BenchContext& context,
               const json* baseline) {
    json cases = json::array();
    for (std::size_t i = 0; i < results.size(); ++i) {
        const CaseResult& r = results[i];
        json passes = json::object(), samples = json::object(), calibration = json::object();
        for (int p = 0; p < render::kPassCount; ++p) {
            const char* name = render::toString(static_cast<render::Pass>(p));
            passes[name] = summaryJson(r.passMs[static_cast<std::size_t>(p)]);
            samples[name] = r.passSamples[static_cast<std::size_t>(p)];
            const PassCalibration& cal = r.calibration[static_cast<std::size_t>(p)];
            calibration[name] = {{"query_ms", cal.queryMs}, {"wall_ms", cal.wallMs}, {"flagged", cal.flagged}};
        }
        json parameters = json::object();
        for (const auto& [k, v] : r.parameters) parameters[k] = v;
        if (r.calibrated) calibration["finish_overhead_ms"] = r.finishOverheadMs;
        json c = {
            {"suite", r.spec.suite},
            {"round", r.spec.round},
            {"label", caseLabel(r)},
            {"scene", r.spec.scene.string()},
            {"scene_name", r.sceneName},
            {"scene_triangles", r.sceneTriangles},
            {"technique", r.technique},
            {"shadow_resolution", r.spec.shadowResolution},
            {"light_resolutions", r.resolutions},
            {"parameters", parameters},
            {"width", r.width},
            {"height", r.height},
            {"pass_gpu_ms", passes},
            {"gpu_frame_ms", summaryJson(r.gpuFrameMs)},
            {"frame_ms", summaryJson(r.frameMs)},
            {"cpu_frame_ms", summaryJson(r.cpuFrameMs)},
            {"frame_ms_pair_median", pairedMedian(r.frameSamples)},
            {"fps", {{"mean", r.fpsMean}, {"min", r.fpsMin}, {"max", r.fpsMax}, {"p95", r.fpsP95}}},
            {"shadow_memory_bytes", r.shadowMemoryBytes},
            {"shadow_triangles_per_frame", r.shadowTrianglesPerFrame},
            {"warmup", {{"frames", r.warmupFrames}, {"seconds", r.warmupSeconds}, {"settled", r.settled}}},
            {"measurement", {{"repeated", r.measurementsRepeated}, {"programs_linked", r.programsLinkedMeasuring},
                             {"interleave_frames", r.interleaveFrames}}},
            {"calibration", r.calibrated ? calibration : json(nullptr)},
            {"sub_pass_wall_ms", r.calibrated ? json(r.subPassMs) : json(nullptr)},
            {"gl_errors", r.glErrors},
            {"gl_warnings", r.glWarnings},
            {"image", r.image.empty() ? json(nullptr) : json(imageName(i, r))},
            {"samples", {{"frame_ms", r.frameSamples}, {"cpu_frame_ms", r.cpuSamples}, {"pass_gpu_ms", samples}}},
        };
        if (baseline) {
            if (const json* old = findBaseline(*baseline, c)) {
                const auto ratio = [](double now, double before) { return before > 0 ? now / before : 0.0; };
                c["baseline"] = {
                    {"frame_ms_mean_ratio", ratio(r.frameMs.mean, (*old)["frame_ms"].value("mean", 0.0))},
                    {"gpu_frame_ms_median_ratio", ratio(r.gpuFrameMs.median, (*old)["gpu_frame_ms"].value("median", 0.0))},
                    {"shadow_ms_median_ratio", ratio(shadowPassMs(r), (*old)["pass_gpu_ms"]["shadow"].value("median", 0.0))},
                    {"shadow_memory_ratio", ratio(static_cast<double>(r.shadowMemoryBytes), (*old).value("shadow_memory_bytes", 0.0))},
                };
            } else {
                c["baseline"] = nullptr;
            }
        }
        cases.push_back(std::move(c));
    }
    json parameters = json::object();
    for (const auto& [k, v] : settings.render.parameters) parameters[k] = v;
    return {
        {"format", "penumbra-bench/1"},
        {"created", context.created},
        {"git_revision", context.gitRevision},
        {"command_line", context.commandLine},
        {"device", context.device},
        {"gl_vendor", context.glVendor},
        {"egl_platform", context.eglPlatform},
        {"malloc", context.malloc},
        {"clocks",
         {{"pass_gpu_ms", "GL_TIME_ELAPSED query per pass, glFlush after glBeginQuery, read from a ring of " +
                              std::to_string(render::FrameTimer::kRingDepth) + " frames"},
          {"gpu_frame_ms", "sum of the pass queries of one frame"},
          {"frame_ms", "std::chrono::steady_clock between consecutive frame starts; at most 2 frames in flight (fences)"},
          {"cpu_frame_ms", "std::chrono::steady_clock from a frame's start (after the wait for the frame two before it) until its calls return: "
                           "the submitting thread's share of the frame (on llvmpipe it also holds the vertex stage and binning)"},
          {"frame_ms_pair_median", "median of the means of consecutive frame_ms pairs (bench::pairedMedian); the rounds' ratios use it"},
          {"calibration", "glFinish before and after each pass, steady_clock around it, beside the same pass's query"},
          {"sub_pass_wall_ms", "with calibration: each debug group's (a pass's parts) glFinish-bounded wall ms per frame, by path, from frames of their own (render/SubPassClock.h)"}}},
        {"settings",
         {{"width", settings.width}, {"height", settings.height}, {"frames", settings.frames}, {"seconds", settings.seconds},
          {"warmup_seconds", settings.warmupSeconds}, {"scene_step_seconds", settings.sceneStep},
          {"calibrate", settings.calibrate}, {"fixed_camera", settings.fixedCamera}, {"interleave_frames", settings.interleaveFrames}, {"transparency", render::toString(settings.render.transparency)},
          {"reuse_still_casters", settings.render.reuseStillCasters}, {"depth_prepass", settings.render.depthPrepass},
          {"cull_solid_back_faces", settings.render.cullSolidBackFaces},
          {"tint_only_where_reached", settings.render.tintOnlyWhereReached},
          {"light_only_where_reached", settings.render.lightOnlyWhereReached},
          {"shadow_only_where_cast", settings.render.shadowOnlyWhereCast},
          {"only_casters_that_shadow", settings.render.onlyCastersThatShadow}, {"float_target", settings.render.floatTarget},
          {"parameters", parameters}}},
        {"baseline", baseline ? json(baseline->value("created", "")) : json(nullptr)},
        {"cases", cases},
        {"shadow_pass_scaling", scalingJson(results)},
        {"floor_ratios", floorRatiosJson(results)},
        {"rounds", roundRatiosJson(results)},
    };
}

static std::string csv(const json& doc) {
    std::ostringstream out;
    out << "suite,scene,scene_triangles,technique,label,shadow_resolution,width,height,frames,frame_ms_mean,frame_ms_p95,"
           "fps_mean,fps_min,fps_max,gpu_frame_ms_median,shadow_ms_median,opaque_ms_median,translucent_ms_median,"
           "post_ms_median,shadow_memory_bytes,shadow_triangles_per_frame,calibration_flagged,baseline_frame_ratio,cpu_frame_ms_median\n";
    const auto quoted = [](const std::string& s) {
        std::string q = "\"";
        for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
        return q + "\"";
    };
    for (const json& c : doc["cases"]) {
        bool flagged = false;
        if (c["calibration"].is_object())
            for (const auto& [pass, cal] : c["calibration"].items())
                flagged = flagged || (cal.is_object() && cal["flagged"].get<bool>());
        const json& p = c["pass_gpu_ms"];
        out << quoted(c["suite"]) << ',' << quoted(c["scene_name"]) << ',' << c["scene_triangles"] << ','
            << quoted(c["technique"]) << ',' << quoted(c["label"]) << ',' << c["shadow_resolution"] << ',' << c["width"] << ','
            << c["height"] << ',' << c["frame_ms"]["count"] << ',' << c["frame_ms"]["mean"] << ',' << c["frame_ms"]["p95"] << ','
            << c["fps"]["mean"] << ',' << c["fps"]["min"] << ',' << c["fps"]["max"] << ',' << c["gpu_frame_ms"]["median"] << ','
            << p["shadow"]["median"] << ',' << p["opaque"]["median"] << ',' << p["translucent"]["median"] << ','
            << p["post"]["median"] << ',' << c["shadow_memory_bytes"] << ',' << c["shadow_triangles_per_frame"] << ','
            << (flagged ? "yes" : "no") << ','
            << (c.contains("baseline") && c["baseline"].is_object() ? c["baseline"]["frame_ms_mean_ratio"].dump() : "") << ','
            << c["cpu_frame_ms"]["median"] << '\n';
    }
    return out.str();
}

// Debian's libjs-chart.js; PENUMBRA_CHARTJS overrides.
static fs::path chartLibrary() {
    if (const char* env = std::getenv("PENUMBRA_CHARTJS")) return env;
    for (const char* candidate : {"/usr/share/javascript/chart.js/chart.min.js", "/usr/share/javascript/chart.js/chart.js"})
        if (fs::exists(candidate)) return candidate;
    return {};
}

static std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(file.string() + ": cannot read");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

static std::string dataUri(int w, int h, const std::vector<std::uint8_t>& rgba) {
    return "data:image/png;base64," + util::base64(util::encodePng(w, h, rgba));
}

// Replaces the one occurrence of `marker` in `page`.
static void fill(std::string& page, const std::string& marker, const std::string& text) {
    const auto at = page.find(marker);
    if (at == std::string::npos) throw std::runtime_error("report template lacks " + marker);
    page.replace(at, marker.size(), text);
}

std::string writeBenchReport(const fs::path& dir, const std::vector<CaseResult>& results, const BenchSettings& settings,
                             const BenchContext& context, const std::optional<json>& baseline,
                             const std::optional<Quality>& quality) {
    util::createOutputDirectory(dir / "images");
    json doc = benchJson(results, settings, context, baseline ? &*baseline : nullptr);
    util::writeJson(dir / "bench.json", doc);
    util::writeText(dir / "bench.csv", csv(doc));

    // The page's data: the document without raw samples, images inline.
    json page = doc;
    for (std::size_t i = 0; i < results.size(); ++i) {
        json& c = page["cases"][i];
        c.erase("samples");
        if (!results[i].image.empty()) {
            util::writePng(dir / c["image"].get<std::string>(), results[i].width, results[i].height, results[i].image);
            c["image_data"] = dataUri(results[i].width, results[i].height, results[i].image);
        }
    }
    if (quality) {
        json rows = json::array();
        for (const QualityRow& q : quality->rows)
            rows.push_back({{"technique", q.technique}, {"rmse", q.rmse}, {"wrong_share", q.wrongShare},
                            {"colour_error", q.colourError}, {"noise", q.noise},
                            {"image_data", dataUri(quality->width, quality->height, q.image)},
                            {"heat_data", dataUri(quality->width, quality->height, q.heatMap)}});
        page["quality"] = {{"scene_name", quality->sceneName}, {"samples", quality->samples},
                           {"reference_seconds", quality->referenceSeconds},
                           {"reference_data", dataUri(quality->width, quality->height, quality->reference)}, {"rows", rows}};
    }

    std::string warning;
    std::string html = readFile(paths::dataRoot() / "src/bench/report.html");
    const fs::path chart = chartLibrary();
    std::string chartJs;
    if (chart.empty()) {
        warning = "Chart.js not found (Debian package libjs-chart.js): report.html has tables and images but no plots";
        chartJs = "window.Chart = undefined;";
    } else {
        chartJs = readFile(chart);
    }
    // "</" inside inline scripts would end them early.
    std::string data = page.dump();
    for (std::size_t at = 0; (at = data.find("</", at)) != std::string::npos; at += 3) data.replace(at, 2, "<\\/");
    fill(html, "/*CHART_JS*/", chartJs);
    fill(html, "/*BENCH_DATA*/", data);
    util::writeText(dir / "report.html", html);
    return warning;
}

}  // namespace penumbra::bench
