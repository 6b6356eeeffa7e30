// Shadow maps of still casters are kept across frames (RenderOptions::reuseStillCasters,
// shadows/common/DepthAndTintMaps): a face whose light, map and still casters are unchanged is not
// redrawn, and where an animated caster reaches it only that caster is drawn over a copy of the
// still depth. The pictures must be exactly those of redrawing every map every frame, through
// animation, a still object edited between frames and a light moved, and so must the 2D maps.
#include "GlTestSupport.h"

#include "gl/Debug.h"
#include "render/Offscreen.h"

#include <cmath>

namespace penumbra::test {
namespace {

// A point light (cube map) and a sun (2D map) over a box, a still green pane and a sphere that
// flies through both lights' views. A tall pole makes the scene's bounds (and so the sun's box)
// hold the sphere's paths.
scene::Scene stillAndMovingCasters() {
    return sceneFromJson(R"({
      "camera": { "position": [0, 7, 6], "target": [0, 0, 0], "fov_deg": 50 },
      "lights": [ { "type": "point", "position": [0, 3, 0], "range": 30, "intensity": 0.6, "shadow": { "resolution": 128 } },
                  { "type": "directional", "direction": [-0.4, -1, -0.3], "intensity": 0.6, "shadow": { "resolution": 256 } } ],
      "objects": [ { "shape": "plane", "size": [12, 12] },
                   { "name": "box", "shape": "box", "position": [-1.5, 0.5, 0] },
                   { "name": "pole", "shape": "box", "size": [0.2, 4, 0.2], "position": [-5, 2, -5] },
                   { "name": "pane", "shape": "plane", "size": [1, 1], "position": [1.5, 1.5, 0],
                     "material": { "transmission": [0.1, 0.9, 0.1] } },
                   { "name": "sphere", "shape": "sphere", "radius": 0.4,
                     "animation": [[0, -3, 1, 1], [1, 3, 1, 1], [2, -3, 1, 1]] } ] })");
}

struct Pair {
    render::Renderer reusing, redrawing;
    render::OffscreenTarget target{64, 64};
    Pair(scene::Scene& s, const std::string& technique)
        : reusing(s, options(technique, true)), redrawing(s, options(technique, false)) {}
    static render::RenderOptions options(const std::string& technique, bool reuse) {
        render::RenderOptions o = optionsFor(technique);
        o.reuseStillCasters = reuse;
        return o;
    }
    // Both renderers draw the frame at `time`; the pictures they make.
    std::pair<std::vector<float>, std::vector<float>> render(const scene::Scene& s, float time) {
        reusing.render(time, s.camera, 64, 64, target.framebuffer());
        std::vector<float> a = reusing.readLinear();
        redrawing.render(time, s.camera, 64, 64, target.framebuffer());
        return {std::move(a), redrawing.readLinear()};
    }
};

// The maps a technique shows in its debug views (2D: depth, tint, moments with their mip levels,
// CSSM's coloured map) are the same texel for texel: a kept map that the picture hides (a thin
// moving shadow under a trilinear lookup) still fails.
// The depth tile bounds (PCF, PCSS) are the exception: a map drawn whole every frame has bounds that
// never agree (DepthTileBounds::neverAgree). expectTileBoundsMadeWhole checks the kept ones.
bool isTileBounds(const shadows::DebugView& v) { return v.label.find("depth tile bounds") != std::string::npos; }

std::size_t differingTexels(const std::vector<float>& a, const std::vector<float>& b) {
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.size(); ++i) differing += a[i] != b[i] && !(std::isnan(a[i]) && std::isnan(b[i]));
    return differing;
}

void expectSameMaps(render::Renderer& reusing, render::Renderer& redrawing, const std::string& what) {
    const auto kept = reusing.technique().debugViews(), redrawn = redrawing.technique().debugViews();
    ASSERT_EQ(kept.size(), redrawn.size()) << what;
    for (std::size_t v = 0; v < kept.size(); ++v) {
        if (isTileBounds(kept[v])) continue;
        const std::vector<float> a = textureLevels(kept[v]), b = textureLevels(redrawn[v]);
        ASSERT_EQ(a.size(), b.size()) << kept[v].label;
        EXPECT_EQ(differingTexels(a, b), 0u) << kept[v].label << ", " << what;
    }
}

// The kept renderer's tile bounds, brought up to date rectangle by rectangle, equal those made
// whole from its own maps: `skip_agreeing_taps` off forgets them, back on makes them whole.
void expectTileBoundsMadeWhole(Pair& pair, const scene::Scene& s, float time, const std::string& what) {
    std::vector<std::vector<float>> kept;
    for (const auto& v : pair.reusing.technique().debugViews())
        if (isTileBounds(v)) kept.push_back(textureLevels(v));
    if (kept.empty()) return;
    for (const char* skip : {"false", "true"}) {
        shadows::applyParameters(pair.reusing.technique().parameters(), {{"skip_agreeing_taps", skip}});
        pair.reusing.render(time, s.camera, 64, 64, pair.target.framebuffer());
    }
    std::size_t k = 0;
    for (const auto& v : pair.reusing.technique().debugViews()) {
        if (isTileBounds(v)) {
            EXPECT_EQ(differingTexels(kept.at(k++), textureLevels(v)), 0u) << v.label << ", " << what;
        }
    }
}

// Both renderers draw the frame at `time`: the same pictures and the same maps. Cascades drawn
// only where their receivers read (`fit_receivers`, the default) leave the rest of each layer
// stale, and a reusing renderer's stale texels differ from a redrawing one's: its layer over the
// still casters' depth is kept over a larger rectangle, where the animated casters are kept up to
// date, while the redrawing one draws only this frame's reads. Those are compared by picture;
// `cascaded:fit_receivers=false` compares the maps of whole layers.
bool wholeMaps(const std::string& technique) { return technique != "cascaded"; }

void expectSameFrame(Pair& pair, const scene::Scene& s, float time, const std::string& what, bool maps) {
    const auto [reused, redrawn] = pair.render(s, time);
    ASSERT_EQ(reused.size(), redrawn.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < reused.size(); ++i) differing += reused[i] != redrawn[i];
    EXPECT_EQ(differing, 0u) << what << " (t = " << time << ")";
    if (!maps) return;
    expectSameMaps(pair.reusing, pair.redrawing, what + ", t = " + std::to_string(time));
    expectTileBoundsMadeWhole(pair, s, time, what + ", t = " + std::to_string(time));
}

// A cascade draws a big mesh's clusters only within the column along the light over what its
// slice reads (CasterSelection::cullPlanes), and a kept layer's key holds the clusters it drew:
// it is drawn again when they change. The camera looks across the shadow of a sphere of 65k
// triangles on the ground and turns: the first cascades' boxes are held and some layers kept while
// their columns move. The pictures stay those of layers redrawn every frame; with a key blind to
// the clusters (before 83ba7f1), 54 values of 8 frames differed.
TEST(KeptCascades, ABigMeshsClustersFollowTheColumnsWhileTheCameraTurns) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [1.5, 1.5, -3], "target": [0, 0, -3], "near": 0.1, "far": 60 },
      "lights": [ { "type": "directional", "direction": [-0.4, -1, -0.3], "shadow": { "resolution": 512 } } ],
      "objects": [ { "shape": "plane", "size": [60, 60] }, { "shape": "sphere", "position": [0, 1.5, 0] } ] })");
    const scene::Mesh& ball = makeBigSphere(s, 1, 1.0f);
    ASSERT_GE(ball.triangleCount(), render::kClusteredPartTriangles);
    Pair pair(s, "cascaded");
    std::size_t kept = 0, redrawn = 0;
    const glm::vec3 from(0.0f, 0.0f, -3.0f), to(-3.0f, 0.0f, 0.0f);
    const int frames = 8;
    for (int frame = 0; frame < frames; ++frame) {
        s.camera.target = glm::mix(from, to, static_cast<float>(frame) / static_cast<float>(frames));
        expectSameFrame(pair, s, 0.0f, "frame " + std::to_string(frame), false);
        kept += pair.reusing.shadowTriangles().at(0);
        redrawn += pair.redrawing.shadowTriangles().at(0);
    }
    EXPECT_LT(kept, redrawn) << "some layers kept";
    EXPECT_LT(redrawn, frames * 4 * ball.triangleCount()) << "clusters culled";
}

class ShadowReuse : public ::testing::TestWithParam<const char*> {};

TEST_P(ShadowReuse, PicturesEqualRedrawingEveryMapEveryFrame) {
    scene::Scene s = stillAndMovingCasters();
    Pair pair(s, GetParam());
    auto expectSame = [&](float time, const char* what) {
        expectSameFrame(pair, s, time, std::string(GetParam()) + ", " + what, wholeMaps(GetParam()));
    };
    expectSame(0.0f, "first frame");
    expectSame(0.25f, "the sphere moved");
    expectSame(0.25f, "the same frame again");
    s.objects[1].position = {-1.0f, 0.5f, 1.5f};  // the still box is edited between frames
    expectSame(0.25f, "a still caster moved");
    s.lights[0].position = {0.5f, 3.5f, 0.0f};
    expectSame(0.25f, "the point light moved");
    s.lights[1].direction = glm::normalize(glm::vec3(-0.2f, -1.0f, -0.5f));
    expectSame(0.5f, "the sun turned");
    s.objects[3].position = {1.0f, 1.2f, 0.5f};  // the still pane
    expectSame(0.5f, "the pane moved");
    s.objects[4].animation = {};  // nothing animated: whole maps and tints are kept
    expectSame(0.5f, "nothing animated");
    expectSame(0.5f, "nothing animated, again");
    s.camera.position = {1.0f, 6.0f, 7.0f};  // cascades and warped maps follow the camera
    expectSame(0.5f, "the camera moved, nothing animated");
    expectSame(0.5f, "the camera stands still again");
    s.objects[3].position = {1.5f, 1.4f, -0.5f};
    expectSame(0.5f, "the pane moved, nothing animated");
    s.objects[1].position = {-1.5f, 0.5f, 0.0f};
    expectSame(0.5f, "the box moved, nothing animated");
    // The sphere flies between the sun and the pane: the pane's map must follow it over the pane,
    // and be drawn again once it has left.
    s.objects[3].position = {1.5f, 1.5f, 0.0f};
    s.objects[4].animation.position = scene::Track({{0.0f, {-2.0f, 2.5f, 0.0f}}, {1.0f, {4.0f, 2.5f, 0.0f}}, {2.0f, {-2.0f, 2.5f, 0.0f}}});
    for (float t : {0.0f, 0.1f, 0.1f, 0.3f, 0.5f, 0.6f, 0.8f, 0.9f, 0.9f})
        expectSame(t, "the sphere crossing over the pane");
    // Higher, wholly in front of the pane as the sun sees them while it crosses the pane's texels:
    // translucent casters are drawn over the still casters' depth, and the sphere's texels are
    // no longer redrawn in the tint and CSSM's map (DepthAndTintMaps::translucentRedo).
    s.objects[4].animation.position = scene::Track({{0.0f, {-2.0f, 3.2f, 1.2f}}, {1.0f, {4.0f, 3.2f, 1.2f}}, {2.0f, {-2.0f, 3.2f, 1.2f}}});
    for (float t : {0.0f, 0.3f, 0.45f, 0.55f, 0.55f, 0.65f, 0.9f, 1.1f}) expectSame(t, "the sphere crossing high over the pane");
}

// Animated translucent casters: the tint and CSSM's coloured map keep what the still casters drew
// and are drawn again only where a glass ball flies, or an opaque one crosses the panes'
// texels (the panes are depth-tested against it), as it is now and as it was last frame
// (DepthAndTintMaps::translucentRedo).
TEST_P(ShadowReuse, PicturesEqualRedrawingEveryMapWithAnimatedGlass) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 7, 6], "target": [0, 0, 0], "fov_deg": 50 },
      "lights": [ { "type": "point", "position": [0, 3, 0], "range": 30, "intensity": 0.6, "shadow": { "resolution": 128 } },
                  { "type": "directional", "direction": [-0.4, -1, -0.3], "intensity": 0.6, "shadow": { "resolution": 256 } } ],
      "objects": [ { "shape": "plane", "size": [12, 12] },
                   { "name": "pole", "shape": "box", "size": [0.2, 4, 0.2], "position": [-5, 2, -5] },
                   { "name": "green pane", "shape": "plane", "size": [2, 2], "position": [1.5, 1.2, 0],
                     "material": { "transmission": [0.1, 0.9, 0.1] } },
                   { "name": "blue pane", "shape": "plane", "size": [1, 1], "position": [-1.5, 1.5, 0.5],
                     "material": { "transmission": [0.2, 0.2, 0.9] } },
                   { "name": "glass ball", "shape": "sphere", "radius": 0.4, "material": { "transmission": [0.9, 0.3, 0.3] },
                     "animation": [[0, -3, 2, 0.2], [1, 3, 2, 0.2], [2, -3, 2, 0.2]] },
                   { "name": "stone", "shape": "sphere", "radius": 0.3,
                     "animation": [[0, 3, 1.6, -0.2], [1, -3, 1.6, -0.2], [2, 3, 1.6, -0.2]] } ] })");
    Pair pair(s, GetParam());
    auto expectSame = [&](float time, const char* what) {
        expectSameFrame(pair, s, time, std::string(GetParam()) + ", " + what, wholeMaps(GetParam()));
    };
    for (float t : {0.0f, 0.1f, 0.1f, 0.2f, 0.35f, 0.5f, 0.6f, 0.6f, 0.75f, 0.9f, 1.2f}) expectSame(t, "glass ball and stone flying");
    s.objects[4].animation = {};  // the glass ball stops: only the stone moves, over the panes and away
    for (float t : {1.3f, 1.4f, 1.4f, 1.6f, 1.8f}) expectSame(t, "the stone alone");
}

// cssm2 with white ξ draws new noise every frame (seeded by the frame index): never kept. A wide
// blur spreads a moving caster's moments beyond its texels: they must be redone there too.
INSTANTIATE_TEST_SUITE_P(Techniques, ShadowReuse, ::testing::Values("hard", "pcf-poisson16", "pcss", "cssm2", "cssm2:xi=white", "vsm", "vsm:blur_radius=16", "vsm:blur_kernel=gaussian",
                                                                  "vsm:compute_blur=true", "vsm:blur_kernel=gaussian:compute_blur=true",
                                                                  "msm", "evsm4", "cascaded", "cascaded:fit_receivers=false", "lispsm", "psm"));

// A map drawn whole every frame makes no tile bounds (the bounds' pass cost llvmpipe more than the
// taps they saved): its layer holds bounds that never agree (a = -4), so the lookups run their whole
// kernels, and the pictures are those of the kept maps' bounds (ShadowReuse above). Kept maps
// make them.
TEST(TileBounds, AMapDrawnWholeEveryFrameHasBoundsThatNeverAgree) {
    scene::Scene s = stillAndMovingCasters();
    Pair pair(s, "pcf-poisson16");
    pair.render(s, 0.0f);
    pair.render(s, 0.25f);
    const auto planesAgreeing = [](render::Renderer& r) {
        std::size_t texels = 0, agreeing = 0;
        for (const auto& v : r.technique().debugViews())
            if (isTileBounds(v)) {
                const std::vector<float> t = textureLevels(v);
                for (std::size_t i = 0; i < t.size(); i += 4) texels++, agreeing += t[i] > -4.0f;
            }
        EXPECT_GT(texels, 0u);
        return agreeing;
    };
    EXPECT_EQ(planesAgreeing(pair.redrawing), 0u) << "maps drawn whole every frame: no bounds made";
    EXPECT_GT(planesAgreeing(pair.reusing), 100u) << "kept maps: bounds made";
    // `tile_bounds_every_frame` makes them for such maps too (to measure the choice on a GPU).
    shadows::applyParameters(pair.redrawing.technique().parameters(), {{"tile_bounds_every_frame", "true"}});
    pair.render(s, 0.5f);
    EXPECT_GT(planesAgreeing(pair.redrawing), 100u) << "tile_bounds_every_frame: bounds made";
}

// Without an animated caster, the second frame of an unchanged view draws no triangle into any
// shadow map; with the sphere in both lights' views only it is drawn into depth, and the pane's
// tint (hard) or coloured stochastic map (cssm2, and its tint for tint_behind_all: the pane twice)
// is redrawn only while the sphere's texels overlap the pane's, since the pane is depth-tested
// against what the sphere writes; not even then once the sphere lies wholly in front of the pane
// (DepthAndTintMaps: translucent casters tested against the still depth).
class KeptMapTriangles : public ::testing::TestWithParam<const char*> {};

TEST_P(KeptMapTriangles, UnchangedMapsDrawNothingAndAnimatedCastersAlone) {
    scene::Scene s = stillAndMovingCasters();
    scene::Object& sphere = s.objects[4];
    const std::size_t sphereTriangles = s.meshes[static_cast<std::size_t>(sphere.mesh)].parts.at(0).indexCount / 3;
    const std::size_t pane = std::string(GetParam()) == "cssm2" ? 2 * 2 : 2;
    // Low over the ground (0.15 m): within a lookup's reach of it under the sun.
    sphere.animation.position = scene::Track({{0.0f, {-3.0f, 0.55f, 1.0f}}, {1.0f, {3.0f, 0.55f, 1.0f}}});
    Pair pair(s, GetParam());
    pair.render(s, 0.0f);  // the sphere at (-3, 0.55, 1): in the sun's view, far from the pane
    const std::vector<std::size_t> first = pair.reusing.shadowTriangles();
    EXPECT_EQ(first, pair.redrawing.shadowTriangles()) << "the first frame draws everything either way";
    pair.render(s, 0.0f);
    EXPECT_EQ(pair.redrawing.shadowTriangles(), first);
    ASSERT_EQ(pair.reusing.shadowTriangles().size(), 2u);
    EXPECT_GE(pair.reusing.shadowTriangles()[0], sphereTriangles);
    EXPECT_LT(pair.reusing.shadowTriangles()[0], first[0]);
    EXPECT_EQ(pair.reusing.shadowTriangles()[1], sphereTriangles) << "the sun draws the sphere alone; the pane's map is kept";

    sphere.animation.position = scene::Track({{0.0f, {1.5f, 2.5f, 0.0f}}, {1.0f, {1.6f, 2.5f, 0.0f}}});  // above the pane, between it and the sun
    // The sphere has left the ground's reach: the ground, drawn whole into the sun's still map
    // while a moving caster came within it, is now drawn only around what rests on it
    // (Renderer::flatCasterNeeds), and the still map once again.
    pair.render(s, 0.0f);
    EXPECT_GT(pair.reusing.shadowTriangles()[1], sphereTriangles + pane) << "the still map drawn again once";
    for (int frame = 0; frame < 2; ++frame) {
        pair.render(s, 0.0f);
        EXPECT_EQ(pair.reusing.shadowTriangles()[1], sphereTriangles + pane)
            << "frame " << frame << " with the sphere over the pane: the pane is drawn again";
    }

    // Well above the pane, wholly in front of it as the sun sees them: the tint and CSSM's colour
    // map are drawn over the still casters' depth, so the sphere's motion leaves them alone. The
    // first frame redraws where the sphere was last.
    sphere.animation.position = scene::Track({{0.0f, {1.5f, 3.5f, 0.0f}}, {1.0f, {1.6f, 3.5f, 0.0f}}});
    pair.render(s, 0.0f);
    for (int frame = 0; frame < 2; ++frame) {
        pair.render(s, 0.0f);
        EXPECT_EQ(pair.reusing.shadowTriangles()[1], sphereTriangles) << "frame " << frame << " with the sphere high over the pane";
    }

    sphere.animation = {};  // nothing moves now
    pair.render(s, 0.0f);   // the maps are drawn once more without the sphere's motion
    pair.render(s, 0.0f);
    EXPECT_EQ(pair.reusing.shadowTriangles(), (std::vector<std::size_t>{0, 0})) << "nothing changed: nothing drawn";
}

INSTANTIATE_TEST_SUITE_P(Techniques, KeptMapTriangles, ::testing::Values("hard", "cssm2"));
// Layered maps (cascades, warped views) over still casters that an animated caster flies through:
// once their views have held for a frame, only the animated caster is drawn into the layers it
// reaches, over a copy of the still casters' depth (LayeredDepthMap), with the pictures and maps
// of drawing every layer whole (ShadowReuse above). Before, those layers were drawn whole.
class KeptLayers : public ::testing::TestWithParam<const char*> {};

TEST_P(KeptLayers, DrawTheAnimatedCasterAlone) {
    scene::Scene s = stillAndMovingCasters();
    const std::size_t sphereTriangles = s.meshes[static_cast<std::size_t>(s.objects[4].mesh)].parts.at(0).indexCount / 3;
    Pair pair(s, GetParam());
    pair.render(s, 0.0f);   // the layers drawn whole
    pair.render(s, 0.05f);  // their views held: the still casters' depth drawn, the sphere over its copy
    for (float t : {0.1f, 0.2f, 0.3f}) {  // the sphere at x = -1.8 .. -1.2, far from the pane's texels
        pair.render(s, t);
        const std::size_t sun = pair.reusing.shadowTriangles().at(1), whole = pair.redrawing.shadowTriangles().at(1);
        EXPECT_GT(sun, 0u) << GetParam() << ", t = " << t << ": the sphere is drawn";
        EXPECT_EQ(sun % sphereTriangles, 0u) << GetParam() << ", t = " << t << ": " << sun << " triangles, the sphere's " << sphereTriangles;
        EXPECT_LT(sun, whole) << GetParam() << ", t = " << t << ": the layers drawn whole";
    }
    EXPECT_EQ(gl::debugErrorCount(), 0);
}

INSTANTIATE_TEST_SUITE_P(Techniques, KeptLayers, ::testing::Values("cascaded", "lispsm", "psm"));

}  // namespace
}  // namespace penumbra::test
