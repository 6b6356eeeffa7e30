#version 450 core
// Depth of opaque casters; alpha-tested (MASK) texels leave holes. Without an alpha test the
// texture is not read at all: the depth pass of a textured caster then costs what an untextured
// one does (a uniform branch).
#include "shaders/common/material.glsl"
in vec2 vUv;
void main() {
    if (uAlphaCutoff > 0.0) materialCoverage(materialTexel(vUv));
}
