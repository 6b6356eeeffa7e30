// Coloured stochastic shadow map lookup (McGuire & Enderton 2011; Mátl 2013 §5.3):
// X += (map.rgb(s + Δ) > s.z) over n taps, received light X·L/n. Filters compared in the
// thesis (CssmFilter.h): PCF 3x3 (9 taps), Poisson 16, Poisson 20, uniform random 30, and the
// 13-tap cross-plus-square {(0,0), (±3,±3), (±4,0), (0,±4), (±7,0), (0,±7)} texels, every tap
// jittered by δ(s) = ([(5 s) mod 2] - 1) / (6 (‖∂s/∂x‖₁, ‖∂s/∂y‖₁)).
#include "src/shadows/common/glsl/kernels.glsl"
#include "src/shadows/cssm/CssmFilter.h"

uniform int uFilter;  // kCssm*
uniform float uStorageEpsilon;  // relative precision of the stored depth (RGBA16F: 2^-10), 0 for fp32
uniform float uRadiusTexels;  // <= 0: automatic, so that the taps land on distinct texels

const vec2 kCross13[13] = vec2[](vec2(0, 0), vec2(3, 3), vec2(-3, 3), vec2(3, -3), vec2(-3, -3), vec2(4, 0),
                                 vec2(-4, 0), vec2(0, 4), vec2(0, -4), vec2(7, 0), vec2(-7, 0), vec2(0, 7), vec2(0, -7));

// Per channel: 1 where the stored (nearest stochastic occluder) depth lies beyond the receiver.
// The receiver's depth is extrapolated along its plane to each tap (receiver-plane depth bias):
// kernels up to 7 texels wide would otherwise shadow sloped receivers with themselves.
vec3 passes(ShadowSite s, vec2 texels) {
    vec3 stored = s.cube ? shadowRawLodCube(s.slot, s.coord + s.tangent * texels.x + s.bitangent * texels.y).rgb
                         : shadowRawLod2D(s.slot, s.coord.xy + texels / s.resolution).rgb;
    float receiver = linearShadowDepth(s.light, tapReceiverDepth(s, texels));
    // Half floats round the stored depth by up to an ulp: a receiver must not shadow itself by that.
    return vec3(greaterThan(stored, vec3(receiver * (1.0 - uStorageEpsilon))));
}

vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    ShadowSite s = shadowSite(light, P, N, NdotL);
    // s in texels, and ∂s/∂x, ∂s/∂y, taken before any branch. Cube maps: coordinates along the
    // face's texel steps (tangent, bitangent), not the direction's x, y (constant on some faces).
    vec2 sTexels = s.cube ? vec2(dot(s.coord, s.tangent), dot(s.coord, s.bitangent)) / dot(s.tangent, s.tangent)
                          : s.coord.xy * s.resolution;
    vec2 dsdx = dFdx(sTexels), dsdy = dFdy(sTexels);
    if (!s.inside) return vec3(1.0);
    vec3 sum = vec3(0.0);
    int n;
    if (uFilter == kCssmPcf9) {
        n = 9;
        for (int j = -1; j <= 1; ++j)
            for (int i = -1; i <= 1; ++i) sum += passes(s, vec2(i, j));
    } else if (uFilter == kCssmPoisson16 || uFilter == kCssmPoisson20) {
        n = uFilter == kCssmPoisson16 ? 16 : 20;
        // n taps need about n texels under the disk: r = sqrt(n / π), with room to spare.
        float radius = uRadiusTexels > 0.0 ? uRadiusTexels : 1.5 * sqrt(float(n) / 3.14159);
        mat2 rot = pixelRotation();
        for (int i = 0; i < n; ++i) sum += passes(s, poissonTap(i, rot, radius));
    } else if (uFilter == kCssmRandom30) {
        n = 30;
        float radius = uRadiusTexels > 0.0 ? uRadiusTexels : 1.5 * sqrt(float(n) / 3.14159);
        for (int i = 0; i < n; ++i) sum += passes(s, randomDiskTap(i, radius));
    } else {  // kCssmCross13
        n = 13;
        // Norms below 1/6 texel per pixel (strong magnification) would push δ past a texel: the
        // jitter is meant to be a micro-offset, so it is bounded to one texel.
        vec2 norms = max(vec2(abs(dsdx.x) + abs(dsdx.y), abs(dsdy.x) + abs(dsdy.y)), vec2(1.0 / 6.0));
        vec2 delta = (mod(5.0 * sTexels, vec2(2.0)) - vec2(1.0)) / (6.0 * norms);
        for (int i = 0; i < 13; ++i) sum += passes(s, kCross13[i] + delta);
    }
    return sum / float(n);
}
