#version 450 core
// With MSAA (MomentShadowMap's `msaa`): a 4x multisampled depth map -> moments, the mean of every
// sample's, into the unblurred moments (or the map itself without a blur). Moments are linear, so
// the mean of a footprint's moments is the footprint's: the point of MSAA for filterable maps.
// Without MSAA the casters' moments are drawn directly (caster_moments.frag).
// MOMENT_DOWNSAMPLE 1: the moment map has half the depth map's resolution, each texel the mean
// of its 2 x 2 depth texels' samples. Both it and the warp are compile-time constants
// (MomentShadowMap::buildPrograms).
#include "src/shadows/moments/moments.glsl"
layout(binding = 1) uniform sampler2DMS uDepthMS;
layout(location = 0) out vec4 outMoments;

const int kSamples = 4;  // llvmpipe offers at most 4 (MomentShadowMap::ensure)

vec4 multisampledMoments(ivec2 p) {
    vec4 sum = vec4(0.0);
    for (int i = 0; i < kSamples; ++i) sum += momentsOf(texelFetch(uDepthMS, p, i).r);
    return sum / float(kSamples);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (MOMENT_DOWNSAMPLE == 0) {
        outMoments = multisampledMoments(p);
        return;
    }
    outMoments = 0.25 * (multisampledMoments(2 * p) + multisampledMoments(2 * p + ivec2(1, 0)) +
                         multisampledMoments(2 * p + ivec2(0, 1)) + multisampledMoments(2 * p + ivec2(1, 1)));
}
