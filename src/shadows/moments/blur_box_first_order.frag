#version 450 core
// blur_box.frag's 2 x 2 box from a raw map of first-order values alone (MomentShadowMap::
// firstOrderRaw): EVSM's warped depths (p = e^{c+ x} and, EVSM4, n = -e^{-c- x}) or MSM's depth t.
// One textureGather per value fetches the four texels around the corner p shares with p + (1, 1),
// and their moments (squares; MSM's powers, quantized once, the affine map commuting with the
// mean) are taken here. The casters' raster writes one or two 32-bit channels instead of four: on
// llvmpipe (every map redrawn, default scene) EVSM4's raster went from 8.8 to 6.0 ms, about VSM's,
// and this pass from 5.7 to 6.5 ms against blur_box.frag's one four-channel fetch
// (docs/measurements.md, stop 71).
#include "src/shadows/moments/MomentWarp.h"
layout(binding = 0) uniform sampler2D uSource;  // first-order values per texel, clamped to its edges
layout(location = 0) out vec4 outValue;

void main() {
    vec2 corner = (gl_FragCoord.xy + 0.5) / vec2(textureSize(uSource, 0));
    vec4 a = textureGather(uSource, corner, 0);
    if (MOMENT_WARP == kWarpMoments4) {
        vec4 a2 = a * a;
        vec4 b = 0.25 * vec4(dot(a, vec4(1.0)), dot(a2, vec4(1.0)), dot(a2, a), dot(a2, a2));
#if MOMENTS_QUANTIZED
        b = kMomentsQuantize * b + kMomentsQuantizeOffset;
#endif
        outValue = b;
        return;
    }
    vec4 n = MOMENT_WARP == kWarpExponentialVariance4 ? textureGather(uSource, corner, 1) : vec4(0.0);
    outValue = 0.25 * vec4(dot(a, vec4(1.0)), dot(a, a), dot(n, vec4(1.0)), dot(n, n));
}
