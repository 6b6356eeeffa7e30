#version 450 core
// Casters into a coloured stochastic shadow map (McGuire & Enderton 2011; Mátl 2013 ch. 4-5).
// A fragment stops light of channel λ with probability ρ_λ = (1 - t_λ) α: it writes its depth
// to that channel when ξ < ρ_λ, and 1 (no occlusion) otherwise; MIN blending keeps the nearest
// occluder per channel. (The thesis's pseudocode prints the comparison reversed; its text and
// CSSM2 agree with this.)
//   CSSM2: one pass, one ξ per fragment shared by the channels.
//   CSSM1: one pass per channel (uChannel), independent ξ per channel; opaque casters too.
#include "shaders/common/material.glsl"
#include "shaders/common/random.glsl"
#include "shaders/common/depth.glsl"
in vec2 vUv;
uniform int uPerspective;
uniform float uNear, uFar;
uniform int uChannel;  // -1: all channels (CSSM2), else 0..2 (CSSM1)
layout(location = 0) out vec4 outDepth;

float linearDepth(float z) { return uPerspective == 0 ? z : perspectiveLinearDepth(z, uNear, uFar); }

void main() {
    vec3 rho = materialStopped(materialCoverage(materialTexel(vUv)));
    float z = linearDepth(gl_FragCoord.z);
    if (uChannel < 0) {
        float xi = fragmentRandom(0u);
        outDepth = vec4(mix(vec3(1.0), vec3(z), lessThan(vec3(xi), rho)), 1.0);
        return;
    }
    float xi = fragmentRandom(uint(uChannel) + 1u);
    outDepth = vec4(xi < rho[uChannel] ? z : 1.0);
}
