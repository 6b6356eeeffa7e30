#version 450 core
// Depth of opaque casters. Only the ALPHA_TEST variant (materials with an alpha cutoff) has a
// fragment stage that does anything: alpha-tested (MASK) texels leave holes. Every other caster
// gets an empty one, with no `discard` that would cost llvmpipe its early depth write
// (DepthCasterProgram in shadows/ShadowTechnique.h).
#ifdef ALPHA_TEST
#include "shaders/common/material.glsl"
in vec2 vUv;
void main() { materialCoverage(materialTexel(vUv)); }
#else
void main() {}
#endif
