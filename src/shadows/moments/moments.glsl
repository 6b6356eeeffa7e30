// What a moment map stores, in every warp of MomentWarp.h: x = linear depth remapped to [-1, 1],
// t = linear depth in [0, 1]. Shared by the casters' raster (caster_moments.frag), the
// conversion of a multisampled depth map (moments.frag) and the box from the raster's depth
// (blur_box_first_order.frag), and matched on the CPU by MomentShadowMap::farMoments for the
// clear where no caster is.
// MOMENT_WARP is a compile-time constant (MomentShadowMap::buildPrograms): llvmpipe runs every
// side of a uniform branch.
#include "shaders/common/depth.glsl"
#include "src/shadows/moments/MomentWarp.h"

const int kWarp = MOMENT_WARP;  // kWarp*
#ifdef LIGHT_PERSPECTIVE  // compiled in: blur_box_first_order.frag linearises four depths a texel
const bool kPerspective = LIGHT_PERSPECTIVE != 0;
#else
uniform int uPerspective;
#define kPerspective (uPerspective != 0)
#endif
uniform float uNear, uFar;
uniform vec2 uExponents;  // c+, c-

// The first-order values of one depth, those the moments are powers of: VSM's x, ESM's e^{c+ x},
// EVSM's p = e^{c+ x} and (EVSM4) n = -e^{-c- x}, MSM's t.
vec2 firstOrderOf(float z) {
    float t = kPerspective ? perspectiveLinearDepth(z, uNear, uFar) : z;
    float x = 2.0 * t - 1.0;
    if (kWarp == kWarpVariance) return vec2(x, 0.0);
    if (kWarp == kWarpExponential || kWarp == kWarpExponentialVariance2) return vec2(exp(uExponents.x * x), 0.0);
    if (kWarp == kWarpExponentialVariance4) return vec2(exp(uExponents.x * x), -exp(-uExponents.y * x));
    return vec2(t, 0.0);
}

// The mean moments of four texels whose first-order values are `a` (and `n`, EVSM4's negative
// warp), as the map stores them: VSM (x, x^2), ESM e^{c x}, EVSM (p, p^2, n, n^2), MSM
// (t, t^2, t^3, t^4) through the optimized quantization (an affine map: it commutes with the mean).
vec4 meanMoments(vec4 a, vec4 n) {
    const vec4 quarter = vec4(0.25);
    if (kWarp == kWarpVariance) return vec4(dot(a, quarter), dot(a * a, quarter), 0.0, 0.0);
    if (kWarp == kWarpExponential) return vec4(dot(a, quarter), 0.0, 0.0, 0.0);
    if (kWarp != kWarpMoments4) return vec4(dot(a, quarter), dot(a * a, quarter), dot(n, quarter), dot(n * n, quarter));
    vec4 a2 = a * a;
    vec4 b = vec4(dot(a, quarter), dot(a2, quarter), dot(a2 * a, quarter), dot(a2 * a2, quarter));
#if MOMENTS_QUANTIZED
    return kMomentsQuantize * b + kMomentsQuantizeOffset;
#else
    return b;
#endif
}

// The moments of one depth.
vec4 momentsOf(float z) {
    vec2 v = firstOrderOf(z);
    return meanMoments(vec4(v.x), vec4(v.y));
}
