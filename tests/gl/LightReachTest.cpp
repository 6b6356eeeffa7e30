// The camera passes shade the screen rectangles of a receiver that a projector or spot light
// cannot reach (outside its frustum: render/TintReach.h, lightReach) with a build that leaves that
// light out (RenderOptions::lightOnlyWhereReached). There the light adds exactly 0, so every pixel
// must be what shading every light everywhere gives: a reach rectangle one pixel too small shows
// as a rim of the projector's picture, or of the spot's light, gone dark. The scene has a projector
// and a spot each lighting part of a big ground, boxes in and out of their frustums, a green pane
// in the translucent pass under the projector, and a sun.
#include "GlTestSupport.h"

#include "render/Offscreen.h"

#include <cmath>

namespace penumbra::test {
namespace {

scene::Scene partlyLitGround() {
    return sceneFromJson(R"({
      "camera": { "position": [0, 9, 10], "target": [0, 0, 0], "fov_deg": 60 },
      "lights": [ { "type": "directional", "direction": [-0.4, -1, -0.3], "intensity": 0.3, "shadow": { "resolution": 512 } },
                  { "type": "projector", "position": [-3, 4, 2], "direction": [0, -1, -0.3], "angle_deg": 40,
                    "image": "quadrants.png", "intensity": 1.5, "range": 20, "shadow": { "resolution": 256 } },
                  { "type": "spot", "position": [4, 3, -2], "direction": [0.2, -1, 0.1], "angle_deg": 50, "intensity": 1.2,
                    "range": 20, "shadow": { "resolution": 256 } } ],
      "objects": [ { "shape": "plane", "size": [24, 24] },
                   { "shape": "box", "size": [0.8, 0.8, 0.8], "position": [-3, 0.4, 0.5] },
                   { "shape": "box", "size": [2.5, 2.5, 2.5], "position": [5, 1.25, 4] },
                   { "shape": "plane", "size": [1.5, 1.5], "position": [-3, 1.6, 1.2],
                     "material": { "diffuse": [0.1, 0.9, 0.1], "transmission": [0.1, 0.9, 0.1] } } ] })");
}

constexpr int kWidth = 192, kHeight = 128;

struct Frames {
    std::vector<float> reached, everywhere;
    std::size_t unlitPieces = 0, unlitPiecesEverywhere = 0;
};

Frames renderBothWays(scene::Scene& s, const std::string& technique) {
    render::RenderOptions reached = optionsFor(technique);
    render::RenderOptions everywhere = reached;
    everywhere.lightOnlyWhereReached = false;
    render::Renderer a(s, reached), b(s, everywhere);
    render::OffscreenTarget target(kWidth, kHeight);
    Frames f;
    a.render(0.0f, s.camera, kWidth, kHeight, target.framebuffer());
    f.reached = a.readLinear();
    f.unlitPieces = a.tintShading().unlitPieces;
    b.render(0.0f, s.camera, kWidth, kHeight, target.framebuffer());
    f.everywhere = b.readLinear();
    f.unlitPiecesEverywhere = b.tintShading().unlitPieces;
    return f;
}

class LightReach : public ::testing::TestWithParam<const char*> {};

TEST_P(LightReach, ShadesEveryPixelAsEveryLightEverywhereDoes) {
    scene::Scene s = partlyLitGround();
    const Frames f = renderBothWays(s, GetParam());
    EXPECT_GT(f.unlitPieces, 0u) << "the ground is split by the projector's and the spot's reach";
    EXPECT_EQ(f.unlitPiecesEverywhere, 0u);
    ASSERT_EQ(f.reached.size(), f.everywhere.size());
    std::size_t lit = 0;
    for (std::size_t i = 0; i < f.everywhere.size(); i += 4)
        lit += f.everywhere[i] + f.everywhere[i + 1] + f.everywhere[i + 2] > 1.2f ? 1 : 0;  // under the projector or the spot
    EXPECT_EQ(differingPixels(f.reached, f.everywhere), 0u) << GetParam();
    EXPECT_GT(lit, 300u) << GetParam() << ": the projector's and the spot's light are in view";
}

// The world boxes behind the tint split and the lights' reach are kept across frames while their
// receiver, caster and light stay put (render/FrameMemo.h). A renderer that keeps them must shade
// every pixel as a new one does: after the camera moved (the sun's footprints are made again where
// its map follows the view; the projector's and the spot's are kept) and after the pane moved (its footprints made again; a
// box kept from its old place would leave its coloured shadow, or the ground's split around it,
// where it was).
TEST(LightReachKept, KeptBoxesShadeAsNewOnes) {
    scene::Scene s = partlyLitGround();
    const render::RenderOptions options = optionsFor("cssm2");
    render::Renderer kept(s, options);
    render::OffscreenTarget target(kWidth, kHeight);
    std::size_t freshFootprints = 0;
    render::Renderer::TintShading freshShading;
    // A new renderer's first frame makes every footprint. The picture and pieces to match are those
    // of a new renderer that came to this view from the first one, as `kept` did: it holds the
    // sun's box as `kept` does (RenderOptions::holdSunBox: the box depends on the views drawn).
    const auto freshFrame = [&](const scene::Camera& camera) {
        render::Renderer first(s, options);
        first.render(0.0f, camera, kWidth, kHeight, target.framebuffer());
        freshFootprints = first.tintShading().footprintsMade;
        render::Renderer fresh(s, options);
        fresh.render(0.0f, s.camera, kWidth, kHeight, target.framebuffer());
        fresh.render(0.0f, camera, kWidth, kHeight, target.framebuffer());
        freshShading = fresh.tintShading();
        return fresh.readLinear();
    };
    // The same pieces as the new renderer's, rectangle for rectangle (counted).
    const auto samePieces = [&] {
        const render::Renderer::TintShading& t = kept.tintShading();
        EXPECT_EQ(t.split, freshShading.split);
        EXPECT_EQ(t.tintedRects, freshShading.tintedRects);
        EXPECT_EQ(t.untintedRects, freshShading.untintedRects);
        EXPECT_EQ(t.behindLayersRects, freshShading.behindLayersRects);
        EXPECT_EQ(t.unlitPieces, freshShading.unlitPieces);
    };
    const auto renderKept = [&](const scene::Camera& camera) {
        kept.render(0.0f, camera, kWidth, kHeight, target.framebuffer());
        return kept.tintShading().footprintsMade;
    };
    EXPECT_GT(renderKept(s.camera), 0u);
    EXPECT_GT(kept.tintShading().unlitPieces, 0u);
    EXPECT_EQ(renderKept(s.camera), 0u) << "nothing moved";

    scene::Camera moved = s.camera;
    moved.position += glm::vec3(2.0f, -1.5f, 1.0f);
    const std::size_t madeAfterCamera = renderKept(moved);
    const std::vector<float> afterCamera = kept.readLinear();
    EXPECT_EQ(differingPixels(afterCamera, freshFrame(moved)), 0u);
    samePieces();
    EXPECT_LT(madeAfterCamera, freshFootprints / 2) << "the projector's and the spot's footprints and reach are kept";
    EXPECT_EQ(renderKept(moved), 0u);

    s.objects.back().position += glm::vec3(3.0f, 0.0f, 1.5f);  // the green pane
    const std::size_t madeAfterPane = renderKept(moved);
    const std::vector<float> afterPane = kept.readLinear();
    EXPECT_EQ(differingPixels(afterPane, freshFrame(moved)), 0u);
    samePieces();
    EXPECT_GT(madeAfterPane, 0u) << "the pane's footprints and reach are new";
    EXPECT_LT(madeAfterPane, freshFootprints) << "the other draws' reach is kept";
    EXPECT_GT(differingPixels(afterPane, afterCamera), 50u) << "the pane and its coloured shadow moved in view";
}

INSTANTIATE_TEST_SUITE_P(Techniques, LightReach, ::testing::Values("hard", "pcss", "vsm", "cssm2"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return testNameOf(info.param); });

}  // namespace
}  // namespace penumbra::test
