#version 450 core
// The opaque casters' moments, drawn straight into the moment map's resolution with a depth
// buffer of its own: each texel the moments of the nearest caster at its centre (Donnelly &
// Lauritzen 2006, who render (z, z^2) the same way). On llvmpipe this costs a sixth of converting
// a depth map: every fetch of a depth texel costs about as much as a texel of this raster.
// ALPHA_TEST: materials with a cutoff leave holes, as in depth.frag.
#include "src/shadows/moments/moments.glsl"
#ifdef ALPHA_TEST
#include "shaders/common/material.glsl"
in vec2 vUv;
#endif
layout(location = 0) out vec4 outMoments;

void main() {
#ifdef ALPHA_TEST
    materialCoverage(materialTexel(vUv));
#endif
    outMoments = momentsOf(gl_FragCoord.z);
}
