#version 450 core
// One mip level of a moment map from the level above it: the mean of its 2 x 2 texels (edges
// clamped), what glGenerateMipmap's box filter computes, but over a rectangle, so that a moving
// caster redoes only the texels under it (MomentShadowMap::update). Moments are linear, so the
// mean of a footprint's moments is the footprint's moments.
layout(binding = 0) uniform sampler2D uFiner;  // a view of the level above alone: no feedback loop
layout(location = 0) out vec4 outMoments;

void main() {
    ivec2 p = 2 * ivec2(gl_FragCoord.xy), last = textureSize(uFiner, 0) - 1;
    outMoments = 0.25 * (texelFetch(uFiner, min(p, last), 0) + texelFetch(uFiner, min(p + ivec2(1, 0), last), 0) +
                         texelFetch(uFiner, min(p + ivec2(0, 1), last), 0) + texelFetch(uFiner, min(p + ivec2(1, 1), last), 0));
}
