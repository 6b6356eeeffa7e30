// Translucency as the camera sees it: every transparency mode transmits exactly Π(1 - ρ) per
// channel through stacked panes; depth peeling matches the painter's result where sorting by
// object is right; the order-independent modes do not care about the order objects are listed.
#include "GlTestSupport.h"

#include "render/Offscreen.h"

#include <algorithm>

namespace penumbra::test {
namespace {

using render::TransparencyMode;

// Three panes in front of an opaque wall lit only by ambient light (wall colour = 1).
Frame seeThrough(TransparencyMode mode, bool reflective, bool reversed) {
    const std::string reflect = reflective ? R"("diffuse": [0.8, 0.3, 0.6], "specular": [0, 0, 0])"
                                           : R"("diffuse": [0, 0, 0], "specular": [0, 0, 0])";
    std::vector<std::string> objects{
        R"({ "shape": "plane", "size": [20, 20], "position": [0, 0, -3], "rotation_deg": [90, 0, 0], "material": { "diffuse": [1, 1, 1] } })",
        R"({ "shape": "plane", "size": [4, 4], "position": [0, 0, 1], "rotation_deg": [90, 0, 0],
             "material": { )" + reflect + R"(, "transmission": [0.1, 0.9, 0.1] } })",
        R"({ "shape": "plane", "size": [4, 4], "position": [0.3, 0, 0], "rotation_deg": [90, 0, 0],
             "material": { )" + reflect + R"(, "transmission": [0.9, 0.2, 0.2] } })",
        R"({ "shape": "plane", "size": [4, 4], "position": [-0.3, 0, -1], "rotation_deg": [90, 0, 0],
             "material": { )" + reflect + R"(, "alpha": 0.25, "transmission": [0.5, 0.5, 0.5] } })"};
    if (reversed) std::reverse(objects.begin(), objects.end());
    std::string list;
    for (const auto& o : objects) list += (list.empty() ? "" : ", ") + o;
    scene::Scene s = sceneFromJson(R"({ "camera": { "position": [0, 0, 8], "target": [0, 0, 0], "fov_deg": 30 },
                                        "ambient": [1, 1, 1], "objects": [ )" + list + "] }");
    render::RenderOptions options;
    options.technique = "none";
    options.transparency = mode;
    render::Renderer renderer(s, options);
    render::OffscreenTarget target(64, 64);
    renderer.render(0.0f, s.camera, 64, 64, target.framebuffer());
    return Frame{64, 64, renderer.readLinear()};
}

// Largest per-channel difference of rgb (alpha carries no meaning in the HDR target).
float largestColourDifference(const Frame& a, const Frame& b) {
    float worst = 0.0f;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const glm::vec3 d = glm::abs(a.at(x, y) - b.at(x, y));
            worst = std::max(worst, std::max(d.r, std::max(d.g, d.b)));
        }
    return worst;
}

const TransparencyMode kModes[] = {TransparencyMode::SortedObjects, TransparencyMode::SortedTriangles,
                                   TransparencyMode::DepthPeeling, TransparencyMode::DualDepthPeeling,
                                   TransparencyMode::WeightedBlended, TransparencyMode::Stochastic};

TEST(Transparency, EveryModeTransmitsTheProductOfLayers) {
    const glm::vec3 expected = glm::vec3(0.1f, 0.9f, 0.1f) * glm::vec3(0.9f, 0.2f, 0.2f) * 0.875f;
    for (auto mode : kModes) {
        const glm::vec3 centre = seeThrough(mode, false, false).at(32, 32);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(centre[c], expected[c], 2e-3f) << render::toString(mode) << " channel " << c;  // RGBA16F targets
    }
}

TEST(Transparency, DepthPeelingMatchesThePainterWhereSortingIsRight) {
    const Frame painter = seeThrough(TransparencyMode::SortedObjects, true, false);
    for (auto mode : {TransparencyMode::DepthPeeling, TransparencyMode::DualDepthPeeling})
        EXPECT_LT(largestColourDifference(painter, seeThrough(mode, true, false)), 2e-3f) << render::toString(mode);
    // Weighted blended and stochastic OIT approximate the reflected colour (their transmittance is
    // exact). Measured distance from the painter at the centre: weighted 0.207, stochastic 0.416;
    // the stochastic weights are scalar (mean opacity) over 4 samples, which coloured glass
    // (opacity 0.63 but green transmission 0.9) defeats. Bounds: 1.2x the measurements.
    const glm::vec3 a = painter.at(32, 32);
    for (auto [mode, bound] : {std::pair{TransparencyMode::WeightedBlended, 0.25f}, std::pair{TransparencyMode::Stochastic, 0.5f}}) {
        const glm::vec3 b = seeThrough(mode, true, false).at(32, 32);
        EXPECT_LT(glm::length(a - b), bound) << render::toString(mode) << " strays too far from the sorted result";
    }
}

TEST(Transparency, OrderIndependentModesIgnoreListOrder) {
    for (auto mode : {TransparencyMode::DepthPeeling, TransparencyMode::DualDepthPeeling, TransparencyMode::WeightedBlended,
                      TransparencyMode::Stochastic,
                      TransparencyMode::SortedObjects}) {
        const Frame forward = seeThrough(mode, true, false), backward = seeThrough(mode, true, true);
        EXPECT_LT(largestColourDifference(forward, backward), 1e-3f) << render::toString(mode);
    }
}

}  // namespace
}  // namespace penumbra::test
