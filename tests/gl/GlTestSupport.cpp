#include "GlTestSupport.h"

#include "gl/Debug.h"
#include "platform/EglContext.h"
#include "render/Offscreen.h"
#include "scene/Shapes.h"
#include "scene/io/SceneFile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <dlfcn.h>
#include <execinfo.h>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <sstream>

namespace penumbra::test {

namespace {
// Where the GL call that raised a debug message came from (synchronous output): module offsets,
// which `addr2line -f -C -e <module>` resolves from the unstripped build, for drivers this machine
// lacks (NVIDIA's warnings arrive only on a GPU machine, where the bundled binaries are stripped).
std::string callSite() {
    void* frames[24];
    const int n = backtrace(frames, 24);
    std::ostringstream out;
    for (int i = 2; i < n; ++i) {
        Dl_info info{};
        if (dladdr(frames[i], &info) == 0 || info.dli_fname == nullptr) continue;
        const std::string module = info.dli_fname;
        out << "\n  " << module.substr(module.find_last_of('/') + 1) << " +0x" << std::hex
            << (reinterpret_cast<std::uintptr_t>(frames[i]) - reinterpret_cast<std::uintptr_t>(info.dli_fbase)) << std::dec;
    }
    return out.str();
}

class GlEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        context_ = platform::EglContext::create("auto", /*debug=*/true);
        gl::enableDebugOutput();
        // Every GL error and every driver warning of medium or high severity (undefined
        // behaviour, ...) fails the test that caused it; the project's own warnings are separate
        // (log::takeWarnings).
        gl::setDebugMessageHook(
            [](const char* message) { ADD_FAILURE() << "GL debug message: " << message << "\ncalled from:" << callSite(); });
    }
    void TearDown() override { context_.reset(); }

private:
    std::unique_ptr<platform::EglContext> context_;
};
}  // namespace

const scene::Mesh& makeBigSphere(scene::Scene& scene, std::size_t object, float radius) {
    scene::Mesh& mesh = scene.meshes[static_cast<std::size_t>(scene.objects[object].mesh)];
    const int material = mesh.parts[0].material;
    mesh = scene::shapes::sphere(radius, 256, 128);
    mesh.parts[0].material = material;
    return mesh;
}

scene::Scene sceneFromJson(const std::string& json) {
    return scene::io::parseSceneJson(json, std::filesystem::path(PENUMBRA_TEST_DATA) / "inline.json");
}

std::vector<float> textureLevels(const shadows::DebugView& view) {
    std::vector<float> all;
    for (GLint level = 0;; ++level) {
        GLint w = 0, h = 0;
        glGetTextureLevelParameteriv(view.texture, level, GL_TEXTURE_WIDTH, &w);
        glGetTextureLevelParameteriv(view.texture, level, GL_TEXTURE_HEIGHT, &h);
        if (w == 0 || h == 0) return all;
        const std::size_t channels = view.depth ? 1 : 4, first = all.size();
        all.resize(first + channels * static_cast<std::size_t>(w * h));
        // An array's view is its one layer, as the overlay shows it.
        const GLint layer = view.target == GL_TEXTURE_2D_ARRAY ? view.layer : 0;
        glGetTextureSubImage(view.texture, level, 0, 0, layer, w, h, 1, view.depth ? GL_DEPTH_COMPONENT : GL_RGBA, GL_FLOAT,
                             static_cast<GLsizei>((all.size() - first) * sizeof(float)), all.data() + first);
    }
}

Frame renderChannel(scene::Scene& scene, render::OutputMode mode, int light, int width, int height,
                    const std::string& technique, const shadows::ParameterValues& parameters) {
    render::RenderOptions options;
    options.technique = technique;
    options.parameters = parameters;
    options.output = mode;
    options.debugLight = light;
    return renderFrame(scene, options, width, height);
}

std::string testNameOf(std::string technique) {
    for (char& c : technique)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return technique;
}

render::RenderOptions optionsFor(const std::string& technique) {
    render::RenderOptions o;
    std::tie(o.technique, o.parameters) = shadows::splitTechniqueParameters(technique);
    return o;
}

Frame renderFrame(scene::Scene& scene, const render::RenderOptions& options, int width, int height) {
    render::Renderer renderer(scene, options);
    render::OffscreenTarget target(width, height);
    renderer.render(0.0f, scene.camera, width, height, target.framebuffer());
    return Frame{width, height, renderer.readLinear()};
}

std::vector<std::uint8_t> renderRgba8(scene::Scene& scene, const render::RenderOptions& options, int width, int height) {
    render::Renderer renderer(scene, options);
    render::OffscreenTarget target(width, height);
    renderer.render(0.0f, scene.camera, width, height, target.framebuffer());
    return target.readRgba8();
}

Ray pixelRay(const scene::Camera& camera, int x, int y, int width, int height) {
    const glm::mat4 inv = glm::inverse(camera.projection(float(width) / float(height)) * camera.view());
    const glm::vec2 ndc{(x + 0.5f) / width * 2.0f - 1.0f, (y + 0.5f) / height * 2.0f - 1.0f};
    glm::vec4 a = inv * glm::vec4(ndc, -1.0f, 1.0f), b = inv * glm::vec4(ndc, 1.0f, 1.0f);
    a /= a.w;
    b /= b.w;
    return {glm::vec3(a), glm::normalize(glm::vec3(b - a))};
}

MaskComparison compareMasks(const std::vector<bool>& expected, const std::vector<bool>& rendered, int w, int h, int tol) {
    MaskComparison c;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            c.expectedOn += expected[i];
            c.renderedOn += rendered[i];
            if (expected[i] == rendered[i]) continue;
            ++c.mismatches;
            bool nearEdge = false;
            for (int dy = -tol; dy <= tol && !nearEdge; ++dy)
                for (int dx = -tol; dx <= tol && !nearEdge; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
                    nearEdge = expected[static_cast<std::size_t>(yy) * w + xx] != expected[i];
                }
            c.mismatchesAwayFromEdges += !nearEdge;
        }
    return c;
}

std::size_t differingPixels(const std::vector<float>& a, const std::vector<float>& b, float tolerance) {
    std::size_t count = 0;
    for (std::size_t i = 0; i + 2 < a.size() && i + 2 < b.size(); i += 4)
        count += std::abs(a[i] - b[i]) > tolerance || std::abs(a[i + 1] - b[i + 1]) > tolerance || std::abs(a[i + 2] - b[i + 2]) > tolerance;
    return count;
}

}  // namespace penumbra::test

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::AddGlobalTestEnvironment(new penumbra::test::GlEnvironment);
    return RUN_ALL_TESTS();
}
