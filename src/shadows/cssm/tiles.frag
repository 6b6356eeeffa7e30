#version 450 core
// Per-tile statistics of a coloured stochastic shadow map, read by the box lookups with
// coverage (lookup.glsl). One output texel per side x side tile of the map - the tiles the
// stratified ξ of caster.frag is drawn over - written into the colour map's own mip level
// log2(side), so that the lookup reads tiles and texels through one fetch. Over the tile's
// texels that a translucent layer covers (alpha, the nearest layer of any channel, below 1):
//   passing: how many let channel λ through (no layer wrote its depth there),
//   covered: how many are covered,
//   a:       the farthest depth any layer wrote in the tile.
// A receiver behind that farthest depth is behind every layer of the tile, so the counts are
// its answer (the lookup counts texel by texel otherwise).
// Packing, exact in RGBA16F (integers up to 2048, and a depth the map itself stored):
//   r = passing.r + M (covered mod 8), g = passing.g + M floor(covered / 8), b = passing.b,
//   with M = side² + 1 (tileCounts in lookup.glsl unpacks it).
#include "src/shadows/cssm/layers.glsl"
layout(binding = 0) uniform sampler2D uMap;  // level 0 of the colour map (face)
uniform int uSide;  // 4 or 8
layout(location = 0) out vec4 outStats;
// 2D maps: the counts through the nearest layer alone, into level log2(side) - 1 at the same
// texel (nearest_layer.frag's header has the layout; cube faces have no such target).
layout(location = 1) out vec4 outNearestCounts;

void main() {
    ivec2 size = textureSize(uMap, 0);
    ivec2 first = ivec2(gl_FragCoord.xy) * uSide;
    vec3 passing = vec3(0.0), passingNearest = vec3(0.0);
    int covered = 0;
    float farthest = 0.0, leastGap = 2.0;
    for (int j = 0; j < uSide; ++j)
        for (int i = 0; i < uSide; ++i) {
            ivec2 p = first + ivec2(i, j);
            if (any(greaterThanEqual(p, size))) continue;
            vec4 texel = texelFetch(uMap, p, 0);
            if (texel.a >= 1.0) continue;  // no translucent layer at this texel
            covered += 1;
            bvec3 written = lessThan(texel.rgb, vec3(1.0));
            passing += vec3(not(written));
            // Written channels hold their layer's depth; alpha (the nearest layer) is never farther.
            farthest = max(farthest, max(texel.a, max(max(written.r ? texel.r : 0.0, written.g ? texel.g : 0.0), written.b ? texel.b : 0.0)));
            vec3 behind = writtenBehind(texel);
            passingNearest += vec3(not(written)) + behind;
            vec3 gap = mix(vec3(2.0), texel.rgb - texel.a, bvec3(behind));
            leastGap = min(leastGap, min(gap.r, min(gap.g, gap.b)));
        }
    float m = float(uSide * uSide + 1);
    outStats = vec4(passing.r + m * float(covered & 7), passing.g + m * float(covered >> 3), passing.b, farthest);
    int b = int(passingNearest.b);
    // A tile no layer covers: zeros, as cleared (renderTiles), however the tile came to be drawn.
    outNearestCounts = vec4(passingNearest.r + m * float(b & 15), passingNearest.g + m * float(b >> 4), covered > 0 ? leastGap : 0.0,
                            float(covered));
}
