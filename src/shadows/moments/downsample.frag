#version 450 core
// One mip level of a moment map from the level above it: the mean of its 2 x 2 texels (edges
// clamped), what glGenerateMipmap's box filter computes, but over a rectangle, so that a moving
// caster redoes only the texels under it (MomentShadowMap::update). Moments are linear, so the
// mean of a footprint's moments is the footprint's moments. One bilinear fetch at the corner the
// four texels share weighs each by 1/4: on llvmpipe it costs less than four texel fetches (vsm,
// default scene, every map redrawn, six alternated rounds: frame 0.954x, 0.922-0.983).
layout(binding = 0) uniform sampler2D uFiner;  // a view of the level above alone, linear filtering
layout(location = 0) out vec4 outMoments;

void main() {
    vec2 finer = vec2(textureSize(uFiner, 0));
    outMoments = texture(uFiner, (2.0 * floor(gl_FragCoord.xy) + 1.0) / finer);
}
