// DepthTileBounds (shadows/common) promises, for every tile of every level, a plane under every
// depth texel of the tile and its border, d >= g . c + a, and the farthest depth there; the PCF and
// PCSS tap skips are exact only while that holds. Checked on the CPU, every texel of every tile,
// against the depth map of a scene with slopes, edges, curved casters and a ridge.
#include "GlTestSupport.h"

#include "render/Offscreen.h"
#include "shadows/common/DepthTileBounds.h"

#include <algorithm>

namespace penumbra::test {
namespace {

std::vector<float> readLevel(GLuint texture, GLint level, GLenum format, int channels, int layers, int& size) {
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_WIDTH, &size);
    std::vector<float> texels(static_cast<std::size_t>(size * size * layers * channels));
    glGetTextureImage(texture, level, format, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
    return texels;
}

TEST(DepthTileBounds, EveryLevelBoundsEveryTexelOfItsTileAndBorder) {
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [5, 6, 7], "target": [0, 0.5, 0], "fov_deg": 45 },
      "lights": [ { "type": "directional", "direction": [-0.5, -1, -0.3], "shadow": { "resolution": 256 } } ],
      "objects": [ { "shape": "plane", "size": [10, 10] },
                   { "shape": "box", "size": [1, 1, 1], "position": [-1, 0.7, 0], "rotation_deg": [20, 30, 10] },
                   { "shape": "sphere", "radius": 0.6, "position": [1.2, 1.0, 1.0] },
                   { "shape": "box", "size": [2, 2, 3], "position": [2.5, 0, -2.5], "rotation_deg": [0, 0, 45] },
                   { "shape": "sphere", "radius": 0.2, "position": [-3, 0.2, 3] } ] })");
    render::RenderOptions options;
    options.technique = "pcss";
    render::Renderer renderer(s, options);
    render::OffscreenTarget target{64, 64};
    renderer.render(0.0f, s.camera, 64, 64, target.framebuffer());
    const auto views = renderer.technique().debugViews();
    const auto find = [&](const std::string& label) {
        const auto it = std::find_if(views.begin(), views.end(), [&](const auto& v) { return v.label.rfind(label, 0) == 0; });
        EXPECT_NE(it, views.end()) << label;
        return it == views.end() ? shadows::DebugView{} : *it;
    };
    const shadows::DebugView depthView = find("light 0 depth"), boundsView = find("light 0 depth tile bounds");
    ASSERT_NE(boundsView.texture, 0u);
    int res = 0;
    const std::vector<float> depth = readLevel(depthView.texture, 0, GL_DEPTH_COMPONENT, 1, 1, res);
    ASSERT_EQ(res, 256);
    const auto depthAt = [&](int x, int y) {
        return depth[static_cast<std::size_t>(std::clamp(y, 0, res - 1) * res + std::clamp(x, 0, res - 1))];
    };
    GLint layers = 0;
    glGetTextureLevelParameteriv(boundsView.texture, 0, GL_TEXTURE_DEPTH, &layers);
    std::vector<int> validTiles;
    long violations = 0, checked = 0;
    GLint levels = 0;
    glGetTextureParameteriv(boundsView.texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    // pcss's default 48-texel reach needs level 3 (tiles of 64, a border of 58); one more level
    // is made against rounding, and no other.
    EXPECT_EQ(levels, shadows::DepthTileBounds::levelFor(48.0f) + 2);
    EXPECT_EQ(shadows::DepthTileBounds::levelFor(48.0f), 3);
    for (int level = 0; level < levels && gpu::kDepthTile << level <= res; ++level) {
        int size = 0;
        const std::vector<float> bounds = readLevel(boundsView.texture, level, GL_RGBA, 4, layers, size);
        const int side = gpu::kDepthTile << level, border = side - gpu::kDepthTileInset, tiles = (res + side - 1) / side;
        ASSERT_GE(size, tiles);
        int valid = 0;
        for (int ty = 0; ty < tiles; ++ty)
            for (int tx = 0; tx < tiles; ++tx) {
                const float* b = &bounds[((static_cast<std::size_t>(boundsView.layer) * size + ty) * size + tx) * 4];
                if (b[0] <= -3.0f) continue;  // a tile whose neighbourhood leaves the map: never agrees
                ++valid;
                for (int y = ty * side - border; y < (ty + 1) * side + border; ++y)
                    for (int x = tx * side - border; x < (tx + 1) * side + border; ++x) {
                        const float d = depthAt(x, y);
                        const float plane = b[1] * (static_cast<float>(x - tx * side) + 0.5f) +
                                            b[2] * (static_cast<float>(y - ty * side) + 0.5f) + b[0];
                        violations += d < plane - 1e-6f || d > b[3];
                        ++checked;
                    }
            }
        validTiles.push_back(valid);
    }
    EXPECT_EQ(violations, 0) << "of " << checked << " texel checks";
    // Levels 0-3 (the radii PCF and PCSS ask for) have tiles inside the map to check.
    ASSERT_GE(validTiles.size(), 4u);
    for (int level = 0; level < 4; ++level) EXPECT_GT(validTiles[static_cast<std::size_t>(level)], 0) << "level " << level;
}

}  // namespace
}  // namespace penumbra::test
