#version 450 core
// blur_box.frag's 2 x 2 box from the casters' depth alone (MomentShadowMap::boxFromDepth): one
// textureGather fetches the four depths around the corner p shares with p + (1, 1), and their
// first-order values (moments.glsl's firstOrderOf) are taken to their mean moments here. The
// casters' raster writes depth only, through an empty fragment stage. On llvmpipe (every map
// redrawn, default scene) against a raster of one 32-bit first-order value per texel: msm's raster
// 5.3 -> 3.8 ms, its box 4.8 -> 5.6 (four values a texel taken here, not one), its shadow pass
// 2.03 -> 1.91x hard's (docs/measurements.md, stop 74). That one value had in turn taken EVSM4's
// raster from 8.8 to 6.0 ms and MSM's from 6.2 to 5.0-5.5 against every moment (stop 71).
#include "src/shadows/moments/moments.glsl"
layout(binding = 0) uniform sampler2D uDepth;  // the casters' window depth per texel, clamped to its edges
uniform vec2 uFarFirstOrder;                   // MomentShadowMap::farFirstOrder: where the raster left depth 1
layout(location = 0) out vec4 outValue;

// Depth 1 is the clear: a caster there fails the raster's depth test. Its values come from the CPU,
// as the moments the clears and mip levels write where no caster is (farMoments).
vec2 firstOrderOfTexel(float z) { return z < 1.0 ? firstOrderOf(z) : uFarFirstOrder; }

void main() {
    vec2 corner = (gl_FragCoord.xy + 0.5) / vec2(textureSize(uDepth, 0));
    vec4 z = textureGather(uDepth, corner, 0);
    vec2 v0 = firstOrderOfTexel(z.x), v1 = firstOrderOfTexel(z.y), v2 = firstOrderOfTexel(z.z), v3 = firstOrderOfTexel(z.w);
    outValue = meanMoments(vec4(v0.x, v1.x, v2.x, v3.x), vec4(v0.y, v1.y, v2.y, v3.y));
}
