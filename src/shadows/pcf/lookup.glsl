// Percentage-closer filtering (Reeves, Salesin & Cook 1987): the fraction of depth comparisons
// that pass over a kernel around the receiver. Kernels (seed 004, SPEC §3):
//   0 grid NxN, 1 hardware bilinear 2x2, 2 Gaussian-weighted NxN, 3 Poisson disk (Bridson 2007),
//   4 uniform random per pixel, 5 jittered grid warped onto a disk from a 3D texture (GPU Gems 2
//   ch. 17 / OSG SoftShadowMap), 6 dithered (two offset sets in a checkerboard), 7 Poisson disk
//   rotated per pixel (interleaved gradient noise), 8 adaptive (5-tap edge test, full kernel
//   only in the penumbra).
#include "shaders/common/shadow_filtering.glsl"

uniform int uKernel;
uniform int uKernelSize;       // N of the grid / Gaussian kernels
uniform int uTaps;             // Poisson / random / jitter / dither tap count
uniform float uRadiusTexels;   // filter radius in shadow texels
uniform float uRadiusWorld;    // > 0: radius in world units instead
uniform int uReceiverPlane;    // 1: receiver-plane depth bias per tap
uniform vec2 uPoisson[32];     // unit-disk points
layout(binding = UNIT_JITTER) uniform sampler3D uJitter;  // rg, ba: two unit-disk offsets per layer

float tap(ShadowSite s, vec2 offsetTexels) {
    // Receiver-plane bias, clamped so that a grazing receiver cannot push taps to infinity.
    float planeOffset = uReceiverPlane != 0 ? tapReceiverDepth(s, offsetTexels) - s.depth : 0.0;
    return compareAt(s, offsetTexels, planeOffset);
}

float poisson(ShadowSite s, float radius, float angle, int count) {
    mat2 rot = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
    float sum = 0.0;
    for (int i = 0; i < count; ++i) sum += tap(s, rot * uPoisson[i] * radius);
    return sum / float(count);
}

float grid(ShadowSite s, float radius, bool gaussian) {
    int n = max(uKernelSize, 1);
    float half_ = float(n - 1) * 0.5;
    float step_ = n > 1 ? radius / half_ : 0.0;
    float sigma = max(radius * 0.5, 1e-3);
    float sum = 0.0, weights = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            vec2 o = (vec2(i, j) - half_) * step_;
            float w = gaussian ? exp(-dot(o, o) / (2.0 * sigma * sigma)) : 1.0;
            sum += w * tap(s, o);
            weights += w;
        }
    return sum / weights;
}

float percentageCloser(ShadowSite s, float radius) {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (uKernel == 1) return tap(s, vec2(0.0));  // the depth map samples with GL_LINEAR
    if (uKernel == 0) return grid(s, radius, false);
    if (uKernel == 2) return grid(s, radius, true);
    if (uKernel == 3) return poisson(s, radius, 0.0, uTaps);
    if (uKernel == 4) {
        float sum = 0.0;
        uint seed = uint(pixel.x) * 1973u + uint(pixel.y) * 9277u;
        for (int i = 0; i < uTaps; ++i) {
            float u = hashToUnit(seed + uint(i) * 26699u), v = hashToUnit(seed + uint(i) * 26699u + 1u);
            float r = sqrt(v), a = 6.2831853 * u;  // uniform on the disk
            sum += tap(s, vec2(cos(a), sin(a)) * r * radius);
        }
        return sum / float(uTaps);
    }
    if (uKernel == 5) {
        float sum = 0.0;
        int layers = uTaps / 2;
        for (int l = 0; l < layers; ++l) {
            vec4 o = texelFetch(uJitter, ivec3(pixel & 31, l), 0);
            sum += tap(s, o.xy * radius) + tap(s, o.zw * radius);
        }
        return sum / float(layers * 2);
    }
    if (uKernel == 6) {
        // Two interleaved halves of a Poisson set: neighbouring pixels use different taps,
        // the eye averages them (GPU Gems 1 ch. 11's dithered 4-tap idea, generalised).
        int parity = (pixel.x + pixel.y) & 1;
        float sum = 0.0;
        int count = uTaps / 2;
        for (int i = 0; i < count; ++i) sum += tap(s, uPoisson[2 * i + parity] * radius);
        return sum / float(count);
    }
    if (uKernel == 7) return poisson(s, radius, 6.2831853 * interleavedGradientNoise(gl_FragCoord.xy), uTaps);
    // Adaptive: a cheap ring test; the full kernel only where it disagrees (the penumbra).
    float probe = tap(s, vec2(0.0));
    float agree = 1.0;
    for (int i = 0; i < 4; ++i) {
        float a = 1.5707963 * float(i) + 0.785398;
        agree *= step(abs(tap(s, vec2(cos(a), sin(a)) * radius) - probe), 0.0);
    }
    return agree > 0.5 ? probe : poisson(s, radius, 0.0, uTaps);
}

vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    ShadowSite s = shadowSite(light, P, N, NdotL);
    if (!s.inside) return vec3(1.0);
    float radius = uRadiusWorld > 0.0 ? uRadiusWorld / s.texelWorld : uRadiusTexels;
    return percentageCloser(s, radius) * tintAt(s);
}
