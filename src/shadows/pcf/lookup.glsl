// Percentage-closer filtering (Reeves, Salesin & Cook 1987): the fraction of depth comparisons
// that pass over a kernel around the receiver. The kernels (PcfKernel.h) are those of the soft-
// shadow lecture and the thesis comparison: grid, hardware bilinear, Gaussian, Poisson disk,
// uniform random, jittered disk texture, dither, per-pixel rotated disk, adaptive.
#include "src/shadows/common/glsl/kernels.glsl"
#include "src/shadows/pcf/PcfKernel.h"

// The kernel is a compile-time constant (PercentageCloserFilter::lookupDefines), so that the
// program holds that kernel's taps alone (llvmpipe ran every kernel's first taps, masked).
const int kKernel = PCF_KERNEL;  // kPcf*
uniform int uKernelSize;       // N of the grid / Gaussian kernels
uniform int uTaps;             // Poisson / random / jitter / dither tap count
uniform float uRadiusTexels;   // filter radius in shadow texels
uniform float uRadiusWorld;    // > 0: radius in world units instead
uniform int uReceiverPlane;    // 1: receiver-plane depth bias per tap
uniform int uSkipAgreeing;     // 1: skip the taps where tapsAgree() knows their answer
uniform float uTapReach;       // the farthest tap along x or y, in units of the radius
layout(binding = kUnitJitter) uniform sampler3D uJitter;  // rg, ba: two unit-disk offsets per layer

float tap(ShadowSite s, vec2 offsetTexels) {
    // Receiver-plane bias, clamped so that a grazing receiver cannot push taps to infinity.
    float planeOffset = uReceiverPlane != 0 ? tapReceiverDepth(s, offsetTexels) - s.depth : 0.0;
    return compareAt(s, offsetTexels, planeOffset);
}

layout(binding = kUnitDepthTiles) uniform sampler2DArray uDepthTiles;  // DepthTileBounds: (a, g, farthest)

// What every tap of a kernel reaching `reach` texels (along each axis) returns, where the depth
// bounds of the receiver's tile (DepthTileBounds) show they all return the same: 1 (lit), 0
// (shadowed); -1 where they do not, or where taps may land past the tile's border (radius *
// uTapReach above kDepthTileBorder texels, cube maps): the taps must run. Exact, not a guess:
// a nearest-filtered tap landing at p + o reads texel floor(p + o), whose centre c lies within
// reach + 0.5 of p, and compares it with s.depth + clamp(slope . o, +-0.01), which is at most
// s.depth + max(slope . (c - p) + |slope|/2, -0.01). Lit: the tile's plane under every texel,
// g . c + a, lies behind that over the whole box of centres (its minimum is at a corner).
// Shadowed: the farthest texel lies in front of the lowest reference any tap can have.
// Measured on llvmpipe (default scene, pcf-poisson16): one fetch, where 4 gathers of the 16
// texels around the receiver cost about what 9 of the 16 taps do.
float tapsAgree(ShadowSite s, float reach) {
    if (uSkipAgreeing == 0 || s.cube || reach + 1e-3 > float(kDepthTileBorder)) return -1.0;
    vec2 slope = uReceiverPlane != 0 ? s.depthSlope : vec2(0.0);
    if (any(isnan(slope)) || any(isinf(slope))) return -1.0;
    vec2 p = s.coord.xy * s.resolution;
    vec2 tile = floor(p / float(kDepthTile));
    vec4 bounds = texelFetch(uDepthTiles, ivec3(tile, s.slot), 0);
    vec2 g = bounds.yz;
    vec2 local = p - tile * float(kDepthTile);  // p relative to the tile's corner
    float box = reach + 0.5 + 1e-3;             // how far a landing texel's centre lies from p, per axis
    float planeAtP = dot(g, local) + bounds.x;
    float slack = 0.5 * (abs(slope.x) + abs(slope.y)) + 1e-6;  // + rounding of the references
    bool behindPlane = planeAtP - dot(abs(g - slope), vec2(box)) >= s.depth + slack;
    bool behindFloor = planeAtP - dot(abs(g), vec2(box)) >= s.depth - 0.01 + 1e-6;
    if (behindPlane && behindFloor) return 1.0;
    float lowest = s.depth + max(-(abs(slope.x) + abs(slope.y)) * reach, -0.01) - 1e-6;
    // A reference past 1 may be clamped to 1 by the sampler: "in front" needs depths below 1.
    return bounds.w < lowest && bounds.w < 1.0 ? 0.0 : -1.0;
}

// Every kernel loop starts with `if (agreed >= 0.0) break;`, `agreed` being tapsAgree()'s answer.
// A loop, not an if: llvmpipe runs both sides of an if for its 8-pixel group, but leaves a loop
// once no lane is left in it (gallivm's lp_exec_endloop). Where the whole group agrees, the kernel
// costs one (masked) tap.
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
    float agreed = tapsAgree(s, radius * uTapReach);
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
    return percentageCloser(s, radius) * tintAt(s);
}
