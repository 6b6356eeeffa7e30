#version 450 core
// One direction of a separable Gaussian (sigma = radius / 2): O(n) per texel instead of O(n^2).
// An exp() per tap, measured on llvmpipe (default scene, vsm, radius 2; shadow pass): 172 ms,
// against 186-190 ms with the incremental Gaussian (GPU Gems 3 ch. 40) and 423 ms with weights
// from a uniform array indexed by the loop counter (a per-lane gather). The fetches dominate.
in vec2 vUv;
layout(binding = 0) uniform sampler2D uSource;
uniform ivec2 uDirection;
uniform int uRadius;
layout(location = 0) out vec4 outValue;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy), size = textureSize(uSource, 0) - 1;
    float sigma = max(float(uRadius) * 0.5, 0.5);
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int i = -uRadius; i <= uRadius; ++i) {
        float w = exp(-float(i * i) / (2.0 * sigma * sigma));
        sum += w * texelFetch(uSource, clamp(p + uDirection * i, ivec2(0), size), 0);
        weights += w;
    }
    outValue = sum / weights;
}
