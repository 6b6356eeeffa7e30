#version 450 core
// Translucent casters as seen from the light (the per-light colour buffer of Nápravník 2020):
// rgb = fraction of light passing, multiplied over every layer by blending (dst * src);
// a = 1 - depth, which MAX blending makes 1 - the nearest translucent layer's depth, so receivers
// in front of it stay untinted (DepthAndTintMaps::TintAlpha::NearestLayer), or MIN 1 - the
// farthest layer's (FarthestAround).
#include "shaders/common/material.glsl"
in vec2 vUv;
// With FarthestAround the second output (R32F, MIN) keeps 1 - the farthest depth per texel in
// full precision, where the bound is made from and CSSM's translucent receivers read it.
layout(location = 0) out vec4 outTransmit;
layout(location = 1) out float outDrawn;
void main() {
    float coverage = materialCoverage(materialTexel(vUv));
    outTransmit = vec4(vec3(1.0) - materialStopped(coverage), 1.0 - gl_FragCoord.z);
    outDrawn = 1.0 - gl_FragCoord.z;
}
