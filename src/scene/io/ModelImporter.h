#pragma once
// Model files (OBJ+MTL, glTF/GLB, PLY, anything Assimp reads) -> one Mesh appended to the
// scene, with its materials and textures mapped onto scene::Material.
#include "scene/Scene.h"

#include <filesystem>

namespace penumbra::scene::io {

// Appends the model's mesh, materials and images to `scene`; returns the mesh index.
// Throws InputError naming the file when the model cannot be read or holds no triangles.
// Assimp first reads the file in a child process (see ModelImporter.cpp), so a crash or a hang
// of the third-party reader becomes this InputError instead of taking the program down.
int importModel(const std::filesystem::path& file, Scene& scene);

// How long the importer may take on one file before it is stopped (default 120 s).
void setModelImportTimeout(int seconds);

// Reads `file` with Assimp in the helper process (importModel's first step after the format
// checks): throws InputError when Assimp crashes on it or overruns the timeout.
void probeWithAssimp(const std::filesystem::path& file);

}  // namespace penumbra::scene::io
