// The bench's floor (bench/FloorRenderer) is what every technique's cost is divided by, so its
// picture must be a correct shadowed frame too. Its shadow map once shared texture unit 0 with
// the diffuse texture GpuScene::draw binds: behind a textured object the lookup compared against
// the texture's red channel (NVIDIA reported it as undefined behaviour every frame).
#include "GlTestSupport.h"

#include "bench/FloorRenderer.h"

namespace penumbra::test {
namespace {

TEST(FloorRenderer, TexturedReceiversGetTheShadowOfTheMapNotOfTheirTexture) {
    // Seen from straight above; the sun at 45 degrees casts the box's shadow towards +x. The
    // ground's missing texture becomes the checker (red 1.0 / 0.08), drawn first.
    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 10, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov_deg": 60 },
      "lights": [ { "type": "directional", "direction": [1, -1, 0], "shadow": { "resolution": 512 } } ],
      "objects": [ { "shape": "plane", "size": [12, 12], "material": { "texture": "no_such_texture.png" } },
                   { "shape": "box", "size": [1, 1, 1], "position": [0, 1, 0] } ] })");
    const int size = 96;
    bench::FloorRenderer floor(s, bench::FloorRenderer::Mode::Lambert, 512);
    floor.render(0.0f, s.camera, size, size);
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(size) * size * 4);
    glBindFramebuffer(GL_FRAMEBUFFER, floor.framebuffer());
    glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    // The box (y 0.5..1.5, x and z -0.5..0.5) shades the ground over x 0..2: beyond the box
    // (x 0.7..1.8, |z| < 0.35) only the 0.08 ambient is left; away from it (x < -2) Lambert
    // adds cos 45 degrees.
    int shadowed = 0, lit = 0, wrong = 0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const Ray r = pixelRay(s.camera, x, y, size, size);
            const glm::vec3 g = r.origin + r.direction * (-r.origin.y / r.direction.y);
            const int value = rgba[(static_cast<std::size_t>(y) * size + x) * 4];
            if (g.x > 0.7f && g.x < 1.8f && std::abs(g.z) < 0.35f) {
                ++shadowed;
                wrong += value > 30;  // 0.08 -> 20
            } else if (g.x < -2.0f && std::abs(g.x) < 5.5f && std::abs(g.z) < 5.5f) {
                ++lit;
                wrong += value < 190;  // 0.787 -> 200
            }
        }
    EXPECT_GT(shadowed, 50);
    EXPECT_GT(lit, 200);
    EXPECT_EQ(wrong, 0) << "of " << shadowed << " shadowed and " << lit << " lit pixels";
}

}  // namespace
}  // namespace penumbra::test
