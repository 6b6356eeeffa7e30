#version 450 core
// `blur_kernel=gaussian` at radius 1 (blur_radius 1-2 at half resolution): the Gaussian, x and y
// at once, from four bilinear fetches: the 1D taps [w, 1 - 2w, w] are the mean of two bilinear
// fetches 2w texels either side of the centre ([2w, 1 - 2w, 0] and [0, 1 - 2w, 2w]), so the 3 x 3
// product is the mean of four at (±2w, ±2w). One pass and four fetches instead of blur.frag's two
// passes of three. On llvmpipe (vsm, default scene, every map redrawn, six alternated rounds) the
// frame took 0.943x (0.887-0.972), the shadow pass ~2 ms less of ~21; linear sampling within each
// separable pass (Rákos 2010) had saved nothing there.
// Edges clamp, as blur.frag's do.
layout(binding = 0) uniform sampler2D uSource;  // linear filtering, clamped to its edges
layout(location = 0) out vec4 outValue;

const float kSigma = BLUR_SIGMA;  // in moment texels (MomentShadowMap::buildPrograms)

void main() {
    const float g = exp(-1.0 / (2.0 * kSigma * kSigma));  // the outer taps' weight before normalising
    const float d = 2.0 * g / (1.0 + 2.0 * g);             // 2w
    vec2 texel = 1.0 / vec2(textureSize(uSource, 0)), c = gl_FragCoord.xy;
    outValue = 0.25 * (texture(uSource, (c + vec2(-d, -d)) * texel) + texture(uSource, (c + vec2(d, -d)) * texel) +
                       texture(uSource, (c + vec2(-d, d)) * texel) + texture(uSource, (c + vec2(d, d)) * texel));
}
