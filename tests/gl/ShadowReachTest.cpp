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

INSTANTIATE_TEST_SUITE_P(Techniques, ShadowReach,
                         ::testing::Values("hard", "pcf-poisson16:radius_texels=6", "pcf-grid:radius_texels=4", "pcss:sun_angle_deg=12", "cssm2", "cssm1"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return testNameOf(info.param); });

}  // namespace
}  // namespace penumbra::test
