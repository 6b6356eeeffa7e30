#pragma once
// Headless GL test support: one EGL context for the whole test binary, scenes from JSON
// strings, and per-pixel access to rendered channels (linear floats, row 0 = bottom).
#include "render/Renderer.h"
#include "scene/Scene.h"

#include <algorithm>
#include <functional>
#include <glm/glm.hpp>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace penumbra::test {

struct Frame {
    int width = 0, height = 0;
    std::vector<float> rgba;
    glm::vec3 at(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
        return {rgba[i], rgba[i + 1], rgba[i + 2]};
    }
    float alpha(int x, int y) const { return rgba[(static_cast<std::size_t>(y) * width + x) * 4 + 3]; }
};

scene::Scene sceneFromJson(const std::string& json);

// Object `object`'s mesh made a sphere of `radius` and 65,536 triangles in one part (its material
// kept): big enough that the renderer cuts it into clusters (render::kClusteredPartTriangles).
const scene::Mesh& makeBigSphere(scene::Scene& scene, std::size_t object, float radius);

// The span of visibility values seen, from [0, 1] outwards: a light's visibility never leaves
// [0, 1] (to 1e-4). Cascades blended past their weights once gave -21..22.
struct VisibilitySpan {
    float lowest = 0.0f, highest = 1.0f;
    void add(float v) { lowest = std::min(lowest, v), highest = std::max(highest, v); }
    void add(const glm::vec3& v) { add(v.r), add(v.g), add(v.b); }
    bool withinZeroAndOne() const { return lowest >= -1e-4f && highest <= 1.0f + 1e-4f; }
};

// A technique's name as a gtest parameter name: only letters, digits and '_' are allowed there
// ("pcf-bilinear" -> "pcf_bilinear", "cssm2:filter=poisson16" -> "cssm2_filter_poisson16").
std::string testNameOf(std::string technique);

// Options for a technique that may carry parameters: "cssm2:xi=white", "vsm:blur_kernel=box:mipmaps=false".
render::RenderOptions optionsFor(const std::string& technique);

// Renders `scene` at time 0 from its camera with `options` and returns the linear picture.
Frame renderFrame(scene::Scene& scene, const render::RenderOptions& options, int width, int height);

// Renders `scene` at time 0 from its camera and returns the chosen channel.
Frame renderChannel(scene::Scene& scene, render::OutputMode mode, int light = 0, int width = 256, int height = 256,
                    const std::string& technique = "hard", const shadows::ParameterValues& parameters = {});

// The sRGB8 RGBA bytes (row 0 = bottom) of `scene` at time 0 from its camera, rendered alone
// with `options` (the reference against which split and region views are compared).
std::vector<std::uint8_t> renderRgba8(scene::Scene& scene, const render::RenderOptions& options, int width, int height);

// Every level of a debug view's texture (of an array, the view's layer), as floats: one per texel of a
// depth view, four (RGBA) of a colour one.
std::vector<float> textureLevels(const shadows::DebugView& view);

// World-space ray through the centre of pixel (x, y) (y up) of the scene camera.
struct Ray {
    glm::vec3 origin, direction;
};
Ray pixelRay(const scene::Camera& camera, int x, int y, int width, int height);

// Compares a rendered boolean mask with an expected one. Pixels that differ but lie within
// `tolerancePx` of a boundary of the expected mask are edge rasterisation, not errors.
struct MaskComparison {
    int expectedOn = 0, renderedOn = 0, mismatches = 0, mismatchesAwayFromEdges = 0;
};
MaskComparison compareMasks(const std::vector<bool>& expected, const std::vector<bool>& rendered, int width, int height,
                            int tolerancePx);

// The pixels of two linear RGBA pictures of one size (Renderer::readLinear) whose red, green or
// blue differ by more than `tolerance`: the same-pixels checks of renderers that draw less.
std::size_t differingPixels(const std::vector<float>& a, const std::vector<float>& b, float tolerance = 1e-6f);

}  // namespace penumbra::test
