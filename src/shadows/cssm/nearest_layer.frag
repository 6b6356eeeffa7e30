#version 450 core
// Per-tile statistics of the nearest translucent layer of a coloured stochastic shadow map, for
// receivers just behind that layer: the back face of a pane behind its own front face, which
// tiles.frag's counts cannot serve, since the receiver's own face wrote into its tile (issue 11:
// on the glass scene those receivers counted their tile texel by texel, 64 fetches each).
// Relative to the nearest layer, whose depth the alpha channel holds at every texel it covers,
// the slopes of parallel faces cancel: a receiver at depth d behind it sees, at texel p, the
// gap d(p) - alpha(p), and every other layer wrote no nearer to alpha than the tile's least gap.
// Written into the colour map's mip level log2(side) - 1, two texels per tile at (2 tx, 2 ty)
// and (2 tx + 1, 2 ty) (rows 2 ty + 1 are not used):
//   [0] r = passing.r + M (passing.b mod 16), g = passing.g + M floor(passing.b / 16), with
//       passing.λ the covered texels where the nearest layer did not write channel λ and
//       M = side² + 1 (exact in RGBA16F); b = the least gap (w - alpha) of any channel's write w
//       behind the nearest layer (2 if none); a = the covered texels.
//   [1] the least-squares plane of alpha over the covered texels, alpha ≈ a0 + g.(p - centre)
//       in texel units from the tile's centre: (a0, g.x, g.y, the largest |alpha - plane|).
// The lookup (lookup.glsl, colouredByTiles) bounds the receiver's gap over the tile from its own
// plane and this one, and takes `passing` when that bound lies between 0 and the least gap.
layout(binding = 0) uniform sampler2D uMap;  // level 0 of the colour map (face)
uniform int uSide;                           // 4 or 8
layout(location = 0) out vec4 outStats;

void main() {
    ivec2 at = ivec2(gl_FragCoord.xy);
    if ((at.y & 1) != 0) { outStats = vec4(0.0); return; }
    ivec2 size = textureSize(uMap, 0);
    ivec2 first = (at >> 1) * uSide;
    float half_ = 0.5 * float(uSide);
    vec3 passing = vec3(0.0);
    float leastGap = 2.0;
    // Normal equations of the plane fit: sums over covered texels of 1, x, y, xx, xy, yy, a, xa, ya.
    float n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, syy = 0.0, sa = 0.0, sxa = 0.0, sya = 0.0;
    for (int j = 0; j < uSide; ++j)
        for (int i = 0; i < uSide; ++i) {
            ivec2 p = first + ivec2(i, j);
            if (any(greaterThanEqual(p, size))) continue;
            vec4 texel = texelFetch(uMap, p, 0);
            if (texel.a >= 1.0) continue;  // no translucent layer at this texel
            // MIN blending: a channel the nearest layer wrote holds exactly its depth (alpha).
            bvec3 byNearest = equal(texel.rgb, vec3(texel.a));
            passing += vec3(not(byNearest));
            bvec3 behind = bvec3(vec3(lessThan(texel.rgb, vec3(1.0))) * vec3(not(byNearest)));  // a later layer wrote λ
            vec3 gaps = mix(vec3(2.0), texel.rgb - texel.a, behind);
            leastGap = min(leastGap, min(gaps.r, min(gaps.g, gaps.b)));
            float x = float(i) + 0.5 - half_, y = float(j) + 0.5 - half_;
            n += 1.0; sx += x; sy += y; sxx += x * x; sxy += x * y; syy += y * y;
            sa += texel.a; sxa += x * texel.a; sya += y * texel.a;
        }
    if ((at.x & 1) == 0) {
        float m = float(uSide * uSide + 1);
        int b = int(passing.b);
        outStats = vec4(passing.r + m * float(b & 15), passing.g + m * float(b >> 4), leastGap, n);
        return;
    }
    if (n < 3.0) { outStats = vec4(0.0, 0.0, 0.0, 2.0); return; }  // too few texels to fit: never decides
    mat3 normal = mat3(n, sx, sy, sx, sxx, sxy, sy, sxy, syy);
    if (abs(determinant(normal)) < 1e-3) { outStats = vec4(0.0, 0.0, 0.0, 2.0); return; }  // collinear texels
    vec3 plane = inverse(normal) * vec3(sa, sxa, sya);  // (a0, g.x, g.y)
    float residual = 0.0;
    for (int j = 0; j < uSide; ++j)
        for (int i = 0; i < uSide; ++i) {
            ivec2 p = first + ivec2(i, j);
            if (any(greaterThanEqual(p, size))) continue;
            float a = texelFetch(uMap, p, 0).a;
            if (a >= 1.0) continue;
            vec2 d = vec2(i, j) + 0.5 - half_;
            residual = max(residual, abs(a - (plane.x + dot(plane.yz, d))));
        }
    outStats = vec4(plane, residual);
}
