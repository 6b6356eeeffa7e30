#version 450 core
// Depth map -> moments of (warped) linear depth, one texel each (blurred afterwards).
//   0 VSM (Donnelly & Lauritzen 2006): (x, x^2), x = linear depth remapped to [-1, 1]
//   1 ESM (Annen et al. 2008): exp(c x)
//   2 EVSM2: (e^{c+ x}, e^{2 c+ x});  3 EVSM4: + (-e^{-c- x}, e^{-2 c- x})
//   4 MSM (Peters & Klein 2015): (t, t^2, t^3, t^4), t = linear depth in [0, 1]
// With MSAA the depth comes from a multisampled map: the moments of every sample are averaged,
// which is the point of MSAA for filterable maps (moments are linear, depths are not).
#include "../common/depth.glsl"
in vec2 vUv;
layout(binding = 0) uniform sampler2D uDepth;
layout(binding = 1) uniform sampler2DMS uDepthMS;
uniform int uSamples;  // 0: single-sampled uDepth
uniform int uWarp;
uniform int uPerspective;
uniform float uNear, uFar;
uniform vec2 uExponents;  // c+, c-
layout(location = 0) out vec4 outMoments;

vec4 momentsOf(float z) {
    float t = uPerspective != 0 ? perspectiveLinearDepth(z, uNear, uFar) : z;
    float x = 2.0 * t - 1.0;
    if (uWarp == 0) return vec4(x, x * x, 0.0, 0.0);
    if (uWarp == 1) return vec4(exp(uExponents.x * x), 0.0, 0.0, 0.0);
    if (uWarp == 2 || uWarp == 3) {
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
