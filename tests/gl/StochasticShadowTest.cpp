// Coloured stochastic shadow maps (McGuire & Enderton 2011): the received light under translucent panes matches
// ρ = (1 - t) α per layer within the noise its sample count allows; noise falls with taps; the
// white-clear fix; order independence.
#include "GlTestSupport.h"

#include "render/Offscreen.h"

#include <algorithm>
#include <cmath>

namespace penumbra::test {
namespace {

using render::OutputMode;

struct RegionStats {
    glm::vec3 mean{0.0f};
    glm::vec3 stddev{0.0f};  // per-pixel spread
};

// White light straight down through panes (single surfaces) onto a white plane; statistics of
// the visibility over the central 24x24 pixels, all well inside every pane's footprint.
RegionStats underPanes(const std::vector<std::string>& materials, const std::string& technique,
                       const shadows::ParameterValues& parameters = {}, bool reversed = false,
                       Frame* whole = nullptr,
                       const std::string& light = R"({ "type": "directional", "direction": [0, -1, 0], "shadow": { "resolution": 1024 } })") {
    std::vector<std::string> objects{R"({ "shape": "plane", "size": [20, 20] })"};
    float y = 2.0f;
    for (const auto& m : materials) {
        objects.push_back(R"({ "shape": "plane", "size": [3, 3], "position": [0, )" + std::to_string(y) +
                          R"(, 0], "material": )" + m + "}");
        y += 1.0f;
    }
    if (reversed) std::reverse(objects.begin(), objects.end());
    std::string list;
    for (const auto& o : objects) list += (list.empty() ? "" : ", ") + o;
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 12, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 40 },
      "lights": [ )" + light + R"( ],
      "objects": [ )" + list + "] }");
    render::RenderOptions options;
    options.technique = technique;
    options.output = OutputMode::Visibility;
    options.parameters = parameters;
    render::Renderer renderer(s, options);
    render::OffscreenTarget target(96, 96);
    renderer.render(0.0f, s.camera, 96, 96, target.framebuffer());
    const Frame f{96, 96, renderer.readLinear()};
    if (whole) *whole = f;
    RegionStats r;
    int n = 0;
    glm::vec3 sum2(0.0f);
    for (int py = 36; py < 60; ++py)
        for (int px = 36; px < 60; ++px) {
            const glm::vec3 v = f.at(px, py);
            r.mean += v;
            sum2 += v * v;
            ++n;
        }
    r.mean /= float(n);
    r.stddev = glm::sqrt(glm::max(sum2 / float(n) - r.mean * r.mean, glm::vec3(0.0f)));
    return r;
}

const std::string kGlass = R"({ "alpha": 1, "transmission": [0.1, 0.9, 0.1] })";
const std::string kNylon = R"({ "alpha": 0.25, "transmission": [0.5, 0.5, 0.5] })";
const std::string kBlackNylon = R"({ "alpha": 0.25 })";

// Tolerance on the mean over the 576 central pixels. Per pixel the estimate is binomial:
// sd = sqrt(ρ(1-ρ)/n) ≈ 0.083 for green glass with the default 13-tap filter (measured 0.081).
// The pixels read mostly distinct texels (about 10 map texels per pixel), so the mean's sd is
// about 0.083 / sqrt(576) ≈ 0.0035 per channel; 0.025 is 7 sd, loose enough for the texel
// correlation between neighbouring pixels, tight enough to catch a wrong ρ (0.1 vs 0.19 for t²).
constexpr float kMeanTolerance = 0.025f;

void expectNear(const glm::vec3& got, const glm::vec3& want, const std::string& what) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], kMeanTolerance) << what << " channel " << c;
}

class Stochastic : public ::testing::TestWithParam<const char*> {};

TEST_P(Stochastic, ReceivedLightUnderPanesMatchesTransmission) {
    const std::string t = GetParam();
    expectNear(underPanes({kGlass}, t).mean, {0.1f, 0.9f, 0.1f}, t + " green glass");
    expectNear(underPanes({kGlass, kGlass}, t).mean, {0.01f, 0.81f, 0.01f}, t + " two green panes");
    expectNear(underPanes({kNylon}, t).mean, glm::vec3(0.875f), t + " translucent nylon");
    expectNear(underPanes({kBlackNylon}, t).mean, glm::vec3(0.75f), t + " black nylon");
}

TEST_P(Stochastic, PointAndSpotLightsTransmitTheSame) {
    // Cube maps (point) and perspective maps (spot) through the same panes, light high above.
    const std::string t = GetParam();
    const std::string point = R"({ "type": "point", "position": [0, 30, 0], "range": 60, "shadow": { "resolution": 1024 } })";
    const std::string spot = R"({ "type": "spot", "position": [0, 30, 0], "direction": [0, -1, 0], "angle_deg": 40,
                                  "range": 60, "shadow": { "resolution": 1024 } })";
    for (const auto& [name, light] : {std::pair{"point", point}, std::pair{"spot", spot}}) {
        expectNear(underPanes({kGlass}, t, {}, false, nullptr, light).mean, {0.1f, 0.9f, 0.1f}, t + " " + name + " green glass");
        expectNear(underPanes({kGlass, kGlass}, t, {}, false, nullptr, light).mean, {0.01f, 0.81f, 0.01f},
                   t + " " + name + " two panes");
    }
}

TEST_P(Stochastic, NoiseFallsAsTapsGrow) {
    // Per-pixel spread inside the uniform green shadow (green channel, p = 0.9) per filter,
    // against the binomial spread sqrt(p (1 - p) / n) of n independent taps.
    const int taps[5] = {9, 16, 20, 30, 13};
    float sd[5];
    for (int filter = 0; filter < 5; ++filter) {
        sd[filter] = underPanes({kGlass}, GetParam(), {{"filter", std::to_string(filter)}}).stddev.g;
        const float binomial = std::sqrt(0.9f * 0.1f / float(taps[filter]));
        std::printf("%s filter %d (%d taps): sd %.4f, binomial %.4f\n", GetParam(), filter, taps[filter], sd[filter], binomial);
        EXPECT_GT(sd[filter], 0.75f * binomial) << "too smooth for a stochastic estimate: filter " << filter;
        EXPECT_LT(sd[filter], 1.3f * binomial) << "taps not independent: filter " << filter;
    }
    EXPECT_LT(sd[1], sd[0]);  // 16 < 9 taps
    EXPECT_LT(sd[2], sd[0]);  // 20 < 9
    EXPECT_LT(sd[3], sd[1]);  // 30 < 16
}

TEST_P(Stochastic, PaneWithNothingOpaqueBehindItIsNotShadowed) {
    // The thesis's white-clear fix: map texels with no opaque caster must read "no occluder".
    // Around the pane's footprint nothing translucent lies above the ground: exactly lit.
    Frame f;
    underPanes({kGlass}, GetParam(), {}, false, &f);
    for (int y : {2, 10, 85, 93})
        for (int x : {2, 10, 85, 93}) EXPECT_EQ(f.at(x, y), glm::vec3(1.0f)) << x << "," << y;
}

TEST_P(Stochastic, ObjectOrderDoesNotChangeTheImage) {
    Frame forward, backward;
    underPanes({kGlass, kNylon}, GetParam(), {}, false, &forward);
    underPanes({kGlass, kNylon}, GetParam(), {}, true, &backward);
    float worst = 0.0f;
    for (std::size_t i = 0; i < forward.rgba.size(); ++i) worst = std::max(worst, std::abs(forward.rgba[i] - backward.rgba[i]));
    EXPECT_EQ(worst, 0.0f) << "ξ is seeded by light-space position and depth, MIN blending commutes";
}

INSTANTIATE_TEST_SUITE_P(Variants, Stochastic, ::testing::Values("cssm1", "cssm2"),
                         [](const auto& info) { return std::string(info.param); });

TEST(StochasticShadows, BothRandomGeneratorsAreUnbiased) {
    for (const char* rng : {"pcg", "sin-fract"}) {
        const RegionStats r = underPanes({kBlackNylon}, "cssm2", {{"rng", rng}, {"filter", "random30"}});
        std::printf("rng %s: black nylon mean %.4f sd %.4f\n", rng, r.mean.g, r.stddev.g);
        EXPECT_NEAR(r.mean.g, 0.75f, kMeanTolerance) << "generator " << rng;
    }
}

}  // namespace
}  // namespace penumbra::test
