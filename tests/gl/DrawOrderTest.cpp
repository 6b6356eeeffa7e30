// The order GpuScene::draws hands the renderer: opaque parts first, those whose farthest corner
// is nearest the eye first, so that a ground plane listed first in the scene is drawn after what
// stands on it and the early depth test spares its hidden fragments; translucent parts after
// them, back to front. The pictures are the same in any opaque order; the cost is not.
#include "GlTestSupport.h"

#include "render/GpuScene.h"

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

}  // namespace
}  // namespace penumbra::test
