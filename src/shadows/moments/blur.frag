#version 450 core
// One direction of a separable Gaussian: O(n) per texel instead of O(n^2). Its radius and
// sigma in moment texels are compile-time constants (BLUR_RADIUS, BLUR_SIGMA; see
// MomentShadowMap::buildPrograms): the taps unroll and their weights fold into constants. (With a uniform radius an exp() per tap measured cheapest on llvmpipe, 172 ms
// for vsm's shadow pass at radius 2, against 186-190 ms with the incremental Gaussian of GPU
// Gems 3 ch. 40 and 423 ms with weights from a uniform array. The fetches dominate.)
in vec2 vUv;
layout(binding = 0) uniform sampler2D uSource;
uniform ivec2 uDirection;
layout(location = 0) out vec4 outValue;

const int kRadius = BLUR_RADIUS;
const float kSigma = BLUR_SIGMA;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy), last = textureSize(uSource, 0) - 1;
    vec4 sum = vec4(0.0);
    float weights = 0.0;
    for (int i = -kRadius; i <= kRadius; ++i) {
        float w = exp(-float(i * i) / (2.0 * kSigma * kSigma));
        sum += w * texelFetch(uSource, clamp(p + uDirection * i, ivec2(0), last), 0);
        weights += w;
    }
    outValue = sum / weights;
}
