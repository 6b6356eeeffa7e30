#version 450 core
// blur_box.frag's 2 x 2 box from a raw map of first-order values alone (MomentShadowMap::
// firstOrderRaw, moments.glsl's firstOrderOf): one textureGather per value fetches the four texels
// around the corner p shares with p + (1, 1), and their mean moments are taken here. The casters'
// raster writes one 32-bit channel (two for EVSM4) instead of two to four, and the gather fetches
// one: on llvmpipe (every map redrawn, default scene) EVSM4's raster went from 8.8 to 6.0 ms and
// MSM's from 6.2 to 5.0-5.5, their box from 5.7 to 6.1-6.7 (docs/measurements.md, stop 71).
#include "src/shadows/moments/moments.glsl"
layout(binding = 0) uniform sampler2D uSource;  // first-order values per texel, clamped to its edges
layout(location = 0) out vec4 outValue;

void main() {
    vec2 corner = (gl_FragCoord.xy + 0.5) / vec2(textureSize(uSource, 0));
    vec4 a = textureGather(uSource, corner, 0);
    vec4 n = kWarp == kWarpExponentialVariance4 ? textureGather(uSource, corner, 1) : vec4(0.0);
    outValue = meanMoments(a, n);
}
