// Fuzz target: model import through penumbra's importer (Assimp underneath), with material,
// alpha and transmission mapping and the bare-model framing `penumbra render model.obj` uses.
// Built once per format: PENUMBRA_FUZZ_MODEL_FILE is the main file's name (model.obj, .gltf,
// .glb, .ply); an OBJ's MTL or a glTF's .bin arrive as `@@file` parts of the input.
#include "FuzzFiles.h"

#include "scene/io/ModelImporter.h"
#include "scene/io/SceneFile.h"
#include "util/Error.h"

#include <cmath>
#include <cstdlib>

using namespace penumbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    scene::io::setModelImportTimeout(3);  // Assimp's PLY reader loops forever on some headers
    const auto file = fuzz::writeParts(fuzz::splitParts(data, size, PENUMBRA_FUZZ_MODEL_FILE));
    try {
        const scene::Scene s = scene::io::loadScene(file);  // importModel + wrapModel
        for (const auto& mesh : s.meshes) {
            for (std::uint32_t i : mesh.indices)
                if (i >= mesh.vertices.size()) std::abort();
            for (const auto& part : mesh.parts)
                if (part.material < 0 || part.material >= static_cast<int>(s.materials.size()) ||
                    std::size_t(part.firstIndex) + part.indexCount > mesh.indices.size())
                    std::abort();
        }
        for (const auto& m : s.materials)
            if (m.diffuseTexture >= static_cast<int>(s.images.size()) || !(m.alpha >= 0 && m.alpha <= 1)) std::abort();
        if (!std::isfinite(s.camera.position.x) || !std::isfinite(s.camera.far)) std::abort();
    } catch (const InputError&) {
    } catch (const std::exception& e) {
        fuzz::unexpectedException("model", e);
    }
    return 0;
}
