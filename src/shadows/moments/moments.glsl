// The moments a map stores of one depth, in every warp of MomentWarp.h: x = linear depth
// remapped to [-1, 1], t = linear depth in [0, 1]. Shared by the casters' raster
// (caster_moments.frag) and the conversion of a multisampled depth map (moments.frag), and
// matched on the CPU by MomentShadowMap::momentsOf for the clear where no caster is.
// MOMENT_WARP is a compile-time constant (MomentShadowMap::buildPrograms): llvmpipe runs every
// side of a uniform branch.
#include "shaders/common/depth.glsl"
#include "src/shadows/moments/MomentWarp.h"

const int kWarp = MOMENT_WARP;  // kWarp*
uniform int uPerspective;
uniform float uNear, uFar;
uniform vec2 uExponents;  // c+, c-

vec4 momentsOf(float z) {
    float t = uPerspective != 0 ? perspectiveLinearDepth(z, uNear, uFar) : z;
    float x = 2.0 * t - 1.0;
    if (kWarp == kWarpVariance) return vec4(x, x * x, 0.0, 0.0);
    if (kWarp == kWarpExponential) return vec4(exp(uExponents.x * x), 0.0, 0.0, 0.0);
    if (kWarp == kWarpExponentialVariance2 || kWarp == kWarpExponentialVariance4) {
        float p = exp(uExponents.x * x), n = kWarp == kWarpExponentialVariance4 ? -exp(-uExponents.y * x) : 0.0;
#if RAW_FIRST_ORDER
        return vec4(p, n, 0.0, 0.0);  // blur_box_first_order.frag squares them
#else
        return vec4(p, p * p, n, n * n);
#endif
    }
#if RAW_FIRST_ORDER
    return vec4(t, 0.0, 0.0, 0.0);  // blur_box_first_order.frag raises it to its powers
#endif
    vec4 b = vec4(t, t * t, t * t * t, t * t * t * t);
#if MOMENTS_QUANTIZED
    return kMomentsQuantize * b + kMomentsQuantizeOffset;
#else
    return b;
#endif
}

