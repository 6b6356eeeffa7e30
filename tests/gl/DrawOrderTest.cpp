// What GpuScene::draws hands the renderer. The order: opaque parts first, those whose farthest corner
// is nearest the eye first, so that a ground plane listed first in the scene is drawn after what
// stands on it and the early depth test spares its hidden fragments; translucent parts after
// them, back to front. The pictures are the same in any opaque order; the cost is not. And which
// parts are solids whose back faces the camera's opaque passes cull (Draw::solid).
#include "GlTestSupport.h"

#include "render/GpuScene.h"

#include <map>

namespace penumbra::test {
namespace {

TEST(DrawOrder, OpaqueNearToFarByFarthestCornerThenTranslucentBackToFront) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 4, 10], "target": [0, 0, 0] },
      "lights": [ { "type": "directional", "direction": [0, -1, 0] } ],
      "objects": [ { "name": "ground", "shape": "plane", "size": [40, 40] },
                   { "name": "far box", "shape": "box", "size": [1, 1, 1], "position": [0, 0.5, -4] },
                   { "name": "far pane", "shape": "box", "size": [2, 2, 0.04], "position": [0, 1, -2],
                     "material": { "transmission": [0.2, 0.8, 0.2] } },
                   { "name": "near box", "shape": "box", "size": [1, 1, 1], "position": [0, 0.5, 4] },
                   { "name": "near pane", "shape": "box", "size": [2, 2, 0.04], "position": [0, 1, 2],
                     "material": { "transmission": [0.2, 0.8, 0.2] } } ] })");
    render::GpuScene gpu(s);
    std::vector<std::string> order;
    for (const render::Draw& d : gpu.draws(0.0f, s.camera.position)) order.push_back(s.objects[d.object].name);
    EXPECT_EQ(order, (std::vector<std::string>{"near box", "far box", "ground", "far pane", "near pane"}));
}

// A box is a solid, a plane is not (two-sided), and a box mirrored by a negative scale is drawn
// whole: its winding is inside out in the world, so culling "back" faces would cull its front.
// Seen from above, the mirrored box's top is where it should be (the world position channel).
TEST(DrawOrder, SolidsAreClosedPartsNotMirrored) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 12, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [0, -1, 0] } ],
      "objects": [ { "name": "ground", "shape": "plane", "size": [20, 20] },
                   { "name": "box", "shape": "box", "size": [2, 2, 2], "position": [-3, 1, 0] },
                   { "name": "mirrored box", "shape": "box", "size": [2, 2, 2], "position": [3, 1, 0], "scale": [-1, 1, 1] } ] })");
    render::GpuScene gpu(s);
    std::map<std::string, bool> solid;
    for (const render::Draw& d : gpu.draws(0.0f, s.camera.position)) solid[s.objects[d.object].name] = d.solid;
    EXPECT_EQ(solid, (std::map<std::string, bool>{{"box", true}, {"ground", false}, {"mirrored box", false}}));
    // ~8.6 px per unit over 96 px: x = -3 is pixel 22, x = +3 pixel 74.
    const Frame f = renderChannel(s, render::OutputMode::WorldPosition, 0, 96, 96);
    EXPECT_NEAR(f.at(22, 48).g, 2.0f, 0.01f) << "the box's top";
    EXPECT_NEAR(f.at(74, 48).g, 2.0f, 0.01f) << "the mirrored box's top";
}

// An alpha-tested box is not a solid: through a cut texel of its top the camera sees the kept
// texels of its bottom from inside. left_half_cut.png cuts u in [0, 0.5) of each repeat; the top's
// u runs along z, the bottom's along x (Shapes.cpp's box), so the ray through pixel (45, 56)
// passes the top at u = 0.26 (cut) and meets the bottom at u = 0.73 (kept).
TEST(DrawOrder, AnAlphaTestedBoxShowsItsInsideThroughItsHoles) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 12, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [0, -1, 0] } ],
      "objects": [ { "name": "ground", "shape": "plane", "size": [20, 20] },
                   { "name": "box", "shape": "box", "size": [2, 2, 2], "position": [0, 2, 0],
                     "material": { "texture": "left_half_cut.png", "alpha_cutoff": 0.5 } } ] })");
    render::GpuScene gpu(s);
    for (const render::Draw& d : gpu.draws(0.0f, s.camera.position)) EXPECT_FALSE(d.solid) << s.objects[d.object].name;
    const Frame f = renderChannel(s, render::OutputMode::WorldPosition, 0, 96, 96);
    EXPECT_NEAR(f.at(45, 56).g, 1.0f, 0.01f) << "the box's bottom, seen from inside";
    EXPECT_NEAR(f.at(45, 40).g, 3.0f, 0.01f) << "a kept texel of its top";
}

}  // namespace
}  // namespace penumbra::test
