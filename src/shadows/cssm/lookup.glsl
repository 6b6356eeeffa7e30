// Coloured stochastic shadow map lookup (McGuire & Enderton 2011; Mátl 2013 §5.3):
// X += (map.rgb(s + Δ) > s.z) over n taps, received light X·L/n. Filters compared in the
// thesis (CssmFilter.h): PCF 3x3 (9 taps), Poisson 16, Poisson 20, uniform random 30, and the
// 13-tap cross-plus-square {(0,0), (±3,±3), (±4,0), (0,±4), (±7,0), (0,±7)} texels, every tap
// jittered by δ(s) = ([(5 s) mod 2] - 1) / (6 (‖∂s/∂x‖₁, ‖∂s/∂y‖₁)); and box16 / box64, which
// count the whole stratified tile (caster.frag) the receiver falls in.
#include "src/shadows/common/glsl/kernels.glsl"
#include "src/shadows/cssm/CssmFilter.h"

// Compile-time choices (ColoredStochasticShadowMap::lookupDefines), so that only the chosen
// filter's taps are in the program.
const int kFilter = CSSM_FILTER;  // kCssm*
const bool kSeparateOpaque = CSSM_SEPARATE_OPAQUE != 0;  // the map holds translucent layers only; opaque casters come from the depth map
const bool kCoverage = CSSM_COVERAGE != 0;  // box filters average over the texels a layer covers; the receiver's own coverage places the edge
uniform float uStorageEpsilon;  // relative precision of the stored depth (RGBA16F: 2^-10), 0 for fp32
uniform float uRadiusTexels;  // the Poisson and random filters' (ColoredStochasticShadowMap::tapRadiusTexels)
uniform int uTileSide;  // 4 or 8: the side of the stratified tiles (box filters)
#ifdef MATERIAL_TRANSLUCENT
const bool kNearestLayer = true;  // the lighting program of translucent surfaces (render/LightingProgram.h)
#else
const bool kNearestLayer = false;
#endif
uniform int uNearestLayer;  // 1: box lookups may decide by the nearest layer's statistics (nearest_layer.frag)
// A receiver behind every layer written around it takes the tint map's transmittance product
// (DepthAndTintMaps, a deterministic per-texel product) instead of the tiles' stratified counts.
// Same mean, but exact per texel: the edge of a second layer inside a first one's shadow stays
// as sharp as the plain map's instead of spreading over the 2 x 2 tiles the counts blend
// (issue 11: glass scene, wrong pixels 1.075 -> 0.822 %, colour error 0.0211 -> 0.0131).
const bool kTintBehindAll = CSSM_TINT_BEHIND_ALL != 0;  // compiled in: llvmpipe would fetch the tint under a uniform's false too

const vec2 kCross13[13] = vec2[](vec2(0, 0), vec2(3, 3), vec2(-3, 3), vec2(3, -3), vec2(-3, -3), vec2(4, 0),
                                 vec2(-4, 0), vec2(0, 4), vec2(0, -4), vec2(7, 0), vec2(-7, 0), vec2(0, 7), vec2(0, -7));

// True when no translucent layer lies in front of the receiver in the side x side texels from
// `corner` (alpha holds the nearest translucent layer of any channel): the coloured term is then
// exactly 1, found with side²/4 gathers instead of side² fetches and comparisons.
bool noLayerInFront(ShadowSite s, vec2 corner, int side) {
    for (int j = 0; j < side; j += 2)
        for (int i = 0; i < side; i += 2) {
            vec2 centre = corner + vec2(i, j) + 0.5;  // between the 2 x 2 texels a gather reads
            vec4 nearest = s.cube ? shadowRawGatherAlphaCube(s.slot, s.coord + s.tangent * centre.x + s.bitangent * centre.y)
                                  : shadowRawGatherAlpha2D(s.slot, s.coord.xy + centre / s.resolution);
            float receiver = linearShadowDepth(s.light, tapReceiverDepth(s, centre));
            if (any(lessThan(nearest, vec4(receiver * (1.0 - uStorageEpsilon))))) return false;
        }
    return true;
}

// A receiver's plane extrapolated to a tap can pass the light's far plane (a floor grazing a
// point light's range), where the map holds its cleared 1.0: nothing can lie beyond, so the tap
// must pass, not read the cleared texel as a layer in front.
float belowClearedDepth(float linearDepth) { return min(linearDepth, 1.0 - 1.0 / 1048576.0); }

// Per channel: 1 where the stored (nearest stochastic occluder) depth lies beyond the receiver.
// The receiver's depth is extrapolated along its plane to each tap (receiver-plane depth bias):
// kernels up to 7 texels wide would otherwise shadow sloped receivers with themselves.
vec3 passesIf(vec3 stored, float receiverDepth, int light) {
    float receiver = belowClearedDepth(linearShadowDepth(light, receiverDepth));
    // Half floats round the stored depth by up to an ulp: a receiver must not shadow itself by that.
    return vec3(greaterThan(stored, vec3(receiver * (1.0 - uStorageEpsilon))));
}

vec3 passes(ShadowSite s, vec2 texels) {
    vec3 stored = s.cube ? shadowRawLodCube(s.slot, s.coord + s.tangent * texels.x + s.bitangent * texels.y).rgb
                         : shadowRawLod2D(s.slot, s.coord.xy + texels / s.resolution).rgb;
    return passesIf(stored, tapReceiverDepth(s, texels), s.light);
}

// ---- Box filters with coverage (2D maps and cube faces alike) ----
// Where colour falls is decided by the receiver's own texels, exactly as the plain map decides
// its edges; how much, by the share of light that passes the covered texels of the stratified
// tiles around the receiver - exact to 1/side² inside a layer, since each tile holds every
// threshold stratum once (caster.frag). The tiles' counts come precomputed (tiles.frag, in the
// map's mip level log2(side)) and are blended bilinearly between the 2 x 2 nearest tiles,
// weighted by how many texels each covers; where the receiver is not behind every layer written
// in those tiles, its own tile is counted texel by texel, each texel tested against the
// receiver's depth there.

// A map texel seen from the receiver: 2D maps address texels directly, cube maps through the
// face the receiver's direction selects (GL 4.5 table 8.19).
struct MapFace { int face; vec2 texel; };  // texel: the receiver in texel units of its face

MapFace mapFace(ShadowSite s) {
    MapFace m;
    m.face = 0;
    if (s.cube) m.texel = cubeFaceCoord(s.coord, m.face).xy * s.resolution;
    else m.texel = s.coord.xy * s.resolution;
    return m;
}

vec3 faceDirection(ShadowSite s, MapFace m, vec2 texel) { return cubeFaceDirection(m.face, texel / s.resolution); }

// The receiver's linear depth where its plane meets the light's ray through `texel`.
float receiverAt(ShadowSite s, MapFace m, vec2 texel) {
    float windowDepth = s.cube ? cubeReceiverDepth(s, faceDirection(s, m, texel)) : tapReceiverDepth(s, texel - m.texel);
    return belowClearedDepth(linearShadowDepth(s.light, windowDepth)) * (1.0 - uStorageEpsilon);
}

// The texel of mip level `level` that holds `texel` (texel units of level 0): at level
// log2(side), the statistics of the tile around it.
vec4 levelTexel(ShadowSite s, MapFace m, vec2 texel, int level) {
    if (s.cube) return shadowRawLevelCube(s.slot, faceDirection(s, m, texel), float(level));
    ivec2 last = (ivec2(s.resolution) >> level) - 1;  // clamped to the map's edge, as a sampler would
    return shadowRawFetch2D(s.slot, clamp(ivec2(texel) >> level, ivec2(0), last), level);
}

// tiles.frag's packing: r = passing.r + M (covered mod 8), g = passing.g + M floor(covered / 8),
// b = passing.b, with M = side² + 1. The half offset keeps floor exact under an approximate division.
void tileCounts(vec4 stats, int side, out vec3 passing, out float covered) {
    float m = float(side * side + 1);
    vec2 high = floor((stats.rg + 0.5) / m);
    passing = vec3(stats.rg - m * high, stats.b);
    covered = high.x + 8.0 * high.y;
}

// Share of the receiver's footprint that a translucent layer in front of it covers: its 2 x 2
// nearest texels, bilinearly weighted, as the plain map's hardware comparison weighs them.
float ownCoverage(ShadowSite s, MapFace m) {
    vec2 t = m.texel - 0.5;
    vec2 centre = floor(t) + 1.0;  // between the 2 x 2 texels a gather reads
    vec4 nearest = s.cube ? shadowRawGatherAlphaCube(s.slot, faceDirection(s, m, centre))
                          : shadowRawGatherAlpha2D(s.slot, centre / s.resolution);
    // The receiver's own depth: receiverAt at its own texel, where the plane adds nothing.
    vec4 c = vec4(lessThan(nearest, vec4(linearShadowDepth(s.light, s.depth) * (1.0 - uStorageEpsilon))));
    vec2 f = fract(t);
    return mix(mix(c.w, c.z, f.x), mix(c.x, c.y, f.x), f.y);  // gather order: (0,1) (1,1) (1,0) (0,0)
}

// nearest_layer.frag's first texel: the counts through the nearest layer alone, and the least gap.
vec3 nearestLayerCounts(vec4 stats, int side) {
    float m = float(side * side + 1);
    vec2 high = floor((stats.rg + 0.5) / m);
    return vec3(stats.rg - m * high, high.x + 16.0 * high.y);
}

// The receiver's gap behind a tile's nearest layer (nearest_layer.frag's plane, `plane` =
// (a0, g.x, g.y, largest deviation)), bounded over the tile of side `side` centred at `centre`
// (texel units): (least, largest). The receiver is the plane through `receiver` (its linear
// depth at its own texel `at`) with `gradient` (per texel), so the gap is affine and its
// extremes lie at the tile's corners. A spot light's linear depth bends a little over a tile;
// the storage margin of the test absorbs that (the comparison with counting texel by texel in
// StochasticShadowTest holds it to 3/255).
vec2 gapBounds(float receiver, vec2 gradient, vec2 at, vec2 centre, int side, vec4 plane) {
    float gap = receiver + dot(gradient, centre - at) - plane.x;
    vec2 slope = abs(gradient - plane.yz);
    float spread = 0.5 * float(side) * (slope.x + slope.y) + plane.w;
    return vec2(gap - spread, gap + spread);
}

// A texel of the receiver's own tile (`v`, level 0): counted (w = 1) where a layer lies in front
// of the receiver there, with the channels that pass every layer in front.
vec4 ownTexelCount(ShadowSite s, MapFace m, vec2 texel, vec4 v) {
    float receiver = receiverAt(s, m, texel);
    return v.a < receiver ? vec4(vec3(greaterThan(v.rgb, vec3(receiver))), 1.0) : vec4(0.0);
}

// Where a receiver sits among the tiles: its face and texel, its own coverage, the 2 x 2 tiles
// around it (base, bilinear weights f), its own tile, and its nearest depth over the four tiles.
struct TileSite {
    MapFace m;
    float own;
    int level;  // tiles.frag's level: log2(side)
    ivec2 base;
    vec2 f;
    float nearest;
    int lastTile;    // the last tile, partial where the resolution is not a multiple of side
    int levelTiles;  // the tiles that have counts in the level (a partial last tile has none)
    vec2 first;      // the receiver's own tile, texel units
};

TileSite tileSite(ShadowSite s, int side) {
    TileSite ts;
    ts.m = mapFace(s);
    ts.own = ownCoverage(s, ts.m);
    ts.level = side == 8 ? 3 : 2;
    vec2 tileCoord = ts.m.texel / float(side) - 0.5;
    ts.base = ivec2(floor(tileCoord));
    ts.f = tileCoord - vec2(ts.base);
    // The receiver's nearest depth over the four tiles: at one of their outer corners (it is planar).
    vec2 lo = vec2(ts.base) * float(side), hi = lo + 2.0 * float(side);
    if (s.cube) {
        ts.nearest = min(min(receiverAt(s, ts.m, lo), receiverAt(s, ts.m, hi)),
                         min(receiverAt(s, ts.m, vec2(lo.x, hi.y)), receiverAt(s, ts.m, vec2(hi.x, lo.y))));
    } else {  // tapReceiverDepth's plane, clamped as there
        vec2 corner = mix(hi, lo, greaterThan(s.depthSlope, vec2(0.0))) - ts.m.texel;
        ts.nearest = linearShadowDepth(s.light, s.depth + clamp(dot(s.depthSlope, corner), -0.01, 0.01)) * (1.0 - uStorageEpsilon);
    }
    ts.lastTile = int(ceil(s.resolution / float(side))) - 1;
    ts.levelTiles = int(s.resolution) >> ts.level;
    ts.first = floor(ts.m.texel / float(side)) * float(side);
    return ts;
}

// The tint map's texel under the receiver, bilinear (DepthAndTintMaps::TintAlpha::FarthestLayer):
// the layers' transmittance product, white where none is. Its alpha is left out: blended, it bounds
// nothing (farthestAround takes the least of the 2 x 2 instead).
vec3 tintAround(ShadowSite s) { return (s.cube ? shadowTintCube(s.slot, s.coord) : shadowTint2D(s.slot, s.coord.xy)).rgb; }
// 1 - the farthest layer's depth, least over the 2 x 2 texels tintAround blends (1: no layer).
// A cube face's texels within a texel of its edge give 0 ("a layer may be in front"): the fetch
// there blends the next face's texels, whose depths are along another axis.
float farthestAround(ShadowSite s, MapFace m) {
    vec4 a = s.cube ? shadowTintAlphaGatherCube(s.slot, s.coord) : shadowTintAlphaGather2D(s.slot, s.coord.xy);
    bool offFace = s.cube && (any(lessThan(m.texel, vec2(1.0))) || any(greaterThan(m.texel, vec2(s.resolution - 1.0))));
    return offFace ? 0.0 : min(min(a.x, a.y), min(a.z, a.w));
}

// A receiver behind every layer written in the 2 x 2 tiles around it: the tint map's product (its
// bilinear blend already weighs in the texels without a layer, as the own coverage would), or
// the tiles' counts blended and weighted by the own coverage.
vec3 behindAll(ShadowSite s, TileSite ts, vec3 passing, float covered) {
    return kTintBehindAll ? tintAround(s) : mix(vec3(1.0), passing / covered, ts.own);
}

// Tile q (0-3) of the 2 x 2 around the receiver, and whether its counts are outside the level.
ivec2 regionTile(TileSite ts, int q, out bool missing) {
    ivec2 t = clamp(ts.base + ivec2(q & 1, q >> 1), ivec2(0), ivec2(ts.lastTile));  // no neighbours across map (face) borders
    missing = any(greaterThanEqual(t, ivec2(ts.levelTiles)));
    return min(t, ivec2(ts.levelTiles - 1));
}

// Tile q's counts `v`, bilinearly weighted into sum(w passing), sum(w covered), and the farthest
// depth any layer wrote in the four tiles; nothing where `counted` is false (a loop pass that
// read something else: every pass runs this, as llvmpipe runs both sides of an if).
void addTileCounts(TileSite ts, int side, int q, bool counted, bool missing, vec4 v, inout vec3 passing, inout float covered,
                   inout float farthest) {
    vec3 p;
    float c;
    tileCounts(v, side, p, c);
    float w = counted ? ((q & 1) != 0 ? ts.f.x : 1.0 - ts.f.x) * ((q & 2) != 0 ? ts.f.y : 1.0 - ts.f.y) : 0.0;
    passing += w * p;
    covered += w * c;
    farthest = counted ? max(farthest, missing ? 2.0 : v.a) : farthest;
}

// Opaque receivers with tint_behind_all. One bilinear fetch of the tint map and one gather of its
// alpha answer almost every receiver: the least alpha is 1 - the farthest layer's depth over the
// 2 x 2 texels the fetch blends (farthestAround), so least > 1 - depth means the receiver is
// behind every layer there, or no layer is there, and the blended product is the answer (white
// without a layer). Elsewhere (in front of some layer: a floor under a pane's foot, a receiver
// between panes) one loop, one fetch per pass, reads the receiver's 2 x 2 texels for its own
// coverage, then counts its own tile's texels. llvmpipe runs the loop's body once for every pixel
// even where no pass is due (see colouredByTiles): the whole lookup then costs the tint fetch, the
// gather and one texel fetch, against a gather, the tiles' counts and the tint in colouredByTiles
// (issue 15, llvmpipe, default scene: opaque pass 50.9 -> 43.5 ms, cssm2 / hard frame 1.35 -> 1.20).
vec3 colouredByTint(ShadowSite s, int side) {
    vec3 tint = tintAround(s);
    MapFace m = mapFace(s);
    // The half-float alpha (1 - depth) rounds by up to 2^-11 of itself: a receiver within 2^-10 of
    // (1 - its depth) behind the farthest layer is counted instead (and within 2^-23, half floats'
    // subnormal steps, right at the far plane). Relative, not absolute: a perspective light's 1 - depth is small far from it, and
    // 2^-10 of window depth is 0.85 m on scenes/glass.json's floor, 6.6 m from its spot (near
    // 0.05, far 20), so the floor that close behind each pane counted texels for nothing.
    bool behindEveryLayer = farthestAround(s, m) > (1.0 - s.depth) * (1.0 + 1.0 / 1024.0) + 1.0 / 8388608.0;
    vec2 t = m.texel - 0.5;
    vec2 f = fract(t);
    vec2 footprint = floor(t) + 0.5;  // the centre of the first of the 2 x 2 texels
    vec2 first = floor(m.texel / float(side)) * float(side);
    float ownDepth = linearShadowDepth(s.light, s.depth) * (1.0 - uStorageEpsilon);
    float own = 0.0;
    vec4 acc = vec4(0.0);
    int passes = behindEveryLayer ? 0 : 4 + uTileSide * uTileSide;  // a uniform bound: see colouredByTiles
    for (int k = 0; k < passes; ++k) {
        if (k == 4 && own <= 0.0) break;  // no layer in front of the receiver's own texels
        bool footprintPass = k < 4;
        int e = k - 4;
        vec2 texel = footprintPass ? footprint + vec2(k & 1, k >> 1) : first + vec2(e % side, e / side) + 0.5;
        vec4 v = levelTexel(s, m, texel, 0);
        // ownCoverage's bilinear weights, texel by texel.
        float w = ((k & 1) != 0 ? f.x : 1.0 - f.x) * ((k & 2) != 0 ? f.y : 1.0 - f.y);
        own += footprintPass && v.a < ownDepth ? w : 0.0;
        acc += footprintPass ? vec4(0.0) : ownTexelCount(s, m, texel, v);
    }
    if (behindEveryLayer) return tint;
    return mix(vec3(1.0), acc.w > 0.0 ? acc.rgb / acc.w : vec3(1.0), own);
}

// Opaque receivers. One loop, one fetch per pass: passes 0-3 read the 2 x 2 tiles' counts (level
// log2(side)), blended as sum(w passing) / sum(w covered) with w the bilinear weights; then,
// unless those decide, the rest count the own tile's texels (level 0). llvmpipe runs an if's both
// sides for every 8-pixel group and a loop's body at least once, but leaves a loop once no lane is
// left in it: a loop over tiles and another over texels cost a fetch each where no layer covers
// the receiver, this one costs one (measured: a second loop cost the default scene's opaque pass
// 5 ms). The bound comes from a uniform: an unrolled loop would run every pass.
vec3 colouredByTiles(ShadowSite s, int side) {
    TileSite ts = tileSite(s, side);
    vec3 passing = vec3(0.0);
    float covered = 0.0, farthest = 0.0;
    vec4 acc = vec4(0.0);
    bool tilesDecide = false;
    int passes = uTileSide > 0 ? 4 + uTileSide * uTileSide : 0;
    for (int k = 0; k < passes; ++k) {
        if (ts.own <= 0.0) break;  // no layer in front of the receiver's own texels
        if (k == 4) {
            tilesDecide = farthest < ts.nearest && covered > 0.0;
            if (tilesDecide) break;
        }
        bool tile = k < 4, missing;
        ivec2 t = regionTile(ts, k & 3, missing);
        int e = k - 4;
        vec2 texel = tile ? (vec2(t) + 0.5) * float(side) : ts.first + vec2(e % side, e / side) + 0.5;
        vec4 v = levelTexel(s, ts.m, texel, tile ? ts.level : 0);
        addTileCounts(ts, side, k & 3, tile, missing, v, passing, covered, farthest);
        acc += tile ? vec4(0.0) : ownTexelCount(s, ts.m, texel, v);
    }
    if (tilesDecide) return behindAll(s, ts, passing, covered);
    return mix(vec3(1.0), acc.w > 0.0 ? acc.rgb / acc.w : vec3(1.0), ts.own);
}

// Translucent receivers whose own layers are known, at each of the 2 x 2 texels the tint map
// blends around them (ownLayersAround in shadow_filtering.glsl): the tint's product with those
// divided out is the light that reaches them, the deterministic product opaque receivers behind
// every layer get (colouredByTint), without counting texels. There the texel counts erred
// besides, as a curved far side's own stochastic writes stand in front of its tangent plane. One
// bilinear fetch: on llvmpipe, weighing the 2 x 2 texels' divided products one by one (as
// pcf-bilinear does) made the CSSM lighting program of a scene with four lights compile in over
// a minute instead of 6 s; by its rim, where the texels differ, it counts as before.
// Cube maps (point lights) take the one texel the receiver lands in and its tint, as the plain
// map's nearest tint does: exact per texel, without a soft rim. Their 2 x 2 (a gather on the cube,
// or four fetches) made that program compile in 34 s and 78 s, against 13 s this way and 9 s
// counting texels (llvmpipe, shader cache off, sun + spot + point + projector). Measured on the
// glass scene with its spot made a point light: the translucent pass 61-72 -> 33-36 ms, as the
// division spares the texel loop.
bool decidedThroughOwnLayers(ShadowSite s, out vec3 light) {
    vec4 landing;
    if (s.cube) return landingTintThroughOwnLayers(s, light, landing);
    vec2 texel, centre;
    vec4 own = ownLayersAround(s, texel, centre);
    float layers = all(equal(own, own.xxxx)) ? own.x : -1.0;
    light = throughOwnLayers(tintAround(s), layers);
    return ownLayersDividable(layers);
}

// Translucent receivers (the lighting program's MATERIAL_TRANSLUCENT build). Passes 0-3 read the
// 2 x 2 tiles' counts as above. Unless those decide, passes 4-6 read the own tile's nearest-layer
// statistics (level log2(side) - 1, nearest_layer.frag: counts, least gap and covered texels;
// the layer's plane; the plane of the gaps behind it), which decide for a receiver behind that
// layer at every covered texel of its tile and, by its gap, in front of every other layer's
// write there (margins of 1.5 storage quanta, for the half-float rounding of alpha, the writes
// and the planes): the back face of a pane behind its own front face, a block's far face behind
// its near one. They count the very texels the texel loop would, with the same answer. Where
// they do not decide either, a second loop counts the own tile texel by texel (level 0).
// Measured on the glass scene (issue 11): that second, lean loop costs translucent receivers
// 49 ms against 69 ms in the shared loop above; opaque ones would pay its empty pass everywhere.
vec3 colouredByNearestLayer(ShadowSite s, int side) {
    vec3 throughOwn;
    if (kTintBehindAll && decidedThroughOwnLayers(s, throughOwn)) return throughOwn;
    TileSite ts = tileSite(s, side);
    vec3 passing = vec3(0.0), passingNearest = vec3(0.0);
    float covered = 0.0, farthest = 0.0, leastGap = 2.0, ownCovered = 0.0;
    vec4 alphaPlane = vec4(0.0);
    ivec2 ownTile = ivec2(ts.first) / side;
    bool byNearestLayer = uNearestLayer != 0 && !s.cube && all(lessThan(ownTile, ivec2(ts.levelTiles)));  // not the partial last tile
    // One storage quantum of the receiver's depth (RGBA16F: 2^-10 of it); fp32 maps get a hair.
    float receiverDepth = linearShadowDepth(s.light, s.depth);
    float quantum = max(uStorageEpsilon, 1.0 / 1048576.0) * receiverDepth;
    // The receiver's linear depth per texel, for the gap bounds.
    vec2 gradient = vec2(linearShadowDepth(s.light, tapReceiverDepth(s, vec2(1.0, 0.0))),
                         linearShadowDepth(s.light, tapReceiverDepth(s, vec2(0.0, 1.0)))) - receiverDepth;
    vec2 centre = ts.first + 0.5 * float(side);  // of the own tile
    int passes = uTileSide <= 0 ? 0 : byNearestLayer ? 7 : 4;
    for (int k = 0; k < passes; ++k) {
        if (ts.own <= 0.0) break;  // no layer in front of the receiver's own texels
        if (k == 4 && farthest < ts.nearest && covered > 0.0) break;  // the tiles decide
        bool tile = k < 4, layerCounts = k == 4, layerPlane = k == 5, gapPlane = k == 6, missing;
        ivec2 t = regionTile(ts, k & 3, missing);
        // One fetch whatever the pass (llvmpipe would run both sides of a choice between two).
        ivec2 layerTexel = (ownTile + ts.levelTiles * ivec2(layerPlane ? 1 : 0, gapPlane ? 1 : 0)) << (ts.level - 1);  // in level-0 texels
        vec4 v = levelTexel(s, ts.m, tile ? (vec2(t) + 0.5) * float(side) : vec2(layerTexel) + 0.5, tile ? ts.level : ts.level - 1);
        addTileCounts(ts, side, k & 3, tile, missing, v, passing, covered, farthest);
        // The own tile through its nearest layer alone: its counts, least gap and covered texels,
        // alpha's plane, then the gaps' plane, and whether the receiver's gap fits: behind alpha
        // everywhere, and in front of every other write, by the least gap or by the gaps' plane
        // (gap - gaps' plane, bounded as one plane against alpha + gaps).
        passingNearest = layerCounts ? nearestLayerCounts(v, side) : passingNearest;
        leastGap = layerCounts ? v.b : leastGap;
        ownCovered = layerCounts ? v.a : ownCovered;
        alphaPlane = layerPlane ? v : alphaPlane;
        vec2 gap = gapBounds(receiverDepth, gradient, ts.m.texel, centre, side, alphaPlane);
        vec2 beyondWrites = gapBounds(receiverDepth, gradient, ts.m.texel, centre, side, alphaPlane + v);
        bool fits = gap.x > 1.5 * quantum && (gap.y <= leastGap + 1.5 * quantum || beyondWrites.y <= 1.5 * quantum);
        byNearestLayer = byNearestLayer && (!gapPlane || fits);
    }
    bool tilesDecide = farthest < ts.nearest && covered > 0.0;  // also where the loop ended before pass 4
    bool nearestDecides = !tilesDecide && byNearestLayer && ownCovered > 0.0;
    vec4 acc = vec4(0.0);
    int texels = ts.own > 0.0 && !tilesDecide && !nearestDecides ? uTileSide * uTileSide : 0;
    for (int e = 0; e < texels; ++e) {
        vec2 texel = ts.first + vec2(e % side, e / side) + 0.5;
        acc += ownTexelCount(s, ts.m, texel, levelTexel(s, ts.m, texel, 0));
    }
    if (tilesDecide) return behindAll(s, ts, passing, covered);
    return mix(vec3(1.0), nearestDecides ? passingNearest / ownCovered : (acc.w > 0.0 ? acc.rgb / acc.w : vec3(1.0)), ts.own);
}

// The box filters on a cube face: the side x side texels of the face's tile grid that hold the
// receiver, read at their centres (directions through them).
vec3 cubeTileSum(ShadowSite s, int side) {
    int face;
    vec3 st = cubeFaceCoord(s.coord, face);
    vec2 first = floor(st.xy * s.resolution / float(side)) * float(side);
    vec3 sum = vec3(0.0);
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            vec3 d = cubeFaceDirection(face, (first + vec2(i, j) + 0.5) / s.resolution);
            sum += passesIf(shadowRawLodCube(s.slot, d).rgb, cubeReceiverDepth(s, d), s.light);
        }
    return sum;
}

vec3 stochasticVisibility(int light, vec3 P, vec3 N, float NdotL) {
    ShadowSite s = shadowSite(light, P, N, NdotL);
    // s in texels, and ∂s/∂x, ∂s/∂y, taken before any branch. Cube maps: coordinates along the
    // face's texel steps (tangent, bitangent), not the direction's x, y (constant on some faces).
    vec2 sTexels = s.cube ? vec2(dot(s.coord, s.tangent), dot(s.coord, s.bitangent)) / dot(s.tangent, s.tangent)
                          : s.coord.xy * s.resolution;
    vec2 dsdx = dFdx(sTexels), dsdy = dFdy(sTexels);
    if (!s.inside) return vec3(1.0);
#if defined(RECEIVER_UNTINTED) && defined(MATERIAL_TRANSLUCENT)
    // Every other translucent layer around this receiver lies behind it, or none is there
    // (render/TintReach.h, tintFootprintNotInFront), and it is flat or a convex solid
    // (Draw::ownLayersKnown): the only layers in front of it are its own, known without a fetch.
    return compareAt(s, vec2(0.0), 0.0) * ownLayersInFront(NdotL);
#elif defined(RECEIVER_UNTINTED)
    // No translucent layer reaches this receiver's texels (render/TintReach.h): with the opaque
    // casters in the depth map, the coloured term is exactly 1 and only the hard test is left.
    if (kSeparateOpaque) return vec3(compareAt(s, vec2(0.0), 0.0));
#endif
#if defined(RECEIVER_BEHIND_LAYERS) && defined(MATERIAL_TRANSLUCENT)
    // Every other translucent layer around this receiver lies in front of it (tintFootprintNotBehind),
    // and its own layers are known: the deterministic tint with those divided out is what the
    // stochastic counts below estimate. Only those tell layers in front from layers behind, which
    // this receiver has none of but its own. The division is at the texel the lookup lands in, as
    // the plain map's (tintThroughOwnLayers): one fetch of the tint and one of the drawn depths,
    // where weighing the 2 x 2 texels bilinearly (bilinearThroughOwnLayers, until stop 64) took
    // two gathers of the drawn depths and four of the tint. Measured on llvmpipe, glass scene,
    // alternated runs: the translucent pass 21.2-23.0 -> 19.6-21.3 ms; with
    // `compare --translucent-receivers`, colour error 0.0101 -> 0.0105 and wrong pixels 0.511 ->
    // 0.507 % (hard's 0.0119 and 0.484 %): the soft rim as the light sees it was worth less than
    // its cost. Cube maps go on to the whole lookup (s.cube is a constant of the light's slot, so
    // 2D maps' builds hold none of it): its one-texel division where the own layers are known, the
    // counts where not (a slab's rim, where light enters through a side: the 2 x 2 division was
    // 0.12 off there, GL test TranslucentReceiver).
    if (!s.cube) return compareAt(s, vec2(0.0), 0.0) * tintThroughOwnLayers(s);
#elif defined(RECEIVER_BEHIND_LAYERS)
    // Every translucent layer around this receiver lies in front of it (render/TintReach.h,
    // tintFootprintNotBehind; ColoredStochasticShadowMap::behindLayersBuild): colouredByTint's
    // behindEveryLayer holds, so the tint's product is its answer, without the fallback loop
    // that llvmpipe would run masked for every pixel.
    return compareAt(s, vec2(0.0), 0.0) * tintAround(s);
#endif
    vec3 sum = vec3(0.0);
    int n;
    if (kFilter == kCssmBox16 || kFilter == kCssmBox64) {
        // The side x side texels nearest the receiver, at their centres: with the stratified ξ
        // one whole stratified tile (up to alignment), so the share of passing texels is the layer's 1 - ρ to within
        // 1/side².
        int side = kFilter == kCssmBox16 ? 4 : 8;
        n = side * side;
        float h = 0.5 * float(side - 1);
        // 2D maps: the whole tile the receiver falls in, so that every layer counts exactly its
        // stratified share (windows across tile borders would mix partial, unstratified tiles).
        vec2 texel = s.coord.xy * s.resolution;
        vec2 corner = s.cube ? vec2(-h) : floor(texel / float(side)) * float(side) + 0.5 - texel;
        if (kSeparateOpaque && kCoverage)
            return compareAt(s, vec2(0.0), 0.0) * (kNearestLayer ? colouredByNearestLayer(s, side)
                                                   : kTintBehindAll ? colouredByTint(s, side)
                                                                    : colouredByTiles(s, side));
        if (kSeparateOpaque && !s.cube && noLayerInFront(s, corner, side)) return compareAt(s, vec2(0.0), 0.0) * vec3(1.0);
        if (s.cube) {
            sum = cubeTileSum(s, side);
        } else {
            for (int j = 0; j < side; ++j)
                for (int i = 0; i < side; ++i) sum += passes(s, corner + vec2(i, j));
        }
    } else if (kFilter == kCssmPcf9) {
        n = 9;
        for (int j = -1; j <= 1; ++j)
            for (int i = -1; i <= 1; ++i) sum += passes(s, vec2(i, j));
    } else if (kFilter == kCssmPoisson16 || kFilter == kCssmPoisson20) {
        n = kFilter == kCssmPoisson16 ? 16 : 20;
        mat2 rot = pixelRotation();
        for (int i = 0; i < n; ++i) sum += passes(s, poissonTap(i, rot, uRadiusTexels));
    } else if (kFilter == kCssmRandom30) {
        n = 30;
        for (int i = 0; i < n; ++i) sum += passes(s, randomDiskTap(i, uRadiusTexels));
    } else {  // kCssmCross13
        n = 13;
        // Norms below 1/6 texel per pixel (strong magnification) would push δ past a texel: the
        // jitter is meant to be a micro-offset, so it is bounded to one texel.
        vec2 norms = max(vec2(abs(dsdx.x) + abs(dsdx.y), abs(dsdy.x) + abs(dsdy.y)), vec2(1.0 / 6.0));
        vec2 delta = (mod(5.0 * sTexels, vec2(2.0)) - vec2(1.0)) / (6.0 * norms);
        for (int i = 0; i < 13; ++i) sum += passes(s, kCross13[i] + delta);
    }
    vec3 coloured = sum / float(n);
    // Opaque occlusion is a hard test at the receiver, exactly as the plain shadow map's: the
    // wide colour filter then never blurs opaque shadow edges, nor takes a lit wall beside the
    // receiver (its depth is nearer the light) for an occluder.
    if (kSeparateOpaque) return compareAt(s, vec2(0.0), 0.0) * coloured;
    return coloured;
}

// Bounded as plainMapTint bounds the plain tint: the counts and the tint product of the whole
// lookup may miss a thin pane's near side in front of its far side.
vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    return atMostOwnLayersInFront(stochasticVisibility(light, P, N, NdotL), NdotL);
}
