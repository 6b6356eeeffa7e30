#pragma once
// Model files (OBJ+MTL, glTF/GLB, PLY, anything Assimp reads) -> one Mesh appended to the
// scene, with its materials and textures mapped onto scene::Material.
#include "scene/Scene.h"

#include <filesystem>

namespace penumbra::scene::io {

// Appends the model's mesh, materials and images to `scene`; returns the mesh index.
// Throws InputError naming the file when the model cannot be read or holds no triangles.
int importModel(const std::filesystem::path& file, Scene& scene);

}  // namespace penumbra::scene::io
