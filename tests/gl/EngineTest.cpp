// Engine behaviour seen in pixels: projector pictures, moving shadows, fog, missing textures,
// shader errors, degenerate sizes, and a clean KHR_debug log for every technique and light.
#include "GlTestSupport.h"

#include "gl/Debug.h"
#include "gl/Program.h"
#include "render/Offscreen.h"
#include "util/Log.h"

#include <fstream>

namespace penumbra::test {
namespace {

using render::OutputMode;

glm::vec3 srgbToLinear(glm::vec3 c) {
    for (int i = 0; i < 3; ++i) c[i] = c[i] <= 0.04045f ? c[i] / 12.92f : std::pow((c[i] + 0.055f) / 1.055f, 2.4f);
    return c;
}

TEST(Projector, PicturesLandUprightAndShadowsCutThem) {
    // A projector straight down onto a white plane, no ambient: the lit colour is the picture.
    // A small box in the beam blocks part of it.
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 10, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 40 },
      "ambient": [0, 0, 0],
      "lights": [ { "type": "projector", "position": [0, 6, 0], "direction": [0, -1, 0], "angle_deg": 40,
                    "image": "quadrants.png" } ],
      "objects": [ { "shape": "plane", "size": [20, 20], "material": { "diffuse": [1, 1, 1], "specular": [0, 0, 0] } },
                   { "shape": "box", "size": [0.3, 0.3, 0.3], "position": [1.0, 3.0, 1.0],
                     "material": { "diffuse": [0, 0, 0], "specular": [0, 0, 0] } } ] })");
    const int n = 128;
    const Frame f = renderChannel(s, OutputMode::Shaded, 0, n, n);
    // Where does each quadrant land? The projector's shadow matrix says: sample the four
    // quadrant centres of the picture's projection, found from the same matrix the engine uses.
    const shadows::LightSpace ls = shadows::computeLightSpace(s.lights[0], 256, s.boundsAt(0), s.camera, 1.0f);
    auto colourAtPictureUv = [&](float u, float vTop) {
        // Ground point whose projector uv is (u, 1 - vTop) (image rows run top to bottom).
        const glm::mat4 inv = glm::inverse(ls.shadowMatrix);
        glm::vec4 a = inv * glm::vec4(u, 1.0f - vTop, 0.0f, 1.0f), b = inv * glm::vec4(u, 1.0f - vTop, 1.0f, 1.0f);
        a /= a.w;
        b /= b.w;
        const glm::vec3 g = glm::vec3(a) + (glm::vec3(b) - glm::vec3(a)) * (a.y / (a.y - b.y));
        const glm::vec4 clip = s.camera.projection(1.0f) * s.camera.view() * glm::vec4(g, 1.0f);
        const glm::vec2 px = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * float(n);
        // Divide out Lambert's cosine: what is left is the picture's colour.
        const float NdotL = glm::normalize(s.lights[0].position - g).y;
        return f.at(int(px.x), int(px.y)) / NdotL;
    };
    auto near = [](glm::vec3 a, glm::vec3 b) { return glm::all(glm::lessThan(glm::abs(a - b), glm::vec3(0.02f))); };
    EXPECT_TRUE(near(colourAtPictureUv(0.25f, 0.25f), {1, 0, 0})) << "top-left of the picture is red";
    EXPECT_TRUE(near(colourAtPictureUv(0.75f, 0.25f), {0, 1, 0})) << "top-right is green";
    EXPECT_TRUE(near(colourAtPictureUv(0.25f, 0.75f), {0, 0, 1})) << "bottom-left is blue";
    // The box at (1, 3, 1) shadows the ground around (2, 0, 2) (from (0,6,0) through the box, doubled).
    const glm::vec4 clip = s.camera.projection(1.0f) * s.camera.view() * glm::vec4(2.0f, 0.0f, 2.0f, 1.0f);
    const glm::vec2 px = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * float(n);
    EXPECT_LT(glm::length(f.at(int(px.x), int(px.y))), 0.02f) << "the caster's shadow cuts the picture";
    // Outside the projector's frame: no light at all.
    EXPECT_LT(glm::length(f.at(2, 2)), 0.02f);
}

// The ground under a moving sphere: the shadow must follow it (maps re-rendered every frame).
TEST(Animation, ShadowFollowsTheMovingCaster) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 12, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [0, -1, 2] } ],
      "objects": [ { "shape": "plane", "size": [20, 20] },
                   { "shape": "sphere", "radius": 0.6, "animation": [[0, -3, 1, 0], [1, 3, 1, 0], [2, -3, 1, 0]] } ] })");
    render::RenderOptions options;
    options.output = OutputMode::Visibility;
    render::Renderer renderer(s, options);
    render::OffscreenTarget target(96, 96);
    auto shadowCentroidX = [&](float t) {
        renderer.render(t, s.camera, 96, 96, target.framebuffer());
        const Frame f{96, 96, renderer.readLinear()};
        double sum = 0;
        int count = 0;
        for (int y = 0; y < 96; ++y)
            for (int x = 0; x < 96; ++x)
                if (f.at(x, y).r < 0.5f) { sum += x; ++count; }
        EXPECT_GT(count, 20);
        return count ? sum / count : -1.0;
    };
    const double left = shadowCentroidX(0.0f), right = shadowCentroidX(1.0f);
    // 6 world units apart at ~0.117 units per pixel (12 * tan(25°) * 2 / 96).
    EXPECT_NEAR(right - left, 6.0 / (2 * 12 * std::tan(glm::radians(25.0)) / 96), 2.0);
}

// The lighting program is specialised to the lights' types and shadow slots: lights edited
// between frames (a shadow switched on, a light added, a light retyped) must rebuild it, and the
// frame must follow. A slab at height 2 over x in [-4, -2] shadows the ground at x = -1 (pixel
// 40 of 96 at ~8.6 px per unit) under a sun leaning towards +x, and under a light at (-5, 6, 0).
TEST(LightLayout, LightsEditedBetweenFramesRebuildTheLighting) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 12, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [1, -1, 0], "shadow": { "enabled": false } } ],
      "objects": [ { "shape": "plane", "size": [20, 20] }, { "shape": "box", "size": [2, 0.2, 2], "position": [-3, 2, 0] } ] })");
    const scene::Scene second = sceneFromJson(R"({ "lights": [
      { "type": "spot", "position": [-5, 6, 0], "direction": [0, -1, 0], "angle_deg": 120, "range": 30 } ],
      "objects": [ { "shape": "box" } ] })");
    render::Renderer renderer(s, {});
    render::OffscreenTarget target(96, 96);
    // Shadow visibility of `light` on the ground at x = -1 (in the slab's shadow) and x = +2.
    auto visibility = [&](int light) {
        renderer.setOutputMode(OutputMode::Visibility, light);
        renderer.render(0.0f, s.camera, 96, 96, target.framebuffer());
        const Frame f{96, 96, renderer.readLinear()};
        return std::pair{f.at(40, 48).r, f.at(65, 48).r};
    };
    EXPECT_EQ(visibility(0), std::pair(1.0f, 1.0f)) << "the sun casts no shadow yet";
    s.lights[0].shadow.enabled = true;
    EXPECT_EQ(visibility(0), std::pair(0.0f, 1.0f)) << "its shadow switched on";
    s.lights.push_back(second.lights.front());
    EXPECT_EQ(visibility(1), std::pair(0.0f, 1.0f)) << "a spot light added";
    EXPECT_EQ(visibility(0), std::pair(0.0f, 1.0f)) << "the sun keeps its shadow beside it";
    s.lights[1].type = scene::Light::Type::Point;
    EXPECT_EQ(visibility(1), std::pair(0.0f, 1.0f)) << "the spot turned into a point light (a cube map)";
}

// Shaded builds of the lighting program hold no debug channel (DEBUG_OUTPUT): a channel chosen
// between frames must rebuild them and show what it names, and going back to the shaded frame
// must give its pixels again, bit for bit.
TEST(LightLayout, ADebugChannelChosenBetweenFramesIsShownAndLeftAgain) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 6, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 50 },
      "ambient": [0.25, 0.5, 1.0],
      "lights": [ { "type": "directional", "direction": [0.3, -1, 0.2] } ],
      "objects": [ { "shape": "plane", "size": [20, 20], "material": { "diffuse": [0.8, 0.4, 0.2] } } ] })");
    render::Renderer renderer(s, {});
    render::OffscreenTarget target(32, 32);
    auto frame = [&](OutputMode mode) {
        renderer.setOutputMode(mode, 0);
        renderer.render(0.0f, s.camera, 32, 32, target.framebuffer());
        return Frame{32, 32, renderer.readLinear()};
    };
    const Frame shaded = frame(OutputMode::Shaded);
    const glm::vec3 ambient = frame(OutputMode::Ambient).at(16, 16), normal = frame(OutputMode::Normal).at(16, 16);
    EXPECT_NEAR(ambient.r, 0.2f, 1e-5f);  // ambient x diffuse
    EXPECT_NEAR(ambient.g, 0.2f, 1e-5f);
    EXPECT_NEAR(ambient.b, 0.2f, 1e-5f);
    EXPECT_NEAR(normal.g, 1.0f, 1e-5f) << "the ground's normal";
    EXPECT_GT(shaded.at(16, 16).r, ambient.r + 0.1f) << "the sun lights the ground in the shaded frame";
    EXPECT_EQ(frame(OutputMode::Shaded).rgba, shaded.rgba);
}

// A program for a scene without translucent casters leaves the tint lookups out
// (SCENE_TRANSLUCENT_CASTERS 0): a slab made green glass between frames must rebuild it and tint
// its shadow, t² = (0.01, 0.81, 0.01) through the slab's two faces, and turn it back to a black
// shadow when made opaque again.
TEST(LightLayout, CastersTurnedTranslucentBetweenFramesTintTheirShadow) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 12, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [1, -1, 0] } ],
      "objects": [ { "shape": "plane", "size": [20, 20] },
                   { "shape": "box", "size": [2, 0.2, 2], "position": [-3, 2, 0], "material": { "diffuse": [1, 1, 1] } } ] })");
    ASSERT_GE(s.objects[1].materialOverride, 0);
    scene::Material& slab = s.materials[static_cast<std::size_t>(s.objects[1].materialOverride)];
    for (const char* technique : {"hard", "pcf-poisson16"}) {
        render::RenderOptions options;
        options.technique = technique;
        render::Renderer renderer(s, options);
        render::OffscreenTarget target(96, 96);
        auto visibility = [&]() {  // on the ground at x = -1 (in the slab's shadow) and x = +2
            renderer.setOutputMode(OutputMode::Visibility, 0);
            renderer.render(0.0f, s.camera, 96, 96, target.framebuffer());
            const Frame f{96, 96, renderer.readLinear()};
            return std::pair{f.at(40, 48), f.at(65, 48)};
        };
        slab.transmission = glm::vec3(0.0f);
        auto [shadowed, lit] = visibility();
        EXPECT_LT(glm::length(shadowed), 1e-3f) << technique << ": opaque slab";
        EXPECT_NEAR(lit.g, 1.0f, 1e-3f) << technique;
        slab.transmission = glm::vec3(0.1f, 0.9f, 0.1f);
        std::tie(shadowed, lit) = visibility();
        EXPECT_NEAR(shadowed.r, 0.01f, 2.0f / 255) << technique << ": green glass";
        EXPECT_NEAR(shadowed.g, 0.81f, 2.0f / 255) << technique << ": green glass";
        EXPECT_NEAR(shadowed.b, 0.01f, 2.0f / 255) << technique << ": green glass";
        slab.transmission = glm::vec3(0.0f);
        std::tie(shadowed, lit) = visibility();
        EXPECT_LT(glm::length(shadowed), 1e-3f) << technique << ": opaque again";
    }
}

// Two opaque-textured plates over the ground, one cut at 0.5 (every texel kept) and one at 1.1
// (every texel a hole), 2 units up, seen from above (~8.6 px per unit over 96 px: x = -4 is
// pixel 14, x = 0 pixel 48, x = +2 pixel 65). Under a sun at 45 degrees towards +x, their
// shadows fall clear of them, around x = -2 (pixel 31) and x = +4 (pixel 82).
scene::Scene alphaTestedPlates() {
    return sceneFromJson(R"({
      "camera": { "position": [0, 12, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [1, -1, 0] } ],
      "objects": [ { "shape": "plane", "size": [20, 20] },
        { "shape": "plane", "size": [2, 2], "position": [-4, 2, 0], "material": { "texture": "quadrants.png", "alpha_cutoff": 0.5 } },
        { "shape": "plane", "size": [2, 2], "position": [2, 2, 0], "material": { "texture": "quadrants.png", "alpha_cutoff": 1.1 } } ] })");
}

// Alpha-tested casters go through their own depth program (DepthCasterProgram: the plain one
// has no alpha test at all), in every kind of map.
class AlphaTestedCasters : public ::testing::TestWithParam<const char*> {};

TEST_P(AlphaTestedCasters, CutOutTexelsCastNoShadow) {
    scene::Scene s = alphaTestedPlates();
    const Frame f = renderChannel(s, OutputMode::Visibility, 0, 96, 96, GetParam());
    EXPECT_LT(f.at(31, 48).r, 0.1f) << "the kept plate shadows the ground";
    EXPECT_NEAR(f.at(82, 48).r, 1.0f, 0.05f) << "the all-holes plate casts nothing";
    EXPECT_NEAR(f.at(48, 48).r, 1.0f, 0.05f) << "open ground";
}

// One technique per kind of depth map: DepthAndTintMaps, LayeredDepthMap, moment maps.
INSTANTIATE_TEST_SUITE_P(EveryDepthMap, AlphaTestedCasters, ::testing::Values("hard", "cascaded", "vsm"));

// The camera sees through cut-out texels too: only materials with a cutoff get the lighting
// build with the alpha test (LightingPrograms: the others have no `discard`). World position
// channel: height 2 on the kept plate, the ground's 0 through the all-holes one.
TEST(AlphaTestedSurfaces, TheCameraSeesThroughTheirHoles) {
    scene::Scene s = alphaTestedPlates();
    const Frame f = renderChannel(s, OutputMode::WorldPosition, 0, 96, 96);
    EXPECT_NEAR(f.at(14, 48).g, 2.0f, 0.01f) << "the kept plate";
    EXPECT_NEAR(f.at(65, 48).g, 0.0f, 0.01f) << "the ground through the all-holes plate";
    EXPECT_NEAR(f.at(65, 48).r, 2.0f, 0.15f) << "the ground below the all-holes plate's centre";
}

// A translucent caster's texture alpha weighs the light it stops (coverage, McGuire & Enderton
// 2011): the tint pass draws textured materials with the build that samples their texture, and
// only untextured ones with the build that leaves the sample out (TintCasterProgram). The plate
// has no transmission, so a kept texel (alpha 1) stops all light and a cut one (alpha 0) none;
// left_half_cut.png's columns make stripes along z, which the sun (along +x) casts unchanged.
class TexturedTranslucentCasters : public ::testing::TestWithParam<const char*> {};

// The plate's stripes on the ground, the sun's visibility as `technique` draws it. Ground x = -2
// is pixel 30; z = -0.76 is pixel 54 (u = 0.24, a cut texel), z = -0.29 pixel 50 (u = 0.71,
// bilinearly 0.92 of a kept texel: 0.08 of the light passes); pixel 70 is open ground.
void expectPlateStripes(const std::string& technique, float tolerance, const shadows::ParameterValues& parameters = {}) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 12, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [1, -1, 0] } ],
      "objects": [ { "shape": "plane", "size": [20, 20] },
        { "shape": "plane", "size": [2, 2], "position": [-4, 2, 0], "material": { "texture": "left_half_cut.png" } } ] })");
    const Frame f = renderChannel(s, OutputMode::Visibility, 0, 96, 96, technique, parameters);
    EXPECT_NEAR(f.at(30, 54).r, 1.0f, tolerance) << "under a cut texel";
    EXPECT_NEAR(f.at(30, 50).r, 0.08f, tolerance) << "under a kept texel";
    EXPECT_NEAR(f.at(70, 48).r, 1.0f, 0.05f) << "open ground";
}

TEST_P(TexturedTranslucentCasters, TheirTextureAlphaWeighsTheLightTheyStop) { expectPlateStripes(GetParam(), 0.05f); }

INSTANTIATE_TEST_SUITE_P(TintMaps, TexturedTranslucentCasters, ::testing::Values("hard", "cascaded", "vsm", "cssm2"));

// The same through CSSM's own colour map: with tint_behind_all off, the ground reads the
// stochastic layers the casters drew (ColoredStochasticShadowMap::buildCasters' textured build),
// not the tint map's product. The box filter's 8 x 8 tiles soften the stripes (0.94 and 0.07; a
// build that ignored the texture drew every texel as kept: 0 under the whole plate).
TEST(TexturedTranslucentCasters, TheirTextureAlphaWeighsTheStochasticLayers) {
    expectPlateStripes("cssm2", 0.1f, {{"tint_behind_all", "false"}});
}

// The depth pre-pass (RenderOptions::depthPrepass) shades each visible pixel once and must
// change no pixel: overdraw (a sphere behind a box), a plate whose every texel is alpha-tested
// away in front of both (the pre-pass must leave its holes too), a green pane (translucent pass
// against the pre-pass's depth), and techniques whose lookups differ in kind.
class DepthPrepass : public ::testing::TestWithParam<const char*> {};

TEST_P(DepthPrepass, ChangesNoPixel) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 4, 7], "target": [0, 0.5, 0], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [-0.4, -1, -0.3], "size": 0.5, "shadow": { "resolution": 512 } },
                  { "type": "point", "position": [2, 3, 2], "intensity": 0.5, "shadow": { "resolution": 256 } } ],
      "objects": [ { "shape": "plane", "size": [12, 12] },
        { "shape": "sphere", "radius": 0.8, "position": [0, 0.8, -1.5] },
        { "shape": "box", "size": [1.5, 1.5, 1.5], "position": [0, 0.75, 0] },
        { "shape": "plane", "size": [3, 3], "position": [0, 1.5, 2], "rotation_deg": [90, 0, 0],
          "material": { "texture": "quadrants.png", "alpha_cutoff": 1.1 } },
        { "shape": "plane", "size": [1, 1], "position": [1.5, 1.2, 1], "rotation_deg": [90, 0, 0],
          "material": { "transmission": [0.1, 0.9, 0.1] } } ] })");
    render::RenderOptions options{.technique = GetParam()};
    const std::vector<std::uint8_t> shaded = renderRgba8(s, options, 160, 120);
    options.depthPrepass = true;
    const std::vector<std::uint8_t> prepassed = renderRgba8(s, options, 160, 120);
    ASSERT_EQ(shaded.size(), prepassed.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < shaded.size(); ++i) differing += shaded[i] != prepassed[i];
    EXPECT_EQ(differing, 0u) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Techniques, DepthPrepass, ::testing::Values("hard", "pcss", "cssm2", "shadow-volumes"));

// A material with specular (0, 0, 0) is shaded by a build without Blinn-Phong's highlight
// (LightingPrograms, MATERIAL_NO_SPECULAR). It must change no pixel: against a specular of 1e-30,
// which takes the full build and adds nothing a float can hold beside the diffuse light, every
// byte is the same, for an opaque sphere and a glass pane in front of it. A specular material
// beside them still shines: the specialisation must not reach it.
TEST(Lighting, AMaterialWithoutSpecularLosesOnlyAHighlightOfZero) {
    const auto sceneWith = [](const std::string& specular) {
        return sceneFromJson(R"({
          "camera": { "position": [0, 1.5, 5], "target": [0, 0.8, 0], "fov_deg": 45 },
          "ambient": [0.05, 0.05, 0.05],
          "lights": [ { "type": "directional", "direction": [-0.3, -0.6, -0.75], "shadow": { "resolution": 512 } } ],
          "objects": [ { "shape": "plane", "size": [10, 10], "material": { "specular": )" + specular + R"( } },
            { "shape": "sphere", "radius": 0.8, "position": [0, 0.8, 0],
              "material": { "diffuse": [0.2, 0.2, 0.2], "specular": )" + specular + R"(, "shininess": 20 } },
            { "shape": "plane", "size": [1, 1], "position": [1.2, 1.0, 1.5], "rotation_deg": [90, 0, 0],
              "material": { "specular": )" + specular + R"(, "transmission": [0.1, 0.9, 0.1] } } ] })");
    };
    const render::RenderOptions options{.technique = "hard"};
    scene::Scene none = sceneWith("[0, 0, 0]"), tiny = sceneWith("[1e-30, 1e-30, 1e-30]"), shiny = sceneWith("[0.5, 0.5, 0.5]");
    const std::vector<std::uint8_t> withoutHighlight = renderRgba8(none, options, 160, 120);
    const std::vector<std::uint8_t> fullBuild = renderRgba8(tiny, options, 160, 120);
    const std::vector<std::uint8_t> highlighted = renderRgba8(shiny, options, 160, 120);
    ASSERT_EQ(withoutHighlight.size(), fullBuild.size());
    std::size_t differing = 0;
    int brightest = 0;
    for (std::size_t i = 0; i < withoutHighlight.size(); ++i) {
        differing += withoutHighlight[i] != fullBuild[i];
        brightest = std::max(brightest, int(highlighted[i]) - int(withoutHighlight[i]));
    }
    EXPECT_EQ(differing, 0u);
    EXPECT_GE(brightest, 60) << "the specular sphere's highlight (bytes above the same without specular)";
}

TEST(Fog, FarSurfacesFadeToTheBackground) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 1, 0], "target": [0, 1, -1], "fov_deg": 60, "far": 100 },
      "background": [0.2, 0.4, 0.8], "ambient": [1, 1, 1], "fog": { "start": 10, "end": 40 },
      "objects": [ { "shape": "box", "size": [2, 2, 0.1], "position": [0, 1, -5], "material": { "diffuse": [1, 0, 0] } },
                   { "shape": "box", "size": [400, 400, 0.1], "position": [0, 1, -60], "material": { "diffuse": [1, 0, 0] } } ] })");
    render::Renderer renderer(s);
    render::OffscreenTarget target(64, 64);
    renderer.render(0, s.camera, 64, 64, target.framebuffer());
    const auto pixels = target.readRgba8();  // image order, sRGB
    auto rgb = [&](int x, int y) {
        const std::size_t i = (static_cast<std::size_t>(y) * 64 + x) * 4;
        return srgbToLinear(glm::vec3(pixels[i], pixels[i + 1], pixels[i + 2]) / 255.0f);
    };
    const glm::vec3 nearBox = rgb(32, 32), farWall = rgb(2, 2);
    EXPECT_NEAR(nearBox.r, 1.0f, 0.01f);
    EXPECT_NEAR(nearBox.b, 0.0f, 0.01f);
    EXPECT_NEAR(farWall.r, 0.2f, 0.02f) << "beyond fog end the colour is the background";
    EXPECT_NEAR(farWall.b, 0.8f, 0.02f);
}

// Fog goes by the distance along each pixel's ray, not by view depth: a wall facing the camera at
// view depth 20 is fogged more at the image's corners (distance up to 20 * 1.29) than at its centre.
TEST(Fog, FollowsTheDistanceAlongEachPixelsRay) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 0, 0], "target": [0, 0, -1], "fov_deg": 60, "near": 0.5, "far": 100 },
      "background": [0.2, 0.4, 0.8], "ambient": [1, 1, 1], "fog": { "start": 10, "end": 40 },
      "objects": [ { "shape": "box", "size": [200, 200, 0.1], "position": [0, 0, -20.05], "material": { "diffuse": [1, 0, 0] } } ] })");
    render::Renderer renderer(s);
    render::OffscreenTarget target(64, 64);
    renderer.render(0, s.camera, 64, 64, target.framebuffer());
    const auto pixels = target.readRgba8();  // image order, sRGB
    const float slope = std::tan(glm::radians(30.0f));
    for (const glm::ivec2 p : {glm::ivec2(32, 32), glm::ivec2(0, 0), glm::ivec2(63, 5), glm::ivec2(10, 50)}) {
        const glm::vec2 ndc = (glm::vec2(p) + 0.5f) / 32.0f - 1.0f;
        const float distance = 20.0f * std::sqrt(1.0f + glm::dot(ndc * slope, ndc * slope));
        const glm::vec3 expected = glm::mix(glm::vec3(1, 0, 0), glm::vec3(0.2f, 0.4f, 0.8f), glm::smoothstep(10.0f, 40.0f, distance));
        const std::size_t i = (static_cast<std::size_t>(p.y) * 64 + p.x) * 4;
        const glm::vec3 got = srgbToLinear(glm::vec3(pixels[i], pixels[i + 1], pixels[i + 2]) / 255.0f);
        EXPECT_NEAR(got.r, expected.r, 0.01f) << "pixel " << p.x << "," << p.y << " at distance " << distance;
        EXPECT_NEAR(got.b, expected.b, 0.01f) << "pixel " << p.x << "," << p.y << " at distance " << distance;
    }
}

TEST(BadInput, MissingTextureRendersAVisibleChecker) {
    log::takeWarnings();
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 5, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 40 },
      "ambient": [1, 1, 1],
      "objects": [ { "shape": "plane", "size": [4, 4], "material": { "diffuse": [1, 1, 1], "texture": "gone.png" } } ] })");
    EXPECT_FALSE(log::takeWarnings().empty());
    const Frame f = renderChannel(s, OutputMode::Shaded, 0, 64, 64);
    int magenta = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const glm::vec3 c = f.at(x, y);
            magenta += c.r > 0.5f && c.g < 0.05f && c.b > 0.5f;
        }
    EXPECT_GT(magenta, 64 * 64 / 5) << "the fallback must be visible, not silently white";
}

TEST(BadInput, ShaderCompileErrorNamesFileAndLine) {
    const std::string path = std::string(PENUMBRA_TEST_DATA) + "/bad_shader.frag";
    try {
        gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = path});
        FAIL() << "a broken shader compiled";
    } catch (const gl::ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("bad_shader.frag:3"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("undefinedThing"), std::string::npos) << e.what();
    }
    try {
        gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = "shaders/no_such_file.frag"});
        FAIL() << "a missing shader compiled";
    } catch (const gl::ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("no_such_file.frag"), std::string::npos) << e.what();
    }
}

TEST(BadInput, IncludedFileErrorsPointIntoTheIncludedFile) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "penumbra_include_test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "helper.glsl") << "// helper\nfloat helper() {\n  return missingSymbol;\n}\n";
    std::ofstream(dir / "main.frag") << "#version 450 core\n#include \"helper.glsl\"\nout vec4 c;\nvoid main() { c = vec4(helper()); }\n";
    try {
        gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = dir / "main.frag"});
        FAIL();
    } catch (const gl::ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("helper.glsl:3"), std::string::npos) << e.what();
    }
}

TEST(BadInput, ZeroSizedFrameIsSkipped) {
    scene::Scene s = sceneFromJson(R"({ "lights": [ { "type": "directional", "direction": [0, -1, 0] } ],
                                        "objects": [ { "shape": "box" } ] })");
    render::Renderer renderer(s);
    gl::resetDebugErrorCount();
    EXPECT_NO_THROW(renderer.render(0, s.camera, 0, 0, 0));
    EXPECT_NO_THROW(renderer.render(0, s.camera, 0, 480, 0));
    EXPECT_EQ(gl::debugErrorCount(), 0);
}

// A driver repeats a warning every frame while its cause lasts: the log shows it three times and
// says the rest are counted; the count and the hook (tests' failures) see every one.
TEST(DriverMessages, ARepeatedMessageIsLoggedThreeTimesAndCountedEveryTime) {
    const gl::DebugMessageHook tests = gl::setDebugMessageHook(nullptr);
    const int before = gl::debugWarningCount();
    const std::string text = "penumbra test: the same driver message, again";
    ::testing::internal::CaptureStderr();
    for (int i = 0; i < 10; ++i)
        glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_PORTABILITY, 7, GL_DEBUG_SEVERITY_MEDIUM, -1, text.c_str());
    const std::string logged = ::testing::internal::GetCapturedStderr();
    gl::setDebugMessageHook(tests);
    std::size_t shown = 0;
    for (std::size_t at = logged.find(text); at != std::string::npos; at = logged.find(text, at + 1)) ++shown;
    EXPECT_EQ(shown, 3u) << logged;
    EXPECT_NE(logged.find("further repeats are counted"), std::string::npos) << logged;
    EXPECT_EQ(gl::debugWarningCount() - before, 10);
}

TEST(BadInput, UnknownTechniqueListsTheKnownOnes) {
    scene::Scene s = sceneFromJson(R"({ "objects": [ { "shape": "box" } ] })");
    render::Renderer renderer(s);
    try {
        renderer.setTechnique("wobbly");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("hard"), std::string::npos) << e.what();
    }
    EXPECT_EQ(renderer.technique().name(), "hard") << "the previous technique stays active";
}

TEST(BadInput, TooManyProjectorsOrShadowedLightsAreReported) {
    std::string projectors;
    for (int i = 0; i < 3; ++i)
        projectors += std::string(i ? ", " : "") +
                      R"({ "type": "projector", "position": [0, 3, 0], "direction": [0, -1, 0], "image": "quadrants.png" })";
    scene::Scene three = sceneFromJson(R"({ "lights": [ )" + projectors + R"( ], "objects": [ { "shape": "box" } ] })");
    try {
        render::Renderer renderer(three);
        FAIL() << "three projectors were accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("at most 2"), std::string::npos) << e.what();
    }
    std::string suns;
    for (int i = 0; i < 5; ++i) suns += std::string(i ? ", " : "") + R"({ "type": "directional", "direction": [0, -1, 0] })";
    scene::Scene five = sceneFromJson(R"({ "lights": [ )" + suns + R"( ], "objects": [ { "shape": "box" } ] })");
    log::takeWarnings();
    render::Renderer renderer(five);
    const auto warnings = log::takeWarnings();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("only the first 4"), std::string::npos) << warnings[0];
}

// Every technique with every light type (several at once) renders without GL errors. One test per
// technique: compiling each one's lighting programs for four light types takes seconds on
// llvmpipe, 30 techniques together near five minutes.
std::vector<std::string> techniqueNames() {
    std::vector<std::string> names;
    for (const auto& info : shadows::techniqueRegistry()) names.push_back(info.name);
    return names;
}

class DebugOutput : public ::testing::TestWithParam<std::string> {};

TEST_P(DebugOutput, EveryLightTypeIsClean) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [4, 4, 6], "target": [0, 0, 0] },
      "lights": [ { "type": "directional", "direction": [-1, -2, -1] },
                  { "type": "spot", "position": [2, 4, 2], "direction": [-0.5, -1, -0.5], "angle_deg": 60 },
                  { "type": "point", "position": [-2, 3, 1], "color": [1, 0.5, 0.5] },
                  { "type": "projector", "position": [0, 3, 5], "direction": [0, -0.5, -1], "image": "quadrants.png" } ],
      "objects": [ { "shape": "plane", "size": [10, 10] },
                   { "shape": "box", "position": [0, 0.5, 0] },
                   { "shape": "plane", "size": [1, 1], "position": [1, 1.5, 0], "material": { "transmission": [0.1, 0.9, 0.1] } } ] })");
    gl::resetDebugErrorCount();
    for (auto mode : {OutputMode::Shaded, OutputMode::Visibility}) {
        render::RenderOptions options;
        options.technique = GetParam();
        options.output = mode;
        options.debugOverlay = true;
        render::Renderer renderer(s, options);
        render::OffscreenTarget target(64, 48);
        renderer.render(0.5f, s.camera, 64, 48, target.framebuffer());
        EXPECT_GT(renderer.waitForTimes().totalMs(), 0.0);
    }
    EXPECT_EQ(gl::debugErrorCount(), 0) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Techniques, DebugOutput, ::testing::ValuesIn(techniqueNames()),
                         [](const auto& info) { return testNameOf(info.param); });

// Every technique's visibility channel, for each light type, stays within [0, 1]: a weight or a
// filter that leaves it (cascaded's blend with select=projection once gave -21..22) lights a
// receiver negatively or over-brightly, and the thresholded tests may not see it. The camera looks
// down a long floor, so cascades and warped maps are stretched; a pane casts a coloured shadow.
class VisibilityRange : public ::testing::TestWithParam<std::string> {};

TEST_P(VisibilityRange, EveryLightsVisibilityStaysWithinZeroAndOne) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 2, 6], "target": [0, 0.5, -20], "fov_deg": 60, "far": 80 },
      "lights": [ { "type": "directional", "direction": [-0.5, -1, 0.3], "shadow": { "resolution": 512 } },
                  { "type": "spot", "position": [2, 4, 2], "direction": [-0.5, -1, -0.5], "angle_deg": 60, "shadow": { "resolution": 256 } },
                  { "type": "point", "position": [-2, 3, 1], "shadow": { "resolution": 128 } } ],
      "objects": [ { "shape": "plane", "size": [20, 60], "position": [0, 0, -20] },
                   { "shape": "box", "position": [0, 0.5, 0] }, { "shape": "box", "position": [1, 1, -12] },
                   { "shape": "sphere", "radius": 0.6, "position": [-1.5, 1, -5] },
                   { "shape": "plane", "size": [1, 1], "position": [1, 1.5, 0], "material": { "transmission": [0.1, 0.9, 0.1] } } ] })");
    for (int light = 0; light < 3; ++light) {
        render::RenderOptions options = optionsFor(GetParam());
        options.output = OutputMode::Visibility;
        options.debugLight = light;
        const Frame f = renderFrame(s, options, 96, 64);
        VisibilitySpan range;
        for (std::size_t i = 0; i < f.rgba.size(); ++i)
            if (i % 4 != 3) range.add(f.rgba[i]);  // not alpha
        EXPECT_TRUE(range.withinZeroAndOne()) << GetParam() << ", light " << light << ": " << range.lowest << " .. " << range.highest;
    }
}

static std::vector<std::string> techniquesAndVariants() {
    std::vector<std::string> names = techniqueNames();
    names.push_back("cascaded:select=projection");
    return names;
}

INSTANTIATE_TEST_SUITE_P(Techniques, VisibilityRange, ::testing::ValuesIn(techniquesAndVariants()),
                         [](const auto& info) { return testNameOf(info.param); });

// The overlay shows each light's screen mask (a layer of one R8 array; ScreenShadowMask keeps no
// 2D views of it, which an NVIDIA driver read back wrong) as grey tiles along the bottom, left to
// right in debugViews() order: 8 px margins, tiles min(w, h) / 4 wide, sampled bilinearly.
TEST(DebugOverlay, ShowsEachLightsScreenMaskLayerAsGrey) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 6, 7], "target": [0, 0.5, 0] },
      "lights": [ { "type": "directional", "direction": [-0.4, -1, -0.3] },
                  { "type": "spot", "position": [2, 4, 1], "direction": [-0.5, -1, -0.2], "angle_deg": 70 } ],
      "objects": [ { "shape": "plane", "size": [12, 12] },
                   { "shape": "box", "size": [1, 1.5, 1], "position": [-1, 0.75, 0] },
                   { "shape": "sphere", "radius": 0.7, "position": [1, 1, -1] } ] })");
    render::RenderOptions options = optionsFor("shadow-volumes");
    options.debugOverlay = true;
    constexpr int size = 256, tile = size / 4, margin = 8;
    render::Renderer renderer(s, options);
    render::OffscreenTarget target(size, size);
    renderer.render(0.0f, s.camera, size, size, target.framebuffer());
    const std::vector<std::uint8_t> picture = target.readRgba8();
    const auto views = renderer.technique().debugViews();
    ASSERT_EQ(views.size(), 2u);
    std::vector<std::vector<float>> masks;
    for (const auto& view : views) masks.push_back(textureLevels(view));
    ASSERT_NE(masks[0], masks[1]) << "the two lights' masks must differ for the tiles to tell them apart";
    for (std::size_t k = 0; k < views.size(); ++k) {
        const std::vector<float>& mask = masks[k];
        ASSERT_EQ(mask.size(), std::size_t{size} * size * 4) << views[k].label;
        auto texel = [&](int x, int y) { return mask[(static_cast<std::size_t>(y) * size + x) * 4]; };
        std::size_t checked[2] = {0, 0}, wrong = 0, coloured = 0;
        for (int ty = 0; ty < tile; ++ty)
            for (int tx = 0; tx < tile; ++tx) {
                // The tile's pixel centre samples the mask midway between texels 4t+1 and 4t+2.
                const int mx = 4 * tx + 1, my = 4 * ty + 1;
                const float v = texel(mx, my);
                if (texel(mx + 1, my) != v || texel(mx, my + 1) != v || texel(mx + 1, my + 1) != v) continue;
                const int gx = margin + static_cast<int>(k) * (tile + margin) + tx, gy = margin + ty;  // GL: from the bottom
                const std::uint8_t* px = &picture[(static_cast<std::size_t>(size - 1 - gy) * size + gx) * 4];
                coloured += px[0] != px[1] || px[1] != px[2];
                wrong += std::abs(px[0] - v * 255.0f) > 2.0f;
                ++checked[v > 0.5f];
            }
        EXPECT_GT(checked[0], 20u) << views[k].label << ": shadowed texels seen";
        EXPECT_GT(checked[1], 20u) << views[k].label << ": lit texels seen";
        EXPECT_EQ(wrong, 0u) << views[k].label;
        EXPECT_EQ(coloured, 0u) << views[k].label;
    }
}

}  // namespace
}  // namespace penumbra::test
