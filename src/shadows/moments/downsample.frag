#version 450 core
// One mip level of a moment map from the level above it: the mean of its 2 x 2 texels (edges
// clamped), what glGenerateMipmap's box filter computes, but over a rectangle, so that a moving
// caster redoes only the texels under it (MomentShadowMap::makeMipLevels). Moments are linear, so
// the mean of a footprint's moments is the footprint's moments. One bilinear fetch at the corner the
// four texels share weighs each by 1/4: on llvmpipe it costs less than four texel fetches (vsm,
// default scene, every map redrawn, six alternated rounds: frame 0.954x, 0.922-0.983). Texels of
// the face's rectangle that no caster reaches hold the far plane's moments (uFar), which is what
// averaging them gives, without a fetch (and without a clear of their own).
layout(binding = 0) uniform sampler2DArray uFiner;  // every face of the level above alone, linear filtering
uniform ivec4 uReached[6];  // per face: the level's texels a caster reaches
uniform vec4 uFar;
flat in int vFace;
layout(location = 0) out vec4 outMoments;

void main() {
    const ivec2 p = ivec2(gl_FragCoord.xy);
    const ivec4 r = uReached[vFace];
    if (any(lessThan(p, r.xy)) || any(greaterThanEqual(p, r.zw))) {
        outMoments = uFar;
        return;
    }
    const vec2 finer = vec2(textureSize(uFiner, 0).xy);
    outMoments = texture(uFiner, vec3((2.0 * floor(gl_FragCoord.xy) + 1.0) / finer, float(vFace)));
}
