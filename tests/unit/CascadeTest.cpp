// Directional maps, the geometry: cascades' split placement, texel density on a long scene, and
// the stabilisation that keeps cascades and the plain map (LightSpace.cpp) from shimmering, and
// CSSM's stratified tiles from crawling.
#include "shadows/LightSpace.h"
#include "shadows/cascaded/CascadeFit.h"

#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

TEST(Cascades, SplitsFollowTheLogUniformBlend) {
    const auto uniform = cascadeSplits(1.0f, 101.0f, 4, 0.0f);
    EXPECT_FLOAT_EQ(uniform[1], 26.0f);
    EXPECT_FLOAT_EQ(uniform[2], 51.0f);
    const auto logarithmic = cascadeSplits(1.0f, 10000.0f, 4, 1.0f);
    EXPECT_NEAR(logarithmic[1], 10.0f, 1e-3f);
    EXPECT_NEAR(logarithmic[3], 1000.0f, 1e-1f);
    const auto half = cascadeSplits(1.0f, 10000.0f, 4, 0.5f);
    EXPECT_NEAR(half[1], 0.5f * 10.0f + 0.5f * (1.0f + 9999.0f / 4.0f), 1e-2f);
    EXPECT_EQ(half.front(), 1.0f);
    EXPECT_EQ(half.back(), 10000.0f);
}

struct LongScene {
    scene::Light sun;
    scene::Camera camera;
    scene::Bounds bounds;
    LongScene() {
        sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f));
        camera.position = {0.0f, 2.0f, 0.0f};
        camera.target = {0.0f, 1.5f, -100.0f};
        camera.fovDeg = 60.0f;
        camera.near = 0.1f;
        camera.far = 1000.0f;
        bounds.add(glm::vec3(-10.0f, 0.0f, -1000.0f));  // a ground 20 m wide, 1 km deep, posts 3 m tall
        bounds.add(glm::vec3(10.0f, 3.0f, 0.0f));
    }
};

// `camera` with its position and target moved by `by`.
scene::Camera movedBy(scene::Camera camera, const glm::vec3& by) {
    camera.position += by;
    camera.target += by;
    return camera;
}

TEST(Cascades, NearTexelsAreFarDenserThanOnePlainMapOfTheSameMemory) {
    const LongScene s;
    const int res = 2048, count = 4;
    const auto splits = cascadeSplits(s.camera.near, s.camera.far, count, 0.75f);
    const Cascade nearest = fitCascade(s.sun, s.camera, 16.0f / 9.0f, splits[0], splits[1], s.bounds, res, true);
    // Same memory: one map with count * res^2 texels.
    const int plainRes = static_cast<int>(std::lround(res * std::sqrt(static_cast<double>(count))));
    const LightSpace plain = computeLightSpace(s.sun, plainRes, s.bounds, s.camera, 16.0f / 9.0f);
    const double linear = plain.texelScale / nearest.texelWorld;
    std::printf("texel world size near the camera: plain %.4f m, first cascade %.4f m: %.1fx per axis, %.0fx per area\n",
                plain.texelScale, nearest.texelWorld, linear, linear * linear);
    EXPECT_GE(linear * linear, 4.0) << "texels per screen pixel (an area) near the camera";
}

TEST(Cascades, StabilisationIgnoresSubTexelCameraMotion) {
    LongScene s;
    const auto splits = cascadeSplits(s.camera.near, 200.0f, 4, 0.75f);
    const Cascade before = fitCascade(s.sun, s.camera, 1.5f, splits[1], splits[2], s.bounds, 1024, true);
    // Move the camera sideways by 0.3 of a texel of this cascade.
    const scene::Camera moved = movedBy(s.camera, glm::vec3(0.3f * before.texelWorld, 0.0f, 0.0f));
    const Cascade after = fitCascade(s.sun, moved, 1.5f, splits[1], splits[2], s.bounds, 1024, true);
    EXPECT_EQ(before.viewProj, after.viewProj) << "shimmer: the stabilised box moved";
    const Cascade looseBefore = fitCascade(s.sun, s.camera, 1.5f, splits[1], splits[2], s.bounds, 1024, false);
    const Cascade looseAfter = fitCascade(s.sun, moved, 1.5f, splits[1], splits[2], s.bounds, 1024, false);
    EXPECT_NE(looseBefore.viewProj, looseAfter.viewProj) << "without stabilisation the box follows the camera";
    // Turning the camera keeps the box size (the slice's bounding sphere) exactly.
    scene::Camera turned = s.camera;
    turned.target = s.camera.position + glm::vec3(10.0f, -0.5f, -100.0f);
    const Cascade rotated = fitCascade(s.sun, turned, 1.5f, splits[1], splits[2], s.bounds, 1024, true);
    EXPECT_FLOAT_EQ(rotated.texelWorld, before.texelWorld);
}

glm::vec2 texelOf(const LightSpace& ls, const glm::vec3& p) {
    return glm::vec2(ls.shadowMatrix * glm::vec4(p, 1.0f)) * static_cast<float>(ls.resolution);
}

// Between two fits of one size, the world point `probe` stays on its texel or moves by whole
// 8-texel tiles (the snapping grid, CSSM's tiles).
void expectWholeTiles(const LightSpace& before, const LightSpace& now, const glm::vec3& probe, int frame) {
    const glm::vec2 tiles = (texelOf(now, probe) - texelOf(before, probe)) / 8.0f;
    EXPECT_NEAR(tiles.x, std::round(tiles.x), 1e-3f) << "frame " << frame;
    EXPECT_NEAR(tiles.y, std::round(tiles.y), 1e-3f) << "frame " << frame;
}

// A pan of 60 steps of 0.3 texel: the box keeps its size except across a size-ladder step (a
// few times at most), and otherwise a fixed world point stays on the same texel or moves by
// whole 8-texel tiles: the map's content and CSSM's tile grid stay put in the world.
TEST(PlainDirectionalMap, MovesByWholeTilesAsTheCameraPans) {
    LongScene s;  // the camera sees 60 m of the 1 km ground: the view, not the scene, bounds the box
    s.camera.far = 60.0f;
    const int res = 1024;
    LightSpace before = computeLightSpace(s.sun, res, s.bounds, s.camera, 16.0f / 9.0f);
    const glm::vec3 step(0.3f * before.texelScale, 0.0f, 0.0f);
    const glm::vec3 probe(1.0f, 0.0f, -30.0f);
    int resized = 0, moved = 0;
    for (int k = 1; k <= 60; ++k) {
        const scene::Camera camera = movedBy(s.camera, step * static_cast<float>(k));
        const LightSpace now = computeLightSpace(s.sun, res, s.bounds, camera, 16.0f / 9.0f);
        if (now.viewProj[0] != before.viewProj[0]) ++moved;
        if (std::abs(now.texelScale - before.texelScale) > 1e-6f * before.texelScale) ++resized;
        else expectWholeTiles(before, now, probe, k);
        // Still covering what the camera looks at.
        const glm::vec2 target = texelOf(now, camera.target) / static_cast<float>(res);
        EXPECT_TRUE(target.x > 0.0f && target.x < 1.0f && target.y > 0.0f && target.y < 1.0f) << "frame " << k;
        before = now;
    }
    std::printf("60 pan steps of 0.3 texel: the box moved %d times, resized %d times\n", moved, resized);
    EXPECT_LE(resized, 3);
    EXPECT_LT(moved, 30) << "the box must not follow every sub-texel step";
}

// Holding the box (computeLightSpace's `previous`, RenderOptions::holdSunBox) under a camera that
// flies 4 texels a frame along the long scene: the held box moves in a third of the frames a box
// fitted afresh moves in (every other), or fewer; it always holds the part of the camera's frustum
// inside the scene; it is at most a size step and the slack coarser; and while its size stays, the
// map's content moves by whole 8-texel tiles.
TEST(PlainDirectionalMap, AHeldBoxMovesRarelyAndHoldsTheView) {
    LongScene s;
    s.camera.far = 60.0f;
    const int res = 1024;
    const float aspect = 16.0f / 9.0f;
    LightSpace held = computeLightSpace(s.sun, res, s.bounds, s.camera, aspect);
    LightSpace fitted = held;
    const glm::vec3 step(0.0f, 0.0f, -4.0f * held.texelScale);
    const glm::vec3 probe(1.0f, 0.0f, -40.0f);
    int heldMoves = 0, fittedMoves = 0;
    for (int k = 1; k <= 100; ++k) {
        const scene::Camera camera = movedBy(s.camera, step * static_cast<float>(k));
        const LightSpace heldNow = computeLightSpace(s.sun, res, s.bounds, camera, aspect, &held);
        const LightSpace fittedNow = computeLightSpace(s.sun, res, s.bounds, camera, aspect);
        heldMoves += heldNow.viewProj[0] != held.viewProj[0];
        fittedMoves += fittedNow.viewProj[0] != fitted.viewProj[0];
        const glm::mat4 cameraViewProj = camera.projection(aspect) * camera.view();
        for (const glm::vec3& p : frustumInsideBox(cameraViewProj, s.bounds)) {
            const glm::vec2 uv = texelOf(heldNow, p) / static_cast<float>(res);
            ASSERT_TRUE(uv.x > -1e-4f && uv.x < 1.0001f && uv.y > -1e-4f && uv.y < 1.0001f)
                << "frame " << k << ": a point the camera sees lies outside the held box (" << uv.x << ", " << uv.y << ")";
        }
        EXPECT_LE(heldNow.texelScale, fittedNow.texelScale * kHeldCoarser * 1.001f) << "frame " << k;
        if (heldNow.box.z == held.box.z && heldNow.box.w == held.box.w) expectWholeTiles(held, heldNow, probe, k);
        held = heldNow;
        fitted = fittedNow;
    }
    std::printf("100 frames flying 4 texels each: the box moved %d times held, %d times fitted afresh\n", heldMoves, fittedMoves);
    EXPECT_GE(fittedMoves, 45) << "a fitted box moves by 8 texels: every other frame";
    EXPECT_LE(heldMoves * 3, fittedMoves);
}

// Held cascades (fitCascade's `previous`) under a camera flying along the long scene: each box
// holds its slice's corners (to within the texel its centre snaps by), is at most the slack
// coarser than a fitted one, and the nearest moves in a third of the frames a fitted one moves in,
// or fewer.
TEST(Cascades, AHeldCascadeMovesRarelyAndHoldsItsSlice) {
    LongScene s;
    const int res = 1024, count = 4;
    const float aspect = 16.0f / 9.0f;
    const auto splits = cascadeSplits(s.camera.near, 200.0f, count, 0.75f);
    const auto fitAll = [&](const scene::Camera& camera, const std::vector<Cascade>* previous) {
        std::vector<Cascade> cascades;
        for (std::size_t c = 0; c < count; ++c)
            cascades.push_back(fitCascade(s.sun, camera, aspect, splits[c], splits[c + 1], s.bounds, res, true,
                                          previous ? &(*previous)[c] : nullptr));
        return cascades;
    };
    std::vector<Cascade> held = fitAll(s.camera, nullptr), fitted = held;
    const float nearTexel = held[0].texelWorld;
    std::array<int, count> heldMoves{}, fittedMoves{};
    for (int k = 1; k <= 100; ++k) {
        const glm::vec3 step(0.3f * nearTexel, 0.0f, -2.0f * nearTexel);  // forward and a little sideways
        const scene::Camera camera = movedBy(s.camera, step * static_cast<float>(k));
        const std::vector<Cascade> heldNow = fitAll(camera, &held), fittedNow = fitAll(camera, nullptr);
        for (std::size_t c = 0; c < count; ++c) {
            heldMoves[c] += heldNow[c].viewProj != held[c].viewProj;
            fittedMoves[c] += fittedNow[c].viewProj != fitted[c].viewProj;
            const float tolerance = 1.5f / static_cast<float>(res);
            for (const glm::vec3& p : frustumCorners(glm::perspective(glm::radians(camera.fovDeg), aspect, splits[c], splits[c + 1]) * camera.view())) {
                const glm::vec4 uv = heldNow[c].shadowMatrix * glm::vec4(p, 1.0f);
                ASSERT_TRUE(uv.x > -tolerance && uv.x < 1.0f + tolerance && uv.y > -tolerance && uv.y < 1.0f + tolerance)
                    << "frame " << k << ", cascade " << c << ": a corner of its slice outside the held box (" << uv.x << ", " << uv.y << ")";
            }
            EXPECT_LE(heldNow[c].texelWorld, fittedNow[c].texelWorld * (1.0f + kBoxSlack) + 2.0f / 16.0f / static_cast<float>(res))
                << "frame " << k << ", cascade " << c;
        }
        held = heldNow;
        fitted = fittedNow;
    }
    std::printf("100 frames flying 2 texels of the nearest cascade each: cascade moves held %d %d %d %d, fitted %d %d %d %d\n",
                heldMoves[0], heldMoves[1], heldMoves[2], heldMoves[3], fittedMoves[0], fittedMoves[1], fittedMoves[2], fittedMoves[3]);
    EXPECT_GE(fittedMoves[0], 50);
    EXPECT_LE(heldMoves[0] * 3, fittedMoves[0]);
}

// frustumInsideBox spans exactly the part of the frustum inside the box: the frustum's corners
// when the box holds it, the box's corners when the frustum holds the box, nothing when apart,
// and for a slab through the frustum the slab's cut of it.
TEST(Cascades, FrustumInsideBoxSpansTheirIntersection) {
    const glm::mat4 frustum = glm::perspective(glm::radians(60.0f), 1.0f, 1.0f, 10.0f);  // looks down -z
    auto span = [](const std::vector<glm::vec3>& points) {
        scene::Bounds b;
        for (const glm::vec3& p : points) b.add(p);
        return b;
    };
    scene::Bounds huge{glm::vec3(-100.0f), glm::vec3(100.0f)};
    const scene::Bounds all = span(frustumInsideBox(frustum, huge));
    const float half = 10.0f * std::tan(glm::radians(30.0f));
    EXPECT_NEAR(all.min.x, -half, 1e-3f);
    EXPECT_NEAR(all.max.z, -1.0f, 1e-3f);
    EXPECT_NEAR(all.min.z, -10.0f, 1e-3f);

    scene::Bounds inner{glm::vec3(-0.5f, -0.5f, -5.0f), glm::vec3(0.5f, 0.5f, -4.0f)};
    const scene::Bounds small = span(frustumInsideBox(frustum, inner));
    EXPECT_NEAR(small.min.x, -0.5f, 1e-4f);
    EXPECT_NEAR(small.max.z, -4.0f, 1e-4f);

    EXPECT_TRUE(frustumInsideBox(frustum, scene::Bounds{glm::vec3(20.0f, 0.0f, -5.0f), glm::vec3(21.0f, 1.0f, -4.0f)}).empty());
    EXPECT_TRUE(frustumInsideBox(frustum, scene::Bounds{glm::vec3(-1.0f), glm::vec3(1.0f, 1.0f, -0.5f)}).empty()) << "before the near plane";

    // A slab y in [-0.1, 0.1] across the whole frustum: its cut spans the frustum's width at the far
    // plane and no more height than the slab.
    scene::Bounds slab{glm::vec3(-100.0f, -0.1f, -100.0f), glm::vec3(100.0f, 0.1f, 100.0f)};
    const scene::Bounds cut = span(frustumInsideBox(frustum, slab));
    EXPECT_NEAR(cut.min.x, -half, 1e-3f);
    EXPECT_NEAR(cut.max.y, 0.1f, 1e-4f);
    EXPECT_NEAR(cut.min.z, -10.0f, 1e-3f);
    EXPECT_NEAR(cut.max.z, -1.0f, 1e-3f);
}

// columnPlanes bounds the column along the light over a cascade's read points by the sides of their
// hull in the map, a margin of texels out: under a sun straight down (light x, y = world x, -z over
// a 20 m box, 200 texels), a triangle of points on the ground. A box over the triangle, or over
// the ground within the margin of its hypotenuse, is inside every plane at any height; one over the
// triangle's bounding rectangle's empty corner, past the margin, lies outside one; collinear points
// give no planes (nothing culled).
TEST(Cascades, ColumnPlanesHoldTheHullOfTheReadPointsAlongTheLight) {
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 50.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
    const glm::mat4 viewProj = glm::ortho(-10.0f, 10.0f, -10.0f, 10.0f, 1.0f, 100.0f) * view;
    const std::vector<glm::vec3> triangle{{-8, 0, 8}, {8, 0, 8}, {-8, 0, -8}, {0, 0, 8}};  // a point on an edge too
    const float margin = 3.0f;  // texels of 0.1 m
    const std::vector<glm::vec4> planes = columnPlanes(triangle, viewProj, 200, margin);
    ASSERT_EQ(planes.size(), 3u) << "the hull's three sides";
    const auto outside = [&](const scene::Bounds& box) {
        for (const glm::vec4& p : planes) {
            float farthest = -1e30f;
            for (int k = 0; k < 8; ++k) farthest = std::max(farthest, glm::dot(glm::vec3(p), box.corner(k)) + p.w);
            if (farthest < 0.0f) return true;
        }
        return false;
    };
    const auto at = [](glm::vec2 xz, float y0, float y1) { return scene::Bounds{glm::vec3(xz.x - 0.5f, y0, xz.y - 0.5f), glm::vec3(xz.x + 0.5f, y1, xz.y + 0.5f)}; };
    EXPECT_FALSE(outside(at({-4, 4}, 0, 1))) << "inside the triangle";
    EXPECT_FALSE(outside(at({-4, 4}, 20, 30))) << "high over it: the column holds the light's direction";
    // The hypotenuse runs from (8, 8) to (-8, -8), x = z: a point (x, 0) lies x / sqrt 2 past it.
    EXPECT_FALSE(outside(scene::Bounds{glm::vec3(0.35f, 0.0f, 0.0f), glm::vec3(0.4f, 1.0f, 0.0f)})) << "0.25 m past: within the margin";
    EXPECT_TRUE(outside(scene::Bounds{glm::vec3(0.5f, 0.0f, 0.0f), glm::vec3(0.6f, 1.0f, 0.0f)})) << "0.35 m past the margin";
    EXPECT_TRUE(outside(at({6, -6}, 0, 30))) << "the rectangle's empty corner";
    EXPECT_FALSE(outside(at({8.2f, 8.2f}, 0, 1))) << "over the corner, within the margin";
    EXPECT_TRUE(columnPlanes({{-8, 0, 8}, {0, 0, 0}, {8, 0, -8}}, viewProj, 200, margin).empty()) << "collinear";
    EXPECT_TRUE(columnPlanes({}, viewProj, 200, margin).empty());
}

}  // namespace
}  // namespace penumbra::shadows
