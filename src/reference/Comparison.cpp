#include "reference/Comparison.h"

#include "render/Offscreen.h"
#include "util/Error.h"

#include <array>
#include <chrono>
#include <cmath>
#include <limits>

namespace penumbra::reference {

using render::OutputMode;

std::vector<glm::vec4> Comparison::captureFrom(render::Renderer& renderer, const scene::Camera& camera,
                                               OutputMode mode, int light) {
    renderer.setOutputMode(mode, light);
    render::OffscreenTarget target(width_, height_);
    renderer.render(time_, camera, width_, height_, target.framebuffer());
    const std::vector<float> rgba = renderer.readLinear();
    std::vector<glm::vec4> out(static_cast<std::size_t>(width_) * height_);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2], rgba[4 * i + 3]};
    return out;
}

std::vector<glm::vec3> Comparison::capture(render::Renderer& renderer, OutputMode mode, int light) {
    const std::vector<glm::vec4> rgba = captureFrom(renderer, scene_.camera, mode, light);
    std::vector<glm::vec3> out(rgba.size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = glm::vec3(rgba[i]);
    if (mode == OutputMode::WorldPosition)
        for (std::size_t i = 0; i < out.size(); ++i) points_.covered[i] = rgba[i].a > 0.5f;
    return out;
}

Comparison::Comparison(scene::Scene& scene, int width, int height, float time, Surfaces surfaces)
    : scene_(scene), width_(width), height_(height), time_(time), surfaces_(surfaces) {
    if (scene.lights.empty()) throw InputError(scene.source, "the scene has no lights: there are no shadows to compare");
    render::Renderer renderer(scene, optionsFor("none", 0, {}));
    points_.width = width;
    points_.height = height;
    points_.covered.assign(static_cast<std::size_t>(width) * height, false);
    std::vector<bool> throughGlass;
    if (surfaces == Surfaces::BehindGlass) {
        throughGlass = captureNearestDepth(renderer);
        renderer.showBehind(&nearestDepth_);
    }
    points_.position = capture(renderer, OutputMode::WorldPosition, 0);
    for (std::size_t i = 0; i < throughGlass.size(); ++i) points_.covered[i] = points_.covered[i] && throughGlass[i];
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

// The window depth of the nearest surface, kept for Renderer::showBehind, and the pixels where
// that surface is translucent (the nearest opaque one lies farther).
std::vector<bool> Comparison::captureNearestDepth(render::Renderer& renderer) {
    const std::size_t count = static_cast<std::size_t>(width_) * height_;
    std::vector<float> opaque(count), nearest(count);
    for (std::vector<float>* depth : {&opaque, &nearest}) {
        renderer.options().debugTranslucent = depth == &nearest;
        captureFrom(renderer, scene_.camera, OutputMode::WorldPosition, 0);
        const gl::Texture& frameDepth = renderer.cameraDepth();
        glGetTextureImage(frameDepth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, static_cast<GLsizei>(count * sizeof(float)),
                          depth->data());
        if (depth != &nearest) continue;
        nearestDepth_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, width_, height_);
        nearestDepth_.setFilter(GL_NEAREST, GL_NEAREST);
        glCopyImageSubData(frameDepth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, nearestDepth_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, width_,
                           height_, 1);
    }
    std::vector<bool> translucent(count);
    for (std::size_t i = 0; i < count; ++i) translucent[i] = nearest[i] < opaque[i];
    return translucent;
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

render::RenderOptions Comparison::optionsFor(const std::string& technique, int shadowResolution,
                                             const shadows::ParameterValues& parameters) const {
    render::RenderOptions options = base_;
    options.technique = technique;
    options.debugTranslucent = surfaces_ != Surfaces::NearestOpaque;
    options.shadowResolution = shadowResolution;
    options.parameters = parameters;
    options.output = render::OutputMode::Shaded;  // each capture sets its own
    options.debugOverlay = false;                 // (the maps drawn over the frame are no surface)
    options.floatTarget = true;                   // the captures read floats (Renderer::readLinear)
    return options;
}

TechniqueScore Comparison::evaluate(const std::string& technique, int shadowResolution, int timedFrames,
                                    const shadows::ParameterValues& parameters) {
    TechniqueScore score;
    score.name = technique;
    score.shadowResolution = shadowResolution;
    render::Renderer renderer(scene_, optionsFor(technique, shadowResolution, parameters));
    if (surfaces_ == Surfaces::BehindGlass) renderer.showBehind(&nearestDepth_);

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

namespace {

// One frame of a pan: where each pixel's surface is (a > 0.5: covered) and, per light, its
// visibility where the light reaches it unshadowed (NaN elsewhere).
struct MotionFrame {
    glm::mat4 viewProj;
    std::vector<glm::vec4> position;
    std::vector<std::vector<glm::vec3>> visibility;
};

constexpr float kNotLit = std::numeric_limits<float>::quiet_NaN();
constexpr float kCrawlThreshold = 8.0f / 255.0f;

}  // namespace

MotionScore Comparison::evaluateMotion(const std::string& technique, int shadowResolution, int frames,
                                       float pixelsPerFrame, const shadows::ParameterValues& parameters) {
    render::Renderer renderer(scene_, optionsFor(technique, shadowResolution, parameters));  // no showBehind: the camera moves
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    const scene::Camera& start = scene_.camera;
    const glm::vec3 forward = glm::normalize(start.target - start.position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, start.up));
    const float targetDistance = glm::length(start.target - start.position);
    // World size of one pixel at the target's distance.
    const float pixel = 2.0f * targetDistance *
                        std::tan(glm::radians(start.fovDeg) * 0.5f) / static_cast<float>(height_);

    auto renderFrame = [&](int k) {
        scene::Camera camera = start;
        const glm::vec3 shift = right * (pixel * pixelsPerFrame * static_cast<float>(k));
        camera.position += shift;
        camera.target += shift;
        MotionFrame f{camera.projection(aspect) * camera.view(),
                      captureFrom(renderer, camera, OutputMode::WorldPosition, 0), {}};
        for (std::size_t l = 0; l < scene_.lights.size(); ++l) {
            const auto reach = captureFrom(renderer, camera, OutputMode::Contribution, static_cast<int>(l));
            const auto seen = captureFrom(renderer, camera, OutputMode::Visibility, static_cast<int>(l));
            std::vector<glm::vec3> v(seen.size(), glm::vec3(kNotLit));
            for (std::size_t i = 0; i < v.size(); ++i)
                if (f.position[i].a > 0.5f && glm::max(glm::max(reach[i].r, reach[i].g), reach[i].b) > 1e-5f)
                    v[i] = glm::vec3(seen[i]);
            f.visibility.push_back(std::move(v));
        }
        return f;
    };

    MotionScore score;
    score.frames = frames;
    double squared = 0;
    std::size_t crawling = 0;
    MotionFrame before = renderFrame(0);
    for (int k = 1; k < frames; ++k) {
        MotionFrame now = renderFrame(k);
        for (int y = 0; y < height_; ++y)
            for (int x = 0; x < width_; ++x) {
                const std::size_t i = static_cast<std::size_t>(y) * width_ + x;
                if (now.position[i].a <= 0.5f) continue;
                const glm::vec3 p(now.position[i]);
                const glm::vec4 clip = before.viewProj * glm::vec4(p, 1.0f);
                if (clip.w <= 0.0f) continue;
                // Pixel centres at (x + 0.5, y + 0.5): the 2x2 around the reprojected point.
                const glm::vec2 at = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(width_, height_) - 0.5f;
                const glm::ivec2 corner = glm::ivec2(glm::floor(at));
                if (corner.x < 0 || corner.y < 0 || corner.x + 1 >= width_ || corner.y + 1 >= height_) continue;
                // The same surface: all four neighbours within a few pixels' size of the point
                // (no disocclusion, no silhouette).
                const float tolerance = 4.0f * pixel * std::max(1.0f, clip.w / targetDistance);
                std::array<std::size_t, 4> n{};
                bool same = true;
                for (int c = 0; c < 4; ++c) {
                    n[c] = static_cast<std::size_t>(corner.y + (c >> 1)) * width_ + corner.x + (c & 1);
                    same = same && before.position[n[c]].a > 0.5f &&
                           glm::length(glm::vec3(before.position[n[c]]) - p) < tolerance;
                }
                if (!same) continue;
                for (std::size_t l = 0; l < now.visibility.size(); ++l) {
                    const glm::vec3 v = now.visibility[l][i];
                    if (std::isnan(v.r)) continue;
                    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
                    bool lit = true;
                    for (std::size_t c : n) {
                        const glm::vec3 w = before.visibility[l][c];
                        lit = lit && !std::isnan(w.r);
                        lo = glm::min(lo, w);
                        hi = glm::max(hi, w);
                    }
                    if (!lit) continue;
                    const glm::vec3 outside = glm::max(lo - v, glm::max(v - hi, glm::vec3(0.0f)));
                    squared += glm::dot(outside, outside) / 3.0;
                    crawling += glm::max(glm::max(outside.r, outside.g), outside.b) > kCrawlThreshold ? 1 : 0;
                    ++score.pixels;
                }
            }
        before = std::move(now);
    }
    if (score.pixels) {
        score.temporalError = std::sqrt(squared / static_cast<double>(score.pixels));
        score.crawlShare = static_cast<double>(crawling) / static_cast<double>(score.pixels);
    }
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
