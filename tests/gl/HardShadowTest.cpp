// Hard shadow maps against analytic expectations: the shadow of a known occluder covers
// exactly the pixels that a ray test says it should (±2 px at edges), for every light type;
// acne appears without bias and disappears with the defaults; Peter Panning appears with
// too much bias.
#include "GlTestSupport.h"

#include "gl/Debug.h"
#include "render/Offscreen.h"
#include "shadows/LightSpace.h"
#include "shadows/warped/WarpedShadowMap.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>

namespace penumbra::test {
namespace {

using render::OutputMode;

struct Box {
    glm::vec3 min, max;
};

// Ray/box slab test; returns the entry distance in (tMin, tMax).
std::optional<float> hit(const Box& b, const glm::vec3& o, const glm::vec3& d, float tMin, float tMax) {
    for (int a = 0; a < 3; ++a) {
        if (std::abs(d[a]) < 1e-9f) {
            if (o[a] < b.min[a] || o[a] > b.max[a]) return std::nullopt;
            continue;
        }
        float t0 = (b.min[a] - o[a]) / d[a], t1 = (b.max[a] - o[a]) / d[a];
        if (t0 > t1) std::swap(t0, t1);
        tMin = std::max(tMin, t0);
        tMax = std::min(tMax, t1);
        if (tMin > tMax) return std::nullopt;
    }
    return tMin;
}

// Expected shadow mask for a scene made of a ground plane (y = 0) and box occluders.
std::vector<bool> expectedShadow(const scene::Scene& s, const std::vector<Box>& occluders, int w, int h) {
    const scene::Light& light = s.lights[0];
    std::vector<bool> mask(static_cast<std::size_t>(w) * h, false);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Ray r = pixelRay(s.camera, x, y, w, h);
            const float tGround = -r.origin.y / r.direction.y;
            if (std::any_of(occluders.begin(), occluders.end(), [&](const Box& b) { return hit(b, r.origin, r.direction, 0.0f, tGround).has_value(); }))
                continue;  // sees an occluder: lit side
            const glm::vec3 g = r.origin + r.direction * tGround;
            glm::vec3 toLight = -light.direction;
            float maxT = 1e9f;
            if (light.type != scene::Light::Type::Directional) {
                toLight = light.position - g;
                maxT = glm::length(toLight);
                toLight /= maxT;
            }
            mask[static_cast<std::size_t>(y) * w + x] =
                std::any_of(occluders.begin(), occluders.end(), [&](const Box& b) { return hit(b, g, toLight, 1e-4f, maxT).has_value(); });
        }
    return mask;
}

std::vector<bool> expectedShadow(const scene::Scene& s, const Box& occluder, int w, int h) {
    return expectedShadow(s, std::vector<Box>{occluder}, w, h);
}

std::vector<bool> renderedShadow(const Frame& f) {
    std::vector<bool> mask(static_cast<std::size_t>(f.width) * f.height);
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) mask[static_cast<std::size_t>(y) * f.width + x] = f.at(x, y).r < 0.5f;
    return mask;
}

std::string sceneWith(const std::string& light, const std::string& occluder, const std::string& shadow = "{}") {
    return R"({
      "camera": { "position": [2, 12, 0], "target": [2, 0, 0], "up": [0, 0, -1], "fov_deg": 60, "near": 0.5, "far": 40 },
      "lights": [ )" + light.substr(0, light.size() - 1) + R"(, "shadow": )" + shadow + R"( } ],
      "objects": [
        { "shape": "plane", "size": [20, 20] },
        )" + occluder + R"(
      ] })";
}

const char* kSquare = R"({ "shape": "box", "size": [2, 0.02, 2], "position": [0, 2, 0] })";
const Box kSquareBox{{-1, 1.99f, -1}, {1, 2.01f, 1}};

struct LightCase {
    const char* name;
    const char* json;
};

class AnalyticShadow : public ::testing::TestWithParam<LightCase> {};

TEST_P(AnalyticShadow, QuadShadowCoversTheProjectedSquare) {
    scene::Scene s = sceneFromJson(sceneWith(GetParam().json, kSquare));
    const int w = 256, h = 256;
    const Frame f = renderChannel(s, OutputMode::Visibility, 0, w, h);
    const MaskComparison c = compareMasks(expectedShadow(s, kSquareBox, w, h), renderedShadow(f), w, h, 2);
    EXPECT_GT(c.expectedOn, 1000) << "the test scene must show a sizeable shadow";
    EXPECT_EQ(c.mismatchesAwayFromEdges, 0) << "pixels wrong by more than 2 px from the analytic edge";
    EXPECT_NEAR(c.renderedOn, c.expectedOn, 0.03 * c.expectedOn);
    EXPECT_EQ(gl::debugErrorCount(), 0);
}

INSTANTIATE_TEST_SUITE_P(
    LightTypes, AnalyticShadow,
    ::testing::Values(
        LightCase{"directional", R"({ "type": "directional", "direction": [2, -1, 0] })"},
        LightCase{"spot", R"({ "type": "spot", "position": [-4, 6, 0], "direction": [1, -1, 0], "angle_deg": 100 })"},
        LightCase{"point", R"({ "type": "point", "position": [-4, 6, 0] })"},
        LightCase{"point_close", R"({ "type": "point", "position": [-1.5, 3.5, 0.5] })"}),
    [](const auto& info) { return std::string(info.param.name); });

// Share of ground pixels that a lit plane shows as shadowed (it casts on nothing but itself). A
// plane whose shadow falls on no other surface is left out of the maps by default
// (RenderOptions::onlyCastersThatShadow), which no acne survives: drawn here, as every caster.
float acneShare(const std::string& shadow) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 6, 6], "target": [0, 0, 0], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [1, -0.6, 0.4], "shadow": )" + shadow + R"( } ],
      "objects": [ { "shape": "plane", "size": [12, 12] } ] })");
    render::RenderOptions options;
    options.output = OutputMode::Visibility;
    options.onlyCastersThatShadow = false;
    const Frame f = renderFrame(s, options, 200, 150);
    int covered = 0, dark = 0;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x) {
            if (f.alpha(x, y) < 0.5f) continue;  // background
            ++covered;
            dark += f.at(x, y).r < 0.5f;
        }
    EXPECT_GT(covered, 10000);
    return float(dark) / float(covered);
}

TEST(ShadowBias, NoBiasShowsAcneDefaultsShowNone) {
    const float unbiased = acneShare(R"({ "bias": 0, "slope_bias": 0, "normal_offset": 0, "polygon_offset": [0, 0] })");
    const float defaults = acneShare("{}");
    EXPECT_GT(unbiased, 0.10f) << "self-shadowing (acne) must be reproducible by turning the bias off";
    EXPECT_EQ(defaults, 0.0f) << "the default bias must remove acne entirely";
}

TEST(ShadowBias, LargeBiasDetachesTheShadow) {
    // A cube standing on the ground: with too much bias its shadow leaves the contact (Peter Panning).
    const char* cube = R"({ "shape": "box", "size": [1, 1, 1], "position": [0, 0.5, 0] })";
    const Box cubeBox{{-0.5f, 0, -0.5f}, {0.5f, 1, 0.5f}};
    const char* sun = R"({ "type": "directional", "direction": [1, -0.7, 0.3] })";
    const int w = 256, h = 256;

    scene::Scene good = sceneFromJson(sceneWith(sun, cube));
    const std::vector<bool> expected = expectedShadow(good, cubeBox, w, h);
    const MaskComparison ok = compareMasks(expected, renderedShadow(renderChannel(good, OutputMode::Visibility, 0, w, h)), w, h, 2);
    EXPECT_EQ(ok.mismatchesAwayFromEdges, 0);

    scene::Scene panning = sceneFromJson(sceneWith(sun, cube, R"({ "bias": 150 })"));
    const MaskComparison bad =
        compareMasks(expected, renderedShadow(renderChannel(panning, OutputMode::Visibility, 0, w, h)), w, h, 2);
    EXPECT_GT(bad.mismatchesAwayFromEdges, ok.expectedOn / 20) << "a 150-texel bias must open a visible gap; mismatches "
                                                                << bad.mismatches << " rendered " << bad.renderedOn
                                                                << " expected " << bad.expectedOn;
    EXPECT_LT(bad.renderedOn, ok.renderedOn);
}

// Light straight down through translucent panes (single surfaces) onto a white plane: the received light under
// the panes is the product of (1 - rho) over the layers, rho = (1 - t) * alpha (McGuire & Enderton 2011).
glm::vec3 lightUnderPanes(const std::vector<std::string>& materials) {
    std::string objects = R"({ "shape": "plane", "size": [20, 20] })";
    float y = 2.0f;
    for (const auto& m : materials) {
        objects += R"(, { "shape": "plane", "size": [3, 3], "position": [0, )" + std::to_string(y) +
                   R"(, 0], "material": )" + m + "}";
        y += 1.0f;
    }
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 12, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 40 },
      "lights": [ { "type": "directional", "direction": [0, -1, 0] } ],
      "objects": [ )" + objects + "] }");
    const Frame f = renderChannel(s, OutputMode::Visibility, 0, 64, 64);
    // The centre 8x8 pixels lie well inside every pane's footprint.
    glm::vec3 sum(0.0f);
    for (int y0 = 28; y0 < 36; ++y0)
        for (int x0 = 28; x0 < 36; ++x0) sum += f.at(x0, y0);
    return sum / 64.0f;
}

constexpr float kHalfFloatTolerance = 2e-3f;  // RGBA16F tint map: 11-bit mantissa

TEST(ColouredShadow, DeterministicTintMatchesTransmission) {
    const std::string glass = R"({ "alpha": 1, "transmission": [0.1, 0.9, 0.1] })";
    const glm::vec3 one = lightUnderPanes({glass});
    EXPECT_NEAR(one.r, 0.1f, kHalfFloatTolerance);
    EXPECT_NEAR(one.g, 0.9f, kHalfFloatTolerance);
    EXPECT_NEAR(one.b, 0.1f, kHalfFloatTolerance);
    const glm::vec3 two = lightUnderPanes({glass, glass});
    EXPECT_NEAR(two.r, 0.01f, kHalfFloatTolerance);
    EXPECT_NEAR(two.g, 0.81f, kHalfFloatTolerance);
    EXPECT_NEAR(two.b, 0.01f, kHalfFloatTolerance);
    const glm::vec3 nylon = lightUnderPanes({R"({ "alpha": 0.25, "transmission": [0.5, 0.5, 0.5] })"});
    EXPECT_NEAR(nylon.g, 0.875f, kHalfFloatTolerance);
    const glm::vec3 black = lightUnderPanes({R"({ "alpha": 0.25 })"});
    EXPECT_NEAR(black.g, 0.75f, kHalfFloatTolerance);
}


// Translucent receivers under the plain tint map (and CSSM's, which shares the division): the tint
// at a texel multiplies every translucent layer there, the receiver's own among them. Where
// ownLayersFrom knows that the receiver's own layers are all the tint holds behind it, they are
// divided out (shadow_filtering.glsl, tintThroughOwnLayers), leaving the light that reaches the
// receiver:
// - a grey pane (t = 0.5) lit through a green one: its own layer is the farthest, green x grey
//   divided by grey;
// - the lit top face of a grey glass slab (a closed box, 4 cm thick) lit through the green pane:
//   behind it lies the slab's bottom face, where the light leaves it, so green x grey x grey is
//   divided by grey twice.
// The receiver is turned 20 degrees, so its rim (as the light sees it) crosses the map's texels at
// every offset; the green pane is out of view. The visibility channel shows the nearest surface,
// panes included (RenderOptions::debugTranslucent), under a sun, a spot and a point light.
// Measured (llvmpipe, 96 x 96): every technique 0 pixels off under every light (CSSM under a point
// light was off by 0.0375 over the whole receiver while it counted texels there). The worst by the
// rim: 0.0001 for the nearest-filtered tint (hard, PCF, PCSS) and for CSSM under a point light (one
// texel, as they); CSSM, which counts texels where the 2 x 2 differ, 0.0094 under the sun and
// 0.053-0.056 (one pixel) under the spot; pcf-bilinear 0.0166 (spot) and 0.0867 (point,
// the slab): its 2 x 2 blend a texel where the light enters the slab through a side, whose own
// layers are not known, with its product of every layer. Before (one product of every layer):
// 0.45 (pane) and 0.675 (slab) off everywhere on the receiver; treating the slab as open (no
// closed parts): 0.675 off over its interior.
struct TranslucentReceiverCase {
    const char* technique;
    float rimTolerance;  // within 0.1 m of the receiver's rim (as the camera sees it)
};

class TranslucentReceiver : public ::testing::TestWithParam<TranslucentReceiverCase> {};

TEST_P(TranslucentReceiver, GetsTheGreenPaneInFrontOfItExactly) {
    const TranslucentReceiverCase c = GetParam();
    const std::string lights[3] = {
        R"({ "type": "directional", "direction": [1.5, -1, 0.1], "shadow": { "resolution": 512 } })",
        R"({ "type": "spot", "position": [-4.5, 3, -0.3], "direction": [1.5, -1, 0.1], "angle_deg": 40, "range": 20, "shadow": { "resolution": 512 } })",
        R"({ "type": "point", "position": [-4.5, 3, -0.3], "range": 20, "shadow": { "resolution": 512 } })"};
    const char* lightNames[3] = {"sun", "spot", "point"};
    const std::string receivers[2] = {
        R"({ "shape": "plane", "size": [0.9, 0.9], "rotation_deg": [0, 20, 0], "material": { "alpha": 1, "transmission": 0.5 } })",
        R"({ "shape": "box", "size": [0.9, 0.04, 0.9], "position": [0, -0.02, 0], "rotation_deg": [0, 20, 0], "material": { "alpha": 1, "transmission": 0.5 } })"};
    const glm::vec3 green(0.1f, 0.9f, 0.1f);
    for (int l = 0; l < 3; ++l)
        for (int r = 0; r < 2; ++r) {
            scene::Scene s = sceneFromJson(R"({
              "camera": { "position": [0, 4, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 20 },
              "lights": [ )" + lights[l] + R"( ],
              "objects": [ { "shape": "plane", "size": [1.6, 1.6], "position": [-1.5, 1, -0.1], "material": { "alpha": 1, "transmission": [0.1, 0.9, 0.1] } },
                           )" + receivers[r] + " ] }");
            render::RenderOptions options;
            options.technique = c.technique;
            options.output = OutputMode::Visibility;
            options.debugTranslucent = true;
            const Frame f = renderFrame(s, options, 96, 96);
            const glm::mat4 toReceiver = glm::inverse(s.objects[1].transformAt(0.0f));
            int interior = 0, interiorOff = 0, rim = 0, rimOff = 0;
            float worstInterior = 0.0f, worstRim = 0.0f;
            for (int y = 0; y < 96; ++y)
                for (int x = 0; x < 96; ++x) {
                    const Ray ray = pixelRay(s.camera, x, y, 96, 96);
                    const glm::vec3 p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);  // the lit face, y = 0
                    const glm::vec3 local = glm::vec3(toReceiver * glm::vec4(p, 1.0f));
                    const float inside = 0.45f - std::max(std::abs(local.x), std::abs(local.z));
                    if (inside < 0.003f) continue;  // off the receiver, or on its rim
                    const glm::vec3 d = glm::abs(f.at(x, y) - green);
                    const float off = std::max(d.x, std::max(d.y, d.z));
                    if (inside >= 0.1f) {
                        ++interior;
                        interiorOff += off > 1.5f / 255.0f;
                        worstInterior = std::max(worstInterior, off);
                    } else {
                        ++rim;
                        rimOff += off > c.rimTolerance;
                        worstRim = std::max(worstRim, off);
                    }
                }
            std::printf("%s, %s, %s: interior %d of %d off by > 1.5/255 (worst %.4f), by the rim %d of %d (worst %.4f)\n",
                        c.technique, lightNames[l], r == 0 ? "pane" : "slab", interiorOff, interior, worstInterior,
                        rimOff, rim, worstRim);
            EXPECT_GT(interior, 500);
            EXPECT_EQ(interiorOff, 0) << lightNames[l] << ", " << (r == 0 ? "pane" : "slab");
            EXPECT_EQ(rimOff, 0) << lightNames[l] << ", " << (r == 0 ? "pane" : "slab");
        }
}

INSTANTIATE_TEST_SUITE_P(Techniques, TranslucentReceiver,
                         ::testing::Values(TranslucentReceiverCase{"hard", 1.5f / 255.0f},
                                           TranslucentReceiverCase{"pcf-poisson16", 1.5f / 255.0f},
                                           TranslucentReceiverCase{"pcss", 1.5f / 255.0f},
                                           TranslucentReceiverCase{"pcf-bilinear", 0.1f},
                                           TranslucentReceiverCase{"cssm1", 0.06f},
                                           TranslucentReceiverCase{"cssm2", 0.06f}),
                         [](const auto& info) { return testNameOf(info.param.technique); });

// A camera panning over two grounds, together far wider than its view, so that the view, not the
// scene, bounds the sun's box. Held (RenderOptions::holdSunBox), the box moves, and so the sun's
// map is drawn again, in a few frames; fitted afresh each frame, in most. In every frame, either
// way, the squares' shadows cover the pixels the rays say (±2 px). The second ground and its
// square come into view during the pan, 5 m past the first: cascades draw only the texels their
// slices' surfaces read (fit_receivers), so the second's must be drawn into a held layer then.
struct PanResult {
    int mapsDrawn = 0;
    float coarsestTexel = 0.0f, finestTexel = 1e9f;
};

// The sun's texel: the plain box's or the cascades' (LightSpace), or where the camera looks, a
// warped map's (LiSPSM, PSM).
float sunTexel(const render::Renderer& renderer, const scene::Scene& s) {
    if (const auto* warped = dynamic_cast<const shadows::WarpedShadowMap*>(&renderer.technique()))
        return shadows::warpedTexelWorld(warped->views().at(0).shadowMatrix, s.camera.target, s.lights[0].direction,
                                         s.lights[0].shadow.resolution);
    return renderer.lightSpaces().at(0).texelScale;
}

PanResult panOverTheSquares(const std::string& technique, bool holdSunBox, int frames, float startZ = -5.0f, float step = 0.5f) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [2, 12, -5], "target": [2, 0, -5], "up": [0, 0, -1], "fov_deg": 60, "near": 0.5, "far": 40 },
      "lights": [ { "type": "directional", "direction": [1, -1, 0], "shadow": { "resolution": 512 } } ],
      "objects": [ { "shape": "plane", "size": [200, 200], "position": [0, 0, -98] }, )" + std::string(kSquare) + R"(,
                   { "shape": "plane", "size": [200, 200], "position": [0, 0, 107] },
                   { "shape": "box", "size": [2, 0.02, 2], "position": [0, 2, 8.2] } ] })");
    const std::vector<Box> squares{kSquareBox, {{-1, 1.99f, 7.2f}, {1, 2.01f, 9.2f}}};
    render::RenderOptions options = optionsFor(technique);
    options.output = OutputMode::Visibility;
    options.holdSunBox = holdSunBox;
    render::Renderer renderer(s, options);
    const int w = 128, h = 128;
    render::OffscreenTarget target(w, h);
    PanResult result;
    for (int frame = 0; frame < frames; ++frame) {
        s.camera.position.z = s.camera.target.z = startZ + step * static_cast<float>(frame);
        renderer.render(0.0f, s.camera, w, h, target.framebuffer());
        result.mapsDrawn += frame > 0 && renderer.shadowTriangles().at(0) > 0;
        const Frame f{w, h, renderer.readLinear()};
        std::vector<bool> expected = expectedShadow(s, squares, w, h), rendered = renderedShadow(f);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const Ray r = pixelRay(s.camera, x, y, w, h);
                const float z = r.origin.z + r.direction.z * (-r.origin.y / r.direction.y);
                if (z > 2.0f && z < 7.0f) expected[static_cast<std::size_t>(y) * w + x] = rendered[static_cast<std::size_t>(y) * w + x];  // the gap
            }
        const MaskComparison c = compareMasks(expected, rendered, w, h, 2);
        EXPECT_GT(c.expectedOn, 300) << "frame " << frame;
        EXPECT_EQ(c.mismatchesAwayFromEdges, 0) << "frame " << frame << (holdSunBox ? ", held box" : ", fitted box");
        const float texel = sunTexel(renderer, s);
        result.coarsestTexel = std::max(result.coarsestTexel, texel);
        result.finestTexel = std::min(result.finestTexel, texel);
    }
    return result;
}

class SunBox : public ::testing::TestWithParam<const char*> {};

TEST_P(SunBox, AHeldBoxIsDrawnAgainEveryFewFramesOfAPanAndShadowsWhereRaysSay) {
    const int frames = 21;
    const PanResult fitted = panOverTheSquares(GetParam(), false, frames), held = panOverTheSquares(GetParam(), true, frames);  // 5 texels a frame
    std::printf("%s, 20 pan frames: the sun's map drawn in %d (boxes fitted each frame), %d (held); texel %.4f-%.4f "
                "against %.4f-%.4f m\n", GetParam(), fitted.mapsDrawn, held.mapsDrawn, held.finestTexel, held.coarsestTexel,
                fitted.finestTexel, fitted.coarsestTexel);
    EXPECT_GE(fitted.mapsDrawn, 10) << "the pan must move a fitted box in most frames";
    EXPECT_LE(held.mapsDrawn * 2, fitted.mapsDrawn) << "held, in half the frames or fewer (cascaded: any of four boxes)";
    // What holding costs: at most a step of the size ladder and the slack over a fitted box.
    EXPECT_LE(held.coarsestTexel, fitted.coarsestTexel * shadows::kHeldCoarser * 1.001f);
    EXPECT_EQ(gl::debugErrorCount(), 0);
}

// A slower pan, 1.5 m in all, which cascades' held boxes follow only every several frames: the second
// ground and square come into view of layers that are kept, and must be drawn into them
// (LayeredDepthMap draws a layer again when the texels read leave those it drew last).
TEST(HeldCascades, DrawWhatComesIntoView) {
    const int frames = 31;
    const PanResult fitted = panOverTheSquares("cascaded", false, frames, -0.5f, 0.05f);
    const PanResult held = panOverTheSquares("cascaded", true, frames, -0.5f, 0.05f);
    std::printf("cascaded, 30 frames of 0.05 m: maps drawn in %d (fitted), %d (held)\n", fitted.mapsDrawn, held.mapsDrawn);
    EXPECT_LT(held.mapsDrawn, fitted.mapsDrawn);
    EXPECT_EQ(gl::debugErrorCount(), 0);
}

// hard: the plain map's box (LightSpace); cascaded: each cascade's (fitCascade), kept layer by layer.
INSTANTIATE_TEST_SUITE_P(Techniques, SunBox, ::testing::Values("hard", "cascaded"));

// LiSPSM's and PSM's views (followWarpedView) over the slow pan: a warp follows the view closely,
// so a pan of 5 texels a frame moves it in most frames either way (15 of 20 held), but one of half
// a texel, as a walk would, every few. Every frame's shadows lie where the rays say.
TEST(HeldWarps, AreDrawnAgainEveryFewFramesOfASlowPanAndShadowWhereRaysSay) {
    for (const char* technique : {"lispsm", "psm"}) {
        const int frames = 31;
        const PanResult fitted = panOverTheSquares(technique, false, frames, -0.5f, 0.05f);
        const PanResult held = panOverTheSquares(technique, true, frames, -0.5f, 0.05f);
        std::printf("%s, 30 frames of 0.05 m: maps drawn in %d (fitted), %d (held); texel where the camera looks %.4f-%.4f "
                    "against %.4f-%.4f m\n", technique, fitted.mapsDrawn, held.mapsDrawn, held.finestTexel, held.coarsestTexel,
                    fitted.finestTexel, fitted.coarsestTexel);
        EXPECT_EQ(fitted.mapsDrawn, frames - 1) << technique << ": fitted, the view moves in every frame";
        EXPECT_LE(held.mapsDrawn * 3, fitted.mapsDrawn) << technique;
        EXPECT_LE(held.coarsestTexel, fitted.coarsestTexel * shadows::kHeldCoarser * 1.001f) << technique;
    }
    EXPECT_EQ(gl::debugErrorCount(), 0);
}

}  // namespace
}  // namespace penumbra::test
