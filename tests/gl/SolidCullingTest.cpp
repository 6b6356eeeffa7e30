// Depth maps cull the faces solids turn away from the light (shadows::CasterSelection::
// nearestDepthOnly, Renderer's facesTurnedAway): along any ray the nearest surface of a solid
// is a front face, so the maps, and the pictures, must be those of drawing both faces
// (RenderOptions::cullSolidBackFaces = false), texel for texel. Culling the wrong faces (a
// projection whose winding was misjudged) leaves each solid's far side in the map: measured,
// 1299 of the sun's 65536 texels and 3719 of the spot's 16384 differ, while the pictures hardly
// change (the far side still shadows what lies behind).
//
// The lights have no polygon offset here. With one, the maps differ at a few silhouette texels
// (30 of the sun's 65536): a front face seen edge-on gets a large slope offset, and drawing both
// faces lets the back face behind it win there.
#include "GlTestSupport.h"

#include "render/Offscreen.h"

#include <cctype>
#include <cmath>
#include <utility>

namespace penumbra::test {
namespace {

// A sun (2D map, cascades, warped maps), a spot and a point light (cube map) over solids: a box,
// a sphere, a tilted box, a box mirrored by a negative scale, and an alpha-tested box whose cut
// texels show its inside; a plane as the ground.
scene::Scene solids() {
    return sceneFromJson(R"({
      "camera": { "position": [0, 6, 7], "target": [0, 0.5, 0], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [-0.4, -1, -0.3], "intensity": 0.5, "shadow": { "resolution": 256, "polygon_offset": [0, 0] } },
                  { "type": "spot", "position": [2, 4, 1], "direction": [-0.5, -1, -0.2], "angle_deg": 70, "intensity": 0.4,
                    "shadow": { "resolution": 128, "polygon_offset": [0, 0] } },
                  { "type": "point", "position": [-1, 3, 2], "range": 30, "intensity": 0.4, "shadow": { "resolution": 128, "polygon_offset": [0, 0] } } ],
      "objects": [ { "shape": "plane", "size": [12, 12] },
                   { "shape": "box", "size": [1, 1.5, 1], "position": [-2, 0.75, 0] },
                   { "shape": "sphere", "radius": 0.7, "position": [0, 1, -1.5] },
                   { "shape": "box", "size": [1, 0.4, 1.6], "position": [1.5, 1.2, 0], "rotation_deg": [30, 20, 10] },
                   { "shape": "box", "size": [0.8, 0.8, 0.8], "position": [0, 0.4, 1.5], "scale": [-1, 1, 1] },
                   { "shape": "box", "size": [1.2, 1.2, 1.2], "position": [2.5, 0.6, -2],
                     "material": { "texture": "left_half_cut.png", "alpha_cutoff": 0.5 } } ] })");
}

// `technique`'s options as they are (culling), and with both faces drawn.
std::pair<render::RenderOptions, render::RenderOptions> cullingAndBothFaces(const char* technique) {
    render::RenderOptions culling = optionsFor(technique);
    render::RenderOptions both = culling;
    both.cullSolidBackFaces = false;
    return {culling, both};
}

// Channel values of two pictures that differ by more than 1e-4.
std::size_t differingValues(const std::vector<float>& a, const std::vector<float>& b) {
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.size(); ++i) differing += std::abs(a[i] - b[i]) > 1e-4f;
    return differing;
}

class SolidCulling : public ::testing::TestWithParam<const char*> {};

TEST_P(SolidCulling, LeavesEveryMapAndPixelAsDrawingBothFaces) {
    scene::Scene s = solids();
    const auto [culling, both] = cullingAndBothFaces(GetParam());
    render::Renderer a(s, culling), b(s, both);
    render::OffscreenTarget target(96, 96);
    a.render(0.0f, s.camera, 96, 96, target.framebuffer());
    const std::vector<float> pictureA = a.readLinear();
    b.render(0.0f, s.camera, 96, 96, target.framebuffer());
    const std::vector<float> pictureB = b.readLinear();
    const auto viewsA = a.technique().debugViews(), viewsB = b.technique().debugViews();
    ASSERT_EQ(viewsA.size(), viewsB.size());
    for (std::size_t v = 0; v < viewsA.size(); ++v) {
        const std::vector<float> mapA = textureLevels(viewsA[v]), mapB = textureLevels(viewsB[v]);
        ASSERT_EQ(mapA.size(), mapB.size()) << viewsA[v].label;
        std::size_t differing = 0;
        for (std::size_t i = 0; i < mapA.size(); ++i)
            differing += mapA[i] != mapB[i] && !(std::isnan(mapA[i]) && std::isnan(mapB[i]));
        EXPECT_EQ(differing, 0u) << viewsA[v].label;
    }
    // The point light's cube map has no debug view: its faces are judged by the same rule
    // (lookAt and glm::perspective, as the spot's map above), and the picture shows only what a
    // wrong winding would hardly change. Moment maps' filtered lookups round differently in the
    // last bits at a few dozen pixels (at most 2.2e-5 measured).
    ASSERT_EQ(pictureA.size(), pictureB.size());
    EXPECT_EQ(differingValues(pictureA, pictureB), 0u) << "channel values of the picture";
}

// The last three draw the camera's view too (ShadowFrame::drawSurfaces): the shadow volumes'
// and the planar shadows' screen masks, cascaded's depth-bounds pre-pass (sdsm).
INSTANTIATE_TEST_SUITE_P(EveryDepthMap, SolidCulling,
                         ::testing::Values("hard", "cascaded", "lispsm", "psm", "vsm", "cssm2", "shadow-volumes", "planar", "cascaded:sdsm=true"),
                         [](const auto& info) {
                             std::string name = info.param;
                             for (char& ch : name) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                             return name;
                         });

// With the lights' default polygon offset, a front face seen nearly edge-on from the light gets
// a large slope offset, and culling leaves no back face behind it in the map: along a grazing
// sun's and spot's silhouettes a map texel can hold the pushed-back front face where drawing both
// faces kept the back face, and let light pass there. Measured at 160 x 90: hard and cascaded
// give the same picture; pcf-bilinear one pixel on a shadow's edge, 0.027 brighter (sRGB 110
// against 100). At 1280 x 720, with one more sphere, compare's scores and pictures were identical
// for hard, pcf-bilinear, cascaded and vsm. The bound below lets such a texel through, not a leak
// along a whole silhouette.
class SolidCullingUnderGrazingLight : public ::testing::TestWithParam<const char*> {};

TEST_P(SolidCullingUnderGrazingLight, LeavesThePictureAsDrawingBothFacesButForAFewEdgePixels) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 5, 9], "target": [0, 0.5, 0], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [-1, -0.18, -0.35] },
                  { "type": "spot", "position": [6, 1.2, 2], "direction": [-1, -0.12, -0.3], "angle_deg": 60, "intensity": 0.8 } ],
      "objects": [ { "shape": "plane", "size": [20, 20] },
                   { "shape": "box", "size": [1, 1.5, 1], "position": [-2, 0.75, 0] },
                   { "shape": "sphere", "radius": 0.7, "position": [0, 0.7, -1.5] },
                   { "shape": "box", "size": [1, 0.4, 1.6], "position": [1.5, 1.2, 0], "rotation_deg": [30, 20, 10] },
                   { "shape": "box", "size": [0.8, 0.8, 0.8], "position": [0.5, 0.4, 1.5], "rotation_deg": [0, 35, 0] } ] })");
    const auto [culling, both] = cullingAndBothFaces(GetParam());
    const Frame a = renderFrame(s, culling, 160, 90), b = renderFrame(s, both, 160, 90);
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    std::size_t differing = 0, shadowed = 0;
    float largest = 0.0f;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        float d = 0.0f;
        for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(a.rgba[i + c] - b.rgba[i + c]));
        differing += d > 1e-4f;
        largest = std::max(largest, d);
        shadowed += a.rgba[i] < 0.1f;
    }
    EXPECT_LE(differing, 3u);
    EXPECT_LE(largest, 0.05f);
    EXPECT_GT(shadowed, 500u) << "the long shadows must be in the picture";
}

INSTANTIATE_TEST_SUITE_P(DefaultPolygonOffset, SolidCullingUnderGrazingLight, ::testing::Values("hard", "pcf-bilinear", "cascaded"),
                         [](const auto& info) { return testNameOf(info.param); });

// An eye inside a solid, or a near plane that cuts one open, sees its inside: those solids keep
// both faces (render::nearPlaneMayCut). A room made of one closed box, with the camera and a
// point light inside it and a crate on its floor, must look as it does drawing both faces; culled
// like any solid, its walls vanished for the camera (the background showed) and for the light's
// cube map (the crate's shadow and the walls' own shadowing were lost).
TEST(SolidCullingFromInside, ARoomMadeOfOneClosedBoxLooksAsDrawingBothFaces) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 2, 3.5], "target": [0, 1, -2], "fov_deg": 70 },
      "lights": [ { "type": "point", "position": [1.5, 3, 0], "range": 30, "intensity": 2 },
                  { "type": "directional", "direction": [-0.3, -1, -0.2], "intensity": 0.5 } ],
      "objects": [ { "shape": "box", "size": [10, 4, 10], "position": [0, 2, 0] },
                   { "shape": "box", "size": [1, 1, 1], "position": [0, 0.6, -1.5] } ] })");
    for (const char* technique : {"hard", "shadow-volumes"}) {
        const auto [culling, both] = cullingAndBothFaces(technique);
        const Frame a = renderFrame(s, culling, 96, 96), b = renderFrame(s, both, 96, 96);
        ASSERT_EQ(a.rgba.size(), b.rgba.size());
        EXPECT_EQ(differingValues(a.rgba, b.rgba), 0u) << technique;
    }
}

}  // namespace
}  // namespace penumbra::test
