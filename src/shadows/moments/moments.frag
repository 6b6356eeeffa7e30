#version 450 core
// Depth map -> moments of (warped) linear depth, one texel each, into a scratch map that
// blur.frag blurs into the moment map (x, then y), so that a pass may redo just a rectangle of
// the moment map where the depth changed (MomentShadowMap::update) without leaving unblurred
// moments around it.
// The warps are those of MomentWarp.h; x = linear depth remapped to [-1, 1], t = linear depth
// in [0, 1]. MOMENT_WARP and MOMENT_DOWNSAMPLE are compile-time constants
// (MomentShadowMap::buildPrograms): llvmpipe runs every side of a uniform branch.
// MOMENT_DOWNSAMPLE 1: the moment map has half the depth map's resolution, each texel the mean
// of its 2 x 2 depth texels' moments (moments are linear, so this is exact box filtering: part
// of the pre-filter, at a quarter of the texels to convert, blur and mipmap).
// With MSAA the depth comes from a multisampled map: the moments of every sample are averaged,
// which is the point of MSAA for filterable maps (moments are linear, depths are not).
#include "shaders/common/depth.glsl"
#include "src/shadows/moments/MomentWarp.h"
in vec2 vUv;
layout(binding = 0) uniform sampler2D uDepth;
layout(binding = 1) uniform sampler2DMS uDepthMS;
uniform int uSamples;  // 0: single-sampled uDepth
uniform int uPerspective;
uniform float uNear, uFar;
uniform vec2 uExponents;  // c+, c-
layout(location = 0) out vec4 outMoments;

const int kWarp = MOMENT_WARP;  // kWarp*
const bool kDownsample = MOMENT_DOWNSAMPLE != 0;

vec4 momentsOf(float z) {
    float t = uPerspective != 0 ? perspectiveLinearDepth(z, uNear, uFar) : z;
    float x = 2.0 * t - 1.0;
    if (kWarp == kWarpVariance) return vec4(x, x * x, 0.0, 0.0);
    if (kWarp == kWarpExponential) return vec4(exp(uExponents.x * x), 0.0, 0.0, 0.0);
    if (kWarp == kWarpExponentialVariance2 || kWarp == kWarpExponentialVariance4) {
        float p = exp(uExponents.x * x), n = -exp(-uExponents.y * x);
        return vec4(p, p * p, n, n * n);
    }
    return vec4(t, t * t, t * t * t, t * t * t * t);
}

vec4 multisampledMoments(ivec2 p) {
    vec4 sum = vec4(0.0);
    for (int i = 0; i < uSamples; ++i) sum += momentsOf(texelFetch(uDepthMS, p, i).r);
    return sum / float(uSamples);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (!kDownsample) {
        outMoments = uSamples == 0 ? momentsOf(texelFetch(uDepth, p, 0).r) : multisampledMoments(p);
        return;
    }
    if (uSamples == 0) {  // the 2 x 2 depth texels meeting at this texel's centre, in one gather
        vec4 z = textureGather(uDepth, vec2(2 * p + 1) / vec2(textureSize(uDepth, 0)), 0);
        outMoments = 0.25 * (momentsOf(z.x) + momentsOf(z.y) + momentsOf(z.z) + momentsOf(z.w));
        return;
    }
    outMoments = 0.25 * (multisampledMoments(2 * p) + multisampledMoments(2 * p + ivec2(1, 0)) +
                         multisampledMoments(2 * p + ivec2(0, 1)) + multisampledMoments(2 * p + ivec2(1, 1)));
}
