#pragma once
// The lighting program (shaders/passes/lighting.frag with a technique's lookup), specialised to
// the scene's light layout: each light's type, shadow slot and projector slot become
// compile-time constants, so the shader's light loop unrolls and every lookup addresses one
// sampler instead of switching over all of them per pixel.
#include "gl/Program.h"
#include "gpu/ShaderContract.h"
#include "scene/Material.h"

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace penumbra::render {

// SCENE_LIGHT_COUNT, SHADE_EACH_LIGHT (the unrolled light loop: SHADE_LIGHT(0) SHADE_LIGHT(1) ..),
// SCENE_LIGHT_TYPES, SCENE_SHADOW_SLOTS and SCENE_PROJECTOR_SLOTS read from a
// packed light block (so they cannot disagree with what the block holds);
// SCENE_SUN_LIGHT: the light the view-dependent techniques take over (ShadowSlots::sun, -1: none),
// so that each other light's lookup holds none of their code; and
// SCENE_TRANSLUCENT_CASTERS: 0 when no translucent object casts a shadow, so that the
// lookups' tint fetches fold away (every tint map is white then). Equal defines = the same program.
std::vector<std::string> lightLayoutDefines(const gpu::LightBlock& block, int sunLight = -1, bool translucentCasters = true);

// lighting.vert + lighting.frag with `lookup` as "shadow_lookup.glsl" and `defines` (a light
// layout, a transparency variant).
gl::Program buildLightingProgram(const std::filesystem::path& lookup, const std::vector<std::string>& defines);

// What a receiver's lookup must read of the coloured shadows (render/TintReach.h): all of it;
// none, as no translucent caster's shadow reaches it (RECEIVER_UNTINTED; for a translucent
// receiver: none but its own layers', as every other layer lies behind it,
// ShadowTechnique::ownLayersBuild); or only what lies in front of it, as it is behind every layer
// around it (RECEIVER_BEHIND_LAYERS, ShadowTechnique::behindLayersBuild; for a translucent
// receiver, behind every other layer: ownLayersBuild).
enum class TintLookup { Whole, Untinted, BehindLayers };

// The lighting program in up to 48 builds: with or without a diffuse texture, for opaque or
// translucent surfaces, with or without an alpha test, with or without a specular term, and each
// TintLookup.
// - MATERIAL_UNTEXTURED never samples the texture: llvmpipe runs the sample under
//   `uHasTexture != 0` for every fragment whatever the uniform says (measured, default scene,
//   none: ~2.5 ms of a 21 ms opaque pass).
// - MATERIAL_TRANSLUCENT lets a lookup pick what suits receivers that are themselves translucent
//   layers (CSSM's nearest-layer statistics).
// - MATERIAL_NO_ALPHA_TEST (materials without a cutoff) leaves the alpha test's `discard` out, as
//   DepthCasterProgram does for casters.
// - MATERIAL_NO_SPECULAR (specular (0, 0, 0), as the osgShadow peer's material has) leaves
//   Blinn-Phong's highlight out, which would add exactly 0 there. Measured on the 98k grid from
//   its camera (llvmpipe, `none`, switched every 8 frames in one process): opaque pass 20.5 ->
//   14.6 ms.
// The build the scene needs first is compiled at once, so shader errors still surface there; the
// others when a surface first asks for them.
class LightingPrograms {
public:
    LightingPrograms() = default;
    LightingPrograms(std::filesystem::path lookup, std::vector<std::string> defines, bool anyTexturedMaterial);
    // `translucent`: the surface is drawn in the translucent pass (render::Draw::translucent).
    // `tint`: what the pixels it shades need of the coloured shadows. `unlit`: a bit per light
    // that reaches none of the pixels shaded (SKIPPED_LIGHTS; Renderer's light reach): the build
    // leaves those lights out. `unshadowed`: a bit per light whose shadow reaches none of them
    // (UNSHADOWED_LIGHTS; Renderer's shadow reach): the build shades those lights without a lookup.
    const gl::Program& of(const scene::Material& material, bool translucent = false, TintLookup tint = TintLookup::Whole,
                          unsigned unlit = 0, unsigned unshadowed = 0);
    template <class F>
    void forEachBuilt(F&& f) const {
        for (const auto& [key, p] : builds_)
            if (p.id()) f(p);
    }

private:
    std::filesystem::path lookup_;
    std::vector<std::string> defines_;
    // Keyed by untextured + 2 translucent + 4 alpha-tested + 8 no specular + 16 TintLookup + 48
    // unlit lights, and the unshadowed lights in the upper 32 bits.
    std::map<std::uint64_t, gl::Program> builds_;
};

}  // namespace penumbra::render
