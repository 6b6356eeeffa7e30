// Fuzz target: model import through penumbra's importer (Assimp underneath), with material,
// alpha and transmission mapping and the bare-model framing `penumbra render model.obj` uses.
// Built once per format: PENUMBRA_FUZZ_MODEL_FILE is the main file's name (model.obj, .gltf,
// .glb, .ply); an OBJ's MTL or a glTF's .bin arrive as `@@file` parts of the input.
#include "DrawableScene.h"
#include "FuzzFiles.h"

#include "scene/io/ModelImporter.h"
#include "scene/io/SceneFile.h"
#include "util/Error.h"

using namespace penumbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    scene::io::setModelImportTimeout(3);  // Assimp's PLY reader loops forever on some headers
    const auto file = fuzz::writeParts(fuzz::splitParts(data, size, PENUMBRA_FUZZ_MODEL_FILE));
    try {
        const scene::Scene s = scene::io::loadScene(file);  // importModel + wrapModel
        fuzz::requireDrawable("model", s);
    } catch (const InputError&) {
    } catch (const std::exception& e) {
        fuzz::unexpectedException("model", e);
    }
    return 0;
}
