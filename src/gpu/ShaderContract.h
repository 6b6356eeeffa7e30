// The contract between the C++ side and the GLSL side, in one file that both compile (as
// Falcor's host/device shared headers do): texture units, limits, light-type codes and the
// std140 light block. C++ includes it as "gpu/ShaderContract.h"; GLSL as
// "src/gpu/ShaderContract.h" through gl::Program's #include resolver. Nothing here may be
// written again elsewhere: a unit or a limit changes in this file only.
#ifndef PENUMBRA_GPU_SHADER_CONTRACT_H
#define PENUMBRA_GPU_SHADER_CONTRACT_H

#ifdef __cplusplus
#include <glm/glm.hpp>
// GPU_CONST declares an integer constant both languages read; GPU_NAMESPACE_* wrap C++ only.
#define GPU_CONST inline constexpr int
// GPU_CONSTANT(type) declares a constant of a GLSL type (vec4, mat4) both languages read.
#define GPU_CONSTANT(type) inline const type
#define GPU_NAMESPACE_BEGIN namespace penumbra::gpu {
#define GPU_NAMESPACE_END }
GPU_NAMESPACE_BEGIN
using mat4 = glm::mat4;
using vec4 = glm::vec4;
using ivec4 = glm::ivec4;
GPU_NAMESPACE_END
#else
#define GPU_CONST const int
#define GPU_CONSTANT(type) const type
#define GPU_NAMESPACE_BEGIN
#define GPU_NAMESPACE_END
#endif

GPU_NAMESPACE_BEGIN

// Limits of the lighting shader.
GPU_CONST kMaxLights = 8;
GPU_CONST kMaxShadow2D = 4;    // shadowed directional / spot / projector lights
GPU_CONST kMaxShadowCube = 2;  // shadowed point lights
GPU_CONST kMaxProjectors = 2;

// Texture units of the lighting shader (and of every lighting variant). Per-slot ranges hold
// one unit per shadow slot: kUnitShadow2D + slot, ...
GPU_CONST kUnitDiffuse = 0;
GPU_CONST kUnitProjector = 1;       // .. + kMaxProjectors
GPU_CONST kUnitJitter = 3;          // 3D jitter texture of the PCF family
GPU_CONST kUnitShadow2D = 4;        // depth with hardware compare
GPU_CONST kUnitTint2D = 8;          // transmittance of translucent casters
GPU_CONST kUnitRaw2D = 12;          // raw depth (no compare) or a technique's own map (moments, CSSM)
GPU_CONST kUnitShadowCube = 16;
GPU_CONST kUnitTintCube = 18;
GPU_CONST kUnitRawCube = 20;
GPU_CONST kUnitLayered = 22;        // sampler2DArrayShadow of a LayeredDepthMap (cascades, LiSPSM tiles)
GPU_CONST kUnitScreenShadow = 23;   // R8 array, per-light visibility in screen space (shadow volumes, planar)
GPU_CONST kUnitScreenDepth = 24;    // the camera depth pre-pass of that mask
GPU_CONST kUnitDepthTiles = 25;     // RGBA32F array, a layer per 2D slot: DepthTileBounds (PCF, PCSS)
GPU_CONST kUnitDualDepth = 28;      // camera transparency: dual depth peeling bounds
GPU_CONST kUnitStochasticDepth = 29;  // stochastic transparency's multisampled depth
GPU_CONST kUnitPeelDepth = 30;      // depth peeling: the previous layer
GPU_CONST kUnitOpaqueDepth = 31;    // the opaque surfaces' depth
GPU_CONST kUnitDrawnFarthest2D = 32;  // RG32F, 1 - the farthest translucent layer / entry per texel (translucent receivers)
GPU_CONST kUnitDrawnFarthestCube = 36;  // the same for point lights (cube maps)
GPU_CONST kUnitBehindDepth = 38;    // debug channels: the depth of the surface to look behind (compare --behind-glass)
GPU_CONST kLightingUnits = 39;      // units the lighting shader may read (all unbound before shadow passes)

// DepthTileBounds: level-0 tiles of kDepthTile^2 texels, each bounding its texels and
// kDepthTileBorder more on every side; level k: tiles of kDepthTile << k, each bounding one
// level-(k-1) tile and its border more, so the border is (kDepthTile << k) - kDepthTileInset
// (2, 10, 26, ...).
GPU_CONST kDepthTile = 8;
GPU_CONST kDepthTileBorder = 2;
GPU_CONST kDepthTileInset = kDepthTile - kDepthTileBorder;

GPU_CONST kLightBlockBinding = 0;

// Light types, in the order of scene::Light::Type (checked in render/LightBlock.cpp).
GPU_CONST kLightDirectional = 0;
GPU_CONST kLightSpot = 1;
GPU_CONST kLightPoint = 2;
GPU_CONST kLightProjector = 3;

// Per-fragment random number generators of shaders/common/random.glsl (uRandomGenerator).
GPU_CONST kRandomPcg = 0;      // PCG-style integer hash
GPU_CONST kRandomSinFract = 1; // fract(sin(dot(p, k)) * 43758.5453), as Mátl 2013 used

// One light of the std140 light block (160 bytes).
struct LightData {
    mat4 shadowMatrix;   // world -> shadow texture space [0,1]^3 (directional, spot, projector)
    vec4 colorType;      // rgb: radiance (colour * intensity); w: kLight*
    vec4 positionNear;   // xyz: position; w: shadow near plane
    vec4 directionFar;   // xyz: direction light travels; w: shadow far plane
    vec4 cone;           // x: cos(outer half-angle); y: cos(inner); z: projector slot; w: shadow slot (-1: none)
    vec4 shadow;         // x: bias, y: slope bias, z: normal offset (all in shadow texels); w: texel scale
    vec4 misc;           // x: unused (perspective = not directional: lightPerspective() in lights.glsl); y: resolution; z: light size (world units)
};

#ifdef __cplusplus
struct LightBlock {
    ivec4 count;  // x: number of lights
    LightData lights[kMaxLights];
};
static_assert(sizeof(LightData) == 160, "std140 layout of LightData");
#else
layout(std140, binding = kLightBlockBinding) uniform LightBlock {
    ivec4 uLightCount;
    LightData uLights[kMaxLights];
};
#endif

GPU_NAMESPACE_END

#endif
