// Shadow maps of still casters are kept across frames (RenderOptions::reuseStillCasters,
// shadows/common/DepthAndTintMaps): a face whose light, map and still casters are unchanged is not
// redrawn, and where an animated caster reaches it only that caster is drawn over a copy of the
// still depth. The pictures must be exactly those of redrawing every map every frame, through
// animation, a still object edited between frames and a light moved.
#include "GlTestSupport.h"

#include "render/Offscreen.h"

namespace penumbra::test {
namespace {

// A point light (cube map) and a sun (2D map) over a box, a still green pane and a sphere that
// flies through both lights' views.
scene::Scene stillAndMovingCasters() {
    return sceneFromJson(R"({
      "camera": { "position": [0, 7, 6], "target": [0, 0, 0], "fov_deg": 50 },
      "lights": [ { "type": "point", "position": [0, 3, 0], "range": 30, "intensity": 0.6, "shadow": { "resolution": 128 } },
                  { "type": "directional", "direction": [-0.4, -1, -0.3], "intensity": 0.6, "shadow": { "resolution": 256 } } ],
      "objects": [ { "shape": "plane", "size": [12, 12] },
                   { "name": "box", "shape": "box", "position": [-1.5, 0.5, 0] },
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
        render::RenderOptions o;
        o.technique = technique;
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

class ShadowReuse : public ::testing::TestWithParam<const char*> {};

TEST_P(ShadowReuse, PicturesEqualRedrawingEveryMapEveryFrame) {
    scene::Scene s = stillAndMovingCasters();
    Pair pair(s, GetParam());
    auto expectSame = [&](float time, const char* what) {
        const auto [reused, redrawn] = pair.render(s, time);
        ASSERT_EQ(reused.size(), redrawn.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < reused.size(); ++i) differing += reused[i] != redrawn[i];
        EXPECT_EQ(differing, 0u) << GetParam() << ", " << what << " (t = " << time << ")";
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
    s.objects[2].position = {1.0f, 1.2f, 0.5f};  // the still pane
    expectSame(0.5f, "the pane moved");
    s.objects[3].animation = {};  // nothing animated: whole maps and tints are kept
    expectSame(0.5f, "nothing animated");
    expectSame(0.5f, "nothing animated, again");
    s.objects[2].position = {1.5f, 1.4f, -0.5f};
    expectSame(0.5f, "the pane moved, nothing animated");
    s.objects[1].position = {-1.5f, 0.5f, 0.0f};
    expectSame(0.5f, "the box moved, nothing animated");
}

INSTANTIATE_TEST_SUITE_P(Techniques, ShadowReuse, ::testing::Values("hard", "pcf-poisson16", "cssm2", "vsm"));

// Without an animated caster, the second frame of an unchanged view draws no triangle into any
// shadow map; with the sphere in both lights' views only it is drawn into depth (and the pane
// into the tint).
TEST(ShadowReuse, UnchangedMapsDrawNothingAndAnimatedCastersAlone) {
    scene::Scene s = stillAndMovingCasters();
    const std::size_t sphereTriangles = s.meshes[static_cast<std::size_t>(s.objects[3].mesh)].parts.at(0).indexCount / 3;
    Pair pair(s, "hard");
    pair.render(s, 0.5f);
    const std::vector<std::size_t> first = pair.reusing.shadowTriangles();
    EXPECT_EQ(first, pair.redrawing.shadowTriangles()) << "the first frame draws everything either way";
    pair.render(s, 0.5f);
    EXPECT_EQ(pair.redrawing.shadowTriangles(), first);
    // The sphere at (0, 1, 1) lies in the sun's view and in some of the point light's cube faces.
    ASSERT_EQ(pair.reusing.shadowTriangles().size(), 2u);
    EXPECT_GE(pair.reusing.shadowTriangles()[0], sphereTriangles);
    EXPECT_LT(pair.reusing.shadowTriangles()[0], first[0]);
    const std::size_t pane = 2;  // triangles: the tint is redrawn, since the sphere changes the depth it is tested against
    EXPECT_EQ(pair.reusing.shadowTriangles()[1], sphereTriangles + pane) << "the sun draws the sphere and the pane's tint alone";

    s.objects[3].animation = {};  // nothing moves now
    pair.render(s, 0.5f);         // the maps are drawn once more without the sphere's motion
    pair.render(s, 0.5f);
    EXPECT_EQ(pair.reusing.shadowTriangles(), (std::vector<std::size_t>{0, 0})) << "nothing changed: nothing drawn";
}

}  // namespace
}  // namespace penumbra::test
