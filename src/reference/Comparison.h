#pragma once
// One frame of a scene compared between shadow techniques and the ray-traced reference on the
// *same visible surfaces*: the rasteriser's G-buffer (world position, normal) feeds the rays,
// so the difference measures shadowing alone. Needs a current GL context.
#include "reference/Metrics.h"
#include "reference/Visibility.h"
#include "render/Renderer.h"
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace penumbra::reference {

struct TechniqueScore {
    std::string name;
    int shadowResolution = 0;  // 0: per light
    double rmse = 0, wrongShare = 0, colourError = 0;
    // Per-pixel standard deviation of the visibility from frame to frame (stochastic techniques;
    // 0 for deterministic ones): sqrt(mean((v1 - v2)^2) / 2) over two frames with different seeds.
    double noise = 0;
    std::size_t pixels = 0, colouredPixels = 0;
    double shadowMs = 0, totalMs = 0;  // mean GPU ms of full shaded frames
    std::size_t memoryBytes = 0;
    std::vector<std::vector<glm::vec3>> visibility;  // per light, GL row order
    std::vector<float> maxError;                     // per pixel, over lights
};

// Shadows under a slow camera pan over the static scene (its time fixed): the truth does not
// change, so every change of a surface point's visibility from one frame to the next is error
// (shimmer of a refitted map, crawling of a stochastic pattern).
struct MotionScore {
    int frames = 0;
    // RMS, over surface points seen in consecutive frames, of how far a point's visibility leaves
    // the range of the 2x2 pixels it reprojects to in the frame before; resampling a still
    // shadow stays inside that range, so a still image scores 0.
    double temporalError = 0;
    double crawlShare = 0;  // share of those points whose visibility left the range by > 8/255
    std::size_t pixels = 0;
};

// Which surface of each pixel a Comparison scores.
enum class Surfaces {
    NearestOpaque,  // the nearest opaque surface (what lies behind glass, the glass left out)
    Nearest,        // the nearest surface, translucent ones too: scored by the light reaching them
    // The surface seen through the nearest one, at the pixels whose nearest surface is translucent
    // (a glass box's far side through its near side, the floor through a pane): the light reaching
    // the second surface along the view. The motion score (evaluateMotion) scores Nearest instead.
    BehindGlass,
};

class Comparison {
public:
    // Captures the G-buffer, ambient term and each light's unshadowed contribution of the surfaces
    // `surfaces` names. Throws InputError when the scene has no lights.
    Comparison(scene::Scene& scene, int width, int height, float time, Surfaces surfaces = Surfaces::NearestOpaque);

    // Ray-traces every light's visibility (samples per pixel for area lights). `onProgress`, if
    // set, hears the share done over all lights (0..1) from a worker thread now and then. No GL:
    // it may run on another thread (BackgroundReference.h).
    void traceReference(int samples, bool showProgress, const Progress& onProgress = {});
    double referenceSeconds() const { return referenceSeconds_; }

    // The options every evaluation below renders with, but for its own technique, shadow
    // resolution and parameters (default: RenderOptions' defaults): a command's shared flags
    // (--tint-everywhere, --transparency, --redraw-shadow-maps, ...), so that the scores are of
    // the pixels those flags draw.
    void setRenderOptions(const render::RenderOptions& base) { base_ = base; }

    // Renders `technique`'s visibility for every light and scores it against the reference;
    // `timedFrames` full frames (after one warm-up; 0: none) measure its GPU cost.
    TechniqueScore evaluate(const std::string& technique, int shadowResolution, int timedFrames,
                            const shadows::ParameterValues& parameters = {});

    // `frames` frames of `technique` while the camera pans sideways by `pixelsPerFrame` pixels
    // (measured at its target) per frame; no reference is needed.
    MotionScore evaluateMotion(const std::string& technique, int shadowResolution, int frames, float pixelsPerFrame,
                               const shadows::ParameterValues& parameters = {});

    // The frame shaded with the given per-light visibility (the reference's or a technique's):
    // ambient + sum(contribution * visibility), fog, background; RGBA8 sRGB top row first.
    std::vector<std::uint8_t> shade(const std::vector<std::vector<glm::vec3>>& visibility) const;
    std::vector<std::uint8_t> heatMap(const TechniqueScore& score) const;

    const std::vector<std::vector<glm::vec3>>& referenceVisibility() const { return reference_; }
    const std::vector<bool>& litMask(std::size_t light) const { return lit_[light]; }
    const SurfacePoints& surfaces() const { return points_; }
    int width() const { return width_; }
    int height() const { return height_; }

private:
    std::vector<glm::vec3> capture(render::Renderer& renderer, render::OutputMode mode, int light);
    std::vector<glm::vec4> captureFrom(render::Renderer& renderer, const scene::Camera& camera,
                                       render::OutputMode mode, int light);
    render::RenderOptions optionsFor(const std::string& technique, int shadowResolution,
                                     const shadows::ParameterValues& parameters) const;
    // BehindGlass: keeps the nearest surface's depth and returns which pixels it is translucent at.
    std::vector<bool> captureNearestDepth(render::Renderer& renderer);
    scene::Scene& scene_;
    int width_, height_;
    float time_;
    Surfaces surfaces_;
    gl::Texture nearestDepth_;  // BehindGlass: the nearest surface's window depth (Renderer::showBehind)
    render::RenderOptions base_;
    SurfacePoints points_;
    std::vector<glm::vec3> ambient_;
    std::vector<std::vector<glm::vec3>> contribution_;  // per light
    std::vector<std::vector<bool>> lit_;                // per light: the light reaches the surface unshadowed
    std::vector<std::vector<glm::vec3>> reference_;     // per light
    double referenceSeconds_ = 0;
};


}  // namespace penumbra::reference
