// The window's reference mode (issue 13): the reference traced on worker threads from a frozen
// copy of the scene, while the caller keeps drawing and may change the live scene.
#include "GlTestSupport.h"

#include "reference/BackgroundReference.h"

namespace penumbra::test {
namespace {

TEST(BackgroundReference, MatchesTheForegroundReferenceWhileTheLiveSceneChanges) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 6, 5], "target": [0, 0, 0] },
      "lights": [ { "type": "directional", "direction": [-0.3, -1, -0.4], "size": 2, "shadow": { "resolution": 512 } },
                  { "type": "spot", "position": [2, 4, 2], "direction": [-0.4, -1, -0.4], "angle_deg": 70, "range": 20 } ],
      "objects": [ { "shape": "plane", "size": [10, 10] }, { "shape": "box", "position": [0, 1, 0] },
                   { "shape": "plane", "size": [1.5, 1.5], "position": [1.5, 1.5, 0], "rotation_deg": [90, 0, 0],
                     "material": { "transmission": [0.1, 0.9, 0.1] } } ] })");
    const int w = 48, h = 32, samples = 4;
    reference::BackgroundReference background(s, w, h, 0.0f, samples);
    // The live scene moves on while the tracer works: the reference must not see it.
    const scene::Scene frozen = s;
    s.lights[0].direction = glm::vec3(1, -1, 0);
    s.objects[1].position += glm::vec3(3, 0, 0);
    background.wait();
    ASSERT_TRUE(background.ready());
    EXPECT_EQ(background.progress(), 1.0);

    scene::Scene again = frozen;
    reference::Comparison foreground(again, w, h, 0.0f);
    foreground.traceReference(samples, false);
    EXPECT_EQ(background.image(), foreground.shade(foreground.referenceVisibility()))
        << "the background reference is the frozen frame's, byte for byte";
    EXPECT_EQ(background.heatMap("hard"), foreground.heatMap(foreground.evaluate("hard", 0, 0)));
}

TEST(BackgroundReference, ReportsProgressFromZeroToOne) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 6, 5], "target": [0, 0, 0] },
      "lights": [ { "type": "directional", "direction": [-0.3, -1, -0.4] } ],
      "objects": [ { "shape": "plane", "size": [10, 10] }, { "shape": "box", "position": [0, 1, 0] } ] })");
    reference::BackgroundReference background(s, 32, 24, 0.0f, 1);
    const double first = background.progress();
    EXPECT_GE(first, 0.0);
    EXPECT_LE(first, 1.0);
    background.wait();
    EXPECT_TRUE(background.ready());
    EXPECT_EQ(background.progress(), 1.0);
    EXPECT_EQ(background.image().size(), 32u * 24u * 4u);
}

}  // namespace
}  // namespace penumbra::test
