// Fuzz target: the scene-file loader (JSON -> Scene), camera paths and animation keys included.
// The input is the scene text; models and textures it names resolve relative to the scratch
// folder, where any `@@file` parts of the input are written (a scene with its own OBJ, say).
#include "FuzzFiles.h"

#include "scene/io/SceneFile.h"
#include "util/Error.h"

#include <cmath>
#include <cstdlib>

using namespace penumbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto parts = fuzz::splitParts(data, size, "scene.json");
    const auto file = fuzz::writeParts(parts);
    try {
        const scene::Scene s = scene::io::loadScene(file);
        // What the loader accepts, the renderer can draw: finite camera, lights, objects.
        const auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
        if (s.objects.empty() || !finite(s.camera.position) || !finite(s.camera.target)) std::abort();
        for (const auto& o : s.objects)
            if (o.mesh < 0 || o.mesh >= static_cast<int>(s.meshes.size()) || !finite(o.position) || !finite(o.scale))
                std::abort();
        for (const auto& l : s.lights)
            if (!finite(l.position) || !finite(l.direction) || !std::isfinite(l.intensity)) std::abort();
        for (const auto& img : s.images)
            if (img.rgba.size() != static_cast<std::size_t>(img.width) * img.height * 4 || img.width <= 0) std::abort();
    } catch (const InputError&) {
    } catch (const std::exception& e) {
        fuzz::unexpectedException("scene_file", e);
    }
    return 0;
}
