// TintReach: where a translucent caster's coloured shadow may fall on a receiver's box, and the
// screen rectangles the renderer splits a receiver's pixels into. The footprint must hold every
// receiver point whose ray to the light passes through the caster (else the renderer would shade
// coloured shadow with a program that reads no tint), and should hold little else.
#include "render/TintReach.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <cstdio>
#include <random>

namespace penumbra::render {
namespace {

scene::Bounds box(glm::vec3 lo, glm::vec3 hi) { return scene::Bounds{lo, hi}; }

gpu::LightData directional(glm::vec3 direction, float texelScale) {
    gpu::LightData l{};
    l.colorType = glm::vec4(1.0f, 1.0f, 1.0f, static_cast<float>(gpu::kLightDirectional));
    l.directionFar = glm::vec4(glm::normalize(direction), 100.0f);
    l.shadow = glm::vec4(0.0f, 0.0f, 0.0f, texelScale);
    return l;
}

gpu::LightData perspective(int type, glm::vec3 position, float texelScale) {
    gpu::LightData l{};
    l.colorType = glm::vec4(1.0f, 1.0f, 1.0f, static_cast<float>(type));
    l.positionNear = glm::vec4(position, 0.05f);
    l.directionFar = glm::vec4(0.0f, -1.0f, 0.0f, 50.0f);
    l.shadow = glm::vec4(0.0f, 0.0f, 0.0f, texelScale);
    return l;
}

bool inside(const scene::Bounds& b, glm::vec3 p, float slack = 1e-4f) {
    return glm::all(glm::greaterThanEqual(p, b.min - slack)) && glm::all(glm::lessThanEqual(p, b.max + slack));
}

// Whether the segment from p towards the light (direction -d, or to the light's position) meets the box.
bool segmentMeets(glm::vec3 from, glm::vec3 to, const scene::Bounds& b) {
    float t0 = 0.0f, t1 = 1.0f;
    const glm::vec3 d = to - from;
    for (int a = 0; a < 3; ++a) {
        if (std::abs(d[a]) < 1e-9f) {
            if (from[a] < b.min[a] || from[a] > b.max[a]) return false;
            continue;
        }
        float ta = (b.min[a] - from[a]) / d[a], tb = (b.max[a] - from[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

// A caster: a box turned about a random axis every other trial (a rotated pane), as the renderer
// passes translucent parts (their mesh bounds under their model matrix).
struct Caster {
    scene::Bounds local;
    glm::mat4 model;
    OrientedBox box() const { return OrientedBox(local, model); }
    bool meets(glm::vec3 from, glm::vec3 to) const {
        const glm::mat4 inverse = glm::inverse(model);
        return segmentMeets(glm::vec3(inverse * glm::vec4(from, 1.0f)), glm::vec3(inverse * glm::vec4(to, 1.0f)), local);
    }
};
Caster turned(const scene::Bounds& world, float angle, glm::vec3 axis) {
    const glm::vec3 c = world.center(), h = 0.5f * (world.max - world.min);
    return Caster{box(-h, h), glm::rotate(glm::translate(glm::mat4(1.0f), c), angle, glm::normalize(axis))};
}

TEST(TintReach, ASunStraightDownTintsTheGroundUnderThePaneAndItsPaddingOnly) {
    const gpu::LightData sun = directional({0, -1, 0}, 0.01f);
    const scene::Bounds pane = box({-1, 1, -0.5f}, {1, 1.02f, 0.5f});
    const scene::Bounds ground = box({-10, 0, -10}, {10, 0, 10});
    const scene::Bounds f = tintFootprint(sun, pane, ground, 10.0f);  // 10 texels = 0.1 world units
    ASSERT_FALSE(f.empty());
    EXPECT_NEAR(f.min.x, -1.1f, 1e-4f);
    EXPECT_NEAR(f.max.x, 1.1f, 1e-4f);
    EXPECT_NEAR(f.min.z, -0.6f, 1e-4f);
    EXPECT_NEAR(f.max.z, 0.6f, 1e-4f);
    EXPECT_NEAR(f.min.y, 0.0f, 1e-6f);
    EXPECT_NEAR(f.max.y, 0.0f, 1e-6f);
    // A box beside the shadow's column gets nothing.
    EXPECT_TRUE(tintFootprint(sun, pane, box({2, 0, 2}, {3, 1, 3}), 10.0f).empty());
}

// An oblique sun: the footprint on the ground is the box's own shadow (its corners along the light
// onto the ground) and the padding, not a rectangle around its silhouette in some frame across
// the light. The default scene's sun and moving sphere's box: measured, that rectangle's cut held
// 2.44 x 2.34 where the shadow is 1.30 x 1.22.
TEST(TintReach, AnObliqueSunsFootprintOnTheGroundIsTheBoxsShadowAndItsPadding) {
    const glm::vec3 d = glm::normalize(glm::vec3(-0.45f, -1.0f, -0.35f));
    const gpu::LightData sun = directional(d, 0.01f);
    const scene::Bounds ball = box({-3.45f, 1.15f, 3.05f}, {-2.55f, 2.05f, 3.95f});
    const scene::Bounds ground = box({-12, 0, -12}, {12, 0, 12});
    scene::Bounds shadow;
    for (int k = 0; k < 8; ++k) shadow.add(ball.corner(k) - d * (ball.corner(k).y / d.y));
    const float pad = 5.0f * 0.01f;
    const scene::Bounds f = tintFootprint(sun, ball, ground, 5.0f);
    ASSERT_FALSE(f.empty());
    for (int a : {0, 2}) {
        EXPECT_LE(f.min[a], shadow.min[a]) << "axis " << a;
        EXPECT_GE(f.max[a], shadow.max[a]) << "axis " << a;
        EXPECT_GE(f.min[a], shadow.min[a] - 3.0f * pad) << "axis " << a;
        EXPECT_LE(f.max[a], shadow.max[a] + 3.0f * pad) << "axis " << a;
    }
}

TEST(TintReach, ASpotsPyramidWidensWithDistanceAndALightInsideTheCasterReachesEverything) {
    // Light 5 above the ground, pane halfway down: its shadow is twice the pane on the ground.
    const gpu::LightData spot = perspective(gpu::kLightSpot, {0, 5, 0}, 1e-4f);
    const scene::Bounds pane = box({-1, 2.5f, -1}, {1, 2.5f, 1});
    const scene::Bounds ground = box({-10, 0, -10}, {10, 0, 10});
    const scene::Bounds f = tintFootprint(spot, pane, ground, 4.0f);
    ASSERT_FALSE(f.empty());
    EXPECT_LE(f.min.x, -2.0f);
    EXPECT_GE(f.max.x, 2.0f);
    EXPECT_GT(f.min.x, -2.1f);
    EXPECT_LT(f.max.x, 2.1f);
    // A point light inside a glass ball may colour anything around it.
    const gpu::LightData point = perspective(gpu::kLightPoint, {0, 1, 0}, 1e-3f);
    const scene::Bounds ball = box({-0.5f, 0.5f, -0.5f}, {0.5f, 1.5f, 0.5f});
    const scene::Bounds all = tintFootprint(point, ball, ground, 4.0f);
    EXPECT_EQ(all.min, ground.min);
    EXPECT_EQ(all.max, ground.max);
}

// Random lights, casters and receivers for the conservativeness tests: every light type in
// turn, casters turned about a random axis every other trial, some receivers flat (as planes are).
struct RandomTrials {
    std::mt19937 rng;
    std::uniform_real_distribution<float> u{-1.0f, 1.0f}, size{0.05f, 2.0f};
    explicit RandomTrials(unsigned seed) : rng(seed) {}
    scene::Bounds randomBox(glm::vec3 centre, float spread) {
        const glm::vec3 c = centre + spread * glm::vec3(u(rng), u(rng), u(rng));
        const glm::vec3 h(size(rng), size(rng) * (u(rng) > 0.6f ? 0.0f : 1.0f), size(rng));
        return box(c - h, c + h);
    }
    struct Trial {
        int kind;  // 0 sun, 1 spot, 2 point
        glm::vec3 lightPos, sunDir;
        gpu::LightData light;
        Caster caster;
        scene::Bounds receiver;
        // The segment from receiver point p towards the light, and from p away from it.
        glm::vec3 towards(glm::vec3 p) const { return kind == 0 ? p - 100.0f * sunDir : lightPos; }
        glm::vec3 beyond(glm::vec3 p) const { return p + 100.0f * (kind == 0 ? sunDir : glm::normalize(p - lightPos)); }
    };
    Trial trial(int index, float casterHeight, float receiverHeight, float receiverSpread) {
        Trial t;
        t.kind = index % 3;
        t.lightPos = glm::vec3(3 * u(rng), 8.0f + u(rng), 3 * u(rng));
        t.sunDir = glm::normalize(glm::vec3(u(rng), -1.5f, u(rng)));
        t.light = t.kind == 0 ? directional(t.sunDir, 0.01f) : perspective(t.kind == 1 ? gpu::kLightSpot : gpu::kLightPoint, t.lightPos, 1e-3f);
        t.caster = turned(randomBox({0, casterHeight, 0}, 2.0f), index % 2 ? 2.0f * u(rng) : 0.0f, {u(rng), u(rng), 1.0f});
        t.receiver = randomBox({0, receiverHeight, 0}, receiverSpread);
        return t;
    }
    glm::vec3 pointIn(const scene::Bounds& b) {
        const glm::vec3 t(0.5f + 0.5f * u(rng), 0.5f + 0.5f * u(rng), 0.5f + 0.5f * u(rng));
        return b.min + t * (b.max - b.min);
    }
    // 200 random points of the trial's receiver: how many the caster shadows (their segment to
    // the light meets it), and how many of those lie outside `box`.
    struct Shadowed {
        int points = 0, outside = 0;
    };
    Shadowed shadowedPoints(const Trial& t, const scene::Bounds& box) {
        Shadowed s;
        for (int i = 0; i < 200; ++i) {
            const glm::vec3 p = pointIn(t.receiver);
            if (!t.caster.meets(p, t.towards(p))) continue;
            ++s.points;
            s.outside += inside(box, p) ? 0 : 1;
        }
        return s;
    }
};

// No padding: each receiver point whose segment to the light crosses the caster lies in the
// footprint (it is conservative).
TEST(TintReach, EveryReceiverPointBehindTheCasterIsInItsFootprint) {
    RandomTrials random(7);
    int behind = 0, checked = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const RandomTrials::Trial t = random.trial(trial, 4.0f, 1.0f, 4.0f);
        const RandomTrials::Shadowed s = random.shadowedPoints(t, tintFootprint(t.light, t.caster.box(), t.receiver, 0.0f));
        checked += 200;
        behind += s.points;
        ASSERT_EQ(s.outside, 0) << "trial " << trial << " kind " << t.kind;
    }
    EXPECT_GT(behind, checked / 50);  // the trials do put receivers behind casters
}

// The same with the receiver a turned box too (a translucent pane as a receiver, Renderer's
// footprintsOf): its points behind the caster lie in the footprint, and the footprint of a turned
// receiver is never wider than that of its world box.
TEST(TintReach, EveryPointOfATurnedReceiverBehindTheCasterIsInItsFootprint) {
    RandomTrials random(11);
    int behind = 0, checked = 0, tighter = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const RandomTrials::Trial t = random.trial(trial, 4.0f, 1.0f, 4.0f);
        const Caster receiver = turned(t.receiver, 1.5f * random.u(random.rng), {random.u(random.rng), 1.0f, random.u(random.rng)});
        const OrientedBox receiverBox = receiver.box();
        scene::Bounds world;
        for (const glm::vec3& c : receiverBox.corners) world.add(c);
        const scene::Bounds f = tintFootprint(t.light, t.caster.box(), receiverBox, 0.0f);
        const scene::Bounds wide = tintFootprint(t.light, t.caster.box(), world, 0.0f);
        if (!f.empty()) {
            ASSERT_FALSE(wide.empty()) << "trial " << trial;
            ASSERT_TRUE(inside(wide, f.min) && inside(wide, f.max)) << "trial " << trial;
            tighter += glm::length(f.extent()) < 0.9f * glm::length(wide.extent());
        }
        for (int i = 0; i < 200; ++i) {
            const glm::vec3 local = random.pointIn(receiver.local);
            const glm::vec3 p = glm::vec3(receiver.model * glm::vec4(local, 1.0f));
            ++checked;
            if (!t.caster.meets(p, t.towards(p))) continue;
            ++behind;
            ASSERT_TRUE(inside(f, p, 1e-3f)) << "trial " << trial << " kind " << t.kind;
        }
    }
    EXPECT_GT(behind, checked / 50);
    EXPECT_GT(tighter, 10) << "a turned receiver's own box cuts its footprint";
}

TEST(TintReach, GroundBelowAFloatingPaneIsBehindItButNotAtTheFootOfABlockStandingOnIt) {
    const scene::Bounds ground = box({-10, 0, -10}, {10, 0, 10});
    const scene::Bounds pane = box({-1, 2.5f, -1}, {1, 2.52f, 1});
    const scene::Bounds block = box({2, 0, 2}, {3, 1, 3});
    for (const gpu::LightData& light : {directional({0.3f, -1, 0.2f}, 0.01f), perspective(gpu::kLightSpot, {0, 5, 0}, 1e-3f),
                                        perspective(gpu::kLightPoint, {0, 5, 0}, 1e-3f)}) {
        const int type = static_cast<int>(light.colorType.w);
        ASSERT_FALSE(tintFootprint(light, pane, ground, 4.0f).empty()) << type;
        EXPECT_TRUE(tintFootprintNotBehind(light, pane, ground, 4.0f).empty()) << type << ": the ground lies behind the pane";
        // The ground at the block's foot is as far from the light as the block's bottom.
        const scene::Bounds foot = tintFootprintNotBehind(light, block, ground, 4.0f);
        ASSERT_FALSE(foot.empty()) << type;
        EXPECT_TRUE(inside(foot, {2.5f, 0, 2.5f})) << type;
        EXPECT_TRUE(inside(tintFootprint(light, block, ground, 4.0f), foot.min) && inside(tintFootprint(light, block, ground, 4.0f), foot.max))
            << type << ": within the footprint";
    }
}

// A ground under a spot or point light shadows a box on the light's side of it by more than a
// lookup reaches (2 pad texels at the box's depth, and the depth reach turned into view depth),
// not one resting on it, just above it, or seen from under the ground. Randomly, under an oblique
// spot: wherever it says a box is lit, every tap's ray near a box point (a light ray through a
// point up to 2 pad texels across the axis from it) meets the ground deeper in the light's window
// depth than the compare reaches.
TEST(TintReach, AFlatCasterUnderASpotOrPointLightShadowsNothingClearlyAboveIt) {
    const glm::vec4 ground(0, 1, 0, 0);
    const float pad = 5.0f, texelScale = 2.0f * std::tan(glm::radians(30.0f)) / 512.0f;
    for (int type : {gpu::kLightSpot, gpu::kLightPoint}) {
        const gpu::LightData light = perspective(type, {0, 5, 0}, type == gpu::kLightPoint ? 2.0f / 512.0f : texelScale);
        EXPECT_TRUE(flatCasterShadowsNone(light, ground, OrientedBox(box({0.5f, 1, 0.5f}, {1.5f, 2, 1.5f})), pad, 0.0f)) << type;
        EXPECT_FALSE(flatCasterShadowsNone(light, ground, OrientedBox(box({0.5f, 0, 0.5f}, {1.5f, 1, 1.5f})), pad, 0.0f))
            << type << ": resting on it";
        EXPECT_FALSE(flatCasterShadowsNone(light, ground, OrientedBox(box({0.5f, 0.01f, 0.5f}, {1.5f, 1, 1.5f})), pad, 0.0f))
            << type << ": a hair above it";
        EXPECT_FALSE(flatCasterShadowsNone(light, ground, OrientedBox(box({0.5f, 0.4f, 0.5f}, {1.5f, 1, 1.5f})), pad, 1e-3f))
            << type << ": above it by less than the depth reach";
        gpu::LightData under = light;
        under.positionNear = glm::vec4(0, -5, 0, 0.05f);
        under.directionFar = glm::vec4(0, 1, 0, 50.0f);
        EXPECT_FALSE(flatCasterShadowsNone(under, ground, OrientedBox(box({0.5f, 1, 0.5f}, {1.5f, 2, 1.5f})), pad, 0.0f))
            << type << ": the light under the ground";
    }
    gpu::LightData spot = perspective(gpu::kLightSpot, {0, 5, 0}, texelScale);
    const glm::vec3 axis = glm::normalize(glm::vec3(0.7f, -0.7f, 0.2f));  // oblique: a tap beside a point may lie lower
    spot.directionFar = glm::vec4(axis, spot.directionFar.w);
    const glm::vec3 eye(spot.positionNear);
    const glm::vec3 across1 = glm::normalize(glm::cross(axis, glm::vec3(0, 0, 1))), across2 = glm::cross(axis, across1);
    const float near = spot.positionNear.w, far = spot.directionFar.w;
    const auto window = [&](float z) { return far / (far - near) - far * near / ((far - near) * z); };
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int lit = 0;
    for (int i = 0; i < 400; ++i) {
        const glm::vec3 lo(u(rng) * 6 + 1, u(rng) * 1.5f, u(rng) * 6 - 3);
        const scene::Bounds b = box(lo, lo + glm::vec3(0.2f + u(rng), 0.2f + u(rng), 0.2f + u(rng)));
        const float reach = u(rng) < 0.5f ? 0.0f : 2e-4f;
        if (!flatCasterShadowsNone(spot, ground, OrientedBox(b), pad, reach)) continue;
        ++lit;
        for (int k = 0; k < 50; ++k) {
            const glm::vec3 p = glm::mix(b.min, b.max, glm::vec3(u(rng), u(rng), u(rng)));
            const float z = glm::dot(p - eye, axis), texel = z * texelScale;
            const float angle = u(rng) * 6.2832f;  // a tap up to 2 pad texels across the axis
            const glm::vec3 side = (std::cos(angle) * across1 + std::sin(angle) * across2) * (2.0f * pad * texel * u(rng));
            const glm::vec3 ray = glm::normalize(p + side - eye);
            ASSERT_LT(ray.y, 0.0f);
            const glm::vec3 hit = eye + ray * (-eye.y / ray.y);  // where it meets the ground
            EXPECT_GT(window(glm::dot(hit - eye, axis)), window(z) + reach) << "box " << i << ", point " << k;
        }
    }
    EXPECT_GT(lit, 40) << "boxes clearly above the ground";
}

// Under a sun at an angle t to a ground's normal, a lookup's pad holds its normal offset o (any
// direction) and its taps' reach a across the light along each axis of the map (o + a <= pad): a
// tap stands for a point up to o + sqrt(2) a sin t nearer the ground. Randomly: wherever the ground
// is said to shadow nothing of a box, every such tap's ray meets the ground deeper than the box
// point's own depth plus the depth reach; and a box a little over pad max(1, sqrt(2) sin t) texels
// above the ground is said to be lit (twice the pad, the margin before, kept a high sun's ground).
TEST(TintReach, AFlatCasterUnderASunShadowsNothingAboveItByTheTapsReachTimesSinT) {
    const glm::vec4 ground(0, 1, 0, 0);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int lit = 0, near = 0;
    for (int i = 0; i < 400; ++i) {
        const float t = glm::radians(5.0f + 75.0f * u(rng)), azimuth = 6.2832f * u(rng);
        const glm::vec3 d(std::sin(t) * std::cos(azimuth), -std::cos(t), std::sin(t) * std::sin(azimuth));
        const float texel = 0.01f + 0.03f * u(rng), pad = 3.0f + 57.0f * u(rng), reach = u(rng) < 0.5f ? 0.0f : 2e-4f;
        const gpu::LightData sun = directional(d, texel);
        const float range = sun.directionFar.w - sun.positionNear.w;
        const float margin = pad * texel * std::max(1.0f, std::sqrt(2.0f) * std::sin(t)) + reach * range + range / 4096.0f;
        // Just over the margin: lit; anywhere from the ground up to three margins: lit where it says so.
        const bool justOver = i % 4 == 0;
        const glm::vec3 lo(u(rng) * 4 - 2, justOver ? 1.01f * margin : u(rng) * 3.0f * margin, u(rng) * 4 - 2);
        const scene::Bounds b = box(lo, lo + glm::vec3(0.2f + u(rng), 0.2f + u(rng), 0.2f + u(rng)));
        const bool none = flatCasterShadowsNone(sun, ground, OrientedBox(b), pad, reach);
        if (justOver) {
            EXPECT_TRUE(none) << "box " << i << ": " << margin << " over the ground, t " << glm::degrees(t);
            ++near;
        }
        if (!none) continue;
        ++lit;
        const glm::vec3 x = glm::normalize(glm::cross(d, glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f)));
        const glm::vec3 y = glm::cross(d, x);  // the map's axes: any turn about the light
        for (int k = 0; k < 50; ++k) {
            const glm::vec3 p = glm::mix(b.min, b.max, glm::vec3(u(rng), u(rng), u(rng)));
            const float o = pad * u(rng), a = pad - o;
            const glm::vec3 offset = glm::normalize(glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f)) * (o * texel);
            const glm::vec3 q = p + offset + (x * (2.0f * u(rng) - 1.0f) + y * (2.0f * u(rng) - 1.0f)) * (a * texel);
            ASSERT_GT(q.y, 0.0f) << "box " << i << ", point " << k;
            // The tap's ray meets the ground q.y / cos t further along the light than the lookup's
            // point (p + offset, at q's depth), which must lie deeper than the compare reaches.
            EXPECT_GT(q.y / std::cos(t), reach * range) << "box " << i << ", point " << k;
        }
    }
    EXPECT_GT(near, 80);
    EXPECT_GT(lit, 150) << "boxes clearly above the ground";
}

// No padding or bias: each receiver point with a layer of the caster at or behind it on its ray
// from the light (the ray beyond it meets the caster) is in the not-behind box; there a lookup
// may find a layer behind the receiver.
TEST(TintReach, EveryReceiverPointNotBehindTheCasterIsInItsNotBehindFootprint) {
    RandomTrials random(11);
    int notBehind = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const RandomTrials::Trial t = random.trial(trial, 3.0f, 2.0f, 2.0f);  // overlapping often
        // Both tolerances: an opaque receiver's lookup's and a translucent one's surface's.
        const scene::Bounds f = tintFootprintNotBehind(t.light, t.caster.box(), t.receiver, 0.0f);
        const scene::Bounds near = tintFootprintNotBehind(t.light, t.caster.box(), t.receiver, 0.0f, SideTolerance::Surface);
        for (int i = 0; i < 200; ++i) {
            const glm::vec3 p = random.pointIn(t.receiver);
            if (!t.caster.meets(p, t.beyond(p))) continue;
            ++notBehind;
            ASSERT_TRUE(inside(f, p)) << "trial " << trial << " kind " << t.kind;
            ASSERT_TRUE(inside(near, p)) << "trial " << trial << " kind " << t.kind << " (surface tolerance)";
        }
    }
    std::printf("%d receiver points not behind their caster\n", notBehind);
    EXPECT_GT(notBehind, 1000);  // the trials do put receivers among the casters' layers
}

// The mirror image: each receiver point with a layer of the caster in front of it (the ray from
// it to the light meets the caster) is in the not-in-front box; elsewhere every layer of the
// caster lies behind the receiver and puts no colour on it.
TEST(TintReach, EveryReceiverPointBehindPartOfTheCasterIsInItsNotInFrontFootprint) {
    RandomTrials random(12);
    int shadowed = 0, tighter = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const RandomTrials::Trial t = random.trial(trial, 3.0f, 2.0f, 2.0f);
        const scene::Bounds f = tintFootprintNotInFront(t.light, t.caster.box(), t.receiver, 0.0f);
        const scene::Bounds all = tintFootprint(t.light, t.caster.box(), t.receiver, 0.0f);
        if (!all.empty()) tighter += f.empty() || glm::length(f.extent()) < 0.9f * glm::length(all.extent());
        const RandomTrials::Shadowed s = random.shadowedPoints(t, f);
        shadowed += s.points;
        ASSERT_EQ(s.outside, 0) << "trial " << trial << " kind " << t.kind;
    }
    EXPECT_GT(shadowed, 1000);
    EXPECT_GT(tighter, 10) << "the cut leaves out receivers in front of the caster";
}

TEST(TintReach, APaneAboveABlockIsInFrontOfItButTheGroundIsNotInFrontOfThePane) {
    const scene::Bounds ground = box({-10, 0, -10}, {10, 0, 10});
    const scene::Bounds pane = box({-1, 2.5f, -1}, {1, 2.52f, 1});
    const scene::Bounds block = box({-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f});
    for (const gpu::LightData& light : {directional({0.1f, -1, 0.05f}, 0.01f), perspective(gpu::kLightSpot, {0, 5, 0}, 1e-3f),
                                        perspective(gpu::kLightPoint, {0, 5, 0}, 1e-3f)}) {
        const int type = static_cast<int>(light.colorType.w);
        ASSERT_FALSE(tintFootprint(light, block, pane, 4.0f).empty()) << type << ": the pane lies in the block's shadow volume";
        // Under a point light, beyond the box around it that holds the pane (six half-spaces).
        EXPECT_TRUE(tintFootprintNotInFront(light, block, pane, 4.0f).empty()) << type << ": the block lies wholly behind the pane";
        EXPECT_FALSE(tintFootprintNotInFront(light, pane, ground, 4.0f).empty()) << type << ": the pane lies in front of the ground";
    }
}

// An opaque caster shadows what lies behind it, and what lies in front of it by less than the
// lookup's reach in depth (receiver-plane taps compare up to 0.01 of window depth deeper).
TEST(TintReach, AnOpaqueCasterJustBehindAReceiverShadowsItOnlyWithinTheLookupsDepthReach) {
    const scene::Bounds plate = box({-1, 1, -1}, {1, 1.02f, 1});
    const scene::Bounds above = box({-0.5f, 2, -0.5f}, {0.5f, 2.5f, 0.5f}), below = box({-0.5f, 0.4f, -0.5f}, {0.5f, 0.9f, 0.5f});
    // Sun: depth 0..1 spans 100 units, so a reach of 0.01 is 1 unit. Spot at y = 5, near 0.05, far 50:
    // the plate at view depth ~4 lies 0.1 in front of the block at ~4.1; window depths differ by ~3e-4.
    // The point light's cube face below it (y the largest axis distance) has the spot's depths.
    const gpu::LightData sun = directional({0, -1, 0}, 0.01f), spot = perspective(gpu::kLightSpot, {0, 5, 0}, 1e-3f),
                         point = perspective(gpu::kLightPoint, {0, 5, 0}, 1e-3f);
    for (const gpu::LightData& light : {sun, spot, point}) {
        const int type = static_cast<int>(light.colorType.w);
        EXPECT_FALSE(opaqueShadowFootprint(light, above, plate, 2.0f, 0.0f).empty()) << type << ": a caster above shadows the plate";
        EXPECT_TRUE(opaqueShadowFootprint(light, below, plate, 2.0f, 0.0f).empty()) << type << ": the block lies wholly behind the plate";
        EXPECT_FALSE(opaqueShadowFootprint(light, below, plate, 2.0f, 0.01f).empty()) << type << ": taps reaching 0.01 deeper meet it";
        EXPECT_FALSE(shadowFootprint(light, below, plate, 2.0f).empty()) << type << ": two-sided, the block's volume holds the plate";
    }
    // The window depth's step between the plate (~4) and the block (~4.1) under the spot.
    EXPECT_TRUE(opaqueShadowFootprint(spot, below, plate, 2.0f, 1e-5f).empty());
    EXPECT_FALSE(opaqueShadowFootprint(spot, below, plate, 2.0f, 1e-3f).empty());
}

TEST(TintReach, QuartersTileABoxAcrossItsTwoLongestSides) {
    const scene::Bounds b = box({-3.0f, -0.05f, -2.0f}, {3.0f, 0.05f, 2.0f});
    const std::array<scene::Bounds, 4> q = quarters(b, glm::mat4(1.0f));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 2000; ++trial) {
        const glm::vec3 p = glm::mix(b.min, b.max, glm::vec3(unit(rng), unit(rng), unit(rng)));
        ASSERT_EQ(std::count_if(q.begin(), q.end(), [&](const scene::Bounds& c) { return inside(c, p, 0.0f); }), 1) << "trial " << trial;
    }
    for (const scene::Bounds& c : q) EXPECT_EQ(c.max.y - c.min.y, b.max.y - b.min.y);  // the thin side stays whole
}

// A projector above a floor, looking down and ahead: its light on the floor is a trapezoid. Cell
// by cell, the reach must still hold every lit floor point (else the renderer would shade lit
// pixels with a build that leaves the light out), and far less of the floor than the whole box's.
TEST(TintReach, AProjectorsReachCellByCellHoldsEveryLitPointOfAFloorAndLessBesides) {
    gpu::LightData projector = perspective(gpu::kLightProjector, {0.0f, 2.4f, 7.5f}, 1e-3f);
    const glm::mat4 toUnit = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 0.0f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 1.0f));
    projector.shadowMatrix = toUnit * glm::perspective(glm::radians(28.0f), 1.0f, 0.05f, 25.0f) *
                             glm::lookAt(glm::vec3(0.0f, 2.4f, 7.5f), glm::vec3(0.0f, 2.4f - 0.08f * 8.0f, -0.5f), glm::vec3(0, 1, 0));
    const OrientedBox floor(box({-12.0f, -0.01f, -12.0f}, {12.0f, 0.0f, 12.0f}));
    const scene::Bounds whole = lightReach(projector, floor);
    ASSERT_FALSE(whole.empty());
    std::vector<scene::Bounds> byCell;
    float cellArea = 0.0f;
    cellsOf([&](const OrientedBox& cell) { return lightReach(projector, cell); }, whole, 3, [&](const scene::Bounds& b) {
        byCell.push_back(b);
        cellArea += (b.max.x - b.min.x) * (b.max.z - b.min.z);
    });
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> across(-12.0f, 12.0f);
    int lit = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const glm::vec3 p(across(rng), 0.0f, across(rng));
        const glm::vec4 s = projector.shadowMatrix * glm::vec4(p, 1.0f);
        if (!(s.w > 0.0f && s.x >= 0.0f && s.x <= s.w && s.y >= 0.0f && s.y <= s.w)) continue;
        ++lit;
        ASSERT_TRUE(std::any_of(byCell.begin(), byCell.end(), [&](const scene::Bounds& b) { return inside(b, p); }))
            << "lit floor point " << p.x << ", " << p.z << " in no cell's reach";
    }
    EXPECT_GT(lit, 500);
    const float litArea = 24.0f * 24.0f * static_cast<float>(lit) / 20000.0f;
    const float wholeArea = (whole.max.x - whole.min.x) * (whole.max.z - whole.min.z);
    std::printf("projector on a floor: lit %.1f m^2; reach of the whole box %.1f m^2, of its cells %.1f m^2\n", litArea, wholeArea,
                cellArea);
    EXPECT_LT(cellArea, 1.1f * litArea);
    EXPECT_GT(wholeArea, 1.3f * litArea);
}

TEST(TintReach, APartitionCoversEveryPixelOnceOnTheRightSide) {
    const PixelRect area{10, 5, 90, 70};
    const std::vector<PixelRect> covered{{20, 10, 40, 30}, {30, 20, 60, 50}, {0, 60, 200, 200}, {85, 0, 95, 8}};
    const RectPartition parts = partition(area, covered);
    std::vector<int> count(100 * 100, 0), side(100 * 100, -1);
    for (int in = 0; in < 2; ++in)
        for (const PixelRect& r : in ? parts.inside : parts.outside)
            for (int y = r.y0; y < r.y1; ++y)
                for (int x = r.x0; x < r.x1; ++x) {
                    ++count[y * 100 + x];
                    side[y * 100 + x] = in;
                }
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 100; ++x) {
            const bool inArea = x >= area.x0 && x < area.x1 && y >= area.y0 && y < area.y1;
            ASSERT_EQ(count[y * 100 + x], inArea ? 1 : 0) << x << "," << y;
            if (!inArea) continue;
            const bool isCovered = std::any_of(covered.begin(), covered.end(), [&](const PixelRect& r) {
                return x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
            });
            ASSERT_EQ(side[y * 100 + x], isCovered ? 1 : 0) << x << "," << y;
        }
    EXPECT_LE(parts.inside.size() + parts.outside.size(), 12u);  // runs merged, not one per grid cell
}

TEST(TintReach, AScreenRectangleHoldsTheBoxAndABoxBehindTheEyeTakesTheWholeView) {
    const glm::mat4 viewProj = glm::perspective(glm::radians(60.0f), 2.0f, 0.1f, 100.0f) *
                               glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    const scene::Bounds b = box({-1, -1, -1}, {1, 1, 1});
    const PixelRect r = screenRect(b, viewProj, 200, 100);
    for (const glm::vec3& c : b.corners()) {
        const glm::vec4 clip = viewProj * glm::vec4(c, 1.0f);
        const glm::vec2 px = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(200, 100);
        EXPECT_GE(px.x, r.x0);
        EXPECT_LE(px.x, r.x1);
        EXPECT_GE(px.y, r.y0);
        EXPECT_LE(px.y, r.y1);
    }
    EXPECT_LT(r.x1 - r.x0, 200);
    const PixelRect whole = screenRect(box({-1, -1, 4}, {1, 1, 7}), viewProj, 200, 100);  // the eye is inside it
    EXPECT_EQ(whole.x0, 0);
    EXPECT_EQ(whole.y0, 0);
    EXPECT_EQ(whole.x1, 200);
    EXPECT_EQ(whole.y1, 100);
}

}  // namespace
}  // namespace penumbra::render
