// Filterable shadow maps: the map stores moments of the occluder depth distribution, filtered
// like any texture (blur, mipmaps, anisotropy), and the lookup bounds the lit fraction.
#include "src/shadows/common/glsl/shadow_filtering.glsl"
#include "src/shadows/moments/MomentWarp.h"

// The warp is compiled in (MomentShadowMap::lookupDefines): llvmpipe would run every warp's
// branch for every pixel.
const int kWarp = MOMENT_WARP;  // kWarp*, as src/shadows/moments/moments.frag
uniform vec2 uExponents;        // c+, c-
uniform float uMinVariance;
uniform float uBleedReduction;  // Lauritzen's light-bleeding reduction: linstep(amount, 1, p_max)
uniform float uMomentBias;      // MSM

// One-sided Chebyshev: p_max = σ² / (σ² + (t - μ)²); lit = 1 when t <= μ (Donnelly & Lauritzen).
float chebyshev(vec2 m, float t, float minVariance) {
    if (t <= m.x) return 1.0;
    float variance = max(m.y - m.x * m.x, minVariance);
    float d = t - m.x;
    float p = variance / (variance + d * d);
    return clamp((p - uBleedReduction) / (1.0 - uBleedReduction), 0.0, 1.0);
}

// Hamburger 4MSM (Peters & Klein 2015, algorithm 2): the shadow intensity bound from four
// moments of depth in [0, 1]. The Hankel system B c = (1, zf, zf^2) is solved through B = L D L^T
// (the paper's Cholesky form), not inverse(B): where the moments come from one depth B is nearly
// singular, and the cofactors' cancellation in fp32 speckled the inside of shadows with lit pixels.
float momentShadowIntensity(vec4 b, float zf) {
    b = mix(b, vec4(0.5), uMomentBias);
    float d22 = b.y - b.x * b.x;                       // D22 = b2 - b1^2, the variance
    float l32 = (b.z - b.x * b.y) / d22;               // L32 = (b3 - b1 b2) / D22
    float d33 = b.w - b.y * b.y - l32 * l32 * d22;     // D33 = b4 - b2^2 - L32^2 D22
    // Forward substitution (L y = rhs), the diagonal, back substitution (L^T c = y).
    vec3 c = vec3(1.0, zf - b.x, 0.0);
    c.z = zf * zf - b.y - l32 * c.y;
    c.y /= d22;
    c.z /= d33;
    c.y -= l32 * c.z;
    c.x -= dot(c.yz, b.xy);
    // The roots z2 <= z3 of c.x + c.y z + c.z z^2 (c.z > 0: B is positive definite).
    float p = c.y / c.z, q = c.x / c.z;
    float r = sqrt(max(0.25 * p * p - q, 0.0));
    float z2 = -0.5 * p - r, z3 = -0.5 * p + r;
    if (zf <= z2) return 0.0;
    if (zf <= z3) return clamp((zf * z3 - b.x * (zf + z3) + b.y) / ((z3 - z2) * (zf - z2)), 0.0, 1.0);
    return clamp(1.0 - (z2 * z3 - b.x * (z2 + z3) + b.y) / ((zf - z2) * (zf - z3)), 0.0, 1.0);
}

vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    ShadowSite s = shadowSite(light, P, N, NdotL);
    // Sample before any branch: mipmapped lookups need derivatives from uniform control flow.
    vec4 m = s.cube ? shadowRawFilteredCube(s.slot, s.coord) : shadowRawFiltered2D(s.slot, s.coord.xy);
    if (!s.inside) return vec3(1.0);
    float t = linearShadowDepth(light, s.depth);
    float x = 2.0 * t - 1.0;
    float lit;
    if (kWarp == kWarpVariance) {
        lit = chebyshev(m.xy, x, uMinVariance);
    } else if (kWarp == kWarpExponential) {
        lit = clamp(m.x * exp(-uExponents.x * x), 0.0, 1.0);
    } else if (kWarp == kWarpExponentialVariance2 || kWarp == kWarpExponentialVariance4) {
        // Variance is warped too: scale the minimum by the warp's slope squared.
        float p = exp(uExponents.x * x);
        lit = chebyshev(m.xy, p, uMinVariance * pow(uExponents.x * p, 2.0));
        if (kWarp == kWarpExponentialVariance4) {
            float n = -exp(-uExponents.y * x);
            lit = min(lit, chebyshev(m.zw, n, uMinVariance * pow(uExponents.y * n, 2.0)));
        }
    } else {
#if MOMENTS_QUANTIZED
        m = kMomentsDequantize * (m - kMomentsQuantizeOffset);
#endif
        lit = 1.0 - momentShadowIntensity(m, t);
    }
    return lit * plainMapTint(s, NdotL);
}
