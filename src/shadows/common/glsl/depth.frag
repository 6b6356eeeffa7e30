#version 450 core
// Depth of opaque casters; alpha-tested (MASK) texels leave holes.
#include "shaders/common/material.glsl"
in vec2 vUv;
void main() { materialCoverage(materialTexel(vUv)); }
