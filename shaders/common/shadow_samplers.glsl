// The per-light shadow textures, one sampler per slot. Access goes through a switch with
// constant indices: llvmpipe (Mesa 22.3 / LLVM 15) crashes compiling dynamically indexed
// shadow-sampler arrays, and a switch is what a driver would generate anyway.
#include "bindings.glsl"

layout(binding = UNIT_SHADOW_2D) uniform sampler2DShadow uShadowDepth[MAX_SHADOW_2D];
layout(binding = UNIT_SHADOW_CUBE) uniform samplerCubeShadow uShadowCube[MAX_SHADOW_CUBE];
layout(binding = UNIT_TINT_2D) uniform sampler2D uShadowTint[MAX_SHADOW_2D];
layout(binding = UNIT_TINT_CUBE) uniform samplerCube uShadowTintCube[MAX_SHADOW_CUBE];

#define SLOT_SWITCH_8(EXPR) \
    switch (slot) { \
        case 0: return EXPR(0); case 1: return EXPR(1); case 2: return EXPR(2); case 3: return EXPR(3); \
        case 4: return EXPR(4); case 5: return EXPR(5); case 6: return EXPR(6); default: return EXPR(7); }
#define SLOT_SWITCH_4(EXPR) \
    switch (slot) { case 0: return EXPR(0); case 1: return EXPR(1); case 2: return EXPR(2); default: return EXPR(3); }

float shadowCompare2D(int slot, vec3 uvDepth) {
#define S(i) texture(uShadowDepth[i], uvDepth)
    SLOT_SWITCH_8(S)
#undef S
}
float shadowCompareCube(int slot, vec3 dir, float depth) {
#define S(i) texture(uShadowCube[i], vec4(dir, depth))
    SLOT_SWITCH_4(S)
#undef S
}
vec4 shadowTint2D(int slot, vec2 uv) {
#define S(i) textureLod(uShadowTint[i], uv, 0.0)
    SLOT_SWITCH_8(S)
#undef S
}
vec4 shadowTintCube(int slot, vec3 dir) {
#define S(i) textureLod(uShadowTintCube[i], dir, 0.0)
    SLOT_SWITCH_4(S)
#undef S
}
