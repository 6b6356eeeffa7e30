#version 450 core
// Darkens the receiver by uOpacity where a flattened caster lands (dst *= 1 - alpha). Only what
// lies between the plane and the light casts, unless uNaive shows the method's classic errors.
#include "shaders/common/material.glsl"
in vec2 vUv;
in float vAbovePlane;
in float vBelowLight;
uniform float uOpacity;
uniform float uPlaneEpsilon;  // the receiver itself (and what lies on it) does not cast
uniform int uNaive;
out vec4 fragColor;
void main() {
    materialCoverage(materialTexel(vUv));
    if (abs(vAbovePlane) <= uPlaneEpsilon) discard;
    if (uNaive == 0 && (vAbovePlane < 0.0 || vBelowLight < 0.0)) discard;
    fragColor = vec4(0.0, 0.0, 0.0, uOpacity);
}
