#include "reference/Comparison.h"

#include "render/Offscreen.h"
#include "util/Error.h"

#include <chrono>
#include <cmath>

namespace penumbra::reference {

using render::OutputMode;

std::vector<glm::vec3> Comparison::capture(render::Renderer& renderer, OutputMode mode, int light) {
    renderer.setOutputMode(mode, light);
    render::OffscreenTarget target(width_, height_);
    renderer.render(time_, scene_.camera, width_, height_, target.framebuffer());
    const std::vector<float> rgba = renderer.readLinear();
    std::vector<glm::vec3> out(static_cast<std::size_t>(width_) * height_);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]};
    if (mode == OutputMode::WorldPosition)
        for (std::size_t i = 0; i < out.size(); ++i) points_.covered[i] = rgba[4 * i + 3] > 0.5f;
    return out;
}

Comparison::Comparison(scene::Scene& scene, int width, int height, float time)
    : scene_(scene), width_(width), height_(height), time_(time) {
    if (scene.lights.empty()) throw InputError(scene.source, "the scene has no lights: there are no shadows to compare");
    render::RenderOptions options;
    options.technique = "none";
    render::Renderer renderer(scene, options);
    points_.width = width;
    points_.height = height;
    points_.covered.assign(static_cast<std::size_t>(width) * height, false);
    points_.position = capture(renderer, OutputMode::WorldPosition, 0);
    points_.normal = capture(renderer, OutputMode::Normal, 0);
    ambient_ = capture(renderer, OutputMode::Ambient, 0);
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        contribution_.push_back(capture(renderer, OutputMode::Contribution, static_cast<int>(l)));
        std::vector<bool> lit(points_.covered.size());
        for (std::size_t i = 0; i < lit.size(); ++i) {
            const glm::vec3& c = contribution_.back()[i];
            lit[i] = points_.covered[i] && glm::max(glm::max(c.r, c.g), c.b) > 1e-5f;
        }
        lit_.push_back(std::move(lit));
    }
}

void Comparison::traceReference(int samples, bool showProgress, const Progress& onProgress) {
    const auto start = std::chrono::steady_clock::now();
    const RayScene rays(scene_, time_);
    reference_.clear();
    for (std::size_t l = 0; l < scene_.lights.size(); ++l) {
        const Progress console = showProgress ? consoleProgress("reference: " + scene_.lights[l].name) : Progress{};
        const double lights = static_cast<double>(scene_.lights.size());
        const Progress progress = [&, l](double fraction) {
            if (console) console(fraction);
            if (onProgress) onProgress((static_cast<double>(l) + fraction) / lights);
        };
        reference_.push_back(traceVisibility(rays, scene_.lights[l], points_, samples, progress));
    }
    referenceSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TechniqueScore Comparison::evaluate(const std::string& technique, int shadowResolution, int timedFrames,
                                    const shadows::ParameterValues& parameters) {
    TechniqueScore score;
    score.name = technique;
    score.shadowResolution = shadowResolution;
    render::RenderOptions options;
    options.technique = technique;
    options.shadowResolution = shadowResolution;
    options.parameters = parameters;
    render::Renderer renderer(scene_, options);

    // Cost of the technique's real frames (shaded, translucency and fog included).
    render::OffscreenTarget target(width_, height_);
    if (timedFrames > 0) renderer.render(time_, scene_.camera, width_, height_, target.framebuffer());  // warm-up
    for (int f = 0; f < timedFrames; ++f) {
        renderer.render(time_, scene_.camera, width_, height_, target.framebuffer());
        const render::PassTimes& times = renderer.waitForTimes();
        score.shadowMs += times.shadowMs / timedFrames;
        score.totalMs += times.totalMs() / timedFrames;
    }
    score.memoryBytes = renderer.shadowMemoryBytes();

    VisibilityError error;
    double noiseSquared = 0;
    std::size_t noisePixels = 0;
    for (std::size_t l = 0; l < scene_.lights.size(); ++l) {
        score.visibility.push_back(capture(renderer, OutputMode::Visibility, static_cast<int>(l)));
        error.add(score.visibility.back(), reference_[l], lit_[l]);
        accumulateMaxError(score.maxError, score.visibility.back(), reference_[l], lit_[l]);
        const std::vector<glm::vec3> again = capture(renderer, OutputMode::Visibility, static_cast<int>(l));
        for (std::size_t i = 0; i < again.size(); ++i) {
            if (!lit_[l][i]) continue;
            const glm::vec3 d = again[i] - score.visibility.back()[i];
            noiseSquared += glm::dot(d, d) / 3.0;
            ++noisePixels;
        }
    }
    score.noise = noisePixels ? std::sqrt(noiseSquared / static_cast<double>(noisePixels) / 2.0) : 0.0;
    score.rmse = error.rmse();
    score.wrongShare = error.wrongShare();
    score.colourError = error.colourError();
    score.pixels = error.pixels();
    score.colouredPixels = error.colouredPixels();
    return score;
}

std::vector<std::uint8_t> Comparison::shade(const std::vector<std::vector<glm::vec3>>& visibility) const {
    std::vector<glm::vec3> color(ambient_);
    for (std::size_t i = 0; i < color.size(); ++i) {
        if (!points_.covered[i]) {
            color[i] = scene_.background;
            continue;
        }
        for (std::size_t l = 0; l < visibility.size(); ++l) color[i] += contribution_[l][i] * visibility[l][i];
        if (scene_.fog.enabled) {  // as shaders/passes/resolve.frag
            const float d = glm::length(points_.position[i] - scene_.camera.position);
            color[i] = glm::mix(color[i], scene_.background, glm::smoothstep(scene_.fog.start, scene_.fog.end, d));
        }
    }
    return encodeSrgb(color, width_, height_);
}

std::vector<std::uint8_t> Comparison::heatMap(const TechniqueScore& score) const {
    std::vector<bool> compared(points_.covered.size(), false);
    for (const auto& lit : lit_)
        for (std::size_t i = 0; i < lit.size(); ++i) compared[i] = compared[i] || lit[i];
    return reference::heatMap(score.maxError, compared, width_, height_);
}

}  // namespace penumbra::reference
