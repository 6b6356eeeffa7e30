// Live shader editing: reloading picks up edited files; a file with an error leaves the last
// good programs drawing and reports the file and line.
#include "GlTestSupport.h"

#include "render/Offscreen.h"
#include "util/DataPaths.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace penumbra::test {
namespace {

namespace fs = std::filesystem;
using render::OutputMode;

TEST(ShaderReload, AnEditShowsAndABrokenFileKeepsTheLastGoodProgram) {
    const fs::path original = paths::dataRoot();
    const fs::path copy = fs::temp_directory_path() / "penumbra_shader_reload";
    fs::remove_all(copy);
    fs::create_directories(copy);
    fs::copy(original / "shaders", copy / "shaders", fs::copy_options::recursive);
    fs::copy(original / "src", copy / "src", fs::copy_options::recursive);
    ::setenv("PENUMBRA_SHADER_DIR", copy.c_str(), 1);

    scene::Scene s = sceneFromJson(R"({
      "camera": { "position": [0, 6, 0.001], "target": [0, 0, 0], "up": [0, 0, -1] },
      "lights": [ { "type": "directional", "direction": [0, -1, 0] } ],
      "objects": [ { "shape": "plane", "size": [10, 10] } ] })");
    render::RenderOptions options;
    options.technique = "hard";
    options.output = OutputMode::Visibility;
    render::Renderer renderer(s, options);
    render::OffscreenTarget target(32, 32);
    auto centre = [&] {
        renderer.render(0.0f, s.camera, 32, 32, target.framebuffer());
        const Frame f{32, 32, renderer.readLinear()};
        return f.at(16, 16);
    };
    EXPECT_EQ(centre(), glm::vec3(1.0f));

    const fs::path lookup = copy / "src/shadows/hard/lookup.glsl";
    std::string text;
    {
        std::ifstream in(lookup);
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    const int lines = static_cast<int>(std::count(text.begin(), text.end(), '\n'));
    std::ofstream(lookup, std::ios::app) << "this is not GLSL;\n";
    const std::string error = renderer.reloadShaders();
    EXPECT_NE(error.find("hard/lookup.glsl:" + std::to_string(lines + 1)), std::string::npos) << error;
    EXPECT_EQ(centre(), glm::vec3(1.0f)) << "the last good program keeps drawing";

    // A visible edit: every light reaches half way.
    std::ofstream(lookup) << text << R"(
vec3 halfVisibility(int light, vec3 P, vec3 N, float NdotL) { return 0.5 * shadowVisibility(light, P, N, NdotL); }
#define shadowVisibility halfVisibility
)";
    EXPECT_EQ(renderer.reloadShaders(), "");
    EXPECT_EQ(centre(), glm::vec3(0.5f));

    ::unsetenv("PENUMBRA_SHADER_DIR");
    fs::remove_all(copy);
}

}  // namespace
}  // namespace penumbra::test
