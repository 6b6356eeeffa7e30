// Seed 002's combined technique (issue 13): regions of one scene drawn at once with their own
// techniques and map resolutions. Seen from above, two ground tiles each carry a box; the left
// tile and its box are region "sharp" (hard shadows, 2048²), the right ones region "soft" (PCF
// with a wide kernel on a 256² map); the background belongs to the scene's own technique.
// Every pixel must be, byte for byte, what its owner's technique renders for the whole scene
// alone, and each region's shadow edge must have its technique's width.
#include "GlTestSupport.h"

#include "render/Offscreen.h"
#include "render/RegionView.h"
#include "scene/io/SceneFile.h"
#include "util/Error.h"

namespace penumbra::test {
namespace {

constexpr int kWidth = 128, kHeight = 64;

const char* kScene = R"({
  "camera": { "position": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 37 },
  "technique": "none",
  "lights": [ { "type": "directional", "direction": [-2, -1, 0], "shadow": { "resolution": 1024 } } ],
  "regions": [ { "name": "sharp", "technique": "hard", "shadow_resolution": 2048 },
               { "name": "soft", "technique": "pcf-poisson16", "shadow_resolution": 256,
                 "parameters": { "radius_texels": 8 } } ],
  "objects": [ { "shape": "plane", "size": [6, 6], "position": [-3, 0, 0], "region": "sharp" },
               { "shape": "box", "size": [1, 1, 2], "position": [-2, 0.5, 0], "region": "sharp" },
               { "shape": "plane", "size": [6, 6], "position": [3, 0, 0], "region": "soft" },
               { "shape": "box", "size": [1, 1, 2], "position": [4, 0.5, 0], "region": "soft" } ] })";

// Where the ray of pixel (x, y) meets the ground plane y = 0.
glm::vec3 groundPoint(const scene::Camera& camera, int x, int y) {
    const Ray ray = pixelRay(camera, x, y, kWidth, kHeight);
    return ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
}

// Pixels of row `y` whose ground point lies within world x in [from, to], as green bytes.
std::vector<int> groundRow(const std::vector<std::uint8_t>& pixels, const scene::Camera& camera, int y, float from, float to) {
    std::vector<int> row;
    for (int x = 0; x < kWidth; ++x) {
        const float wx = groundPoint(camera, x, y).x;
        if (wx >= from && wx <= to) row.push_back(pixels[(static_cast<std::size_t>(y) * kWidth + x) * 4 + 1]);
    }
    return row;
}

// Pixels between lit and shadowed (more than 10 % from either) along a row crossing one edge;
// the row must hold both (a contrast of at least 60 levels), else -1.
int penumbraWidth(const std::vector<int>& row) {
    const int lit = *std::max_element(row.begin(), row.end()), dark = *std::min_element(row.begin(), row.end());
    if (lit - dark < 60) return -1;
    const float margin = 0.1f * static_cast<float>(lit - dark);
    return static_cast<int>(std::count_if(row.begin(), row.end(), [&](int v) { return v > dark + margin && v < lit - margin; }));
}

TEST(RegionView, EachRegionHasItsTechniquesPixelsAndEdges) {
    scene::Scene s = sceneFromJson(kScene);
    render::RegionView view(s, {});
    ASSERT_EQ(view.regionCount(), 2u);
    EXPECT_EQ(view.base().technique().name(), "none");
    EXPECT_EQ(view.region(0).technique().name(), "hard");
    EXPECT_EQ(view.region(1).technique().name(), "pcf-poisson16");
    EXPECT_EQ(view.region(1).options().shadowResolution, 256);

    const auto none = renderRgba8(s, {.technique = "none"}, kWidth, kHeight);
    const auto sharp = renderRgba8(s, render::regionOptions({}, s.regions[0]), kWidth, kHeight);
    const auto soft = renderRgba8(s, render::regionOptions({}, s.regions[1]), kWidth, kHeight);
    render::OffscreenTarget target(kWidth, kHeight);
    view.render(0.0f, s.camera, kWidth, kHeight, target.framebuffer());
    const auto pixels = target.readRgba8();

    // Owner of each pixel from the geometry: the tile its ray meets (boxes stand on their own
    // tile), else the background; a band along tile borders is left out.
    int wrong[3] = {}, counted[3] = {};
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const glm::vec3 p = groundPoint(s.camera, x, y);
            const bool inside = std::abs(p.x) < 5.85f && std::abs(p.z) < 2.85f, outside = std::abs(p.x) > 6.15f || std::abs(p.z) > 3.15f;
            if (!inside && !outside) continue;
            const int owner = outside ? 0 : std::abs(p.x) < 0.15f ? -1 : p.x < 0 ? 1 : 2;
            if (owner < 0) continue;
            const auto& expected = owner == 0 ? none : owner == 1 ? sharp : soft;
            const std::size_t i = (static_cast<std::size_t>(y) * kWidth + x) * 4;
            ++counted[owner];
            for (int c = 0; c < 3; ++c)
                if (pixels[i + c] != expected[i + c]) { ++wrong[owner]; break; }
        }
    const char* names[3] = {"background (the scene's technique, none)", "region sharp (hard 2048)", "region soft (pcf 256)"};
    for (int k = 0; k < 3; ++k) {
        EXPECT_GT(counted[k], 200) << names[k];
        EXPECT_EQ(wrong[k], 0) << names[k] << ": pixels that differ from its technique rendered alone, of " << counted[k];
    }

    // Each tile's box shadow edge (the row through the boxes' middle, left of each box): hard
    // shadows step from lit to shadow within a pixel or two, the wide PCF kernel spreads over
    // several (8 texels of 12/256 world units each side: about 0.75 world units = 8 pixels).
    const int row = kHeight / 2;
    const int hardWidth = penumbraWidth(groundRow(pixels, s.camera, row, -5.9f, -2.9f));
    const int softWidth = penumbraWidth(groundRow(pixels, s.camera, row, 0.2f, 3.4f));
    EXPECT_GE(hardWidth, 0) << "region sharp: its row must cross lit ground and the box's shadow";
    EXPECT_GE(softWidth, 0) << "region soft: its row must cross lit ground and the box's shadow";
    EXPECT_LE(hardWidth, 2) << "region sharp: hard shadow edge";
    EXPECT_GE(softWidth, 4) << "region soft: wide PCF penumbra";
    EXPECT_NE(sharp, soft) << "the two techniques must differ for the test to mean anything";
}

// Seed 002's street itself: seen from above, each block's pixels are those of the block's own
// technique and map resolution (256 .. 4096, soft PCF, LiSPSM) rendered alone, and the blocks
// really differ from one another.
TEST(RegionView, EveryBlockOfTheStreetIsDrawnByItsRegion) {
    scene::Scene s = scene::io::loadScene(std::filesystem::path(PENUMBRA_TEST_DATA) / "../../scenes/street.json");
    ASSERT_EQ(s.regions.size(), 7u);
    // Each block is drawn after a jump of the camera; the sun's box is fitted to each view, as a
    // renderer drawing it alone fits it (a held box would come from the last block's view).
    render::RenderOptions options;
    options.holdSunBox = false;
    render::RegionView view(s, options);
    const int w = 64, h = 64;
    render::OffscreenTarget target(w, h);
    for (std::size_t k = 0; k < s.regions.size(); ++k) {
        const float x = 12.0f * static_cast<float>(k) + 6.0f;  // the block's centre (scripts/make_demo_scenes.py)
        s.camera.position = {x, 7.0f, 0.0f};
        s.camera.target = {x, 0.0f, -0.5f};
        s.camera.up = {0, 0, -1};
        s.camera.fovDeg = 60.0f;  // the ground within about +-4 m of the centre: this block only
        view.render(0.0f, s.camera, w, h, target.framebuffer());
        const auto pixels = target.readRgba8();
        const auto expected = renderRgba8(s, render::regionOptions(options, s.regions[k]), w, h);
        // The neighbouring region's technique or resolution draws this view differently, so the
        // comparison above can tell regions apart.
        const auto otherPixels = renderRgba8(s, render::regionOptions(options, s.regions[(k + 1) % s.regions.size()]), w, h);
        int differing = 0, differingFromOther = 0;
        for (std::size_t i = 0; i < pixels.size(); ++i) {
            if (i % 4 == 3) continue;
            differing += pixels[i] != expected[i];
            differingFromOther += pixels[i] != otherPixels[i];
        }
        EXPECT_EQ(differing, 0) << s.regions[k].name << ": channel values that differ from its technique alone";
        EXPECT_GT(differingFromOther, 20) << s.regions[k].name << ": must differ from " << s.regions[(k + 1) % s.regions.size()].name;
    }
}

TEST(RegionView, SceneFilesNameUnknownRegionsAndTechniques) {
    try {
        sceneFromJson(R"({ "regions": [ { "name": "a" } ],
                           "objects": [ { "shape": "box", "region": "b" } ] })");
        FAIL() << "an object naming an unknown region must be an error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("unknown region 'b'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'a'"), std::string::npos) << "names the known regions: " << e.what();
    }
    scene::Scene s = sceneFromJson(R"({ "regions": [ { "name": "street", "technique": "no-such-technique" } ],
                                        "objects": [ { "shape": "box", "region": "street" } ] })");
    try {
        render::RegionView view(s, {});
        FAIL() << "a region with an unknown technique must be an error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("regions[0] 'street'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("no-such-technique"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace penumbra::test
