#version 450 core
// Per-tile statistics of the nearest translucent layer of a coloured stochastic shadow map, for
// receivers just behind that layer: the back face of a pane behind its own front face, which
// tiles.frag's counts cannot serve, since the receiver's own face wrote into its tile (issue 11:
// on the glass scene those receivers counted their tile texel by texel, 64 fetches each).
// Relative to the nearest layer, whose depth the alpha channel holds at every texel it covers,
// the slopes of parallel faces cancel: a receiver at depth d behind it sees, at texel p, the
// gap d(p) - alpha(p), and every other layer wrote no nearer to alpha than the tile's least gap.
// Level log2(side) - 1 of the colour map holds, for the N x N tiles (N = the map's side / side),
// three texels per tile:
//   (tx, ty), written by tiles.frag: r = passing.r + M (passing.b mod 16),
//       g = passing.g + M floor(passing.b / 16), with passing.λ the covered texels where the
//       nearest layer did not write channel λ and M = side² + 1 (exact in RGBA16F); b = the least
//       gap (w - alpha) of any channel's write w behind the nearest layer (2 if none); a = the
//       covered texels;
//   (N + tx, ty), written here: the least-squares plane of alpha over the covered texels,
//       alpha ≈ a0 + g.(p - centre) in texel units from the tile's centre:
//       (a0, g.x, g.y, the largest |alpha - plane|);
//   (tx, N + ty), written here: the same for the gaps w - alpha of the writes behind the nearest
//       layer (every written channel a sample): where the layer behind is a face at an angle to
//       the nearest one (a block's far face), the gap is not constant but planar.
//   A plane that cannot be fitted (fewer than three samples, or collinear) is (0, 0, 0, 2); a
//   tile that no layer covers is all zeros, as renderTiles clears tiles outside the layers'
//   texels, so that a tile redrawn alone reads as it would after a whole redraw.
// The lookup (lookup.glsl, colouredByTiles) bounds the receiver's gap over its tile from its own
// plane and alpha's, and takes `passing` when that bound lies behind the nearest layer and in
// front of every other write: below the least gap, or below the gaps' plane.
#include "src/shadows/cssm/layers.glsl"
layout(binding = 0) uniform sampler2D uMap;  // level 0 of the colour map (face)
uniform int uSide;                           // 4 or 8
layout(location = 0) out vec4 outStats;

// Least-squares planes through samples (x, y, value), x and y in texels from the tile's centre.
struct PlaneFit { float n, sx, sy, sxx, sxy, syy, sv, sxv, syv; };

void addSample(inout PlaneFit f, vec2 d, float value, float weight) {
    f.n += weight; f.sx += weight * d.x; f.sy += weight * d.y;
    f.sxx += weight * d.x * d.x; f.sxy += weight * d.x * d.y; f.syy += weight * d.y * d.y;
    f.sv += weight * value; f.sxv += weight * d.x * value; f.syv += weight * d.y * value;
}

// (v0, g.x, g.y), or false where the samples cannot fix a plane (fewer than 3, or collinear).
bool solve(PlaneFit f, out vec3 plane) {
    mat3 normal = mat3(f.n, f.sx, f.sy, f.sx, f.sxx, f.sxy, f.sy, f.sxy, f.syy);
    plane = vec3(0.0);
    if (f.n < 3.0 || abs(determinant(normal)) < 1e-3) return false;
    plane = inverse(normal) * vec3(f.sv, f.sxv, f.syv);
    return true;
}

void main() {
    ivec2 at = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uMap, 0);
    int tiles = size.x / uSide;
    bool gaps = at.y >= tiles;  // renderTiles draws only the two regions
    ivec2 first = (gaps ? at - ivec2(0, tiles) : at - ivec2(tiles, 0)) * uSide;
    float half_ = 0.5 * float(uSide);
    PlaneFit fit = PlaneFit(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    bool covered = false;
    for (int j = 0; j < uSide; ++j)
        for (int i = 0; i < uSide; ++i) {
            ivec2 p = first + ivec2(i, j);
            if (any(greaterThanEqual(p, size))) continue;
            vec4 texel = texelFetch(uMap, p, 0);
            if (texel.a >= 1.0) continue;  // no translucent layer at this texel
            covered = true;
            vec3 behind = writtenBehind(texel);
            vec3 gap = texel.rgb - texel.a;
            vec2 d = vec2(i, j) + 0.5 - half_;
            if (gaps) {
                addSample(fit, d, gap.r, behind.r);
                addSample(fit, d, gap.g, behind.g);
                addSample(fit, d, gap.b, behind.b);
            } else {
                addSample(fit, d, texel.a, 1.0);
            }
        }
    vec3 plane;
    if (!solve(fit, plane)) { outStats = vec4(0.0, 0.0, 0.0, covered ? 2.0 : 0.0); return; }  // never decides by this plane
    float deviation = 0.0;
    for (int j = 0; j < uSide; ++j)
        for (int i = 0; i < uSide; ++i) {
            ivec2 p = first + ivec2(i, j);
            if (any(greaterThanEqual(p, size))) continue;
            vec4 texel = texelFetch(uMap, p, 0);
            if (texel.a >= 1.0) continue;
            float predicted = plane.x + dot(plane.yz, vec2(i, j) + 0.5 - half_);
            vec3 off = abs(gaps ? texel.rgb - texel.a - predicted : vec3(texel.a - predicted)) * (gaps ? writtenBehind(texel) : vec3(1.0));
            deviation = max(deviation, max(off.r, max(off.g, off.b)));
        }
    outStats = vec4(plane, deviation);
}
