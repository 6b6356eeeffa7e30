// LiSPSM and PSM, the geometry: texel density where they should win, the optimal n and its
// uniform fallback, the three PSM cases (sun in front, behind, beside the viewer), and that no
// visible point of the body ever falls outside its warped map over a sweep of angles.
#include "shadows/LightSpace.h"
#include "shadows/warped/WarpFit.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

constexpr float kAspect = 16.0f / 9.0f;

struct Road {  // 20 m wide, 200 m long, the camera low at one end looking along it
    scene::Light sun;
    scene::Camera camera;
    scene::Bounds bounds;
    Road() {
        sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, 0.3f));
        camera.position = {0.0f, 1.7f, 0.0f};
        camera.target = {0.0f, 1.2f, -30.0f};
        camera.fovDeg = 60.0f;
        camera.near = 0.1f;
        camera.far = 220.0f;
        bounds.add(glm::vec3(-10.0f, 0.0f, -200.0f));
        bounds.add(glm::vec3(10.0f, 3.0f, 0.0f));
    }
    glm::mat4 viewProj() const { return camera.projection(kAspect) * camera.view(); }
};

TEST(Warp, ClippedBodyIsTheFrustumInsideTheScene) {
    const Road r;
    const auto body = frustumInsideBox(r.viewProj(), r.bounds);
    ASSERT_FALSE(body.empty());
    for (const auto& p : body) {
        EXPECT_GE(p.y, -1e-3f);
        EXPECT_LE(p.y, 3.0f + 1e-3f);
        EXPECT_GE(p.z, -200.0f - 1e-2f);
    }
    scene::Bounds sky;  // a box the camera looks away from
    sky.add(glm::vec3(-1, 0, 10));
    sky.add(glm::vec3(1, 1, 12));
    EXPECT_TRUE(frustumInsideBox(r.viewProj(), sky).empty());
}

TEST(Warp, NearTexelsAreDenserThanOnePlainMap) {
    const Road r;
    const int res = 1024;
    const LightSpace plain = computeLightSpace(r.sun, res, r.bounds, r.camera, kAspect);
    const WarpedView lispsm = fitLispsm(r.sun, r.camera, r.viewProj(), r.bounds);
    const WarpedView psm = fitPsm(r.sun, r.camera, r.viewProj(), r.bounds);
    ASSERT_TRUE(lispsm.valid && psm.valid);
    EXPECT_FALSE(lispsm.uniform);
    for (const glm::vec3 p : {glm::vec3(0.5f, 0.0f, -3.0f), glm::vec3(-2.0f, 0.0f, -6.0f)}) {
        const float plainTexel = warpedTexelWorld(plain.shadowMatrix, p, r.sun.direction, res);
        const float lispsmGain = plainTexel / warpedTexelWorld(lispsm.shadowMatrix, p, r.sun.direction, res);
        const float psmGain = plainTexel / warpedTexelWorld(psm.shadowMatrix, p, r.sun.direction, res);
        std::printf("texel world size at (%.1f, %.1f, %.1f): plain %.4f m; gain per axis LiSPSM %.1fx, PSM %.1fx\n", p.x, p.y,
                    p.z, plainTexel, lispsmGain, psmGain);
        EXPECT_GE(lispsmGain * lispsmGain, 4.0) << "texels per area near the camera";
        EXPECT_GE(psmGain * psmGain, 4.0);
    }
}

TEST(Warp, LispsmUsesWimmersOptimalN) {
    Road r;
    r.sun.direction = {0.0f, -1.0f, 0.0f};  // overhead sun, level camera: γ = 90°
    r.camera.target = r.camera.position + glm::vec3(0.0f, 0.0f, -1.0f);
    const WarpedView w = fitLispsm(r.sun, r.camera, r.viewProj(), r.bounds);
    ASSERT_TRUE(w.valid);
    EXPECT_NEAR(w.sinGamma, 1.0f, 1e-5f);
    // With sin γ = 1: n_opt = z_n + sqrt(z_n z_f), z_f = z_n + depth of the body along the view.
    const auto body = frustumInsideBox(r.viewProj(), r.bounds);
    float zn = 1e9f, zmin = 1e9f, zmax = -1e9f;
    for (const auto& p : body) {
        zn = std::min(zn, -p.z);
        zmin = std::min(zmin, p.z);
        zmax = std::max(zmax, p.z);
    }
    zn = std::max(zn, r.camera.near);
    const float zf = zn + (zmax - zmin);
    EXPECT_NEAR(w.n, zn + std::sqrt(zn * zf), 1e-3f * w.n);
    const WarpedView doubled = fitLispsm(r.sun, r.camera, r.viewProj(), r.bounds, {2.0f, 0.05f});
    EXPECT_NEAR(doubled.n, 2.0f * w.n, 1e-3f * w.n);
}

TEST(Warp, LispsmFallsBackToUniformWhenLookingAlongTheLight) {
    Road r;
    r.sun.direction = glm::normalize(glm::vec3(0.0f, -1.0f, -0.02f));
    r.camera.position = {0.0f, 20.0f, -50.0f};
    r.camera.target = r.camera.position + r.sun.direction;  // looking down with the sun
    const WarpedView w = fitLispsm(r.sun, r.camera, r.viewProj(), r.bounds);
    ASSERT_TRUE(w.valid);
    EXPECT_TRUE(w.uniform) << "sin γ = " << w.sinGamma;
    r.camera.target = r.camera.position + glm::normalize(glm::vec3(0.0f, -1.0f, -0.5f));
    EXPECT_FALSE(fitLispsm(r.sun, r.camera, r.viewProj(), r.bounds).uniform);
}

TEST(Warp, PsmTurnsTheSunIntoAPointLightInFrontOrBehindTheViewer) {
    Road r;
    r.sun.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.6f));  // travels towards the camera: in front
    WarpedView w = fitPsm(r.sun, r.camera, r.viewProj(), r.bounds);
    EXPECT_TRUE(w.pointInPostPerspective);
    EXPECT_FALSE(w.inverted);
    r.sun.direction = glm::normalize(glm::vec3(0.2f, -1.0f, -0.6f));  // from behind the viewer
    w = fitPsm(r.sun, r.camera, r.viewProj(), r.bounds);
    EXPECT_TRUE(w.inverted);
    r.camera.target = r.camera.position + glm::vec3(0, 0, -1);
    r.sun.direction = glm::normalize(glm::vec3(1.0f, -1.0f, 0.0f));  // across the view: stays directional
    w = fitPsm(r.sun, r.camera, r.viewProj(), r.bounds);
    EXPECT_FALSE(w.pointInPostPerspective);
}

// Over a sweep of sun and camera directions every visible point of the body lands inside its
// map, in front of the projection (no lost shadows from a bad fit), for both warps.
TEST(Warp, EveryVisiblePointFallsInsideTheMapOverASweep) {
    Road r;
    int cases = 0;
    for (int sunAz = 0; sunAz < 360; sunAz += 30)
        for (float sunEl : {15.0f, 45.0f, 80.0f, 89.5f})
            for (float pitch : {0.0f, -20.0f, -60.0f, -89.0f}) {
                const float az = glm::radians(static_cast<float>(sunAz)), el = glm::radians(sunEl);
                r.sun.direction = -glm::vec3(std::cos(el) * std::cos(az), std::sin(el), std::cos(el) * std::sin(az));
                const float p = glm::radians(pitch);
                r.camera.target = r.camera.position + glm::vec3(0.1f * std::cos(p), std::sin(p), -std::cos(p));
                for (int warp = 0; warp < 2; ++warp) {
                    const WarpedView w = warp == 0 ? fitLispsm(r.sun, r.camera, r.viewProj(), r.bounds)
                                                   : fitPsm(r.sun, r.camera, r.viewProj(), r.bounds);
                    ASSERT_TRUE(w.valid);
                    for (const auto& point : frustumInsideBox(r.viewProj(), r.bounds)) {
                        const glm::vec4 h = w.shadowMatrix * glm::vec4(point, 1.0f);
                        const glm::vec3 s = glm::vec3(h) / h.w;
                        ASSERT_GT(h.w, 0.0f) << (warp ? "psm" : "lispsm") << " az " << sunAz << " el " << sunEl << " pitch " << pitch;
                        for (int k = 0; k < 3; ++k) {
                            ASSERT_GE(s[k], -1e-3f) << (warp ? "psm" : "lispsm") << " az " << sunAz << " el " << sunEl << " pitch " << pitch;
                            ASSERT_LE(s[k], 1.0f + 1e-3f) << (warp ? "psm" : "lispsm") << " az " << sunAz << " el " << sunEl << " pitch " << pitch;
                        }
                        ASSERT_GE(glm::dot(w.clipPlane, glm::vec4(point, 1.0f)), 0.0f);
                    }
                    ++cases;
                }
            }
    EXPECT_EQ(cases, 12 * 4 * 4 * 2);
}

// A camera walking 5 m down the road in 100 frames (3 m/s at 60 frames a second), swaying ±6°:
// held views (followWarpedView) move in a fifth of the frames, yet in every frame every point of
// the body and of its extrusion towards the light lies in the view's clip volume, in front of its
// clip plane, and its texels on the body are at most kHeldCoarser those of the frame's own
// fit. Walking faster moves them more often: near the camera a warp's texels grow with the
// distance walked (0.15 m a frame: about every other frame).
TEST(Warp, AHeldViewMovesRarelyAndHoldsTheBody) {
    for (int warp = 0; warp < 2; ++warp) {
        Road r;
        std::optional<WarpedView> last;
        int moves = 0;
        float worstRatio = 0.0f;
        for (int frame = 0; frame < 100; ++frame) {
            const float sway = glm::radians(6.0f) * std::sin(0.15f * static_cast<float>(frame));
            r.camera.position = {0.0f, 1.7f, -0.05f * static_cast<float>(frame)};
            r.camera.target = r.camera.position + glm::vec3(std::sin(sway), -0.02f, -std::cos(sway));
            const WarpedView fitted = warp == 0 ? fitLispsm(r.sun, r.camera, r.viewProj(), r.bounds)
                                                : fitPsm(r.sun, r.camera, r.viewProj(), r.bounds);
            WarpBody body;
            ASSERT_TRUE(fitted.valid && makeWarpBody(r.sun, r.viewProj(), r.bounds, body));
            const WarpedView v = followWarpedView(fitted, last ? &*last : nullptr, body, r.sun.direction);
            if (!last) {
                EXPECT_EQ(v.viewProj, fitted.viewProj) << "the first frame: the fit itself";
            }
            moves += last && v.viewProj != last->viewProj;
            for (const glm::vec3& p : body.casters) {
                const glm::vec4 c = v.viewProj * glm::vec4(p, 1.0f);
                ASSERT_GT(c.w, 0.0f) << "frame " << frame;
                for (int k = 0; k < 3; ++k) {
                    ASSERT_LE(std::abs(c[k]), c.w * 1.00001f) << (warp ? "psm" : "lispsm") << ", frame " << frame;
                }
                ASSERT_GE(glm::dot(v.clipPlane, glm::vec4(p, 1.0f)), 0.0f) << "frame " << frame;
            }
            for (const glm::vec3& p : body.visible)
                worstRatio = std::max(worstRatio, warpedTexelWorld(v.shadowMatrix, p, r.sun.direction, 1) /
                                                      warpedTexelWorld(fitted.shadowMatrix, p, r.sun.direction, 1));
            last = v;
        }
        std::printf("%s, 99 frames of a walk: the held view moved in %d; texels at most %.3fx the fit's\n", warp ? "psm" : "lispsm", moves,
                    worstRatio);
        EXPECT_LE(moves, 33) << "held, the view moves in a third of the frames or fewer";
        EXPECT_LE(worstRatio, kHeldCoarser * 1.0001f);
    }
}

}  // namespace
}  // namespace penumbra::shadows
