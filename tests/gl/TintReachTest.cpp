// The camera's opaque pass shades receivers, or screen rectangles of them, that no translucent
// caster's coloured shadow can reach with a program that reads no tint, and CSSM those behind
// every layer that may reach them with a build without its fallback loop (render/TintReach.h,
// RenderOptions::tintOnlyWhereReached). It must leave every pixel as the whole lookup gives it:
// a footprint one texel too small, or a program that skipped a light's colour where it falls,
// shows as coloured shadow gone white; a receiver taken for behind where a layer lies beside it
// (the ground at the glass block's foot) as the stochastic count gone. The scene has coloured shadows from a sun (2D map), a
// spot (perspective) and a point light (cube map) on a ground that is split on the screen, on
// boxes inside and outside them, and a glass block resting on the ground. The receivers outside
// are big enough (over 3 % of the frame) for the renderer to switch their program.
#include "GlTestSupport.h"

#include "reference/Comparison.h"
#include "render/Offscreen.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

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
                   { "shape": "box", "size": [1.6, 1.6, 1.6], "position": [-4, 0.8, 3] },
                   { "shape": "sphere", "radius": 1.0, "position": [4, 1.0, 3] } ] })");
}

constexpr int kWidth = 192, kHeight = 128;

// The frame's columns [first, last) rendered with and without the split (linear pictures).
struct Pair {
    std::vector<float> reached, everywhere;
    render::Renderer::TintShading shading, shadingEverywhere;
};
// `transparency`: sorted objects lets CSSM split translucent receivers too, whose builds differ
// from the whole lookup at rims (TintReachTranslucent); the order-independent modes draw them
// whole, so that every pixel must be the whole lookup's.
Pair renderBothWays(scene::Scene& s, const char* technique, render::Columns columns = {},
                    render::TransparencyMode transparency = render::TransparencyMode::WeightedBlended) {
    render::RenderOptions reached = optionsFor(technique);
    reached.transparency = transparency;
    render::RenderOptions everywhere = reached;
    everywhere.tintOnlyWhereReached = false;
    render::Renderer a(s, reached), b(s, everywhere);
    render::OffscreenTarget target(kWidth, kHeight);
    a.render(0.0f, s.camera, kWidth, kHeight, target.framebuffer(), columns);
    Pair p{a.readLinear(), {}, a.tintShading(), {}};
    b.render(0.0f, s.camera, kWidth, kHeight, target.framebuffer(), columns);
    p.everywhere = b.readLinear();
    p.shadingEverywhere = b.tintShading();
    return p;
}

// Pixels of columns [first, last) whose colours differ by more than 1e-5.
std::size_t differing(const Pair& p, int first = 0, int last = kWidth) {
    std::size_t n = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = first; x < last; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * kWidth + x) * 4;
            for (int c = 0; c < 3; ++c)
                if (std::abs(p.reached[i + c] - p.everywhere[i + c]) > 1e-5f) {
                    ++n;
                    break;
                }
        }
    return n;
}

class TintReach : public ::testing::TestWithParam<const char*> {};

TEST_P(TintReach, ShadesEveryPixelAsTheWholeLookupDoes) {
    scene::Scene s = colouredShadows();
    const Pair both = renderBothWays(s, GetParam());
    const std::vector<float>&pictureA = both.reached, &pictureB = both.everywhere;
    const render::Renderer::TintShading &shadingA = both.shading, &shadingB = both.shadingEverywhere;
    // The scene does exercise both programs: the ground is split, the far boxes untinted.
    EXPECT_GE(shadingA.split, 1u);
    EXPECT_GE(shadingA.untinted, 1u);
    EXPECT_EQ(shadingB.untinted + shadingB.split + shadingB.behindLayers, 0u);
    // CSSM's box lookup also takes its behind-layers build where every layer lies in front: the
    // ground under the floating pane; the glass block's foot keeps the whole lookup.
    if (std::string(GetParam()) == "cssm2" || std::string(GetParam()) == "cssm1") {
        EXPECT_GE(shadingA.behindLayers + shadingA.behindLayersRects, 1u);
        EXPECT_GE(shadingA.tintedRects, 1u);
    }
    ASSERT_EQ(pictureA.size(), pictureB.size());
    std::size_t tinted = 0;
    for (std::size_t i = 0; i < pictureB.size(); i += 4)
        tinted += pictureB[i + 1] > 1.5f * pictureB[i] + 0.02f;  // green light through the pane
    EXPECT_EQ(differing(both), 0u) << GetParam();
    EXPECT_GT(tinted, 200u) << GetParam() << ": the pane's green shadow is in view";
}

INSTANTIATE_TEST_SUITE_P(Techniques, TintReach,
                         ::testing::Values("hard", "pcf-poisson16", "pcss", "vsm", "shadow-volumes", "cssm2", "cssm1",
                                           "cssm2:filter=poisson16", "cssm1:filter=cross13", "cascaded", "lispsm", "psm"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return testNameOf(info.param); });

// A split view's column range (render::Columns): the rectangles are the full frame's, cut to the
// columns (a frame as wide as the range would put the footprints in the wrong place).
TEST(TintReachColumns, EachHalfOfASplitViewIsShadedAsTheWholeLookupDoes) {
    scene::Scene s = colouredShadows();
    for (const char* technique : {"hard", "cssm2"}) {
        const Pair left = renderBothWays(s, technique, {0, kWidth / 2}), right = renderBothWays(s, technique, {kWidth / 2, kWidth});
        EXPECT_GE(left.shading.split + right.shading.split, 1u) << technique;
        EXPECT_EQ(differing(left, 0, kWidth / 2), 0u) << technique << ": left half";
        EXPECT_EQ(differing(right, kWidth / 2, kWidth), 0u) << technique << ": right half";
    }
}

// Translucent receivers whose own layers are known (a convex glass box, a glass ball, two panes)
// take CSSM's builds for one side (ShadowTechnique::ownLayersBuild): where every other layer lies
// behind them, or none reaches them, their own layers in front alone, read from no map (the
// front pane, from the sun; the box and the ball); where every other layer lies in front, the
// tint with their own layers divided out, bilinearly (the back pane). The whole lookup counts
// stochastic layers at their rims as the light sees them. Pictures agree within 3/255 but for 11
// rim pixels (0.037 at most). Faults each put 180-563 pixels further off: a division that left the
// own layers in (far faces seen through near ones darkened twice) or took every layer out,
// footprints that left out the other panes (one pane's shadow on the other gone), a build for
// layers behind that forgot a solid's entry face in front of its exit face (563), and not-in-front
// footprints left empty (535).
scene::Scene glassReceivers() {
    return sceneFromJson(R"({
      "camera": { "position": [0, 5, 8], "target": [0, 1, 0], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [-0.4, -1, -0.3], "intensity": 0.5, "shadow": { "resolution": 512 } },
                  { "type": "spot", "position": [3, 6, 4], "direction": [-0.4, -1, -0.6], "angle_deg": 70, "intensity": 0.5,
                    "range": 30, "shadow": { "resolution": 512 } },
                  { "type": "point", "position": [-4, 4, 3], "range": 30, "intensity": 0.4, "shadow": { "resolution": 512 } } ],
      "objects": [ { "shape": "plane", "size": [14, 14] },
                   { "shape": "box", "size": [1.2, 1.2, 1.2], "position": [-3, 0.6, 0], "rotation_deg": [0, 30, 0],
                     "material": { "diffuse": [0.9, 0.2, 0.2], "alpha": 1, "transmission": [0.9, 0.2, 0.2] } },
                   { "shape": "sphere", "radius": 0.8, "position": [3.2, 1.2, 0.5],
                     "material": { "diffuse": [0.1, 0.8, 0.8], "alpha": 1, "transmission": [0.1, 0.8, 0.8] } },
                   { "shape": "box", "size": [1.6, 1.8, 0.04], "position": [-0.3, 1.4, -0.6], "rotation_deg": [0, 15, 0],
                     "material": { "diffuse": [0.1, 0.9, 0.1], "alpha": 1, "transmission": [0.1, 0.9, 0.1] } },
                   { "shape": "box", "size": [1.6, 1.8, 0.04], "position": [0.6, 1.4, -1.8], "rotation_deg": [0, -20, 0],
                     "material": { "diffuse": [0.2, 0.2, 0.9], "alpha": 1, "transmission": [0.2, 0.3, 0.9] } } ] })");
}

// Two green glass slabs (4 cm thick), one above the other, under a sun from above, seen from
// between them: every layer of the lower one lies behind the upper, which takes the build for its
// own layers alone, and every layer of the upper one in front of the lower, which takes the
// division. The upper one's underside receives the light its top face lets through, t; the lower
// one's top face that of both of the upper one's faces, t². The whole lookups (hard's and CSSM's)
// gave the upper underside about 1 here until stop 62: with the lower slab behind, the farthest
// layer at its texels is not its own, and the bias lands its lookup in front of its own top face
// (with the upper slab alone they give t, as the split does with or without the lower one). They
// are now bounded by the receiver's own layers in front (plainMapTint, CSSM's shadowVisibility).
TEST(TintReachTranslucent, StackedSlabsGetTheLightTheirLayersInFrontLetThrough) {
    const glm::vec3 t(0.1f, 0.9f, 0.1f);
    for (const char* technique : {"hard", "cssm2", "cssm1"})
        for (const bool upward : {true, false}) {
            scene::Scene s = sceneFromJson(std::string(R"({
              "camera": { "position": [0, 1.6, 0.001], "target": [0, )") + (upward ? "2.5" : "0") + R"(, 0], "up": [0, 0, -1], "fov_deg": 30 },
              "lights": [ { "type": "directional", "direction": [0.2, -1, 0.1], "shadow": { "resolution": 512 } } ],
              "objects": [ { "shape": "plane", "size": [14, 14] },
                           { "shape": "box", "size": [2, 0.04, 2], "position": [0, 2.2, 0],
                             "material": { "alpha": 1, "transmission": [0.1, 0.9, 0.1] } },
                           { "shape": "box", "size": [2, 0.04, 2], "position": [0.1, 1.0, 0.1],
                             "material": { "alpha": 1, "transmission": [0.1, 0.9, 0.1] } } ] })");
            render::RenderOptions options = optionsFor(technique);
            options.output = render::OutputMode::Visibility;
            options.debugTranslucent = true;
            render::Renderer r(s, options);
            render::OffscreenTarget target(64, 64);
            r.render(0.0f, s.camera, 64, 64, target.framebuffer());
            const std::vector<float> v = r.readLinear();
            EXPECT_EQ(upward ? r.tintShading().translucentUntinted : r.tintShading().translucentBehindLayers, 1u) << technique;
            const glm::vec3 expected = upward ? t : t * t;
            float worst = 0.0f;
            for (std::size_t i = 0; i < v.size(); i += 4)
                for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(v[i + static_cast<std::size_t>(c)] - expected[c]));
            std::printf("%s, %s: worst %.4f\n", technique, upward ? "upper underside" : "lower top face", worst);
            EXPECT_LE(worst, 2.0f / 255.0f) << technique << (upward ? ": upper underside" : ": lower top face");
        }
}

TEST(TintReachTranslucent, ReceiversWithOtherLayersOnOneSideAreShadedAsTheWholeLookupDoesButAtRims) {
    // Also the first scene: a floating pane in front of a glass block on the ground.
    for (const bool glass : {true, false})
        for (const char* technique : {"hard", "cssm2", "cssm1", "cascaded", "lispsm"}) {
            scene::Scene s = glass ? glassReceivers() : colouredShadows();
            const Pair both = renderBothWays(s, technique, {}, render::TransparencyMode::SortedObjects);
            const render::Renderer::TintShading& t = both.shading;
            EXPECT_GE(t.translucentSplit + t.translucentUntinted + t.translucentBehindLayers, glass ? 2u : 1u) << technique;
            const render::Renderer::TintShading& e = both.shadingEverywhere;
            EXPECT_EQ(e.translucentSplit + e.translucentUntinted + e.translucentBehindLayers, 0u) << technique;
            std::size_t off = 0;
            float most = 0.0f;
            for (std::size_t i = 0; i < both.reached.size(); i += 4)
                for (std::size_t c = 0; c < 3; ++c) {
                    const float d = std::abs(both.reached[i + c] - both.everywhere[i + c]);
                    most = std::max(most, d);
                    if (d > 3.0f / 255.0f) {
                        ++off;
                        break;
                    }
                }
            std::printf("%s, %s: %zu pixels off by over 3/255, largest difference %.4f\n", glass ? "glass" : "pane and block",
                        technique, off, most);
            // Measured: hard 21 (nearest-texel rims); cssm 55-59 since the box filters' reach is the
            // bilinear tint's 2 texels (7-9 with 18, where the whole lookup's rim counts spread
            // another layer's shadow onto a receiver: closer to the reference without, see below);
            // 180-563 with each of the faults above. Since stop 62 a point light's cut lets the glass
            // scene's panes' far sides, seen through their near sides, take the build for their own
            // layers alone, where the whole lookup reads the layers behind them too: hard 322 pixels
            // (at most 4/255 off, since its whole lookup is bounded by those own layers), cssm 329-349.
            // The reference decides there, and the split is the nearer (below); the pane-and-block
            // scene, without a point light, keeps the rims' bound (hard 0, cssm 20-27).
            EXPECT_LE(off, glass ? 400u : 64u) << technique;
        }
}

// Where the split and the whole lookup differ on translucent receivers (their rims as the light
// sees them, and since stop 62 the panes' far sides under the point light), the split is no farther
// from the ray-traced truth, on the nearest surfaces and on those seen through glass. CSSM's whole
// lookup's count of the receiver's own tile spreads another layer's shadow up to 7 texels onto a
// rim, which the builds for one side leave out. Measured (llvmpipe, 320 x 200), RMSE / wrong, split
// against whole: nearest surfaces cssm2 0.0249557 / 0.3874 % against 0.0249562 / 0.3874 % (8,066
// pixel-lights differing), hard 0.0285447 / 0.1882 % against 0.0285451 / 0.1882 %; behind glass
// hard 0.0330 / 0.59 % against 0.1253 / 9.81 %, cssm2 0.0298 / 0.545 % against 0.0385 / 2.69 % (hard's
// split 5.5 % and cssm2's 5.9 % before the own-layers bound, plainMapTint and CSSM's
// shadowVisibility; hard's 12.2 % before the point light's cut too). Footprints 12 texels short of
// the bilinear tint's reach put cssm2's nearest-surface figures at 0.0568 and 0.78 %.
TEST(TintReachTranslucent, TheSplitIsNoFartherFromTheReferenceThanTheWholeLookup) {
    scene::Scene s = glassReceivers();
    for (const reference::Surfaces surfaces : {reference::Surfaces::Nearest, reference::Surfaces::BehindGlass}) {
        reference::Comparison cmp(s, 320, 200, 0.0f, surfaces);
        cmp.traceReference(1, false);
        render::RenderOptions reached;
        reached.transparency = render::TransparencyMode::SortedObjects;
        render::RenderOptions everywhere = reached;
        everywhere.tintOnlyWhereReached = false;
        for (const char* technique : {"hard", "cssm2"}) {
            cmp.setRenderOptions(reached);
            const auto split = cmp.evaluate(technique, 0, 0);
            cmp.setRenderOptions(everywhere);
            const auto whole = cmp.evaluate(technique, 0, 0);
            std::size_t differ = 0;
            for (std::size_t l = 0; l < split.visibility.size(); ++l)
                for (std::size_t i = 0; i < split.visibility[l].size(); ++i)
                    differ += glm::length(split.visibility[l][i] - whole.visibility[l][i]) > 1e-4f;
            const bool behind = surfaces == reference::Surfaces::BehindGlass;
            std::printf("%s, %s: %zu pixel-lights differ; RMSE split %.7f, whole lookup %.7f; wrong %.4f%% / %.4f%%\n", technique,
                        behind ? "behind glass" : "translucent receivers", differ, split.rmse, whole.rmse, 100 * split.wrongShare,
                        100 * whole.wrongShare);
            EXPECT_GT(split.pixels, 1000u) << technique;
            if (behind || std::string(technique) == "cssm2") {
                EXPECT_GT(differ, 0u) << technique << ": the split must reach the scored renderer";
            }
            // Margins of 0.1 % of the RMSE and 0.01 % of the pixels, for another driver's rounding at
            // the rims: far below what a split that loses coloured shadow gives (2.3x and 2x here).
            EXPECT_LE(split.rmse, whole.rmse * 1.001) << technique;
            EXPECT_LE(split.wrongShare, whole.wrongShare + 1e-4) << technique;
        }
    }
}

}  // namespace
}  // namespace penumbra::test
