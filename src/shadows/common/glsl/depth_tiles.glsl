// Kernel lookups that skip their taps where DepthTileBounds shows every tap's answer (PCF, PCSS).
// Each kernel loop starts with `if (agreed >= 0.0) break;`: a loop and not an if, because
// llvmpipe runs both sides of an if for its 8-pixel group but leaves a loop once no lane is left
// in it (gallivm's lp_exec_endloop). Where a whole group agrees, a kernel costs one masked tap.
#include "src/shadows/common/glsl/shadow_filtering.glsl"

layout(binding = kUnitDepthTiles) uniform sampler2DArray uDepthTiles;  // DepthTileBounds: (a, g, farthest)
uniform int uSkipAgreeing;  // 0: no bounds bound; every kernel runs

// The bounds of the tile that holds every texel a tap within `reach` texels (along each axis) of
// the receiver can land on: over those texels d >= planeAtP + g . (c - p) (c a texel's centre, p
// the receiver, both in texels) and d <= farthest. False where there is no such tile (a cube
// map, no bounds bound, a reach past the coarsest level); a tile whose border leaves the map has
// bounds that never agree.
bool tileAround(ShadowSite s, float reach, out float planeAtP, out vec2 g, out float farthest) {
    planeAtP = -4.0;
    g = vec2(0.0);
    farthest = 1.0;
    if (uSkipAgreeing == 0 || s.cube) return false;
    // The finest level whose border ((kDepthTile << k) - kDepthTileInset texels) holds every texel
    // a tap can land on.
    int level = max(0, int(ceil(log2((reach + 1e-3 + float(kDepthTileInset)) / float(kDepthTile)))));
    if (float((kDepthTile << level) - kDepthTileInset) < reach + 1e-3) ++level;  // log2's rounding
    if (level >= textureQueryLevels(uDepthTiles)) return false;
    float side = float(kDepthTile << level);
    vec2 p = s.coord.xy * s.resolution;
    vec2 tile = floor(p / side);
    vec4 bounds = texelFetch(uDepthTiles, ivec3(tile, s.slot), level);
    g = bounds.yz;
    planeAtP = dot(g, p - tile * side) + bounds.x;
    farthest = bounds.w;
    return true;
}

// What every tap of a kernel reaching `reach` texels (along each axis) returns, comparing with
// references on the receiver plane of `slope` (depth per texel; 0: s.depth itself), where the
// bounds of the receiver's tile show they all return the same: 1 (lit), 0 (shadowed); -1 where
// they do not (a penumbra, a cube map, a tile whose border leaves the map): the taps must run.
// Exact, not a guess: a nearest-filtered tap landing at p + o reads texel floor(p + o), whose
// centre c lies within reach + 0.5 of p, and compares it with s.depth + clamp(slope . o, +-0.01)
// (tapReceiverDepth), at most s.depth + max(slope . (c - p) + |slope|/2, -0.01). Lit: the tile's
// plane lies behind that over the whole box of centres (a linear function: its minimum is at a
// corner). Shadowed: the farthest texel lies in front of the lowest reference any tap can have.
// Measured on llvmpipe (default scene, pcf-poisson16): one fetch, where gathering the 16 texels
// around the receiver cost about what 9 of the 16 taps do.
float tapsAgree(ShadowSite s, float reach, vec2 slope) {
    float planeAtP, farthest;
    vec2 g;
    if (any(isnan(slope)) || any(isinf(slope)) || !tileAround(s, reach, planeAtP, g, farthest)) return -1.0;
    float box = reach + 0.5 + 1e-3;  // how far a landing texel's centre lies from p, per axis
    float slack = 0.5 * (abs(slope.x) + abs(slope.y)) + 1e-6;  // + rounding of the references
    bool behindPlane = planeAtP - dot(abs(g - slope), vec2(box)) >= s.depth + slack;
    bool behindFloor = planeAtP - dot(abs(g), vec2(box)) >= s.depth - 0.01 + 1e-6;
    if (behindPlane && behindFloor) return 1.0;
    float lowest = s.depth + max(-(abs(slope.x) + abs(slope.y)) * reach, -0.01) - 1e-6;
    // A reference past 1 may be clamped to 1 by the sampler: "in front" needs depths below 1.
    return farthest < lowest && farthest < 1.0 ? 0.0 : -1.0;
}
