#pragma once
// A 1x1 texture of the right kind on every texture unit the lighting shader declares, bound
// before the technique binds its own maps. Units of empty slots (a light without shadow, a
// technique without a layered map) then hold a texture their sampler type accepts - a depth
// texture with comparison for shadow samplers - instead of texture 0, which drivers report as
// undefined behaviour (NVIDIA does, every frame). The unit -> sampler type table is the
// lighting shader's declarations of gpu/ShaderContract.h's units.
#include "gl/Texture.h"
#include "gpu/ShaderContract.h"

#include <array>

namespace penumbra::render {

class PlaceholderTextures {
public:
    PlaceholderTextures();
    // Binds a placeholder to every unit below gpu::kUnitDualDepth (the units above belong to the
    // camera-transparency passes, which bind their own), and to the debug channels' kUnitBehindDepth.
    // Two glBindTextures calls (units below kUnitDualDepth, then kUnitDrawnFarthest2D up to
    // kUnitBehindDepth), not one bind per unit: the lighting passes bind them once each.
    void bindAll() const;

private:
    gl::Texture depth2D_, depthCube_, depthArray_;  // depth, comparison on: sampler*Shadow
    gl::Texture white2D_, whiteCube_, whiteArray_, white3D_;
    // The texture of each unit, from 0 and from kUnitDrawnFarthest2D: filled once by the constructor.
    std::array<GLuint, gpu::kUnitDualDepth> low_{};
    std::array<GLuint, gpu::kUnitBehindDepth + 1 - gpu::kUnitDrawnFarthest2D> high_{};
};

}  // namespace penumbra::render
