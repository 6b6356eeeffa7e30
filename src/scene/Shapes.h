#pragma once
// Built-in shapes of the scene format. Each returns a mesh with a single part using material 0
// (the caller remaps it).
#include "scene/Mesh.h"

namespace penumbra::scene::shapes {

Mesh plane(float sizeX, float sizeZ);                 // in XZ, facing +Y, centred on the origin
Mesh box(const glm::vec3& size);                      // full extents, centred on the origin
Mesh sphere(float radius, int slices = 48, int stacks = 24);

}  // namespace penumbra::scene::shapes
