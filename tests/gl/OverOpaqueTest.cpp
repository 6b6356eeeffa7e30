// The tint pass and CSSM's colour map test translucent casters against the opaque casters' depth,
// which the driver pushed back with glPolygonOffset. Their own tested depth is pushed back in the
// shader (over_opaque.glsl) by the light's offset and a few units more, so that a translucent
// face lying on an opaque one fails the test. That holds only if the shader's offset is at least
// the driver's, whose `r` (GL 4.5 §14.6.5) is the implementation's: these tests measure it.
#include "GlTestSupport.h"
#include "gl/Framebuffer.h"
#include "gl/PassState.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "shadows/common/DepthAndTintMaps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace penumbra::test {
namespace {

namespace fs = std::filesystem;

// A plane at window depth uDepth in the viewport's corner (-1, -1), rising by uSlope per pixel along x and
// y (the default depth range: window z = ndc z / 2 + 1/2). uTiles 0: one triangle covering the
// viewport; n > 0: the same plane cut into n x n tiles of two triangles, turned by 25 degrees, as
// a small face lying on a big one is (a glass block's bottom on the floor).
constexpr const char* kPlaneVert = R"(#version 450 core
uniform float uDepth;
uniform vec2 uSlope;
uniform float uWidth;
uniform int uTiles;
void main() {
    vec2 p;
    if (uTiles == 0) {
        p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
    } else {
        const vec2 corner[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));
        int tile = gl_VertexID / 6;
        vec2 q = (vec2(tile % uTiles, tile / uTiles) + corner[gl_VertexID % 6]) / float(uTiles) * 3.0 - 1.5;
        float c = cos(0.4363), s = sin(0.4363);
        p = mat2(c, s, -s, c) * q;
    }
    float z = uDepth + dot(uSlope, p + 1.0) * uWidth;
    gl_Position = vec4(p, z * 2.0 - 1.0, 1.0);
}
)";
constexpr const char* kOpaqueFrag = "#version 450 core\nvoid main() {}\n";
constexpr const char* kTestedFrag = R"(#version 450 core
#include "src/shadows/common/glsl/over_opaque.glsl"
void main() { testBehindOpaqueOffset(); }
)";

fs::path writeShader(const char* name, const char* text) {
    const fs::path dir = fs::temp_directory_path() / "penumbra_over_opaque_test";
    fs::create_directories(dir);
    std::ofstream(dir / name) << text;
    return dir / name;
}

struct OffsetProbe {
    static constexpr int kSize = 32;
    gl::Texture depth = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, kSize, kSize);
    gl::Framebuffer fbo;
    gl::VertexArray vao;
    gl::Program opaque = gl::Program::build({.vertex = writeShader("plane.vert", kPlaneVert), .fragment = writeShader("opaque.frag", kOpaqueFrag)});
    gl::Program tested = gl::Program::build({.vertex = writeShader("plane.vert", kPlaneVert), .fragment = writeShader("tested.frag", kTestedFrag)});

    OffsetProbe() {
        fbo.attach(GL_DEPTH_ATTACHMENT, depth);
        fbo.setNoColor();
        fbo.checkComplete("polygon offset probe");
    }

    // The depths the plane leaves: drawn by `program` whole or in `tiles` x `tiles`, with
    // glPolygonOffset(offset) where given.
    std::vector<float> draw(const gl::Program& program, float z, glm::vec2 slope, const glm::vec2* offset, int tiles = 0) {
        gl::PassState state = gl::PassState::depthOnly();
        state.depthFunc = GL_ALWAYS;
        if (offset) state.withPolygonOffset(offset->x, offset->y);
        const gl::ScopedPassState scope(state);
        fbo.beginDepthPass(kSize, kSize);
        for (const gl::Program* p : {&opaque, &tested}) {
            p->set("uDepth", z);
            p->set("uSlope", slope);
            p->set("uWidth", static_cast<float>(kSize) / 2.0f);
            p->set("uTiles", tiles);
        }
        program.use();
        vao.bind();
        glDrawArrays(GL_TRIANGLES, 0, tiles == 0 ? 3 : 6 * tiles * tiles);
        std::vector<float> out(kSize * kSize);
        glGetTextureImage(depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, static_cast<GLsizei>(out.size() * sizeof(float)), out.data());
        return out;
    }
};

// The float depth's step at z: 2^(e - 23), e its exponent.
double floatStep(float z) {
    int e = 0;
    std::frexp(z, &e);  // z = m 2^e, m in [0.5, 1): the IEEE exponent is e - 1
    return std::ldexp(1.0, e - 1 - 23);
}

// A translucent face lying exactly on an opaque one, at depths from a sun's near range to a spot's
// far one, flat and sloped, cut into the same triangles or into small turned ones (whose depths
// the rasteriser interpolates from other vertices): the depth it is tested with lies behind the
// opaque depth the driver offset, at every pixel. The printout gives the driver's unit and the
// margin in steps of the float depth at the map's centre. Measured: llvmpipe's unit is one step,
// an H200's (driver 580.159.04) two. With the unit taken at the fragment's own depth (before
// 2^-23), the steep plane, a floor reaching from z 0.002 to 0.9 across the map, failed here by
// 3-4 steps, and on the H200 the glass block of CompareTest took its bottom face's tint twice.
TEST(OverOpaque, ATranslucentFaceOnAnOpaqueOneIsTestedBehindTheDriversOffset) {
    OffsetProbe probe;
    const scene::Light light;  // the default shadow polygon offset
    const glm::vec2 lightOffset = light.shadow.polygonOffset;
    const glm::vec2 units{0.0f, 1.0f};
    probe.tested.set("uTestOffset", shadows::DepthAndTintMaps::translucentTestOffset(light));
    int failing = 0;
    for (float z : {0.002f, 0.03f, 0.2f, 0.45f, 0.7f, 0.97f})
        for (glm::vec2 slope : {glm::vec2(0.0f), glm::vec2(2e-5f, 0.7e-5f), glm::vec2(-3e-6f, 1.1e-6f), glm::vec2(0.028f, 0.0f)}) {
            if (slope.x > 0.01f && z > 0.01f) continue;  // the steep plane: from z at the map's left to 0.9 at its right
            const auto flat = probe.draw(probe.opaque, z, glm::vec2(0.0f), nullptr);
            const auto oneUnit = probe.draw(probe.opaque, z, glm::vec2(0.0f), &units);
            const auto plain = probe.draw(probe.opaque, z, slope, nullptr);
            const auto driver = probe.draw(probe.opaque, z, slope, &lightOffset);
            const std::size_t centre = plain.size() / 2 + OffsetProbe::kSize / 2;
            const double step = floatStep(plain[centre]);
            for (int tiles : {0, 12}) {
                const auto shader = probe.draw(probe.tested, z, slope, nullptr, tiles);
                double worstMargin = 1e9;
                for (std::size_t i = 0; i < plain.size(); ++i) {
                    worstMargin = std::min(worstMargin, static_cast<double>(shader[i]) - driver[i]);
                    if (shader[i] <= driver[i]) ++failing;
                }
                std::printf("z %.3f slope %.0e %.0e, %s: the driver's unit %.2f float steps; offsets driver %.1f, shader %.1f steps; worst margin %.1f\n",
                            z, slope.x, slope.y, tiles ? "small turned triangles" : "the same triangle",
                            (oneUnit[centre] - flat[centre]) / floatStep(flat[centre]), (driver[centre] - plain[centre]) / step,
                            (shader[centre] - plain[centre]) / step, worstMargin / step);
            }
        }
    EXPECT_EQ(failing, 0) << "pixels where a translucent face on an opaque one would pass the depth test";
}

}  // namespace
}  // namespace penumbra::test
