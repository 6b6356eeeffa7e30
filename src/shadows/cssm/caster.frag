#version 450 core
// Casters into a coloured stochastic shadow map (McGuire & Enderton 2011; Mátl 2013 ch. 4-5).
// A fragment stops light of channel λ with probability ρ_λ = (1 - t_λ) α: it writes its depth
// to that channel when ξ < ρ_λ, and 1 (no occlusion) otherwise; MIN blending keeps the nearest
// occluder per channel. (The thesis's pseudocode prints the comparison reversed; its text and
// CSSM2 agree with this.)
//   CSSM2: one pass, one ξ per fragment shared by the channels.
//   CSSM1: independent ξ per channel (the thesis draws one pass per channel; one pass with a
//          ξ stream per channel writes the same texels).
// Only translucent casters come here; the opaque ones are in the depth map this pass tests against.
#include "shaders/common/material.glsl"
#include "shaders/common/random.glsl"
#include "shaders/common/depth.glsl"
#include "src/shadows/common/glsl/over_opaque.glsl"
#include "src/shadows/cssm/CssmFilter.h"
in vec2 vUv;
uniform int uPerspective;
uniform float uNear, uFar;
// Compile-time (ColoredStochasticShadowMap::buildCasters): llvmpipe would draw every ξ below for
// every fragment if these were uniforms.
const bool kIndependentChannels = CSSM_INDEPENDENT_CHANNELS != 0;  // false: one ξ for all channels (CSSM2); true: one per channel (CSSM1)
const int kXi = CSSM_XI;  // kXi*
flat in uint vObject;  // a hash of the caster's placement (caster.vert): tells objects apart, in any draw order
layout(location = 0) out vec4 outDepth;

float linearDepth(float z) { return uPerspective == 0 ? z : perspectiveLinearDepth(z, uNear, uFar); }

// Stratified ξ: within every n x n texel tile each of the n² strata [k, k + 1) / n² holds
// exactly one texel's threshold, so the share of texels a layer writes in a whole tile is ρ to
// within 1/n² instead of a binomial draw (sd sqrt(ρ(1 - ρ)/n²)). Which texel gets which stratum
// is a pseudo-random permutation per tile and per layer, and the thresholds are shifted together
// inside their strata, so that the mean is exact. Independent permutations per layer (object
// placement, triangle, side) keep stacked layers independent, so their transmittances multiply.
// Ordered dithers (shifted or XOR-scrambled) were measured first and made two stacked 50 %
// layers coincide or complement per tile. Nothing depends on the frame: a static view does not
// flicker.
uniform int uDitherBits;  // n = 2^bits: 2 (4 x 4 tiles) or 3 (8 x 8)

// A keyed permutation of [0, n²): a 4-round Feistel network on the index's two `bits`-bit halves
// with hashed round functions (Luby & Rackoff 1988). Every index lands on every stratum with
// probability 1/n² over the keys, which is what keeps the layers' means and products exact; it
// costs 4 hashes where ranking the texel's hash among the tile's n² hashes cost n².
uint permuteInTile(uint index, uint key, uint bits) {
    uint mask = (1u << bits) - 1u;
    uint left = index >> bits, right = index & mask;
    for (uint round = 0u; round < 4u; ++round) {
        uint next = left ^ (pcgHash(right ^ pcgHash(key + round)) & mask);
        left = right;
        right = next;
    }
    return (left << bits) | right;
}

float stratifiedXi(uint stream) {
    uvec2 p = uvec2(gl_FragCoord.xy);
    uint bits = uint(uDitherBits), side = 1u << bits;
    uint layer = vObject ^ pcgHash(uint(gl_PrimitiveID) * 2u + (gl_FrontFacing ? 1u : 0u));
    uvec2 tile = p >> bits, inTile = p & (side - 1u);
    uint seed = pcgHash(tile.x ^ pcgHash(tile.y ^ pcgHash(layer ^ pcgHash(stream))));
    uint stratum = permuteInTile(inTile.y * side + inTile.x, seed, bits);
    float shift = float(pcgHash(seed ^ 0x9e3779b9u) >> 8) * (1.0 / 16777216.0);
    return (float(stratum) + shift) / float(side * side);
}

float drawXi(uint stream) { return kXi == kXiStratified ? stratifiedXi(stream) : fragmentRandom(stream); }

void main() {
    testBehindOpaqueOffset();
    vec3 rho = materialStopped(materialCoverage(materialTexel(vUv)));
    float z = linearDepth(gl_FragCoord.z);
    // CSSM2: one ξ shared by the channels. CSSM1: an independent ξ per channel (its own stream),
    // which is what the thesis's one pass per wavelength computes, here in a single pass.
    vec3 xi = kIndependentChannels ? vec3(drawXi(1u), drawXi(2u), drawXi(3u)) : vec3(drawXi(0u));
    // Alpha: the nearest translucent layer of any channel (MIN-blended), whatever ξ drew, so
    // that lookups can tell where no coloured shadow can be.
    outDepth = vec4(mix(vec3(1.0), vec3(z), lessThan(xi, rho)), z);
}
