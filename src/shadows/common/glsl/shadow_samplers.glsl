// The per-light shadow textures, one sampler per slot. Access goes through a switch with
// constant indices: llvmpipe (Mesa 22.3 / LLVM 15) crashes compiling dynamically indexed
// sampler arrays next to cube samplers, and a switch is what a driver would generate anyway.
// "Raw" samplers read the depth map without comparison (blocker searches) or a technique's
// filtered moments; explicit gradients keep mipmapped lookups defined in any control flow.
#include "src/gpu/ShaderContract.h"

layout(binding = kUnitShadow2D) uniform sampler2DShadow uShadowDepth[kMaxShadow2D];
layout(binding = kUnitTint2D) uniform sampler2D uShadowTint[kMaxShadow2D];
layout(binding = kUnitRaw2D) uniform sampler2D uShadowRaw[kMaxShadow2D];
layout(binding = kUnitShadowCube) uniform samplerCubeShadow uShadowCube[kMaxShadowCube];
layout(binding = kUnitTintCube) uniform samplerCube uShadowTintCube[kMaxShadowCube];
layout(binding = kUnitRawCube) uniform samplerCube uShadowRawCube[kMaxShadowCube];
// 1 - the farthest translucent layer's depth per texel, and the farthest entry's (DepthAndTintMaps::LightMaps::drawn).
layout(binding = kUnitDrawnFarthest2D) uniform sampler2D uShadowDrawn[kMaxShadow2D];
layout(binding = kUnitDrawnFarthestCube) uniform samplerCube uShadowDrawnCube[kMaxShadowCube];  // nearest filtering

#define SLOT_SWITCH_4(EXPR) \
    switch (slot) { case 0: return EXPR(0); case 1: return EXPR(1); case 2: return EXPR(2); default: return EXPR(3); }
#define SLOT_SWITCH_2(EXPR) \
    switch (slot) { case 0: return EXPR(0); default: return EXPR(1); }

float shadowCompare2D(int slot, vec3 uvDepth) {
#define S(i) texture(uShadowDepth[i], uvDepth)
    SLOT_SWITCH_4(S)
#undef S
}
float shadowCompareCube(int slot, vec3 dir, float depth) {
#define S(i) texture(uShadowCube[i], vec4(dir, depth))
    SLOT_SWITCH_2(S)
#undef S
}
vec4 shadowTint2D(int slot, vec2 uv) {
#define S(i) textureLod(uShadowTint[i], uv, 0.0)
    SLOT_SWITCH_4(S)
#undef S
}
// The 2 x 2 tint texels around uv unfiltered: columns r, g, b, a, each in gather order.
mat4 shadowTintGather2D(int slot, vec2 uv) {
#define S(i) mat4(textureGather(uShadowTint[i], uv, 0), textureGather(uShadowTint[i], uv, 1), \
                  textureGather(uShadowTint[i], uv, 2), textureGather(uShadowTint[i], uv, 3))
    SLOT_SWITCH_4(S)
#undef S
}
mat4 shadowTintGatherCube(int slot, vec3 dir) {
#define S(i) mat4(textureGather(uShadowTintCube[i], dir, 0), textureGather(uShadowTintCube[i], dir, 1), \
                  textureGather(uShadowTintCube[i], dir, 2), textureGather(uShadowTintCube[i], dir, 3))
    SLOT_SWITCH_2(S)
#undef S
}
// The tint's alpha at the 2 x 2 texels a bilinear fetch at uv (dir) blends, in gather order.
vec4 shadowTintAlphaGather2D(int slot, vec2 uv) {
#define S(i) textureGather(uShadowTint[i], uv, 3)
    SLOT_SWITCH_4(S)
#undef S
}
vec4 shadowTintAlphaGatherCube(int slot, vec3 dir) {
#define S(i) textureGather(uShadowTintCube[i], dir, 3)
    SLOT_SWITCH_2(S)
#undef S
}
vec4 shadowTintCube(int slot, vec3 dir) {
#define S(i) textureLod(uShadowTintCube[i], dir, 0.0)
    SLOT_SWITCH_2(S)
#undef S
}
// The translucent tint at a receiver of window depth `depth` (Nápravník 2020's colour map: the
// colour applies only behind the nearest translucent layer; alpha holds 1 - its depth). A program
// for a scene where no translucent object casts a shadow (SCENE_TRANSLUCENT_CASTERS 0) fetches
// nothing: measured on llvmpipe, the fetch was 2.7 ms of hard's 24 ms opaque pass. Nor does a
// program for receivers no translucent caster's shadow reaches (RECEIVER_UNTINTED: the renderer
// draws them, or their pixels off every coloured shadow's footprint, with it; render/TintReach.h).
vec3 tintBehind(vec4 tint, float depth) { return 1.0 - depth < tint.a ? tint.rgb : vec3(1.0); }  // alpha: 1 - the nearest layer's depth
#if (defined(SCENE_TRANSLUCENT_CASTERS) && SCENE_TRANSLUCENT_CASTERS == 0) || defined(RECEIVER_UNTINTED)
vec3 shadowTintBehind2D(int slot, vec2 uv, float depth) { return vec3(1.0); }
vec3 shadowTintBehindCube(int slot, vec3 dir, float depth) { return vec3(1.0); }
#else
vec3 shadowTintBehind2D(int slot, vec2 uv, float depth) { return tintBehind(shadowTint2D(slot, uv), depth); }
vec3 shadowTintBehindCube(int slot, vec3 dir, float depth) { return tintBehind(shadowTintCube(slot, dir), depth); }
#endif
vec4 shadowRaw2D(int slot, vec2 uv, vec2 dx, vec2 dy) {
#define S(i) textureGrad(uShadowRaw[i], uv, dx, dy)
    SLOT_SWITCH_4(S)
#undef S
}
vec4 shadowRawCube(int slot, vec3 dir, vec3 dx, vec3 dy) {
#define S(i) textureGrad(uShadowRawCube[i], dir, dx, dy)
    SLOT_SWITCH_2(S)
#undef S
}
// Filtered (mipmapped, anisotropic) with the implicit derivatives of `uv` (`dir`): call from uniform
// control flow only. llvmpipe takes textureGrad's explicit gradients on a far slower path, a level
// of detail per pixel instead of per 2 x 2 quad: the moment lookups' opaque pass was 10-12 ms
// dearer that way (default scene, vsm 70 -> 59 ms, msm 76 -> 64; lighting.frag's projectorTexel).
vec4 shadowRawFiltered2D(int slot, vec2 uv) {
#define S(i) texture(uShadowRaw[i], uv)
    SLOT_SWITCH_4(S)
#undef S
}
vec4 shadowRawFilteredCube(int slot, vec3 dir) {
#define S(i) texture(uShadowRawCube[i], dir)
    SLOT_SWITCH_2(S)
#undef S
}
// One texel of a raw map's mip level `lod` (2D), and the texel a direction selects in a level (cube).
vec4 shadowRawFetch2D(int slot, ivec2 texel, int lod) {
#define S(i) texelFetch(uShadowRaw[i], texel, lod)
    SLOT_SWITCH_4(S)
#undef S
}
vec4 shadowRawLevelCube(int slot, vec3 dir, float lod) {
#define S(i) textureLod(uShadowRawCube[i], dir, lod)
    SLOT_SWITCH_2(S)
#undef S
}
vec4 shadowRawLod2D(int slot, vec2 uv) { return shadowRaw2D(slot, uv, vec2(0.0), vec2(0.0)); }
vec4 shadowRawLodCube(int slot, vec3 dir) { return shadowRawCube(slot, dir, vec3(0.0), vec3(0.0)); }
// Alpha of the 2 x 2 raw texels around uv (2D) or dir (cube), without filtering.
vec4 shadowRawGatherAlpha2D(int slot, vec2 uv) {
#define S(i) textureGather(uShadowRaw[i], uv, 3)
    SLOT_SWITCH_4(S)
#undef S
}
// The window depth of the farthest translucent layer, and of the farthest entry into a solid
// (transmit.frag): at the 2 x 2 texels around uv or dir (gather order), or at the one texel.
#define DRAWN_GATHER(SAMPLER, COORD) farthest = vec4(1.0) - textureGather(SAMPLER, COORD, 0); entry = vec4(1.0) - textureGather(SAMPLER, COORD, 1); return;
void shadowDrawnGather2D(int slot, vec2 uv, out vec4 farthest, out vec4 entry) {
#define S(i) DRAWN_GATHER(uShadowDrawn[i], uv)
    switch (slot) { case 0: S(0) case 1: S(1) case 2: S(2) default: S(3) }
#undef S
}
void shadowDrawnGatherCube(int slot, vec3 dir, out vec4 farthest, out vec4 entry) {
#define S(i) DRAWN_GATHER(uShadowDrawnCube[i], dir)
    switch (slot) { case 0: S(0) default: S(1) }
#undef S
}
#undef DRAWN_GATHER
vec2 shadowDrawnFetch2D(int slot, ivec2 texel) {
#define S(i) (vec2(1.0) - texelFetch(uShadowDrawn[i], texel, 0).rg)
    SLOT_SWITCH_4(S)
#undef S
}
vec2 shadowDrawnCube(int slot, vec3 dir) {  // nearest filtering: the texel `dir` selects
#define S(i) (vec2(1.0) - textureLod(uShadowDrawnCube[i], dir, 0.0).rg)
    SLOT_SWITCH_2(S)
#undef S
}
vec4 shadowRawGatherAlphaCube(int slot, vec3 dir) {
#define S(i) textureGather(uShadowRawCube[i], dir, 3)
    SLOT_SWITCH_2(S)
#undef S
}
