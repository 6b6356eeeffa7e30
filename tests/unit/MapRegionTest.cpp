// Which texels of a shadow map a box can cover (shadows/common/MapRegion): every point of the box
// that a light sees lands inside the rectangle, and a perspective light's rectangle holds only the
// box's part in front of its eye.
#include "shadows/common/MapRegion.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <random>

namespace penumbra::shadows {
namespace {

bool inside(const TexelRect& r, glm::vec2 texel) { return texel.x >= r.x && texel.x < r.z && texel.y >= r.y && texel.y < r.w; }

// Random boxes through random perspective and orthographic lights: 2,000 points of each box that
// project into the map in front of the eye all fall in its rectangle. A rectangle made from the
// corners in front alone, without the edges' crossings of the eye's plane, fails this.
TEST(MapRegion, EveryPointOfABoxALightSeesLiesInItsRectangle) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    constexpr int kRes = 256;
    int straddling = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const glm::vec3 eye(u(rng) * 3, u(rng) * 3, u(rng) * 3);
        const glm::vec3 dir = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0.0f, 0.0f, 1e-3f));
        const glm::vec3 up = std::abs(dir.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        const glm::mat4 view = glm::lookAt(eye, eye + dir, up);
        const glm::mat4 proj = trial % 3 == 0 ? glm::ortho(-4.0f, 4.0f, -4.0f, 4.0f, 0.1f, 20.0f)
                                              : glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 20.0f);
        const glm::mat4 vp = proj * view;
        const glm::vec3 a(u(rng) * 4, u(rng) * 4, u(rng) * 4), b(u(rng) * 4, u(rng) * 4, u(rng) * 4);
        scene::Bounds box;
        box.min = glm::min(a, b);
        box.max = glm::max(a, b);
        const TexelRect rect = texelRect(box, vp, kRes);
        bool front = false, behind = false;
        for (int k = 0; k < 2000; ++k) {
            const glm::vec3 t((u(rng) + 1) / 2, (u(rng) + 1) / 2, (u(rng) + 1) / 2);
            const glm::vec4 c = vp * glm::vec4(box.min + t * (box.max - box.min), 1.0f);
            if (c.w <= 1e-3f) {
                behind = true;
                continue;
            }
            front = true;
            const glm::vec2 ndc = glm::vec2(c) / c.w;
            if (glm::any(glm::greaterThan(glm::abs(ndc), glm::vec2(1.0f)))) continue;
            const glm::vec2 texel = (ndc * 0.5f + 0.5f) * float(kRes);
            ASSERT_TRUE(inside(rect, texel)) << "trial " << trial << ": a seen point at texel (" << texel.x << ", " << texel.y
                                             << ") outside [" << rect.x << ", " << rect.y << ", " << rect.z << ", " << rect.w << ")";
        }
        straddling += front && behind;
    }
    EXPECT_GT(straddling, 20) << "enough boxes reach behind the eye to test the crossings";
}

// A point light's cube face over a ground plane: the face looking up sees no texel of it; a face
// looking sideways sees it only below its horizon (rows below the middle); the face looking down
// sees it all.
TEST(MapRegion, APerspectiveLightSeesOnlyTheBoxsPartInFrontOfItsEye) {
    scene::Bounds ground;
    ground.min = {-6.0f, -0.01f, -6.0f};
    ground.max = {6.0f, 0.0f, 6.0f};
    const glm::vec3 light(0.0f, 3.0f, 0.0f);
    const glm::mat4 proj = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 30.0f);
    constexpr int kRes = 128;
    const TexelRect up = texelRect(ground, proj * glm::lookAt(light, light + glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)), kRes);
    EXPECT_TRUE(isEmpty(up)) << up.x << " " << up.y << " " << up.z << " " << up.w;
    const TexelRect side = texelRect(ground, proj * glm::lookAt(light, light + glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)), kRes);
    EXPECT_EQ(side.x, 0);
    EXPECT_EQ(side.z, kRes);
    EXPECT_EQ(side.y, 0);
    EXPECT_LT(side.w, kRes / 2 - kRes / 8) << "the ground's farthest corner lies 3 m below and 6 m out: ndc y -0.5 at most";
    const TexelRect down = texelRect(ground, proj * glm::lookAt(light, light - glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)), kRes);
    EXPECT_EQ(down, TexelRect(0, 0, kRes, kRes));
}

}  // namespace
}  // namespace penumbra::shadows
