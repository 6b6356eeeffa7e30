// Split view (issue 13): one frame, two techniques side by side. Left of the divider the pixels
// are those of technique A rendered alone, right of it those of technique B, byte for byte; the
// two columns at the divider are white.
#include "GlTestSupport.h"

#include "render/Offscreen.h"
#include "render/SplitView.h"

namespace penumbra::test {
namespace {

// Shaded into the float target and resolved, or straight into 8-bit sRGB (RenderOptions::floatTarget).
class SplitView : public ::testing::TestWithParam<bool> {};

TEST_P(SplitView, EachSideHasItsTechniquesPixels) {
    const bool floatTarget = GetParam();
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 7, 6], "target": [0, 0, 0] },
      "lights": [ { "type": "directional", "direction": [-0.3, -1, -0.4], "size": 3, "shadow": { "resolution": 512 } } ],
      "objects": [ { "shape": "plane", "size": [12, 12] },
                   { "shape": "box", "position": [-2, 1, 0] }, { "shape": "box", "position": [2, 1, 0] } ] })");
    const int w = 96, h = 64;
    const auto hard = renderRgba8(s, {.technique = "hard", .floatTarget = floatTarget}, w, h),
               soft = renderRgba8(s, {.technique = "pcf-poisson16", .floatTarget = floatTarget}, w, h);
    ASSERT_NE(hard, soft) << "the two techniques must differ somewhere for the test to mean anything";

    render::RenderOptions left, right;
    left.technique = "hard";
    right.technique = "pcf-poisson16";
    left.floatTarget = right.floatTarget = floatTarget;
    render::SplitView split(s, left, right);
    split.setDivider(0.375f);
    const int divider = split.dividerColumn(w);
    ASSERT_EQ(divider, 36);
    render::OffscreenTarget target(w, h);
    auto compare = [&](const std::vector<std::uint8_t>& leftPixels, const std::vector<std::uint8_t>& rightPixels) {
        split.render(0.0f, s.camera, w, h, target.framebuffer());
        const auto pixels = target.readRgba8();
        int leftWrong = 0, rightWrong = 0, dividerWrong = 0, differingRight = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c) {
                    const std::size_t i = (static_cast<std::size_t>(y) * w + x) * 4 + c;
                    if (x == divider - 1 || x == divider) dividerWrong += pixels[i] != 255;
                    else if (x < divider) leftWrong += pixels[i] != leftPixels[i];
                    else {
                        rightWrong += pixels[i] != rightPixels[i];
                        differingRight += leftPixels[i] != rightPixels[i];
                    }
                }
        EXPECT_EQ(leftWrong, 0) << "left of the divider: the left technique's pixels";
        EXPECT_EQ(rightWrong, 0) << "right of it: the right technique's pixels";
        EXPECT_EQ(dividerWrong, 0) << "the divider is white";
        EXPECT_GT(differingRight, 0) << "the right side must show where the techniques differ";
    };
    compare(hard, soft);
    split.swap();  // the key that swaps the halves
    compare(soft, hard);
}

INSTANTIATE_TEST_SUITE_P(Targets, SplitView, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "FloatTarget" : "Srgb8Target"; });

}  // namespace
}  // namespace penumbra::test
