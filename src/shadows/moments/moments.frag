#version 450 core
// Depth map -> moments of (warped) linear depth, one texel each (blurred afterwards).
// The warps are those of MomentWarp.h; x = linear depth remapped to [-1, 1], t = linear depth
// in [0, 1].
// With MSAA the depth comes from a multisampled map: the moments of every sample are averaged,
// which is the point of MSAA for filterable maps (moments are linear, depths are not).
#include "shaders/common/depth.glsl"
#include "src/shadows/moments/MomentWarp.h"
in vec2 vUv;
layout(binding = 0) uniform sampler2D uDepth;
layout(binding = 1) uniform sampler2DMS uDepthMS;
uniform int uSamples;  // 0: single-sampled uDepth
uniform int uWarp;  // kWarp*
uniform int uPerspective;
uniform float uNear, uFar;
uniform vec2 uExponents;  // c+, c-
layout(location = 0) out vec4 outMoments;

vec4 momentsOf(float z) {
    float t = uPerspective != 0 ? perspectiveLinearDepth(z, uNear, uFar) : z;
    float x = 2.0 * t - 1.0;
    if (uWarp == kWarpVariance) return vec4(x, x * x, 0.0, 0.0);
    if (uWarp == kWarpExponential) return vec4(exp(uExponents.x * x), 0.0, 0.0, 0.0);
    if (uWarp == kWarpExponentialVariance2 || uWarp == kWarpExponentialVariance4) {
        float p = exp(uExponents.x * x), n = -exp(-uExponents.y * x);
        return vec4(p, p * p, n, n * n);
    }
    return vec4(t, t * t, t * t * t, t * t * t * t);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (uSamples == 0) {
        outMoments = momentsOf(texelFetch(uDepth, p, 0).r);
        return;
    }
    vec4 sum = vec4(0.0);
    for (int i = 0; i < uSamples; ++i) sum += momentsOf(texelFetch(uDepthMS, p, i).r);
    outMoments = sum / float(uSamples);
}
