#version 450 core
// Per-tile statistics of a coloured stochastic shadow map, read by the box lookups with
// coverage (lookup.glsl). One output texel per side x side tile of the map - the tiles the
// stratified ξ of caster.frag is drawn over - holding, over the tile's texels that a
// translucent layer covers (alpha, the nearest layer of any channel, below 1):
//   rgb: how many let channel λ through (no layer wrote its depth there),
//   a:   how many are covered, plus (in the fraction) the farthest depth any layer wrote in
//        the tile, rounded up.
// A receiver behind that farthest depth is behind every layer of the tile, so the counts are
// its answer, one fetch instead of side² (the lookup falls back to the texels otherwise).
layout(binding = 0) uniform sampler2D uMap;
uniform int uSide;  // 4 or 8
layout(location = 0) out vec4 outStats;

void main() {
    ivec2 size = textureSize(uMap, 0);
    ivec2 first = ivec2(gl_FragCoord.xy) * uSide;
    vec3 passing = vec3(0.0);
    float covered = 0.0, farthest = 0.0;
    for (int j = 0; j < uSide; ++j)
        for (int i = 0; i < uSide; ++i) {
            ivec2 p = first + ivec2(i, j);
            if (any(greaterThanEqual(p, size))) continue;
            vec4 texel = texelFetch(uMap, p, 0);
            if (texel.a >= 1.0) continue;  // no translucent layer at this texel
            covered += 1.0;
            bvec3 written = lessThan(texel.rgb, vec3(1.0));
            passing += vec3(not(written));
            // Written channels hold their layer's depth; alpha (the nearest layer) is never farther.
            farthest = max(farthest, max(texel.a, max(max(written.r ? texel.r : 0.0, written.g ? texel.g : 0.0), written.b ? texel.b : 0.0)));
        }
    // The fraction keeps 16 bits next to a count below 128 in a 32-bit float.
    outStats = vec4(passing, covered + ceil(min(farthest, 0.999) * 65536.0) / 65536.0);
}
