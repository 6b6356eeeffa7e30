// The camera's opaque pass shades receivers, or screen rectangles of them, that no translucent
// caster's coloured shadow can reach with a program that reads no tint (render/TintReach.h,
// RenderOptions::tintOnlyWhereReached). It must leave every pixel as the whole lookup gives it:
// a footprint one texel too small, or a program that skipped a light's colour where it falls,
// shows as coloured shadow gone white. The scene has coloured shadows from a sun (2D map), a
// spot (perspective) and a point light (cube map) on a ground that is split on the screen, on
// boxes inside and outside them, and a glass block resting on the ground.
#include "GlTestSupport.h"

#include "render/Offscreen.h"

#include <cmath>

namespace penumbra::test {
namespace {

scene::Scene colouredShadows() {
    return sceneFromJson(R"({
      "camera": { "position": [0, 7, 8], "target": [0, 0.5, 0], "fov_deg": 55 },
      "lights": [ { "type": "directional", "direction": [-0.4, -1, -0.3], "intensity": 0.5, "shadow": { "resolution": 512 } },
                  { "type": "spot", "position": [3, 5, 2], "direction": [-0.6, -1, -0.4], "angle_deg": 60, "intensity": 0.5,
                    "range": 30, "shadow": { "resolution": 256 } },
                  { "type": "point", "position": [-3, 3, -1], "range": 30, "intensity": 0.4, "shadow": { "resolution": 128 } } ],
      "objects": [ { "shape": "plane", "size": [14, 14] },
                   { "shape": "box", "size": [2, 0.04, 1.4], "position": [0, 2.2, 0], "rotation_deg": [10, 0, 0],
                     "material": { "diffuse": [0.1, 0.9, 0.1], "alpha": 1, "transmission": [0.1, 0.9, 0.1] } },
                   { "shape": "box", "size": [0.8, 0.8, 0.8], "position": [2, 0.4, -1.5],
                     "material": { "diffuse": [0.9, 0.2, 0.2], "alpha": 1, "transmission": [0.9, 0.2, 0.2] } },
                   { "shape": "box", "size": [0.6, 0.6, 0.6], "position": [-0.3, 0.3, -0.8] },
                   { "shape": "box", "size": [0.6, 1.2, 0.6], "position": [-4, 0.6, 3] },
                   { "shape": "sphere", "radius": 0.5, "position": [4, 0.5, 3] } ] })");
}

class TintReach : public ::testing::TestWithParam<const char*> {};

TEST_P(TintReach, ShadesEveryPixelAsTheWholeLookupDoes) {
    scene::Scene s = colouredShadows();
    render::RenderOptions reached = optionsFor(GetParam()), everywhere = reached;
    everywhere.tintOnlyWhereReached = false;
    constexpr int kWidth = 192, kHeight = 128;
    render::Renderer a(s, reached), b(s, everywhere);
    render::OffscreenTarget target(kWidth, kHeight);
    a.render(0.0f, s.camera, kWidth, kHeight, target.framebuffer());
    const std::vector<float> pictureA = a.readLinear();
    b.render(0.0f, s.camera, kWidth, kHeight, target.framebuffer());
    const std::vector<float> pictureB = b.readLinear();
    // The scene does exercise both programs: the ground is split, the far boxes untinted.
    EXPECT_GE(a.tintShading().split, 1u);
    EXPECT_GE(a.tintShading().untinted, 1u);
    EXPECT_EQ(b.tintShading().untinted + b.tintShading().split, 0u);
    ASSERT_EQ(pictureA.size(), pictureB.size());
    std::size_t differing = 0, tinted = 0;
    for (std::size_t i = 0; i < pictureA.size(); i += 4) {
        const glm::vec3 pa(pictureA[i], pictureA[i + 1], pictureA[i + 2]), pb(pictureB[i], pictureB[i + 1], pictureB[i + 2]);
        differing += glm::any(glm::greaterThan(glm::abs(pa - pb), glm::vec3(1e-5f)));
        tinted += pb.g > 1.5f * pb.r + 0.02f;  // green light through the pane
    }
    EXPECT_EQ(differing, 0u) << GetParam();
    EXPECT_GT(tinted, 200u) << GetParam() << ": the pane's green shadow is in view";
}

INSTANTIATE_TEST_SUITE_P(Techniques, TintReach,
                         ::testing::Values("hard", "pcf-poisson16", "pcss", "vsm", "shadow-volumes", "cssm2", "cssm1",
                                           "cssm2:filter=poisson16"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return testNameOf(info.param); });

// Techniques whose sun maps are their own (cascades, warps) give every receiver the whole lookup.
TEST(TintReachOff, CascadesKeepTheWholeLookupEverywhere) {
    scene::Scene s = colouredShadows();
    render::Renderer r(s, optionsFor("cascaded"));
    render::OffscreenTarget target(64, 48);
    r.render(0.0f, s.camera, 64, 48, target.framebuffer());
    EXPECT_EQ(r.tintShading().untinted + r.tintShading().split, 0u);
    EXPECT_GE(r.tintShading().whole, 4u);
}

}  // namespace
}  // namespace penumbra::test
