// Fuzz target: model import through penumbra's importer (Assimp underneath), with material,
// alpha and transmission mapping and the bare-model framing `penumbra render model.obj` uses.
// Built once per format: PENUMBRA_FUZZ_MODEL_FILE is the main file's name (model.obj, .gltf,
// .glb, .ply); an OBJ's MTL or a glTF's .bin arrive as `@@file` parts of the input.
#include "DrawableScene.h"
#include "FuzzFiles.h"

#include "scene/io/ModelImporter.h"
#include "scene/io/SceneFile.h"
#include "util/Error.h"

#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>

using namespace penumbra;

namespace {

// The importer's helper turns an Assimp hang into an InputError after 3 s, so libFuzzer never
// sees it as a timeout and keeps no artefact. With PENUMBRA_FUZZ_HANGS=DIR such inputs are kept
// in DIR (named by their hash): they show which broken files FormatChecks still lets through to
// Assimp, and each one stalls the fuzzer 3 s.
void keepIfHang(const std::uint8_t* data, std::size_t size, const InputError& e) {
    const char* dir = std::getenv("PENUMBRA_FUZZ_HANGS");
    if (!dir || !*dir || std::string(e.what()).find("did not finish") == std::string::npos) return;
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    std::ofstream(std::string(dir) + "/hang-" + std::to_string(std::hash<std::string>{}(bytes)), std::ios::binary) << bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    scene::io::setModelImportTimeout(3);  // Assimp's PLY reader loops forever on some headers
    const auto file = fuzz::writeParts(fuzz::splitParts(data, size, PENUMBRA_FUZZ_MODEL_FILE));
    try {
        const scene::Scene s = scene::io::loadScene(file);  // importModel + wrapModel
        fuzz::requireDrawable("model", s);
    } catch (const InputError& e) {
        keepIfHang(data, size, e);
    } catch (const std::exception& e) {
        fuzz::unexpectedException("model", e);
    }
    return 0;
}
