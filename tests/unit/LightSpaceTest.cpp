// The plain directional map's fit (LightSpace.cpp): stable under a slowly moving camera, so that
// hard shadows do not shimmer and CSSM's stratified tiles do not crawl, and still covering what
// the camera sees.
#include "shadows/LightSpace.h"

#include <cmath>
#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

struct Courtyard {  // a 40 m x 40 m scene that the camera sees only part of
    scene::Light sun;
    scene::Camera camera;
    scene::Bounds bounds;
    Courtyard() {
        sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
        camera.position = {0.0f, 3.0f, 8.0f};
        camera.target = {0.0f, 0.0f, -4.0f};
        bounds.add(glm::vec3(-20.0f, 0.0f, -20.0f));
        bounds.add(glm::vec3(20.0f, 4.0f, 20.0f));
    }
};

glm::vec2 texelOf(const LightSpace& ls, const glm::vec3& p) {
    return glm::vec2(ls.shadowMatrix * glm::vec4(p, 1.0f)) * static_cast<float>(ls.resolution);
}

// A pan of 60 steps of 0.3 texel: the box keeps its size except across a size-ladder step (a
// few times at most), and otherwise a fixed world point stays on the same texel or moves by
// whole 8-texel tiles: the map's content and CSSM's tile grid stay put in the world.
TEST(PlainDirectionalMap, MovesByWholeTilesAsTheCameraPans) {
    Courtyard s;
    const int res = 1024;
    LightSpace before = computeLightSpace(s.sun, res, s.bounds, s.camera, 16.0f / 9.0f);
    const glm::vec3 step(0.3f * before.texelScale, 0.0f, 0.0f);
    const glm::vec3 probe(1.0f, 0.0f, -3.0f);
    int resized = 0, moved = 0;
    for (int k = 1; k <= 60; ++k) {
        scene::Camera camera = s.camera;
        camera.position += step * static_cast<float>(k);
        camera.target += step * static_cast<float>(k);
        const LightSpace now = computeLightSpace(s.sun, res, s.bounds, camera, 16.0f / 9.0f);
        if (now.viewProj[0] != before.viewProj[0]) ++moved;
        const glm::vec2 a = texelOf(before, probe), b = texelOf(now, probe);
        if (std::abs(now.texelScale - before.texelScale) > 1e-6f * before.texelScale) {
            ++resized;
        } else {
            const glm::vec2 tiles = (b - a) / 8.0f;
            EXPECT_NEAR(tiles.x, std::round(tiles.x), 1e-3f) << "frame " << k;
            EXPECT_NEAR(tiles.y, std::round(tiles.y), 1e-3f) << "frame " << k;
        }
        // Still covering what the camera looks at.
        const glm::vec2 target = texelOf(now, camera.target) / static_cast<float>(res);
        EXPECT_TRUE(target.x > 0.0f && target.x < 1.0f && target.y > 0.0f && target.y < 1.0f) << "frame " << k;
        before = now;
    }
    std::printf("60 pan steps of 0.3 texel: the box moved %d times, resized %d times\n", moved, resized);
    EXPECT_LE(resized, 3);
    EXPECT_LT(moved, 30) << "the box must not follow every sub-texel step";
}

}  // namespace
}  // namespace penumbra::shadows
