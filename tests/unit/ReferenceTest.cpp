// The ray-traced reference checked against closed forms: a quad's hard shadow, the penumbra of
// a disk light behind a straight edge (similar triangles and the disk-segment area), and
// transmittance through translucent layers (McGuire & Enderton 2011).
#include "reference/Metrics.h"
#include "reference/RayScene.h"
#include "reference/Visibility.h"
#include "scene/io/SceneFile.h"

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

namespace penumbra::reference {
namespace {

scene::Scene parse(const std::string& json) {
    return scene::io::parseSceneJson(json, std::filesystem::path(PENUMBRA_TEST_DATA) / "inline.json");
}

const glm::vec3 kUp{0, 1, 0};

TEST(Reference, HardShadowOfAQuad) {
    scene::Scene s = parse(R"({
      "lights": [ { "type": "directional", "direction": [0, -1, 0] } ],
      "objects": [ { "shape": "plane", "size": [20, 20] },
                   { "shape": "plane", "size": [2, 2], "position": [0, 2, 0] } ] })");
    const RayScene rays(s, 0.0f);
    const scene::Light& sun = s.lights[0];
    EXPECT_EQ(visibilityAt(rays, sun, {0, 0, 0}, kUp, 1, 1), glm::vec3(0.0f));
    EXPECT_EQ(visibilityAt(rays, sun, {0.99f, 0, -0.99f}, kUp, 1, 1), glm::vec3(0.0f));
    EXPECT_EQ(visibilityAt(rays, sun, {1.01f, 0, 0}, kUp, 1, 1), glm::vec3(1.0f));
    EXPECT_EQ(visibilityAt(rays, sun, {0, 0, -1.01f}, kUp, 1, 1), glm::vec3(1.0f));
    // A point light at (0, 4, 0): the shadow doubles in size (similar triangles 4 / (4 - 2)).
    scene::Light point;
    point.type = scene::Light::Type::Point;
    point.position = {0, 4, 0};
    EXPECT_EQ(visibilityAt(rays, point, {1.98f, 0, 0}, kUp, 1, 1), glm::vec3(0.0f));
    EXPECT_EQ(visibilityAt(rays, point, {2.02f, 0, 0}, kUp, 1, 1), glm::vec3(1.0f));
}

TEST(Reference, TransmittanceThroughLayers) {
    auto through = [](const std::string& materials) {
        scene::Scene s = parse(R"({ "objects": [ { "shape": "plane", "size": [20, 20] } )" + materials + "] }");
        const RayScene rays(s, 0.0f);
        return rays.transmittance({0, 0.01f, 0}, kUp, 0.0f, 100.0f);
    };
    const std::string glass = R"({ "alpha": 1, "transmission": [0.1, 0.9, 0.1] })";
    auto pane = [](float y, const std::string& m) {
        return R"(, { "shape": "plane", "size": [4, 4], "position": [0, )" + std::to_string(y) + R"(, 0], "material": )" + m + "}";
    };
    const glm::vec3 one = through(pane(1, glass));
    EXPECT_NEAR(one.r, 0.1f, 1e-6f);
    EXPECT_NEAR(one.g, 0.9f, 1e-6f);
    const glm::vec3 two = through(pane(1, glass) + pane(2, glass));
    EXPECT_NEAR(two.r, 0.01f, 1e-6f);
    EXPECT_NEAR(two.g, 0.81f, 1e-6f);
    EXPECT_NEAR(two.b, 0.01f, 1e-6f);
    EXPECT_NEAR(through(pane(1, R"({ "alpha": 0.25, "transmission": [0.5, 0.5, 0.5] })")).g, 0.875f, 1e-6f);
    EXPECT_NEAR(through(pane(1, R"({ "alpha": 0.25 })")).g, 0.75f, 1e-6f);
    EXPECT_EQ(through(pane(1, R"({ "alpha": 1 })") + pane(2, glass)), glm::vec3(0.0f)) << "brick stops everything";
    // Ten nylon layers: 0.875^10, no layer lost.
    std::string ten;
    for (int i = 1; i <= 10; ++i) ten += pane(0.5f * i, R"({ "alpha": 0.25, "transmission": [0.5, 0.5, 0.5] })");
    EXPECT_NEAR(through(ten).g, std::pow(0.875f, 10.0f), 1e-5f);
}

TEST(Reference, AlphaCutoutLetsLightThroughTheHoles) {
    // quadrants.png is opaque (alpha 1): under a 0.5 cut-off it blocks; under a cut-off above 1
    // every texel is a hole.
    scene::Scene s = parse(R"({ "objects": [ { "shape": "plane", "size": [20, 20] },
        { "shape": "plane", "size": [4, 4], "position": [0, 1, 0],
          "material": { "texture": "quadrants.png", "alpha_cutoff": 0.5 } },
        { "shape": "plane", "size": [4, 4], "position": [10, 1, 0],
          "material": { "texture": "quadrants.png", "alpha_cutoff": 1.1 } } ] })");
    const RayScene rays(s, 0.0f);
    EXPECT_EQ(rays.transmittance({0, 0.01f, 0}, kUp, 0, 100), glm::vec3(0.0f));
    EXPECT_EQ(rays.transmittance({10, 0.01f, 0}, kUp, 0, 100), glm::vec3(1.0f));
}

// Fraction of a disk of radius R lying at a > c (the unblocked part behind an edge).
double diskFractionBeyond(double c, double R) {
    if (c <= -R) return 1.0;
    if (c >= R) return 0.0;
    return (R * R * std::acos(c / R) - c * std::sqrt(R * R - c * c)) / (glm::pi<double>() * R * R);
}

TEST(Reference, AreaLightPenumbraMatchesSimilarTriangles) {
    // Disk light of diameter D at height H, facing down; an occluder covering x < 0 at height h.
    // Receiver at (p, 0, 0) sees the light through x = 0 where a light point a satisfies
    // a > -p (H - h) / h; the penumbra spans |p| < D/2 * h / (H - h) (Fernando 2005's w).
    const double D = 1.0, H = 6.0, h = 2.0;
    scene::Scene s = parse(R"({
      "lights": [ { "type": "point", "position": [0, 6, 0], "size": 1.0 } ],
      "objects": [ { "shape": "plane", "size": [40, 40] },
                   { "shape": "plane", "size": [10, 10], "position": [-5, 2, 0] } ] })");
    const RayScene rays(s, 0.0f);
    const double halfWidth = D / 2 * h / (H - h);
    // The disk faces the receiver, not straight down; near the axis the two agree to first order.
    for (double p : {-0.3, -0.2, -0.1, 0.0, 0.1, 0.2, 0.3}) {
        const float vis = visibilityAt(rays, s.lights[0], {static_cast<float>(p), 0, 0}, kUp, 4096, 7).g;
        const double expected = diskFractionBeyond(-p * (H - h) / h, D / 2);
        EXPECT_NEAR(vis, expected, 0.02) << "p = " << p;
    }
    EXPECT_EQ(visibilityAt(rays, s.lights[0], {static_cast<float>(-halfWidth * 1.05), 0, 0}, kUp, 1024, 3).g, 0.0f);
    EXPECT_EQ(visibilityAt(rays, s.lights[0], {static_cast<float>(halfWidth * 1.05), 0, 0}, kUp, 1024, 3).g, 1.0f);
}

TEST(Metrics, CountsWhatTheyClaim) {
    const std::vector<glm::vec3> ref{{1, 1, 1}, {0, 0, 0}, {0.1f, 0.9f, 0.1f}, {1, 1, 1}};
    const std::vector<glm::vec3> tech{{1, 1, 1}, {0.05f, 0.05f, 0.05f}, {0.1f, 0.5f, 0.1f}, {0, 0, 0}};
    VisibilityError e;
    e.add(tech, ref, {true, true, true, false});
    EXPECT_EQ(e.pixels(), 3u);
    EXPECT_NEAR(e.wrongShare(), 1.0 / 3.0, 1e-9);
    EXPECT_EQ(e.colouredPixels(), 1u);
    EXPECT_NEAR(e.colourError(), 0.4 / 3.0, 1e-6);
    EXPECT_NEAR(e.rmse(), std::sqrt((3 * 0.0025 + 0.16) / 9.0), 1e-6);
}

}  // namespace
}  // namespace penumbra::reference
