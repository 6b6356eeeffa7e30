#version 450 core
// Translucent casters as seen from the light (the per-light colour buffer of Nápravník 2020):
// rgb = fraction of light passing, multiplied over every layer by blending (dst * src);
// a = 1 - depth, which MAX blending makes 1 - the nearest translucent layer's depth, so receivers
// in front of it stay untinted (DepthAndTintMaps::TintAlpha::NearestLayer), or MIN 1 - the
// farthest layer's (FarthestLayer).
#include "shaders/common/material.glsl"
#include "src/shadows/common/glsl/over_opaque.glsl"
in vec2 vUv;
// The second output (RG32F, MIN), where the map has one, keeps per texel in full precision
// 1 - the farthest layer's depth (r) and 1 - the farthest entry's (g): a face of a closed part
// (uClosedPart) facing the light, where light enters a solid, or any face of an open surface.
// Translucent receivers read both (ownLayersFrom in shadow_filtering.glsl).
layout(location = 0) out vec4 outTransmit;
layout(location = 1) out vec2 outDrawn;
void main() {
    testBehindOpaqueOffset();
    float coverage = materialCoverage(materialTexel(vUv));
    float drawn = 1.0 - gl_FragCoord.z;
    outTransmit = vec4(vec3(1.0) - materialStopped(coverage), drawn);
    outDrawn = vec2(drawn, uClosedPart == 0 || gl_FrontFacing ? drawn : 1.0);
}
