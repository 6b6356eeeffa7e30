#version 450 core
// Translucent casters as seen from the light (the per-light colour buffer of Nápravník 2020):
// rgb = fraction of light passing, multiplied over every layer by blending (dst * src);
// a = depth of the nearest translucent layer (MIN blending), so receivers in front of it
// stay untinted.
#include "shaders/common/material.glsl"
in vec2 vUv;
layout(location = 0) out vec4 outTransmit;
void main() {
    float coverage = materialCoverage(materialTexel(vUv));
    outTransmit = vec4(vec3(1.0) - materialStopped(coverage), gl_FragCoord.z);
}
