// Percentage-closer filtering (Reeves, Salesin & Cook 1987): the fraction of depth comparisons
// that pass over a kernel around the receiver. The kernels (PcfKernel.h) are those of the soft-
// shadow lecture and the thesis comparison: grid, hardware bilinear, Gaussian, Poisson disk,
// uniform random, jittered disk texture, dither, per-pixel rotated disk, adaptive.
#include "src/shadows/common/glsl/kernels.glsl"
#include "src/shadows/common/glsl/depth_tiles.glsl"
#include "src/shadows/pcf/PcfKernel.h"

// The kernel is a compile-time constant (PercentageCloserFilter::lookupDefines), so that the
// program holds that kernel's taps alone (llvmpipe ran every kernel's first taps, masked).
const int kKernel = PCF_KERNEL;  // kPcf*
uniform int uKernelSize;       // N of the grid / Gaussian kernels
uniform int uTaps;             // Poisson / random / jitter / dither tap count
uniform float uRadiusTexels;   // filter radius in shadow texels
uniform float uRadiusWorld;    // > 0: radius in world units instead
uniform int uReceiverPlane;    // 1: receiver-plane depth bias per tap
uniform float uTapReach;       // the farthest tap along x or y, in units of the radius
layout(binding = kUnitJitter) uniform sampler3D uJitter;  // rg, ba: two unit-disk offsets per layer

float tap(ShadowSite s, vec2 offsetTexels) {
    // Receiver-plane bias, clamped so that a grazing receiver cannot push taps to infinity.
    float planeOffset = uReceiverPlane != 0 ? tapReceiverDepth(s, offsetTexels) - s.depth : 0.0;
    return compareAt(s, offsetTexels, planeOffset);
}

// Every kernel loop starts with `if (agreed >= 0.0) break;`, `agreed` being tapsAgree()'s answer
// (common/glsl/depth_tiles.glsl).
float poisson(ShadowSite s, float radius, mat2 rot, int count, float agreed) {
    float sum = 0.0;
    for (int i = 0; i < count; ++i) {
        if (agreed >= 0.0) { sum = agreed * float(count); break; }
        sum += tap(s, poissonTap(i, rot, radius));
    }
    return sum / float(count);
}

float grid(ShadowSite s, float radius, bool gaussian, float agreed) {
    int n = max(uKernelSize, 1);
    float sigma = max(radius * 0.5, 1e-3);
    float sum = 0.0, weights = 0.0;
    for (int j = 0; j < n; ++j) {
        if (agreed >= 0.0) { sum = agreed; weights = 1.0; break; }
        for (int i = 0; i < n; ++i) {
            vec2 o = gridTap(i, j, n, radius);
            float w = gaussian ? exp(-dot(o, o) / (2.0 * sigma * sigma)) : 1.0;
            sum += w * tap(s, o);
            weights += w;
        }
    }
    return sum / weights;
}

float percentageCloser(ShadowSite s, float radius) {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    if (kKernel == kPcfBilinear) return tap(s, vec2(0.0));
    float agreed = tapsAgree(s, radius * uTapReach, uReceiverPlane != 0 ? s.depthSlope : vec2(0.0));
    if (kKernel == kPcfGrid) return grid(s, radius, false, agreed);
    if (kKernel == kPcfGaussian) return grid(s, radius, true, agreed);
    if (kKernel == kPcfPoisson) return poisson(s, radius, mat2(1.0), uTaps, agreed);
    if (kKernel == kPcfRandom) {
        float sum = 0.0;
        for (int i = 0; i < uTaps; ++i) {
            if (agreed >= 0.0) { sum = agreed * float(uTaps); break; }
            sum += tap(s, randomDiskTap(i, radius));
        }
        return sum / float(uTaps);
    }
    if (kKernel == kPcfJitter) {
        float sum = 0.0;
        int layers = uTaps / 2;
        for (int l = 0; l < layers; ++l) {
            if (agreed >= 0.0) { sum = agreed * float(layers * 2); break; }
            vec4 o = texelFetch(uJitter, ivec3(pixel & 31, l), 0);
            sum += tap(s, o.xy * radius) + tap(s, o.zw * radius);
        }
        return sum / float(layers * 2);
    }
    if (kKernel == kPcfDither) {
        // Two interleaved halves of a Poisson set: neighbouring pixels use different taps,
        // the eye averages them (GPU Gems 1 ch. 11's dithered 4-tap idea, generalised).
        int parity = (pixel.x + pixel.y) & 1;
        float sum = 0.0;
        int count = uTaps / 2;
        for (int i = 0; i < count; ++i) {
            if (agreed >= 0.0) { sum = agreed * float(count); break; }
            sum += tap(s, uPoisson[2 * i + parity] * radius);
        }
        return sum / float(count);
    }
    if (kKernel == kPcfRotated) return poisson(s, radius, pixelRotation(), uTaps, agreed);
    // kPcfAdaptive: a cheap ring test; the full kernel only where it disagrees (the penumbra).
    float probe = tap(s, vec2(0.0));
    float agree = 1.0;
    for (int i = 0; i < 4; ++i) {
        float a = 1.5707963 * float(i) + 0.785398;
        agree *= step(abs(tap(s, vec2(cos(a), sin(a)) * radius) - probe), 0.0);
    }
    return agree > 0.5 ? probe : poisson(s, radius, mat2(1.0), uTaps, agreed);
}

vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    ShadowSite s = shadowSite(light, P, N, NdotL);
    if (!s.inside) return vec3(1.0);
    float radius = uRadiusWorld > 0.0 ? uRadiusWorld / s.texelWorld : uRadiusTexels;
    return percentageCloser(s, radius) * plainMapTint(s, NdotL);
}
