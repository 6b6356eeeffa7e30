// Shading straight into 8-bit sRGB (RenderOptions::floatTarget false, render/SrgbTarget.h) gives
// the picture the float target and its resolve pass give, to within rounding: fog on opaque and
// translucent surfaces, two panes stacked over a fogged floor and over the background, into an
// offscreen texture (shaded into directly) and into a renderbuffer (copied into).
#include "GlTestSupport.h"

#include "gl/Framebuffer.h"
#include "gl/Texture.h"
#include "gpu/ShaderContract.h"
#include "render/Offscreen.h"
#include "util/Srgb.h"

#include <array>
#include <cmath>
#include <stdexcept>

namespace penumbra::test {
namespace {

// Nothing brighter than white behind the panes: an 8-bit target clamps what lies behind glass
// before blending, the float target after (docs/measurements.md).
scene::Scene fogAndPanes() {
    return sceneFromJson(R"({
      "camera": { "position": [0, 2.5, 9], "target": [0, 0.5, 0], "fov_deg": 50, "far": 60 },
      "background": [0.55, 0.6, 0.7], "ambient": [0.15, 0.15, 0.15], "fog": { "start": 4, "end": 30 },
      "lights": [ { "type": "directional", "direction": [-0.4, -1, -0.3], "intensity": 0.7, "shadow": { "resolution": 512 } } ],
      "objects": [ { "shape": "plane", "size": [60, 60], "material": { "diffuse": [0.8, 0.75, 0.7] } },
                   { "shape": "box", "position": [2, 0.5, -2], "material": { "diffuse": [0.7, 0.2, 0.2] } },
                   { "shape": "plane", "size": [4, 3], "position": [-0.5, 1.5, 0], "rotation_deg": [90, 0, 0],
                     "material": { "diffuse": [0.1, 0.4, 0.1], "transmission": [0.2, 0.8, 0.3] } },
                   { "shape": "plane", "size": [4, 3], "position": [0.8, 2.2, -1.5], "rotation_deg": [90, 0, 0],
                     "material": { "diffuse": [0.1, 0.1, 0.4], "alpha": 0.6, "transmission": [0.3, 0.4, 0.9] } } ] })");
}

render::RenderOptions options(const std::string& technique, bool floatTarget) {
    render::RenderOptions o = optionsFor(technique);
    o.floatTarget = floatTarget;
    return o;
}

struct Difference {
    int largest = 0, pixelsOff = 0;  // by more than 1/255 in any channel
};
Difference compareBytes(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    Difference d;
    for (std::size_t p = 0; p + 3 < a.size(); p += 4) {
        int off = 0;
        for (std::size_t c = 0; c < 3; ++c) off = std::max(off, std::abs(int(a[p + c]) - int(b[p + c])));
        d.largest = std::max(d.largest, off);
        d.pixelsOff += off > 1;
    }
    return d;
}

// The picture must hold what the comparison is about: the background, the fog over the far
// floor, a pane over the floor. Rows count from the top (OffscreenTarget::readRgba8).
void expectFogAndPanes(const std::vector<std::uint8_t>& rgba, int w) {
    auto at = [&](int x, int y) {
        const std::size_t i = (static_cast<std::size_t>(y) * w + x) * 4;
        return glm::ivec3(rgba[i], rgba[i + 1], rgba[i + 2]);
    };
    const glm::ivec3 sky = at(20, 10), farFloor = at(20, 39), nearFloor = at(80, 90), pane = at(60, 45);
    EXPECT_NEAR(sky.b, 218, 2) << "the background (0.7 linear)";
    EXPECT_GT(farFloor.b, nearFloor.b + 10) << "the far floor fogged towards the background";
    EXPECT_GT(pane.g, pane.r + 30) << "the green pane over the floor";
}

class SrgbTarget : public ::testing::TestWithParam<std::string> {};

TEST_P(SrgbTarget, ShadesIntoAnOffscreenTextureWhatTheFloatTargetResolves) {
    scene::Scene s = fogAndPanes();
    const int w = 160, h = 96;
    const auto resolved = renderRgba8(s, options(GetParam(), true), w, h);
    const auto direct = renderRgba8(s, options(GetParam(), false), w, h);
    expectFogAndPanes(resolved, w);
    const Difference d = compareBytes(direct, resolved);
    EXPECT_LE(d.largest, 1) << d.pixelsOff << " pixels off by more than 1/255";
}

TEST_P(SrgbTarget, CopiesIntoATargetItCannotShadeIntoWhatTheFloatTargetResolves) {
    scene::Scene s = fogAndPanes();
    const int w = 160, h = 96;
    GLuint colour = 0;
    glCreateRenderbuffers(1, &colour);
    glNamedRenderbufferStorage(colour, GL_RGBA8, w, h);
    gl::Framebuffer window;  // like a window's: a renderbuffer, not a texture
    glNamedFramebufferRenderbuffer(window.id(), GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    window.setDrawBuffers({GL_COLOR_ATTACHMENT0});
    window.checkComplete("renderbuffer target");
    auto draw = [&](bool floatTarget) {
        const float magenta[4] = {1, 0, 1, 1};  // whatever the last draw left there must not pass
        glClearNamedFramebufferfv(window.id(), GL_COLOR, 0, magenta);
        render::Renderer renderer(s, options(GetParam(), floatTarget));
        renderer.render(0.0f, s.camera, w, h, window.id());
        GLint bound = 0;
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
        EXPECT_EQ(static_cast<GLuint>(bound), window.id()) << "what draws next (the window's UI) must draw into the output";
        return render::readFramebufferRgba8(window.id(), w, h);
    };
    const auto resolved = draw(true), copied = draw(false);
    glDeleteRenderbuffers(1, &colour);
    const Difference d = compareBytes(copied, resolved);
    EXPECT_LE(d.largest, 1) << d.pixelsOff << " pixels off by more than 1/255";
}

INSTANTIATE_TEST_SUITE_P(Techniques, SrgbTarget, ::testing::Values("hard", "cssm2", "pcss"),
                         [](const auto& info) { return testNameOf(info.param); });

// Four panes facing the camera, lit by the ambient term alone (the light grazes them: N.L = 0), so
// each channel's linear value is its albedo: twelve values from the transfer function's linear
// segment (below 0.0031308) to white. The frame shaded into sRGB encodes its opaque surfaces in
// the lighting shader (ENCODE_SRGB_IN_SHADER), the float target in the resolve pass; both must give
// the bytes IEC 61966-2-1 gives, to within rounding.
TEST(SrgbTargetUse, OpaqueSurfacesCarryTheTransferFunctionsBytes) {
    const std::array<glm::vec3, 4> albedo = {glm::vec3(0.0008f, 0.0025f, 0.01f), glm::vec3(0.03f, 0.1f, 0.214f),
                                             glm::vec3(0.35f, 0.5f, 0.65f), glm::vec3(0.8f, 0.9f, 1.0f)};
    const auto paneX = [](std::size_t i) { return -3.0 + 2.0 * double(i); };  // each pane's centre, at y = z = 0
    std::string objects;
    for (std::size_t i = 0; i < albedo.size(); ++i) {
        const glm::vec3 a = albedo[i];
        objects += std::string(i ? "," : "") + R"({ "shape": "plane", "size": [1.8, 3], "rotation_deg": [90, 0, 0], "position": [)" +
                   std::to_string(paneX(i)) + R"(, 0, 0], "material": { "diffuse": [)" + std::to_string(a.r) + "," +
                   std::to_string(a.g) + "," + std::to_string(a.b) + R"(], "specular": [0, 0, 0] } })";
    }
    scene::Scene s = sceneFromJson(R"({ "camera": { "position": [0, 0, 10], "target": [0, 0, 0], "fov_deg": 40 },
      "background": [0, 0, 0], "ambient": [1, 1, 1],
      "lights": [ { "type": "directional", "direction": [1, 0, 0], "intensity": 1 } ],
      "objects": [ )" + objects + " ] }");
    const auto srgbByte = [](float linear) { return static_cast<int>(std::lround(255.0f * util::linearToSrgb(linear))); };
    const int w = 160, h = 96;
    for (const bool floatTarget : {false, true}) {
        const auto rgba = renderRgba8(s, options("none", floatTarget), w, h);
        const double halfWidth = 10.0 * std::tan(glm::radians(20.0)) * w / h;  // of the view at z = 0
        for (std::size_t i = 0; i < albedo.size(); ++i) {
            const int x = static_cast<int>(w / 2 + paneX(i) / halfWidth * (w / 2)), y = h / 2;
            const std::size_t at = (static_cast<std::size_t>(y) * w + x) * 4;
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(int(rgba[at + c]), srgbByte(albedo[i][c]), 1)
                    << (floatTarget ? "float target, " : "shaded into sRGB, ") << "linear " << albedo[i][c];
        }
    }
}

TEST(SrgbTargetUse, LinearReadBackOfAFrameShadedIntoSrgbIsAnErrorThatSaysWhatToSet) {
    scene::Scene s = fogAndPanes();
    render::Renderer renderer(s, options("hard", false));
    render::OffscreenTarget target(32, 32);
    renderer.render(0.0f, s.camera, 32, 32, target.framebuffer());
    try {
        (void)renderer.readLinear();
        FAIL() << "readLinear must not return the float target's stale or empty contents";
    } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("floatTarget"), std::string::npos) << e.what();
    }
    renderer.setOutputMode(render::OutputMode::Visibility);  // a debug channel keeps linear values: the float target
    renderer.render(0.0f, s.camera, 32, 32, target.framebuffer());
    EXPECT_EQ(renderer.readLinear().size(), 32u * 32u * 4u);
}

// A technique change hands the old maps back with a draw of its own (Renderer::releaseBoundTextures),
// which must leave the framebuffer the caller had bound: a window's panel draws after it.
TEST(SrgbTargetUse, ATechniqueChangeLeavesTheCallersFramebufferBound) {
    scene::Scene s = fogAndPanes();
    render::Renderer renderer(s, options("hard", false));
    render::OffscreenTarget target(32, 32);
    renderer.render(0.0f, s.camera, 32, 32, target.framebuffer());
    render::OffscreenTarget panel(8, 8);
    glBindFramebuffer(GL_FRAMEBUFFER, panel.framebuffer());
    renderer.setTechnique("pcss");
    GLint draw = 0, read = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
    EXPECT_EQ(static_cast<GLuint>(draw), panel.framebuffer());
    EXPECT_EQ(static_cast<GLuint>(read), panel.framebuffer());
}

// The current program's shadow samplers (sampler*Shadow) whose units hold no depth texture with
// comparison on, as "name[i] (unit u)": what NVIDIA's driver warns of at a draw or clear.
std::vector<std::string> shadowSamplersWithoutDepth() {
    GLint program = 0, uniforms = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    if (program == 0) return {};
    const auto id = static_cast<GLuint>(program);
    glGetProgramiv(id, GL_ACTIVE_UNIFORMS, &uniforms);
    std::vector<std::string> wrong;
    for (GLuint i = 0; i < static_cast<GLuint>(uniforms); ++i) {
        char name[256];
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(id, i, sizeof name, nullptr, &size, &type, name);
        const GLenum binding = type == GL_SAMPLER_2D_SHADOW         ? GL_TEXTURE_BINDING_2D
                               : type == GL_SAMPLER_CUBE_SHADOW     ? GL_TEXTURE_BINDING_CUBE_MAP
                               : type == GL_SAMPLER_2D_ARRAY_SHADOW ? GL_TEXTURE_BINDING_2D_ARRAY
                                                                    : GL_NONE;
        if (binding == GL_NONE) continue;
        std::string base(name);
        if (base.size() > 3 && base.ends_with("[0]")) base.resize(base.size() - 3);
        for (GLint k = 0; k < size; ++k) {
            const std::string element = size > 1 ? base + "[" + std::to_string(k) + "]" : base;
            GLint unit = 0, texture = 0, format = 0, mode = GL_NONE;
            glGetUniformiv(id, glGetUniformLocation(id, element.c_str()), &unit);
            glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
            glGetIntegerv(binding, &texture);
            glActiveTexture(GL_TEXTURE0);
            if (texture != 0) {
                glGetTextureLevelParameteriv(static_cast<GLuint>(texture), 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
                glGetTextureParameteriv(static_cast<GLuint>(texture), GL_TEXTURE_COMPARE_MODE, &mode);
            }
            const bool depth = format == GL_DEPTH_COMPONENT32F || format == GL_DEPTH_COMPONENT24 || format == GL_DEPTH_COMPONENT16;
            if (!depth || mode != GL_COMPARE_REF_TO_TEXTURE) wrong.push_back(element + " (unit " + std::to_string(unit) + ")");
        }
    }
    return wrong;
}

// A frame shaded straight into sRGB ends on a lighting program (the blit that finishes it uses
// none). The next frame's shadow passes unbind the lighting units and clear their maps, and a
// renderer that goes deletes its textures before the caller's next clear. A driver that checks the
// current program at a clear (NVIDIA's, on an H200) then met shadow samplers over empty units.
// Neither may leave a program current that samples what they took away.
TEST(SrgbTargetUse, NoProgramIsLeftSamplingTheShadowUnitsAFrameOrARendererTookAway) {
    scene::Scene s = fogAndPanes();
    for (const bool floatTarget : {false, true})
        for (const char* technique : {"hard", "cssm2", "pcss", "cascaded"}) {
            const std::string what = std::string(technique) + (floatTarget ? ", float target" : ", sRGB");
            {
                render::Renderer renderer(s, options(technique, floatTarget));
                render::OffscreenTarget target(32, 32);
                renderer.render(0.0f, s.camera, 32, 32, target.framebuffer());
                gl::unbindTextureUnits(gpu::kLightingUnits);  // as each shadow pass begins
                auto wrong = shadowSamplersWithoutDepth();
                EXPECT_TRUE(wrong.empty()) << what << ", the shadow passes: " << wrong.size() << " shadow samplers over unbound units, first "
                                           << (wrong.empty() ? "" : wrong.front());
                renderer.render(0.0f, s.camera, 32, 32, target.framebuffer());
            }
            const auto wrong = shadowSamplersWithoutDepth();
            EXPECT_TRUE(wrong.empty()) << what << ", the renderer gone: " << wrong.size() << " shadow samplers over unbound units, first "
                                       << (wrong.empty() ? "" : wrong.front());
        }
}

}  // namespace
}  // namespace penumbra::test
