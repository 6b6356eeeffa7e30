#pragma once
// Packs the scene's lights into the std140 light block whose layout gpu/ShaderContract.h
// defines for C++ and GLSL alike.
#include "gpu/ShaderContract.h"
#include "shadows/ShadowTechnique.h"

#include <vector>

namespace penumbra::render {

// Packs lights (with their light spaces and this frame's shadow slots) into the uniform block.
gpu::LightBlock packLights(const std::vector<scene::Light>& lights, const std::vector<shadows::LightSpace>& spaces,
                           const shadows::ShadowSlots& slots);

}  // namespace penumbra::render
