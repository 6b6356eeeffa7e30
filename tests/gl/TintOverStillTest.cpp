// The plain techniques' tint (DepthAndTintMaps, NearestLayer) is drawn over the still casters'
// depth alone when every pane that shares texels with an animated opaque caster lies behind it
// (translucentBehindMoving): the caster's motion then leaves the tint as it is, and a soft
// shadow's penumbra behind a pane keeps the pane's colour, as the light that passes the caster's
// rim meets the pane. Where a pane lies in front of the animated caster the tint is still tested
// against it, so that the caster itself gets the panes in front of it alone.
#include "GlTestSupport.h"

#include <algorithm>
#include <cmath>

namespace penumbra::test {
namespace {

constexpr int kSize = 128;

// Where the ray through pixel (x, y) first meets a sphere (nullopt: it misses).
std::optional<glm::vec3> hitSphere(const Ray& ray, glm::vec3 centre, float radius) {
    const glm::vec3 oc = ray.origin - centre;
    const float b = glm::dot(oc, ray.direction), c = glm::dot(oc, oc) - radius * radius, disc = b * b - c;
    if (disc < 0.0f) return std::nullopt;
    const float t = -b - std::sqrt(disc);
    if (t <= 0.0f) return std::nullopt;
    return ray.origin + ray.direction * t;
}

// A green pane under an animated stone, the sun nearly straight down, a soft lookup 6 texels wide
// on a 256^2 map: around the stone's shadow on the ground under the pane, every partly lit pixel
// is lit through the pane, (0.1, 0.9, 0.1) times its visibility. (A tint tested against the stone
// left the pane out of the texels under it: those pixels took white light, r = g.)
TEST(TintOverStill, ASoftPenumbraBehindAPaneKeepsThePanesColour) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 8, 2], "target": [0, 0, 0], "fov_deg": 40 },
      "ambient": [0, 0, 0],
      "lights": [ { "type": "directional", "direction": [0.05, -1, 0.02], "shadow": { "resolution": 256 } } ],
      "objects": [ { "shape": "plane", "size": [8, 8] },
                   { "name": "pane", "shape": "plane", "size": [4, 4], "position": [0, 1.5, 0],
                     "material": { "transmission": [0.1, 0.9, 0.1] } },
                   { "name": "stone", "shape": "sphere", "radius": 0.5,
                     "animation": [[0, 0, 3, 0], [1, 0.2, 3, 0]] } ] })");
    const Frame f = renderChannel(s, render::OutputMode::Visibility, 0, kSize, kSize, "pcf-poisson16", {{"radius_texels", "6"}});
    int penumbra = 0, white = 0;
    float worst = 0.0f;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const Ray ray = pixelRay(s.camera, x, y, kSize, kSize);
            if (hitSphere(ray, {0.0f, 3.0f, 0.0f}, 0.55f)) continue;  // the stone itself
            const glm::vec3 p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
            if (std::max(std::abs(p.x), std::abs(p.z)) > 1.6f) continue;  // outside the pane's shadow, or near its edge
            const glm::vec3 v = f.at(x, y);
            if (v.g < 0.05f || v.g > 0.85f) continue;  // umbra or fully lit
            ++penumbra;
            const float off = std::abs(v.r - v.g / 9.0f);
            worst = std::max(worst, off);
            white += off > 0.02f;
        }
    EXPECT_GE(penumbra, 40) << "the stone's penumbra must be in view";
    EXPECT_EQ(white, 0) << "penumbra pixels lit past the pane (worst r off by " << worst << ")";
}

// A red pane above an animated stone, a green one below it, the sun straight down: the stone's lit
// top gets the red pane's (0.9, 0.2, 0.2) alone, never red times green. A pane lies in front of
// the stone, so hard's tint is tested against it; cssm2's colour map, drawn inside depth_'s pass,
// counts only the layers in front of its receiver either way.
class TintOverStillBetweenPanes : public ::testing::TestWithParam<const char*> {};

TEST_P(TintOverStillBetweenPanes, AnAnimatedCasterGetsOnlyThoseInFrontOfIt) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 8, 3], "target": [0, 0, 0], "fov_deg": 40 },
      "ambient": [0, 0, 0],
      "lights": [ { "type": "directional", "direction": [0.02, -1, 0.01], "shadow": { "resolution": 256 } } ],
      "objects": [ { "shape": "plane", "size": [8, 8] },
                   { "name": "red pane", "shape": "plane", "size": [4, 4], "position": [0, 4, 0],
                     "material": { "transmission": [0.9, 0.2, 0.2] } },
                   { "name": "stone", "shape": "sphere", "radius": 0.8,
                     "animation": [[0, 0, 2.5, 0], [1, 0.2, 2.5, 0]] },
                   { "name": "green pane", "shape": "plane", "size": [4, 4], "position": [0, 1, 0],
                     "material": { "transmission": [0.1, 0.9, 0.1] } } ] })");
    const Frame f = renderChannel(s, render::OutputMode::Visibility, 0, kSize, kSize, GetParam());
    int top = 0, off = 0;
    float worst = 0.0f;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const std::optional<glm::vec3> p = hitSphere(pixelRay(s.camera, x, y, kSize, kSize), {0.0f, 2.5f, 0.0f}, 0.8f);
            if (!p || (*p - glm::vec3(0.0f, 2.5f, 0.0f)).y < 0.5f * 0.8f) continue;  // its top only, away from the terminator
            ++top;
            const glm::vec3 d = glm::abs(f.at(x, y) - glm::vec3(0.9f, 0.2f, 0.2f));
            worst = std::max(worst, std::max(d.x, std::max(d.y, d.z)));
            off += std::max(d.x, std::max(d.y, d.z)) > 2.0f / 255.0f;
        }
    EXPECT_GE(top, 200);
    EXPECT_EQ(off, 0) << "pixels of the stone's top not lit through the red pane alone (worst off by " << worst << ")";
}

INSTANTIATE_TEST_SUITE_P(Techniques, TintOverStillBetweenPanes, ::testing::Values("hard", "cssm2"),
                         [](const auto& info) { return testNameOf(info.param); });

}  // namespace
}  // namespace penumbra::test
