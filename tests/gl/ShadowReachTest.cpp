// The camera's opaque pass shades the screen rectangles of a receiver that no other caster's
// shadow volume reaches with a build that leaves the light's lookup out
// (RenderOptions::shadowOnlyWhereCast, Renderer's shadow reach). There the lookup answers exactly
// 1, so every pixel must be what looking every shadow up everywhere gives. The maps are coarse
// (128 texels across), and the kernels wide, so that a footprint padded short (no reach, no
// normal offset) cuts a penumbra off by whole texels, which the 32-pixel grid the rectangles are
// grown to does not hide. Receivers: a flat ground, which cannot shadow itself, and, far enough
// from it that no footprint of the ground covers it, a floor with a fin standing on it in one
// bent part (tests/data/fin_on_floor.obj), whose own fin shadows it: a part that is not flat is
// one of its own casters. Casters besides: a floating box, a sphere above the view whose shadow
// falls in it (every caster counts, seen or not), and a green pane (the tint). Measured broken
// (throwaway switches): the bent part left out of its own casters put 268 pixels off (hard,
// cssm2, cssm1); casters outside the view left out, 1,608-2,261 (all but pcss); no padding at all,
// 29 (pcf-poisson16) and 313 (pcf-grid).
#include "GlTestSupport.h"

#include "render/Offscreen.h"

#include <cmath>

namespace penumbra::test {
namespace {

scene::Scene coarseShadows() {
    return sceneFromJson(R"({
      "camera": { "position": [2, 9, 11], "target": [2, 0, 1], "fov_deg": 60 },
      "lights": [ { "type": "directional", "direction": [-0.5, -1, -0.3], "intensity": 0.8, "shadow": { "resolution": 128 } },
                  { "type": "spot", "position": [3, 5, 3], "direction": [-0.4, -1, -0.4], "angle_deg": 70, "intensity": 1.0,
                    "range": 20, "shadow": { "resolution": 128 } } ],
      "objects": [ { "shape": "plane", "size": [8, 12], "position": [-2, 0, 0] },
                   { "model": "fin_on_floor.obj", "position": [8, 0, 3] },
                   { "shape": "box", "size": [1, 1, 1], "position": [-2.5, 1.5, 1] },
                   { "shape": "sphere", "radius": 0.8, "position": [0, 10, 7] },
                   { "shape": "plane", "size": [1.5, 1.5], "position": [-1, 1.8, -2.5], "rotation_deg": [60, 0, 0],
                     "material": { "diffuse": [0.1, 0.9, 0.1], "transmission": [0.1, 0.9, 0.1] } } ] })");
}

// Opaque casters shadow only what is not clearly in front of them (render/TintReach.h,
// opaqueShadowFootprint). Solids floating over a ground under a steep sun: a faceted box, which no
// lit point of its own can shadow (Draw::selfShadowFree: convex, its faces' own normals), so that
// its top is shaded without the lookup, and a smooth sphere, whose normals light facets turned from
// the light, so that it stays one of its own casters (taken for self-shadow free, 103 pixels of
// pcf-poisson16's picture and 766 of pcf-grid's came out lit that its lookup darkens).
scene::Scene solidsOverGround() {
    return sceneFromJson(R"({
      "camera": { "position": [0, 6, 7], "target": [0, 1, 0], "fov_deg": 60 },
      "lights": [ { "type": "directional", "direction": [-0.3, -1, -0.2], "intensity": 0.8, "shadow": { "resolution": 128 } } ],
      "objects": [ { "shape": "plane", "size": [12, 10] },
                   { "shape": "box", "size": [3, 3, 3], "position": [-2.6, 2.2, -0.5], "rotation_deg": [0, 30, 0] },
                   { "shape": "sphere", "radius": 1.6, "position": [2.4, 2.8, 0] } ] })");
}

// A steep plate whose lower edge hangs 0.09 above a low box, under a sun straight down, its map
// 512 texels across and 20 deep (a pole): PCF's receiver-plane taps past the edge extrapolate the
// plate up to 0.01 of the map's depth (0.2) deeper than itself, meet the box's top and darken the
// edge. The box is then one of the plate's casters although it lies wholly behind it
// (ShadowTechnique::shadowReachDepth; with a reach of 0, 1,392 pixels came out lit).
scene::Scene plateOverBox() {
    return sceneFromJson(R"({
      "camera": { "position": [0, 3.2, 3.2], "target": [0, 0.6, 0], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [0, -1, 0.001], "intensity": 0.9, "shadow": { "resolution": 512, "normal_offset": 0 } } ],
      "objects": [ { "shape": "plane", "size": [8, 8] },
                   { "shape": "box", "size": [0.2, 20, 0.2], "position": [3.5, 10, -3.5] },
                   { "shape": "box", "size": [2, 0.5, 2], "position": [0, 0.25, 0] },
                   { "shape": "plane", "size": [1.6, 1.6], "position": [0, 1.2, -0.3], "rotation_deg": [50, 0, 0] } ] })");
}

constexpr int kWidth = 640, kHeight = 400;

struct Shaded {
    std::vector<float> picture;
    std::size_t unshadowedPieces = 0;
};

Shaded shade(scene::Scene& s, const std::string& technique, bool onlyWhereCast) {
    render::RenderOptions options = optionsFor(technique);
    options.shadowOnlyWhereCast = onlyWhereCast;
    render::Renderer renderer(s, options);
    render::OffscreenTarget target(kWidth, kHeight);
    renderer.render(0.0f, s.camera, kWidth, kHeight, target.framebuffer());
    return {renderer.readLinear(), renderer.tintShading().unshadowedPieces};
}

class ShadowReach : public ::testing::TestWithParam<const char*> {};

TEST_P(ShadowReach, ShadesEveryPixelAsLookingEveryShadowUpDoes) {
    scene::Scene s = coarseShadows();
    const Shaded reached = shade(s, GetParam(), true), everywhere = shade(s, GetParam(), false);
    EXPECT_GT(reached.unshadowedPieces, 0u) << "the ground is split where no shadow falls";
    EXPECT_EQ(everywhere.unshadowedPieces, 0u);
    ASSERT_EQ(reached.picture.size(), everywhere.picture.size());
    // Shadows and lit ground both in view (a black or blank frame would be the same both ways too):
    // pixels the shadows darken against the same scene without shadows, and pixels well lit.
    const Shaded unshadowed = shade(s, "none", false);
    std::size_t shadowed = 0, lit = 0;
    for (std::size_t i = 0; i < everywhere.picture.size(); i += 4) {
        const float sum = everywhere.picture[i] + everywhere.picture[i + 1] + everywhere.picture[i + 2];
        const float sumUnshadowed = unshadowed.picture[i] + unshadowed.picture[i + 1] + unshadowed.picture[i + 2];
        shadowed += sumUnshadowed - sum > 0.1f ? 1 : 0;
        lit += sum > 1.5f ? 1 : 0;
    }
    EXPECT_EQ(differingPixels(reached.picture, everywhere.picture), 0u) << GetParam();
    EXPECT_GT(shadowed, 2000u) << GetParam() << ": shadows are in view";
    EXPECT_GT(lit, 20000u) << GetParam() << ": lit ground is in view";
}

TEST_P(ShadowReach, LeavesOutOnlyLookupsThatSolidsCannotChange) {
    scene::Scene s = solidsOverGround();
    const Shaded reached = shade(s, GetParam(), true), everywhere = shade(s, GetParam(), false);
    EXPECT_GT(reached.unshadowedPieces, 0u);
    EXPECT_EQ(differingPixels(reached.picture, everywhere.picture), 0u) << GetParam();
}

TEST(ShadowReach, KeepsTheLookupWhereReceiverPlaneTapsReachACasterBehind) {
    scene::Scene s = plateOverBox();
    const char* technique = "pcf-poisson16:radius_texels=10";
    const Shaded reached = shade(s, technique, true), everywhere = shade(s, technique, false);
    EXPECT_GT(reached.unshadowedPieces, 0u);
    EXPECT_EQ(differingPixels(reached.picture, everywhere.picture), 0u);
}

INSTANTIATE_TEST_SUITE_P(Techniques, ShadowReach,
                         ::testing::Values("hard", "pcf-poisson16:radius_texels=6", "pcf-grid:radius_texels=4", "pcss:sun_angle_deg=12", "cssm2", "cssm1",
                                           "distance:spacing_texels=4", "cascaded", "cascaded:cascades=2", "lispsm", "lispsm-tiled", "psm"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return testNameOf(info.param); });

}  // namespace
}  // namespace penumbra::test
