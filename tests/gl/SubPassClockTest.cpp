// render::SubPassClock times each gl::DebugGroup of a frame (bench --calibrate's sub_pass_wall_ms):
// every part of a moment map's pass by its path, the parts within their pass's time.
#include "GlTestSupport.h"

#include "render/SubPassClock.h"

#include <map>
#include <string>

namespace penumbra::test {
namespace {

scene::Scene boxOverGround() {
    return sceneFromJson(R"({
      "camera": { "position": [0, 4, 6], "target": [0, 0, 0], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [-0.3, -1, -0.2], "shadow": { "resolution": 256 } } ],
      "objects": [ { "shape": "plane", "size": [10, 10] },
                   { "shape": "box", "position": [0, 1, 0] } ] })");
}

// The sum of the paths one level below `parent`.
double childrenMs(const std::map<std::string, double>& ms, const std::string& parent) {
    double sum = 0.0;
    for (const auto& [path, t] : ms)
        if (path.size() > parent.size() + 1 && path.compare(0, parent.size() + 1, parent + "/") == 0 &&
            path.find('/', parent.size() + 1) == std::string::npos)
            sum += t;
    return sum;
}

TEST(SubPassClock, TimesEachPartOfAPassByItsPathWithinItsPass) {
    scene::Scene s = boxOverGround();
    std::map<std::string, double> ms;
    {
        render::SubPassClock clock(0.0);  // no overhead taken out: the intervals nest exactly
        renderFrame(s, optionsFor("vsm"), 64, 48);
        ms = clock.perFrame(1);
    }
    for (const char* path : {"shadow maps", "shadow maps/moments", "shadow maps/moments/raster", "shadow maps/moments/blur",
                             "shadow maps/moments/mip levels", "opaque"})
        EXPECT_EQ(ms.count(path), 1u) << path;
    for (const auto& [path, t] : ms) {
        EXPECT_GE(t, 0.0) << path;
        EXPECT_LE(childrenMs(ms, path), t) << path;
    }
    EXPECT_GT(ms["shadow maps/moments"], 0.0);

    // Without a clock the groups time nothing: a second clock starts empty.
    renderFrame(s, optionsFor("vsm"), 64, 48);
    const render::SubPassClock idle(0.0);
    EXPECT_TRUE(idle.perFrame(1).empty());
}

}  // namespace
}  // namespace penumbra::test
