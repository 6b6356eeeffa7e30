// Fuzz target: the scene-file loader (JSON -> Scene), camera paths and animation keys included.
// The input is the scene text; models and textures it names resolve relative to the scratch
// folder, where any `@@file` parts of the input are written (a scene with its own OBJ, say).
#include "DrawableScene.h"
#include "FuzzFiles.h"

#include "scene/io/SceneFile.h"
#include "util/Error.h"

using namespace penumbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto parts = fuzz::splitParts(data, size, "scene.json");
    const auto file = fuzz::writeParts(parts);
    try {
        const scene::Scene s = scene::io::loadScene(file);
        fuzz::requireDrawable("scene_file", s);  // what the loader accepts, the renderer can draw
    } catch (const InputError&) {
    } catch (const std::exception& e) {
        fuzz::unexpectedException("scene_file", e);
    }
    return 0;
}
