// View-dependent shadow maps against the ray-traced reference: over a sweep of camera and sun
// directions (sun in front of, behind, beside and above the viewer; camera level to looking
// straight down), LiSPSM, PSM and tiled LiSPSM lose no shadows and invent none, counted per
// pixel.
#include "GlTestSupport.h"
#include "reference/Comparison.h"
#include "render/Offscreen.h"
#include "shadows/cascaded/CascadedShadowMap.h"
#include "shadows/warped/WarpedShadowMap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace penumbra::test {
namespace {

scene::Scene sweepScene() {
    std::string posts;
    for (int i = 0; i < 8; ++i)
        posts += R"(, { "shape": "box", "size": [0.3, 2.5, 0.3], "position": [)" + std::to_string(i % 2 ? 3.0 : -3.0) +
                 ", 1.25, " + std::to_string(-4.0 - 6.0 * i) + "] }";
    return sceneFromJson(R"({
      "camera": { "position": [0, 2.0, 2], "target": [0, 1.0, -20], "fov_deg": 60, "near": 0.1, "far": 80 },
      "lights": [ { "type": "directional", "direction": [-0.5, -1, -0.3], "shadow": { "resolution": 1024 } } ],
      "objects": [ { "shape": "plane", "size": [30, 60], "position": [0, 0, -25] },
                   { "shape": "sphere", "radius": 0.8, "position": [1.0, 1.2, -8] },
                   { "shape": "box", "size": [4, 0.3, 1], "position": [0, 3.5, -14] } )" + posts + "] }");
}

// One case of the sweep: the sun at azimuth `sunAz` and elevation `sunEl` (degrees), the camera
// 14 m from the scene's middle, pitched by `pitch`.
void aimSweep(scene::Scene& s, int sunAz, float sunEl, float pitch) {
    const glm::vec3 target(0.0f, 0.5f, -10.0f);
    const float az = glm::radians(static_cast<float>(sunAz)), el = glm::radians(sunEl), p = glm::radians(pitch);
    s.lights[0].direction = -glm::vec3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
    s.camera.target = target;
    s.camera.position = target - 14.0f * glm::vec3(0.02f, std::sin(p), -std::cos(p));
}

// The case, and the reference traced for it at 160 x 96.
reference::Comparison sweepCase(scene::Scene& s, int sunAz, float sunEl, float pitch) {
    aimSweep(s, sunAz, sunEl, pitch);
    reference::Comparison cmp(s, 160, 96, 0.0f);
    cmp.traceReference(1, false);
    return cmp;
}

// Shadow masks of the reference and of a technique (pixels the light cannot reach count as
// shadowed in both), compared away from the reference's shadow edges: rasterisation and rays
// may differ by a pixel along an edge, a lost or invented shadow shows up inside a region.
MaskComparison compareShadowMasks(const reference::Comparison& cmp, const reference::TechniqueScore& score) {
    const auto& ref = cmp.referenceVisibility()[0];
    const auto& lit = cmp.litMask(0);
    std::vector<bool> expected(ref.size()), rendered(ref.size());
    for (std::size_t i = 0; i < ref.size(); ++i) {
        expected[i] = !lit[i] || ref[i].x < 0.5f;
        rendered[i] = !lit[i] || score.visibility[0][i].x < 0.5f;
    }
    return compareMasks(expected, rendered, cmp.width(), cmp.height(), 1);
}

// Calls each(sunAz, sunEl, pitch) for the sweep's 24 cases: the sun in front of, behind and beside
// the viewer, low and high; the camera level to looking straight down.
template <typename Each>
void forEachSweepCase(Each&& each) {
    for (int sunAz : {0, 90, 180, 270})
        for (float sunEl : {25.0f, 70.0f})
            for (float pitch : {-12.0f, -50.0f, -88.0f}) each(sunAz, sunEl, pitch);
}

TEST(ViewDependent, NoShadowIsLostOverASweepOfCameraAndSunAngles) {
    scene::Scene s = sweepScene();
    int worst = 0, cases = 0;
    forEachSweepCase([&](int sunAz, float sunEl, float pitch) {
        reference::Comparison cmp = sweepCase(s, sunAz, sunEl, pitch);
        for (const char* technique : {"lispsm", "psm", "lispsm-tiled"}) {
            const MaskComparison m = compareShadowMasks(cmp, cmp.evaluate(technique, 1024, 0));
            // A lost shadow is a region; a dozen scattered pixels (0.08%) are sub-pixel
            // slivers of distant posts that no 1024^2 map resolves.
            EXPECT_LE(m.mismatchesAwayFromEdges, 12)
                << technique << " sun az " << sunAz << " el " << sunEl << " pitch " << pitch << ": " << m.mismatchesAwayFromEdges
                << " pixels away from edges differ (" << m.mismatches << " in all, " << m.expectedOn << " shadowed)";
            worst = std::max(worst, m.mismatchesAwayFromEdges);
            ++cases;
        }
    });
    std::printf("sweep of %d technique/camera/sun cases: at most %d pixels away from shadow edges differ\n", cases, worst);
}

// The view-dependent maps pad the shadows whose lookup they leave out by their coarsest texel on
// the camera's body (shadowReachTexels): over the sweep, every shaded pixel is as with every
// lookup made (`--shadow-everywhere`), while pixels are shaded without the lookup in some cases.
TEST(ViewDependent, LookupsLeftOutChangeNoPixelOverTheSweep) {
    scene::Scene s = sweepScene();
    int cases = 0, split = 0;
    forEachSweepCase([&](int sunAz, float sunEl, float pitch) {
        aimSweep(s, sunAz, sunEl, pitch);
        for (const char* technique : {"lispsm", "psm", "lispsm-tiled", "cascaded"}) {
            std::vector<float> pictures[2];
            for (int everywhere = 0; everywhere < 2; ++everywhere) {
                render::RenderOptions options = optionsFor(technique);
                options.shadowOnlyWhereCast = everywhere == 0;
                render::Renderer renderer(s, options);
                render::OffscreenTarget target(160, 96);
                renderer.render(0.0f, s.camera, 160, 96, target.framebuffer());
                pictures[everywhere] = renderer.readLinear();
                if (everywhere == 0) split += renderer.tintShading().unshadowedPieces > 0;
            }
            EXPECT_EQ(differingPixels(pictures[0], pictures[1]), 0u) << technique << " sun az " << sunAz << " el " << sunEl << " pitch " << pitch;
            ++cases;
        }
    });
    std::printf("%d cases, %d of them shaded in part without the sun's lookup\n", cases, split);
    EXPECT_GT(split, cases / 4);
}

// Footprints are padded by the reach of the maps read where they lie (shadowReachTexelsWithin):
// near the camera the first cascade's, or the warped map's finest texels, less than the frame's
// coarsest; over the whole view, and for a far region, the coarsest; other lights' hard lookups 2.
// (The sweep above checks that the pixels stay as with every lookup made.)
TEST(ViewDependent, FootprintsNearTheCameraArePaddedByTheNearMapsTexels) {
    scene::Scene s = sweepScene();
    s.lights.push_back(s.lights[0]);  // a second sun: the view-dependent maps take the first only
    s.lights[1].direction = glm::vec3(0.3f, -1.0f, 0.2f);
    const glm::vec3 eye = s.camera.position, ahead = glm::normalize(s.camera.target - s.camera.position);
    // A patch of the ground `distance` ahead of the camera (receivers lie on surfaces).
    const auto around = [&](float distance) {
        const glm::vec3 at = eye + ahead * distance;
        scene::Bounds b;
        b.add(glm::vec3(at.x - 0.01f * distance, 0.0f, at.z - 0.01f * distance));
        b.add(glm::vec3(at.x + 0.01f * distance, 0.01f, at.z + 0.01f * distance));
        return b;
    };
    for (const char* technique : {"cascaded", "lispsm", "psm"}) {
        render::RenderOptions options = optionsFor(technique);
        render::Renderer renderer(s, options);
        render::OffscreenTarget target(160, 96);
        renderer.render(0.0f, s.camera, 160, 96, target.framebuffer());
        const shadows::ShadowTechnique& t = renderer.technique();
        const float coarsest = t.shadowReachTexels();
        scene::Bounds view;
        view.add(eye);
        view.add(eye + ahead * 60.0f + glm::vec3(20.0f, -2.0f, 0.0f));
        view.add(eye + ahead * 60.0f - glm::vec3(20.0f, 2.0f, 0.0f));
        float nearDistance = 4.0f, farDistance = 40.0f;
        if (std::string(technique) == "cascaded") {
            const auto& cascades = dynamic_cast<const shadows::CascadedShadowMap&>(t).cascades();
            ASSERT_EQ(cascades.size(), 4u);
            nearDistance = 0.5f * cascades[0].splitFar;                        // before its blend band
            farDistance = 0.5f * (cascades[3].splitNear + cascades[3].splitFar);  // the last cascade alone
        }
        std::printf("%s: reach %.0f texels, %.0f at %.2f m, %.0f at %.1f m, %.0f over the view\n", technique, coarsest,
                    t.shadowReachTexelsWithin(0, around(nearDistance)), nearDistance, t.shadowReachTexelsWithin(0, around(farDistance)),
                    farDistance, t.shadowReachTexelsWithin(0, view));
        EXPECT_GT(coarsest, 2.0f) << technique << ": the far maps' texels are coarser than the plain map's";
        EXPECT_LT(t.shadowReachTexelsWithin(0, around(nearDistance)), coarsest) << technique;
        EXPECT_GE(t.shadowReachTexelsWithin(0, around(nearDistance)), 2.0f) << technique;
        EXPECT_EQ(t.shadowReachTexelsWithin(0, view), coarsest) << technique;
        if (std::string(technique) == "cascaded") {
            EXPECT_EQ(t.shadowReachTexelsWithin(0, around(farDistance)), coarsest);
        }
        EXPECT_EQ(t.shadowReachTexelsWithin(1, around(nearDistance)), 2.0f) << technique << ": the second sun's plain map";
    }
}

// Cascades chosen either way (CASCADE_SELECT, compiled into the lookup: by view depth, or by the
// first cascade box that holds the point) lose no shadow and invent none over the sweep's pitches,
// with the sun low behind the viewer and high beside it; and every visibility stays in [0, 1]
// (chosen by box, a point beyond its cascade's split took a blend weight past 1: on the default
// scene, visibilities out of range raised the RMSE against the reference from 0.025 to 0.124).
TEST(ViewDependent, CascadesChosenByDepthOrByBoxLoseNoShadow) {
    scene::Scene s = sweepScene();
    for (const auto& [sunAz, sunEl] : {std::pair(180, 25.0f), std::pair(90, 70.0f)})
        for (float pitch : {-12.0f, -50.0f}) {
            reference::Comparison cmp = sweepCase(s, sunAz, sunEl, pitch);
            for (const char* select : {"depth", "projection"}) {
                const reference::TechniqueScore score = cmp.evaluate("cascaded", 1024, 0, {{"select", select}});
                VisibilitySpan range;
                for (const auto& perLight : score.visibility)
                    for (const glm::vec3& v : perLight) range.add(v);
                EXPECT_TRUE(range.withinZeroAndOne()) << "select=" << select << " sun az " << sunAz << " pitch " << pitch << ": "
                                                      << range.lowest << " .. " << range.highest;
                const MaskComparison m = compareShadowMasks(cmp, score);
                EXPECT_GT(m.expectedOn, 100) << "the scene's shadows are in view";
                EXPECT_LE(m.mismatchesAwayFromEdges, 12) << "select=" << select << " sun az " << sunAz << " el " << sunEl << " pitch "
                                                         << pitch << ": " << m.mismatchesAwayFromEdges << " pixels away from edges differ";
            }
        }
}

// The tile count is compiled into the warped lookup (WARPED_TILES): a grid changed on a live
// renderer must rebuild it in the same frame, each picture equal to the next frame's and to a
// fresh renderer's.
TEST(ViewDependent, ATileGridChangedOnALiveRendererRebuildsTheLookup) {
    scene::Scene s = sweepScene();
    s.camera.position = glm::vec3(0.0f, 6.0f, 4.0f);
    auto render = [&](render::Renderer& r) {
        render::OffscreenTarget target(128, 80);
        r.render(0.0f, s.camera, 128, 80, target.framebuffer());
        return r.readLinear();
    };
    render::RenderOptions options;
    options.technique = "lispsm";
    options.output = render::OutputMode::Visibility;
    render::Renderer live(s, options);
    const std::vector<float> single = render(live);
    for (const char* side : {"2", "1"}) {
        shadows::applyParameters(live.technique().parameters(), {{"cols", side}, {"rows", side}});
        const std::vector<float> changed = render(live);
        EXPECT_EQ(changed, render(live)) << side << " x " << side << " tiles: the first frame after the change as the next";
        options.parameters = {{"cols", side}, {"rows", side}};
        render::Renderer fresh(s, options);
        EXPECT_EQ(changed, render(fresh)) << side << " x " << side << " tiles";
        if (std::string(side) == "2") {
            EXPECT_NE(changed, single) << "four tiles' maps differ from one map";
        }
    }
}

// SDSM: a wall 20 m ahead hides the rest of a 1 km view; the cascades then split [first
// visible, last visible] instead of [near, far], and the first cascade's texels shrink. The first
// visible depth is the floor under the pre-pass's bottom row of pixels (80 x 45, half the view):
// 1.7 m below the eye, seen 30 deg x 44/45 below the axis tilted down by atan(0.2 / 20),
// 1.7 / (0.56452 cos a + sin a) = 2.959 m along the axis; the fit starts 1 % before it.
TEST(ViewDependent, SdsmSplitsOnlyTheVisibleDepthRange) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 1.7, 0], "target": [0, 1.5, -20], "fov_deg": 60, "near": 0.1, "far": 1000 },
      "lights": [ { "type": "directional", "direction": [-0.5, -1, -0.3], "shadow": { "resolution": 512 } } ],
      "objects": [ { "shape": "plane", "size": [100, 1000], "position": [0, 0, -480] },
                   { "shape": "box", "size": [60, 30, 1], "position": [0, 15, -20.5] } ] })");
    auto cascadesWith = [&](bool sdsm) {
        render::RenderOptions options;
        options.technique = "cascaded";
        options.parameters = {{"sdsm", sdsm ? "true" : "false"}};
        render::Renderer renderer(s, options);
        render::OffscreenTarget target(160, 90);
        renderer.render(0.0f, s.camera, 160, 90, target.framebuffer());
        return dynamic_cast<const shadows::CascadedShadowMap&>(renderer.technique()).cascades();
    };
    const auto plain = cascadesWith(false), sdsm = cascadesWith(true);
    ASSERT_EQ(plain.size(), 4u);
    ASSERT_EQ(sdsm.size(), 4u);
    std::printf("first split %.4f m SDSM; last split: %.1f m plain, %.1f m SDSM; first cascade texel %.4f m plain, %.4f m SDSM\n", sdsm.front().splitNear, plain.back().splitFar,
                sdsm.back().splitFar, plain.front().texelWorld, sdsm.front().texelWorld);
    EXPECT_FLOAT_EQ(plain.back().splitFar, 1000.0f);
    // The farthest visible depth (along the view axis) is the wall's face, 20 m ahead.
    EXPECT_GT(sdsm.back().splitFar, 19.9f);
    EXPECT_LT(sdsm.back().splitFar, 21.0f);
    EXPECT_NEAR(sdsm.front().splitNear, 0.99f * 2.959f, 0.01f);
    EXPECT_FLOAT_EQ(plain.front().splitNear, s.camera.near);
    EXPECT_LT(sdsm.front().texelWorld, 0.5f * plain.front().texelWorld);
}

// SDSM's bounds on a grid of 5 % steps: a camera stepping 10 cm towards the wall keeps every split
// (the tight far bound moves from 20.2 m to 20.1, both within the step up to 1.05^62 = 20.6 m), so
// the cascades hold instead of being fitted and redrawn; a 5 m step moves the last split to the
// wall's new distance.
TEST(ViewDependent, SdsmSplitsHoldWhileTheVisibleRangeStaysWithinItsStep) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 1.7, 0], "target": [0, 1.5, -20], "fov_deg": 60, "near": 0.1, "far": 1000 },
      "lights": [ { "type": "directional", "direction": [-0.5, -1, -0.3], "shadow": { "resolution": 512 } } ],
      "objects": [ { "shape": "plane", "size": [100, 1000], "position": [0, 0, -480] },
                   { "shape": "box", "size": [60, 30, 1], "position": [0, 15, -20.5] } ] })");
    render::RenderOptions options;
    options.technique = "cascaded";
    options.parameters = {{"sdsm", "true"}};
    render::Renderer renderer(s, options);
    render::OffscreenTarget target(160, 90);
    auto splitsAt = [&](float z) {
        scene::Camera camera = s.camera;
        camera.position.z = z;
        camera.target.z = z - 20.0f;
        renderer.render(0.0f, camera, 160, 90, target.framebuffer());
        std::vector<float> splits;
        for (const auto& c : dynamic_cast<const shadows::CascadedShadowMap&>(renderer.technique()).cascades())
            splits.insert(splits.end(), {c.splitNear, c.splitFar});
        return splits;
    };
    const std::vector<float> first = splitsAt(0.0f), stepped = splitsAt(-0.1f), far = splitsAt(-5.0f);
    ASSERT_EQ(first.size(), 8u);
    EXPECT_EQ(stepped, first) << "10 cm nearer the wall";
    EXPECT_NEAR(first.back(), std::pow(1.05f, 62.0f), 1e-3f);
    EXPECT_GT(far.back(), 15.0f);
    EXPECT_LT(far.back(), 15.0f * 1.05f * 1.05f);
}

// A warped map's fit is kept while the camera and the objects stand still (WarpedShadowMap::
// fitViews), and made again when either moves (a small scene, whole in view, so that the sun's
// plain box does not follow the camera): with every fit the tight one (holdSunBox off), a
// renderer's views equal those of a fresh renderer that draws that frame alone, after a repeated
// frame, a moved camera and an object risen (the scene's box grows); and they differ from the
// frame before where it moved.
TEST(ViewDependent, AWarpedFitIsKeptWhileNothingMovesAndMadeAgainWhenSomethingDoes) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 9, 12], "target": [0, 0, 0], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [-0.4, -1, -0.3], "shadow": { "resolution": 256 } } ],
      "objects": [ { "shape": "plane", "size": [6, 6] }, { "shape": "box", "position": [0, 0.5, 0] },
                   { "shape": "sphere", "radius": 0.5, "animation": [[0, 0, 1, 0], [1, 0, 9, 0]] } ] })");
    for (const char* technique : {"lispsm", "psm"}) {
        render::RenderOptions options = optionsFor(technique);
        options.holdSunBox = false;
        render::OffscreenTarget target(64, 48);
        const auto viewsAfter = [&](render::Renderer& renderer, float time) {
            renderer.render(time, s.camera, 64, 48, target.framebuffer());
            const auto& warped = dynamic_cast<const shadows::WarpedShadowMap&>(renderer.technique());
            std::vector<glm::mat4> views;
            for (const shadows::WarpedView& v : warped.views()) views.push_back(v.viewProj);
            return views;
        };
        const auto fresh = [&](float time) {
            render::Renderer renderer(s, options);
            return viewsAfter(renderer, time);
        };
        render::Renderer live(s, options);
        const std::vector<glm::mat4> first = viewsAfter(live, 0.0f);
        EXPECT_EQ(viewsAfter(live, 0.0f), first) << technique << ": the same frame again";
        EXPECT_EQ(first, fresh(0.0f)) << technique;
        const scene::Camera still = s.camera;
        s.camera.position = glm::vec3(4, 8, 11);  // the scene still whole in view: the sun's box stays
        const std::vector<glm::mat4> moved = viewsAfter(live, 0.0f);
        EXPECT_NE(moved, first) << technique << ": the camera moved";
        EXPECT_EQ(moved, fresh(0.0f)) << technique << ": the camera moved";
        s.camera = still;
        viewsAfter(live, 0.0f);
        const std::vector<glm::mat4> later = viewsAfter(live, 0.75f);
        EXPECT_NE(later, first) << technique << ": the sphere rose";
        EXPECT_EQ(later, fresh(0.75f)) << technique << ": the sphere rose";
    }
}

}  // namespace
}  // namespace penumbra::test
