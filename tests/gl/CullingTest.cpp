// Per-light caster culling: a shadow pass draws only the casters whose bounds reach that light's
// view volume (or cube face). What the camera cannot see still casts into what it can see.
#include "GlTestSupport.h"

#include "render/Offscreen.h"

#include <cmath>

namespace penumbra::test {
namespace {

using render::OutputMode;

// The visibility of light 0 in `s` rendered with `options`, and the triangles drawn into its maps.
std::vector<float> visibilityAndTriangles(scene::Scene& s, render::RenderOptions options, int width, int height,
                                          std::size_t& triangles) {
    options.output = OutputMode::Visibility;
    render::Renderer renderer(s, options);
    render::OffscreenTarget target(width, height);
    renderer.render(0.0f, s.camera, width, height, target.framebuffer());
    triangles = renderer.shadowTriangles().at(0);
    return renderer.readLinear();
}

// Light 0's visibility with flat casters left out where their shadow falls on nothing (the
// default), against every caster drawn whole (`--every-caster`).
struct AgainstEveryCaster {
    std::size_t differing;         // pixels apart
    std::size_t triangles;         // drawn into light 0's maps
    std::size_t trianglesLeftOut;  // of every caster's
    std::size_t shadowed;          // pixels under half lit
};
AgainstEveryCaster againstEveryCaster(scene::Scene& s, render::RenderOptions options, int width, int height) {
    std::size_t left = 0, every = 0;
    const std::vector<float> leftOut = visibilityAndTriangles(s, options, width, height, left);
    options.onlyCastersThatShadow = false;
    const std::vector<float> all = visibilityAndTriangles(s, options, width, height, every);
    std::size_t shadowed = 0;
    for (std::size_t i = 0; i < leftOut.size(); i += 4) shadowed += leftOut[i] < 0.5f;
    return {differingPixels(all, leftOut, 0.0f), left, every - left, shadowed};
}

// The camera looks straight down at the ground around the origin; a tall post stands well
// outside its view, between the low sun and the ground it sees, so its long shadow falls into
// the view. Culled by the camera it would vanish; culled by the light it stays.
TEST(Culling, ACasterOutsideTheViewButInsideTheLightStillCasts) {
    for (const char* technique : {"hard", "pcf-poisson16", "cssm2", "vsm"}) {
        scene::Scene s = sceneFromJson(R"({
          "camera": { "position": [0, 6, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 40 },
          "lights": [ { "type": "directional", "direction": [-1, -0.35, 0], "shadow": { "resolution": 1024 } } ],
          "objects": [ { "shape": "plane", "size": [40, 40] },
                       { "name": "post", "shape": "box", "size": [0.4, 4, 0.4], "position": [9, 2, 0] } ] })");
        const Frame f = renderChannel(s, OutputMode::Visibility, 0, 96, 96, technique);
        // The post's shadow runs along -x through the view's centre row.
        int shadowed = 0;
        for (int x = 0; x < 96; ++x) shadowed += f.at(x, 48).r < 0.5f;
        EXPECT_GT(shadowed, 80) << technique << ": the off-screen post's shadow is missing";
    }
}

// A point light in the middle of four boxes on its +x, -x, +z and -z sides: each cube face draws
// only the box in front of it (+y and -y draw nothing), so far fewer than 6 x the scene's
// triangles are drawn, and a spot light's cone leaves out the boxes behind it.
TEST(Culling, EachLightDrawsOnlyTheCastersInItsViewVolume) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 10, 0.001], "target": [0, 0, 0], "up": [0, 0, -1] },
      "lights": [ { "type": "point", "position": [0, 1, 0], "range": 30 },
                  { "type": "spot", "position": [0, 1, 0], "direction": [1, 0, 0], "angle_deg": 40, "range": 30 } ],
      "objects": [ { "shape": "box", "position": [4, 1, 0] }, { "shape": "box", "position": [-4, 1, 0] },
                   { "shape": "box", "position": [0, 1, 4] }, { "shape": "box", "position": [0, 1, -4] } ] })");
    render::RenderOptions options;
    options.technique = "hard";
    render::Renderer renderer(s, options);
    render::OffscreenTarget target(64, 64);
    renderer.render(0.0f, s.camera, 64, 64, target.framebuffer());
    const std::size_t box = 12;  // triangles of one box
    ASSERT_EQ(renderer.shadowTriangles().size(), 2u);
    EXPECT_EQ(renderer.shadowTriangles()[0], 4 * box) << "each box once, in the cube face it faces";
    EXPECT_EQ(renderer.shadowTriangles()[1], box) << "the spot looks at the +x box only";
}

// A flat caster whose shadow can fall on no other surface is left out of a sun's maps, with the
// same pixels: a ground under floating casters (its 2 triangles), but not a ground something rests
// on (its bottom lies within a lookup's reach of the ground: drawn, around it alone, the test
// below), nor a platform over a sphere (which it shadows). Every bounded-reach technique, from the
// first frame on (view-dependent maps are fitted before the renderer asks their reach); the
// picture of each against `--every-caster`'s.
TEST(Culling, AFlatCasterWhoseShadowFallsOnNothingIsLeftOut) {
    const auto sceneWith = [](const std::string& objects) {
        return sceneFromJson(R"({
          "camera": { "position": [6, 9, 10], "target": [0, 1.5, 0], "fov_deg": 45 },
          "lights": [ { "type": "directional", "direction": [-0.4, -1, -0.3], "shadow": { "resolution": 1024 } } ],
          "objects": [ )" + objects + " ] }");
    };
    const std::string floating = R"({ "shape": "sphere", "radius": 0.5, "position": [-1, 3, 0] },
                                    { "shape": "box", "position": [1.2, 2.6, 0.5], "rotation_deg": [0, 30, 0] })";
    const std::string ground = R"({ "shape": "plane", "size": [20, 20] }, )";
    struct Case {
        std::string objects;
        std::size_t leftOut;  // triangles
        const char* what;
    };
    const Case cases[] = {
        {ground + floating, 2, "a ground under floating casters"},
        {ground + floating + R"(, { "shape": "box", "position": [0, 0.5, -1.5] })", 0, "a ground with a box resting on it"},
        {floating + R"(, { "shape": "plane", "size": [3, 3], "position": [-1, 4.5, 0] })", 0, "a platform over the sphere"},
    };
    for (const Case& c : cases)
        for (const char* technique : {"hard", "pcf-poisson16", "pcss", "cssm2", "distance", "cascaded", "lispsm", "psm"}) {
            scene::Scene s = sceneWith(c.objects);
            render::RenderOptions options;
            options.technique = technique;
            const AgainstEveryCaster r = againstEveryCaster(s, options, 96, 64);
            // A cascaded map leaves the ground out of each cascade it would have reached.
            if (std::string(technique) == "cascaded" && c.leftOut > 0) {
                EXPECT_GE(r.trianglesLeftOut, c.leftOut) << technique << ", " << c.what;
                EXPECT_EQ(r.trianglesLeftOut % c.leftOut, 0u) << technique << ", " << c.what;
            } else {
                EXPECT_EQ(r.trianglesLeftOut, c.leftOut) << technique << ", " << c.what;
            }
            EXPECT_EQ(r.differing, 0u) << technique << ", " << c.what;
            EXPECT_GT(r.shadowed, 100u) << technique << ", " << c.what << ": shadows in view";
        }
}

// A ground's margin under a sun shrinks with the sun's angle to it: a lookup's taps across the
// light stand for points nearer the ground by their reach times sin t (flatCasterShadowsNone), so
// under a high sun (t 27 degrees here) casters floating 0.3 m over the ground leave it out of the
// map, where twice the lookup's whole pad (the margin before) kept it. pcss reaches less near the
// light's near plane (its penumbra is narrower there: shadowReachTexelsWithin) than its 48-texel
// cap. The wider kernels and coarser maps keep the ground, with the same pixels.
TEST(Culling, CastersFloatingLowUnderAHighSunLeaveTheGroundOut) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [6, 9, 10], "target": [0, 1.5, 0], "fov_deg": 45 },
      "lights": [ { "type": "directional", "direction": [-0.4, -1, -0.3], "shadow": { "resolution": 1024 } } ],
      "objects": [ { "shape": "plane", "size": [20, 20] },
                   { "shape": "sphere", "radius": 0.5, "position": [-1, 0.8, 0] },
                   { "shape": "box", "position": [1.2, 0.8, 0.5], "rotation_deg": [0, 30, 0] } ] })");
    struct Case {
        const char* technique;
        std::size_t leftOut;  // triangles
    };
    for (const Case& c : {Case{"hard", 2}, Case{"pcss", 2}, Case{"cssm2", 2}, Case{"distance", 2}, Case{"psm", 2},
                          Case{"pcf-poisson16", 0}, Case{"lispsm", 0}}) {
        render::RenderOptions options;
        options.technique = c.technique;
        const AgainstEveryCaster r = againstEveryCaster(s, options, 96, 64);
        EXPECT_EQ(r.trianglesLeftOut, c.leftOut) << c.technique;
        EXPECT_EQ(r.differing, 0u) << c.technique;
        EXPECT_GT(r.shadowed, 100u) << c.technique << ": shadows in view";
    }
    // A wider sun widens pcss's penumbrae, and so its reach near the ground: the same renderer
    // draws the ground again once the parameter changes (its answer is not kept past the change).
    render::RenderOptions options;
    options.technique = "pcss";
    options.output = OutputMode::Visibility;
    render::Renderer live(s, options);
    render::OffscreenTarget target(96, 64);
    live.render(0.0f, s.camera, 96, 64, target.framebuffer());
    const std::size_t narrow = live.shadowTriangles().at(0);
    shadows::applyParameters(live.technique().parameters(), {{"sun_angle_deg", "20"}});
    live.render(0.0f, s.camera, 96, 64, target.framebuffer());
    options.onlyCastersThatShadow = false;
    render::Renderer every(s, options);
    shadows::applyParameters(every.technique().parameters(), {{"sun_angle_deg", "20"}});
    every.render(0.0f, s.camera, 96, 64, target.framebuffer());
    EXPECT_EQ(live.shadowTriangles().at(0), narrow + 2) << "a 20-degree sun: the ground drawn";
    EXPECT_EQ(live.shadowTriangles().at(0), every.shadowTriangles().at(0));
    live.render(0.0f, s.camera, 96, 64, target.framebuffer());
    const std::vector<float> wide = live.readLinear();
    every.render(0.0f, s.camera, 96, 64, target.framebuffer());
    EXPECT_EQ(differingPixels(every.readLinear(), wide, 0.0f), 0u);
}

// View-dependent maps are finer near the camera than far away: a ground is judged against each
// receiver by the reach of the lookups at that receiver's surfaces (shadowReachTexelsWithin), not
// by the coarsest texel the view has. A long ground runs from under the camera to the horizon;
// two casters float over it near the camera, high enough above it for their own fine texels but
// not for the far ground's coarse ones. The ground leaves the sun's maps, with the same pixels.
TEST(Culling, AGroundIsJudgedByTheReachOfTheMapsReadAtEachReceiver) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 2.5, 12], "target": [0, 1, 0], "fov_deg": 50 },
      "lights": [ { "type": "directional", "direction": [-0.3, -1, -0.4], "shadow": { "resolution": 1024 } } ],
      "objects": [ { "shape": "plane", "size": [300, 300] },
                   { "shape": "sphere", "radius": 0.5, "position": [0, 3.6, 6] },
                   { "shape": "box", "position": [1.5, 3.5, 4], "rotation_deg": [0, 30, 0] } ] })");
    for (const char* technique : {"lispsm", "cascaded"}) {
        render::RenderOptions options;
        options.technique = technique;
        const AgainstEveryCaster r = againstEveryCaster(s, options, 96, 64);
        EXPECT_GE(r.trianglesLeftOut, 2u) << technique << ": the ground left out";
        EXPECT_EQ(r.differing, 0u) << technique;
        EXPECT_GT(r.shadowed, 40u) << technique << ": shadows in view";
    }
}

// A ground carrying casters is drawn into a light's maps only where their lookups read it: the
// texels of the boxes it may shadow, grown by the lookup's reach (Renderer::flatCasterNeeds). The
// same pixels as `--every-caster`, the same triangles drawn, and far fewer texels of depth: with
// every caster the ground fills the map; here it fills the box's corner of it. A second box far
// across the ground grows what is drawn. Every bounded-reach technique, layered maps too; under a
// sun and a spot light. Under a point light the ground is drawn whole, and into every cube face
// with the sphere alone over it: there its own texels may count in its own lookups (pcss, 15 and
// 3 pixels changed without them); the same pixels (cube faces are not read back).
TEST(Culling, AGroundCarryingCastersIsDrawnOnlyWhereTheirLookupsRead) {
    const auto sceneWith = [](const std::string& light, const std::string& boxes) {
        return sceneFromJson(R"({
          "camera": { "position": [6, 9, 10], "target": [0, 1, 0], "fov_deg": 45 },
          "lights": [ )" + light + R"( ],
          "objects": [ { "shape": "plane", "size": [12, 12] },
                       { "shape": "sphere", "radius": 0.5, "position": [-1, 2.5, 0] } )" + boxes + " ] }");
    };
    // The share of the light's depth texels that hold a surface (under 1), over every depth view
    // (a cascaded or warped map's layers too), and the visibility picture.
    const auto render = [](scene::Scene& s, const std::string& technique, bool everyCaster, std::vector<float>& visibility) {
        render::RenderOptions options;
        options.technique = technique;
        options.output = OutputMode::Visibility;
        options.onlyCastersThatShadow = !everyCaster;
        render::Renderer renderer(s, options);
        render::OffscreenTarget target(96, 64);
        renderer.render(0.0f, s.camera, 96, 64, target.framebuffer());
        visibility = renderer.readLinear();
        std::size_t surface = 0, texels = 0;
        for (const shadows::DebugView& view : renderer.technique().debugViews()) {
            if (!view.depth) continue;
            const std::vector<float> depth = textureLevels(view);
            texels += depth.size();
            for (float z : depth) surface += z < 1.0f;
        }
        return texels ? static_cast<double>(surface) / static_cast<double>(texels) : -1.0;
    };
    const std::string resting = R"(, { "shape": "box", "position": [1.5, 0.5, 1.5] })";
    const std::string farther = R"(, { "shape": "box", "position": [-3.5, 0.5, -3.5] })";
    const std::string lights[] = {
        R"({ "type": "directional", "direction": [-0.4, -1, -0.3], "shadow": { "resolution": 512 } })",
        R"({ "type": "spot", "position": [0.5, 7, 0.5], "direction": [0, -1, 0], "angle_deg": 100, "range": 20, "shadow": { "resolution": 512 } })",
        R"({ "type": "point", "position": [0.5, 5, 0.5], "range": 20, "shadow": { "resolution": 256 } })"};
    for (const std::string& light : lights) {
        const bool point = light.find("point") != std::string::npos;
        for (const char* technique : {"hard", "pcf-poisson16", "pcss", "cssm2", "distance", "cascaded", "lispsm"}) {
            const std::string what = std::string(technique) + ", " + light.substr(0, 30);
            std::vector<float> all, near;
            scene::Scene one = sceneWith(light, resting);
            const double every = render(one, technique, true, all);
            const double oneBox = render(one, technique, false, near);
            EXPECT_EQ(differingPixels(all, near, 0.0f), 0u) << what << ", one box";
            scene::Scene none = sceneWith(light, "");
            render(none, technique, false, near);
            render(none, technique, true, all);
            EXPECT_EQ(differingPixels(all, near, 0.0f), 0u) << what << ", the sphere alone";
            scene::Scene two = sceneWith(light, resting + farther);
            const double twoBoxes = render(two, technique, false, near);
            render(two, technique, true, all);
            EXPECT_EQ(differingPixels(all, near, 0.0f), 0u) << what << ", two boxes";
            // A cascaded or warped layer draws only the texels its receivers read and leaves the
            // rest as it was (its views show a layer whatever the light): not counted.
            const bool layered = std::string(technique) == "cascaded" || std::string(technique) == "lispsm";
            if (layered || point) continue;
            EXPECT_GT(every, 0.4) << what << ": the ground fills the light's view, about the ground";
            EXPECT_LT(oneBox, 0.25 * every) << what << ": the ground only around the box";
            EXPECT_GT(oneBox, 0.0) << what << ": the box and the ground under it";
            EXPECT_GT(twoBoxes, oneBox) << what << ": the ground around both boxes";
            EXPECT_LT(twoBoxes, every) << what << ": still not the whole ground";
        }
    }
}

// Moment maps filter depths before they compare: a ground's own lookup averages its depth with
// its occluders'. So under them a ground is kept in the maps around every shadow on it and every
// receiver it shadows, within the filter's reach (the blur, mip levels up to max_lod, the bilinear
// fetch: MomentShadowMap::filterReachTexels), and only there blurred and mip-mapped; around
// moving casters too, kept maps redrawing its ring around them with them. Over an
// animation (a sphere flying over a box on the ground), with maps kept and redrawn, the same
// pixels as every caster drawn whole into maps redrawn every frame; fewer than half the
// moment texels other than the far plane's (0.18 against 0.43 under the sun); under a sun and a
// spot light. Not MSM, whose pixels it would change (MomentShadowMap::filterReachTexels).
// The share of light 0's moment texels, every level, whose first moment is not the far plane's
// (`far`, what a texel holds where no caster is).
double shareOfMomentsNotFar(const render::Renderer& renderer, float far) {
    for (const shadows::DebugView& view : renderer.technique().debugViews()) {
        if (view.label != "light 0 moments") continue;
        const std::vector<float> moments = textureLevels(view);
        std::size_t near = 0;
        for (std::size_t i = 0; i < moments.size(); i += 4) near += moments[i] < 0.999f * far;
        return static_cast<double>(near) / static_cast<double>(moments.size() / 4);
    }
    return -1.0;
}

TEST(Culling, AGroundUnderMomentMapsIsKeptOnlyAroundTheShadowsOnIt) {
    const std::string lights[] = {
        R"({ "type": "directional", "direction": [-0.4, -1, -0.3], "shadow": { "resolution": 512 } })",
        R"({ "type": "spot", "position": [0.5, 7, 0.5], "direction": [0, -1, 0], "angle_deg": 100, "range": 20, "shadow": { "resolution": 512 } })"};
    struct Technique {
        const char* name;
        float far;  // the first moment where no caster is (0: not counted)
    };
    // From above, and low over the ground, whose far lookups read coarse mip levels around the
    // box's shadow (with half the reach, 45 pixels apart there).
    const std::string cameras[] = {R"({ "position": [6, 9, 10], "target": [0, 1, 0], "fov_deg": 45 })",
                                   R"({ "position": [-5.5, 0.4, 5.5], "target": [1.5, 0.2, 1.5], "fov_deg": 30 })"};
    for (const std::string& camera : cameras)
        for (const std::string& light : lights)
            for (const Technique t : {Technique{"vsm", 1.0f}, Technique{"esm", 0.0f}, Technique{"evsm4", std::exp(40.0f)}}) {
                scene::Scene s = sceneFromJson(R"({
                  "camera": )" + camera + R"(,
                  "lights": [ )" + light + R"( ],
                  "objects": [ { "shape": "plane", "size": [12, 12] },
                               { "shape": "box", "position": [1.5, 0.5, 1.5] },
                               { "shape": "sphere", "radius": 0.5, "animation": [[0, -2, 2.5, 0], [2, 2, 1.2, -2.5], [4, -2, 2.5, 0]] } ] })");
                const std::string what = std::string(t.name) + ", " + light.substr(0, 30) + ", camera " + camera.substr(0, 30);
                render::RenderOptions options;
                options.technique = t.name;
                options.output = OutputMode::Visibility;
                render::Renderer kept(s, options);
                options.reuseStillCasters = false;
                render::Renderer redrawn(s, options);
                options.onlyCastersThatShadow = false;
                render::Renderer every(s, options);
                render::OffscreenTarget target(96, 64);
                const auto cast = [&t](const render::Renderer& renderer) { return shareOfMomentsNotFar(renderer, t.far); };
                for (float time : {0.0f, 0.5f, 1.0f, 1.5f, 2.0f}) {
                    kept.render(time, s.camera, 96, 64, target.framebuffer());
                    const std::vector<float> keptPixels = kept.readLinear();
                    redrawn.render(time, s.camera, 96, 64, target.framebuffer());
                    const std::vector<float> redrawnPixels = redrawn.readLinear();
                    every.render(time, s.camera, 96, 64, target.framebuffer());
                    const std::vector<float> all = every.readLinear();
                    EXPECT_EQ(differingPixels(all, keptPixels, 0.0f), 0u) << what << ", kept, at " << time << " s";
                    EXPECT_EQ(differingPixels(all, redrawnPixels, 0.0f), 0u) << what << ", redrawn, at " << time << " s";
                }
                if (t.far == 0.0f) continue;
                const double whole = cast(every), around = cast(kept);
                EXPECT_EQ(cast(redrawn), around) << what << ": kept and redrawn maps alike";
                EXPECT_GT(whole, 0.4) << what << ": with every caster the ground fills the light's view, about it";
                EXPECT_LT(around, 0.5 * whole) << what << ": the ground around the box and the sphere";
                EXPECT_GT(around, 0.0) << what;
            }
}

// Under a field of floating objects (16 spheres over a wide ground, as the osgShadow grid's 100)
// a moment map's ground is still drawn around their shadows alone: its rectangle leaves the far
// ground out whatever the number of casters over it (with stop 73's limit of 8 it was drawn whole:
// the same share as every caster's). The same pixels as every caster drawn whole.
TEST(Culling, AGroundUnderAFieldOfCastersIsKeptAroundThemInMomentMaps) {
    std::string objects = R"({ "shape": "plane", "size": [40, 40] })";
    for (int i = 0; i < 4; ++i)
        for (int k = 0; k < 4; ++k)
            objects += R"(, { "shape": "sphere", "radius": 0.4, "position": [)" + std::to_string(2 * i - 3) + ", 1.5, " +
                       std::to_string(2 * k - 3) + "] }";
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 12, 16], "target": [0, 0, 0], "fov_deg": 60 },
      "lights": [ { "type": "directional", "direction": [-0.4, -1, -0.3], "shadow": { "resolution": 512 } } ],
      "objects": [ )" + objects + R"( ] })");
    render::RenderOptions options;
    options.technique = "vsm";
    options.output = OutputMode::Visibility;
    options.reuseStillCasters = false;
    render::Renderer cut(s, options);
    options.onlyCastersThatShadow = false;
    render::Renderer every(s, options);
    render::OffscreenTarget target(96, 64);
    cut.render(0.0f, s.camera, 96, 64, target.framebuffer());
    const std::vector<float> pixels = cut.readLinear();
    every.render(0.0f, s.camera, 96, 64, target.framebuffer());
    EXPECT_EQ(differingPixels(every.readLinear(), pixels, 0.0f), 0u);
    const double whole = shareOfMomentsNotFar(every, 1.0f), around = shareOfMomentsNotFar(cut, 1.0f);
    std::printf("moment texels not the far plane's: %.3f, every caster %.3f\n", around, whole);
    EXPECT_GT(whole, 0.4) << "the ground fills the light's view, about it";
    EXPECT_LT(around, 0.5 * whole) << "the ground around the field of spheres";
    EXPECT_GT(around, 0.0);
}

// A live renderer decides it again when the scene changes: a sphere floating over a ground leaves
// the ground out; moved down to rest on it, the ground is drawn; floated up again, left out; with a
// polygon offset that pulls depths towards the light, drawn. (The answer is kept between frames
// while nothing changes.)
TEST(Culling, ALiveRendererDecidesAgainWhatShadowsNothing) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [4, 6, 7], "target": [0, 1, 0], "fov_deg": 45 },
      "lights": [ { "type": "directional", "direction": [-0.4, -1, -0.3], "shadow": { "resolution": 512 } } ],
      "objects": [ { "shape": "plane", "size": [20, 20] }, { "shape": "sphere", "radius": 0.5, "position": [0, 3, 0] } ] })");
    render::RenderOptions options;
    options.technique = "hard";
    options.reuseStillCasters = false;  // every map drawn every frame, to count what goes into it
    render::Renderer renderer(s, options);
    render::OffscreenTarget target(64, 64);
    const auto triangles = [&] {
        renderer.render(0.0f, s.camera, 64, 64, target.framebuffer());
        return renderer.shadowTriangles().at(0);
    };
    const std::size_t floating = triangles();
    EXPECT_EQ(triangles(), floating) << "nothing changed";
    s.objects[1].position.y = 0.5f;
    EXPECT_EQ(triangles(), floating + 2) << "the sphere rests on the ground";
    s.objects[1].position.y = 3.0f;
    EXPECT_EQ(triangles(), floating) << "floating again";
    s.lights[0].shadow.polygonOffset = {-1.0f, -1.0f};
    EXPECT_EQ(triangles(), floating + 2) << "an offset towards the light";
}

// The moment maps draw their casters straight into moments and read no depth map: with no
// translucent caster in view (no tint pass to depth-test), each caster is drawn once per face it
// reaches, as hard draws it, not once for a depth map and again for the moments. With a pane in
// view, the opaque casters under the pane are drawn into the depth the pane's tint is tested
// against, and only those: here the ground, which the pane lies over.
TEST(Culling, MomentMapsDrawEachCasterOncePerFace) {
    const std::string scene = R"({
      "camera": { "position": [0, 10, 0.001], "target": [0, 0, 0], "up": [0, 0, -1] },
      "lights": [ { "type": "point", "position": [0, 1, 0], "range": 30 },
                  { "type": "spot", "position": [0, 1, 0], "direction": [1, 0, 0], "angle_deg": 40, "range": 30 } ],
      "objects": [ { "shape": "box", "position": [4, 1, 0] }, { "shape": "box", "position": [-4, 1, 0] },
                   { "shape": "box", "position": [0, 1, 4] }, { "shape": "box", "position": [0, 1, -4] } )";
    const std::size_t box = 12;
    for (const char* technique : {"vsm", "msm"}) {
        scene::Scene s = sceneFromJson(scene + "] }");
        render::RenderOptions options;
        options.technique = technique;
        render::Renderer renderer(s, options);
        render::OffscreenTarget target(64, 64);
        renderer.render(0.0f, s.camera, 64, 64, target.framebuffer());
        ASSERT_EQ(renderer.shadowTriangles().size(), 2u);
        EXPECT_EQ(renderer.shadowTriangles()[0], 4 * box) << technique << ": each box once, in the cube face it faces";
        EXPECT_EQ(renderer.shadowTriangles()[1], box) << technique << ": the spot looks at the +x box only";
    }
    // A pane (2 triangles) between the spot and the +x box: the box is drawn into moments and,
    // under the pane, into the tint's depth test; the pane into the tint.
    scene::Scene s = sceneFromJson(scene + R"(, { "shape": "plane", "size": [1, 1], "position": [2, 1, 0], "rotation_deg": [0, 0, 90],
      "material": { "transmission": [0.1, 0.9, 0.1] } } ] })");
    render::RenderOptions options;
    options.technique = "vsm";
    render::Renderer renderer(s, options);
    render::OffscreenTarget target(64, 64);
    renderer.render(0.0f, s.camera, 64, 64, target.framebuffer());
    EXPECT_EQ(renderer.shadowTriangles()[1], 2 * box + 2) << "the box into moments and under the pane, the pane into the tint";
}

// A green pane (t = 0.1, 0.9, 0.1) moving along `animation` over the ground, under a spot
// straight down from (0, 5, 0) with cone `angleDeg`; the camera looks down from (0, 6, 0).
scene::Scene paneUnderASpot(int fovDeg, int angleDeg, const std::string& animation) {
    return sceneFromJson(R"({
      "camera": { "position": [0, 6, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": )" + std::to_string(fovDeg) + R"( },
      "lights": [ { "type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0], "angle_deg": )" + std::to_string(angleDeg) + R"(, "range": 20 } ],
      "objects": [ { "shape": "plane", "size": [10, 10] },
                   { "shape": "plane", "size": [1, 1], "material": { "transmission": [0.1, 0.9, 0.1] },
                     "animation": )" + animation + " } ] }");
}

// A light with no translucent caster in view skips its tint clear and pass once the map is
// white. A pane that leaves the spot's cone must not leave its tint behind, and its return must
// bring the tint back.
TEST(Culling, ATranslucentCasterLeavingTheLightLeavesNoStaleTint) {
    scene::Scene s = paneUnderASpot(30, 40, "[[0, 0, 2, 0], [1, 8, 2, 0], [2, 0, 2, 0]]");
    render::RenderOptions options;
    options.technique = "hard";
    options.output = OutputMode::Visibility;
    render::Renderer renderer(s, options);
    render::OffscreenTarget target(32, 32);
    auto centreAt = [&](float time) {
        renderer.render(time, s.camera, 32, 32, target.framebuffer());
        return Frame{32, 32, renderer.readLinear()}.at(16, 16);
    };
    const glm::vec3 tinted(0.1f, 0.9f, 0.1f);
    EXPECT_LT(glm::length(centreAt(0.0f) - tinted), 0.02f) << "the pane tints the ground under it";
    EXPECT_EQ(centreAt(1.0f), glm::vec3(1.0f)) << "the pane left the cone: no stale tint";
    EXPECT_EQ(centreAt(1.0f), glm::vec3(1.0f)) << "and none on the frames after (the skipped passes)";
    EXPECT_LT(glm::length(centreAt(2.0f) - tinted), 0.02f) << "the pane is back";
}

// Tint maps are cleared only where translucent casters were last drawn (MapRegion): a pane
// moving inside a spot's cone, from x = -1 to x = +1 at height 2, tints the ground around
// x = -1.67 (pixel 8 of 32) and then around x = +1.67 (pixel 24), and leaves no trail.
class MovingPane : public ::testing::TestWithParam<const char*> {};

TEST_P(MovingPane, LeavesNoTintBehindInsideTheLight) {
    scene::Scene s = paneUnderASpot(60, 100, "[[0, -1, 2, 0], [1, 1, 2, 0], [2, -1, 2, 0]]");
    render::RenderOptions options;
    options.technique = GetParam();
    options.output = OutputMode::Visibility;
    render::Renderer renderer(s, options);
    render::OffscreenTarget target(32, 32);
    const glm::vec3 tinted(0.1f, 0.9f, 0.1f), white(1.0f);
    auto at = [&](float time, int x) {
        renderer.render(time, s.camera, 32, 32, target.framebuffer());
        return Frame{32, 32, renderer.readLinear()}.at(x, 16);
    };
    EXPECT_LT(glm::length(at(0.0f, 8) - tinted), 0.05f) << "under the pane at its start";
    EXPECT_LT(glm::length(at(0.0f, 24) - white), 0.02f) << "where it is going";
    EXPECT_LT(glm::length(at(1.0f, 8) - white), 0.02f) << "where it was: no stale tint";
    EXPECT_LT(glm::length(at(1.0f, 24) - tinted), 0.05f) << "under the pane at its end";
}

INSTANTIATE_TEST_SUITE_P(TintMaps, MovingPane, ::testing::Values("hard", "cssm2"));

// The view-dependent maps keep the sun's depth in layers of their own: each opaque caster is
// drawn once per layer it reaches, and the sun's plain depth map (kept for the coloured tint)
// is drawn only when a translucent caster needs it as the tint pass's depth test, cropped to that
// caster: there it holds no opaque caster here (the ground is drawn only around the box resting on
// it, far from the pane). The same pixels as every caster drawn whole.
TEST(Culling, ViewDependentMapsDrawTheSunsCastersOncePerLayer) {
    const std::string opaque = R"({ "shape": "plane", "size": [12, 12] }, { "shape": "box", "position": [0, 0.5, 0] })";
    // Far from the box (in the sun's view too): the plain map, cropped to the pane, draws only the ground.
    const std::string pane = R"(, { "shape": "plane", "size": [1, 1], "position": [4, 1.5, 0], "rotation_deg": [90, 0, 0],
                                    "material": { "transmission": [0.1, 0.9, 0.1] } })";
    auto sunTriangles = [&](const std::string& technique, bool withPane) {
        scene::Scene s = sceneFromJson(R"({
          "camera": { "position": [4, 5, 6], "target": [0, 0, 0] },
          "lights": [ { "type": "directional", "direction": [-0.3, -1, -0.2], "shadow": { "resolution": 512 } } ],
          "objects": [ )" + opaque + (withPane ? pane : "") + " ] }");
        render::RenderOptions options;
        options.technique = technique;
        const AgainstEveryCaster r = againstEveryCaster(s, options, 64, 64);
        EXPECT_EQ(r.differing, 0u) << technique << ", pane " << withPane;
        return r.triangles;
    };
    const std::size_t groundTriangles = 2, opaqueTriangles = groundTriangles + 12, paneTriangles = 2;
    for (const char* technique : {"lispsm", "psm"}) {
        EXPECT_EQ(sunTriangles(technique, false), opaqueTriangles) << technique << ": one layer, nothing else";
        EXPECT_EQ(sunTriangles(technique, true), opaqueTriangles + paneTriangles)
            << technique << ": the warped layer and the pane's tint (its plain depth map holds no opaque caster)";
    }
    const std::size_t cascaded = sunTriangles("cascaded", false);
    EXPECT_GE(cascaded, opaqueTriangles) << "every caster reaches the first cascade";
    EXPECT_LE(cascaded, 4 * opaqueTriangles) << "at most once per cascade, and no plain map";
}

// The view-dependent techniques draw the sun's plain depth only under translucent casters, as the
// tint pass's depth test. It must still hold there what hard's full map holds: red glass above an
// opaque tile above green glass, all over the ground. The tile's top gets the red pane alone (the
// green one lies behind the tile's depth); the ground beside the tile's shadow gets both.
TEST(Culling, TheTintsDepthTestUnderViewDependentMapsKeepsTheCastersUnderTheGlass) {
    const std::string json = R"({
      "camera": { "position": [0, 12, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 40 },
      "lights": [ { "type": "directional", "direction": [0.1, -1, 0.05], "shadow": { "resolution": 1024 } } ],
      "objects": [ { "shape": "plane", "size": [20, 20] },
                   { "shape": "plane", "size": [3, 3], "position": [0, 3, 0], "material": { "alpha": 1, "transmission": [0.9, 0.1, 0.1] } },
                   { "shape": "plane", "size": [1, 1], "position": [0, 2, 0] },
                   { "shape": "plane", "size": [3, 3], "position": [0, 1, 0], "material": { "alpha": 1, "transmission": [0.1, 0.9, 0.1] } },
                   { "shape": "box", "position": [8, 0.5, 8] } ] })";
    const glm::vec3 red(0.9f, 0.1f, 0.1f), both = red * glm::vec3(0.1f, 0.9f, 0.1f);
    auto mean = [](const Frame& f, int x0, int y0, int side) {
        glm::vec3 sum(0.0f);
        for (int y = y0; y < y0 + side; ++y)
            for (int x = x0; x < x0 + side; ++x) sum += f.at(x, y);
        return sum / float(side * side);
    };
    for (const char* technique : {"hard", "cascaded", "lispsm", "psm"}) {
        scene::Scene s = sceneFromJson(json);
        const Frame f = renderChannel(s, OutputMode::Visibility, 0, 96, 96, technique);
        const glm::vec3 tile = mean(f, 45, 45, 6), ground = mean(f, 59, 46, 4);  // the tile's middle; the ground at x ~ 1.2
        EXPECT_LT(glm::length(tile - red), 0.02f) << technique << ": tile top (" << tile.r << ", " << tile.g << ", " << tile.b << ")";
        EXPECT_LT(glm::length(ground - both), 0.02f)
            << technique << ": ground under both panes (" << ground.r << ", " << ground.g << ", " << ground.b << ")";
    }
}

// A sphere of 65k triangles (one mesh part, so object culling takes it or leaves it whole) next
// to a point light and under a low sun seen by a camera looking along the ground. Clusters let a
// cube face or cascade skip the sphere's far side; the pictures must stay exactly as with the
// sphere drawn whole, and fewer triangles must be drawn.
TEST(Culling, ClustersOfABigMeshCullPerCubeFaceAndCascadeWithTheSamePixels) {
    struct Case {
        const char* technique;
        const char* light;
        const char* camera;
        float radius;
    };
    const char* lamp = R"({ "type": "point", "position": [1.4, 0.6, 0.3], "range": 30, "shadow": { "resolution": 256 } })";
    const char* sun = R"({ "type": "directional", "direction": [-0.4, -1, -0.3], "shadow": { "resolution": 512 } })";
    const char* near = R"({ "position": [4, 1.5, 4], "target": [0, 0.5, 0], "near": 0.1, "far": 60 })";
    // The first cascade (0.1 to 4.1 from the camera) takes in the near side of a sphere of radius 4.
    const char* close = R"({ "position": [5, 2, 5], "target": [0, 2, 0], "near": 0.1, "far": 60 })";
    for (const Case c : {Case{"hard", lamp, near, 1.0f}, Case{"pcf-poisson16", lamp, near, 1.0f}, Case{"cascaded", sun, close, 4.0f}}) {
        scene::Scene s = sceneFromJson(R"({ "camera": )" + std::string(c.camera) + R"(, "lights": [ )" + c.light + R"( ],
          "objects": [ { "shape": "plane", "size": [60, 60] }, { "shape": "sphere", "position": [0, )" + std::to_string(c.radius) + R"(, 0] } ] })");
        const scene::Mesh& ball = makeBigSphere(s, 1, c.radius);
        ASSERT_GE(ball.triangleCount(), render::kClusteredPartTriangles);
        auto renderWith = [&](bool clusters, std::size_t& triangles) {
            render::RenderOptions options;
            options.technique = c.technique;
            options.clusterCasters = clusters;
            return visibilityAndTriangles(s, options, 96, 96, triangles);
        };
        std::size_t clustered = 0, whole = 0;
        const std::vector<float> withClusters = renderWith(true, clustered), drawnWhole = renderWith(false, whole);
        EXPECT_EQ(withClusters, drawnWhole) << c.technique << ": the clusters changed the picture";
        EXPECT_LT(clustered, whole) << c.technique << ": no cluster was culled";
        EXPECT_GE(clustered, ball.triangleCount() / 2) << c.technique << ": at least the half facing the light is drawn";
        const Frame f{96, 96, withClusters};
        int shadowed = 0;
        for (int y = 0; y < 96; ++y)
            for (int x = 0; x < 96; ++x) shadowed += f.at(x, y).r < 0.5f;
        EXPECT_GT(shadowed, 96 * 96 / 50) << c.technique << ": the sphere casts a shadow";
    }
}

// Cascades fitted to their receivers: a cascade is drawn only where its camera slice (blend band
// included) meets the scene, texels scissored to that and casters culled to the column along the
// light over it (columnPlanes). Posts stand from near
// the camera to far away, under a low sun that throws their shadows across the slices, toward
// the camera and away from it. The pictures must be exactly those of whole cascades, with under
// two thirds of the triangles drawn.
TEST(Culling, CascadesFittedToTheirReceiversKeepEveryPixel) {
    struct Case {
        const char* direction;
        shadows::ParameterValues parameters;
    };
    const Case cases[] = {{"[0.3, -0.45, 1]", {}},
                          {"[0.3, -0.45, -1]", {}},
                          {"[-1, -0.6, 0.2]", {{"blend", "0.4"}}},
                          {"[0.3, -0.45, 1]", {{"sdsm", "true"}, {"blend", "0"}}},
                          {"[0.2, -0.5, -1]", {{"lambda", "0.3"}, {"cascades", "6"}}}};
    for (const Case& c : cases) {
        std::string posts;
        for (const float z : {6.0f, 2.0f, -3.0f, -9.0f, -17.0f, -28.0f})
            posts += R"(, { "shape": "box", "size": [0.6, 3, 0.6], "position": [)" + std::to_string(z * 0.2f) + ", 1.5, " +
                     std::to_string(z) + "] }";
        scene::Scene s = sceneFromJson(R"({
          "camera": { "position": [0, 2.5, 11], "target": [0, 0.5, 0], "near": 0.1, "far": 80 },
          "lights": [ { "type": "directional", "direction": )" + std::string(c.direction) + R"(, "shadow": { "resolution": 512 } } ],
          "objects": [ { "shape": "plane", "size": [40, 80] })" + posts + " ] }");
        auto renderWith = [&](bool fit, std::size_t& triangles) {
            render::RenderOptions options;
            options.technique = "cascaded";
            options.parameters = c.parameters;
            options.parameters.emplace_back("fit_receivers", fit ? "true" : "false");
            return visibilityAndTriangles(s, options, 128, 72, triangles);
        };
        std::size_t fitted = 0, whole = 0;
        const std::vector<float> withFit = renderWith(true, fitted), wholeLayers = renderWith(false, whole);
        EXPECT_EQ(withFit, wholeLayers) << c.direction << ": fitting the cascades to their receivers changed the picture";
        // The posts' columns: 0.38-0.61 of whole layers' triangles; the slices' rectangles alone 0.58-0.95.
        EXPECT_LE(fitted * 100, whole * 65) << c.direction << ": casters outside the column over the slice's receivers were drawn";
        const Frame f{128, 72, withFit};
        int shadowed = 0;
        for (int y = 0; y < 72; ++y)
            for (int x = 0; x < 128; ++x) shadowed += f.at(x, y).r < 0.5f;
        EXPECT_GT(shadowed, 128 * 72 / 50) << c.direction << ": the posts cast shadows";
        std::printf("%s: %zu of %zu triangles, %d shadowed pixels\n", c.direction, fitted, whole, shadowed);
    }
}

}  // namespace
}  // namespace penumbra::test
