// Coloured stochastic shadow map lookup (McGuire & Enderton 2011; Mátl 2013 §5.3):
// X += (map.rgb(s + Δ) > s.z) over n taps, received light X·L/n. Filters compared in the
// thesis (CssmFilter.h): PCF 3x3 (9 taps), Poisson 16, Poisson 20, uniform random 30, and the
// 13-tap cross-plus-square {(0,0), (±3,±3), (±4,0), (0,±4), (±7,0), (0,±7)} texels, every tap
// jittered by δ(s) = ([(5 s) mod 2] - 1) / (6 (‖∂s/∂x‖₁, ‖∂s/∂y‖₁)); and box16 / box64, which
// count the whole stratified tile (caster.frag) the receiver falls in.
#include "src/shadows/common/glsl/kernels.glsl"
#include "src/shadows/cssm/CssmFilter.h"

uniform int uFilter;  // kCssm*
uniform int uSeparateOpaque;  // 1: the map holds translucent layers only; opaque casters come from the depth map
uniform float uStorageEpsilon;  // relative precision of the stored depth (RGBA16F: 2^-10), 0 for fp32
uniform float uRadiusTexels;  // <= 0: automatic, so that the taps land on distinct texels

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

// Per channel: 1 where the stored (nearest stochastic occluder) depth lies beyond the receiver.
// The receiver's depth is extrapolated along its plane to each tap (receiver-plane depth bias):
// kernels up to 7 texels wide would otherwise shadow sloped receivers with themselves.
vec3 passesIf(vec3 stored, float receiverDepth, int light) {
    float receiver = linearShadowDepth(light, receiverDepth);
    // Half floats round the stored depth by up to an ulp: a receiver must not shadow itself by that.
    return vec3(greaterThan(stored, vec3(receiver * (1.0 - uStorageEpsilon))));
}

vec3 passes(ShadowSite s, vec2 texels) {
    vec3 stored = s.cube ? shadowRawLodCube(s.slot, s.coord + s.tangent * texels.x + s.bitangent * texels.y).rgb
                         : shadowRawLod2D(s.slot, s.coord.xy + texels / s.resolution).rgb;
    return passesIf(stored, tapReceiverDepth(s, texels), s.light);
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

vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    ShadowSite s = shadowSite(light, P, N, NdotL);
    // s in texels, and ∂s/∂x, ∂s/∂y, taken before any branch. Cube maps: coordinates along the
    // face's texel steps (tangent, bitangent), not the direction's x, y (constant on some faces).
    vec2 sTexels = s.cube ? vec2(dot(s.coord, s.tangent), dot(s.coord, s.bitangent)) / dot(s.tangent, s.tangent)
                          : s.coord.xy * s.resolution;
    vec2 dsdx = dFdx(sTexels), dsdy = dFdy(sTexels);
    if (!s.inside) return vec3(1.0);
    vec3 sum = vec3(0.0);
    int n;
    if (uFilter == kCssmBox16 || uFilter == kCssmBox64) {
        // The side x side texels nearest the receiver, at their centres: with the stratified ξ
        // one whole stratified tile (up to alignment), so the share of passing texels is the layer's 1 - ρ to within
        // 1/side².
        int side = uFilter == kCssmBox16 ? 4 : 8;
        n = side * side;
        float h = 0.5 * float(side - 1);
        // 2D maps: the whole tile the receiver falls in, so that every layer counts exactly its
        // stratified share (windows across tile borders would mix partial, unstratified tiles).
        vec2 texel = s.coord.xy * s.resolution;
        vec2 corner = s.cube ? vec2(-h) : floor(texel / float(side)) * float(side) + 0.5 - texel;
        if (uSeparateOpaque != 0 && !s.cube && noLayerInFront(s, corner, side)) return compareAt(s, vec2(0.0), 0.0) * vec3(1.0);
        if (s.cube) {
            sum = cubeTileSum(s, side);
        } else {
            for (int j = 0; j < side; ++j)
                for (int i = 0; i < side; ++i) sum += passes(s, corner + vec2(i, j));
        }
    } else if (uFilter == kCssmPcf9) {
        n = 9;
        for (int j = -1; j <= 1; ++j)
            for (int i = -1; i <= 1; ++i) sum += passes(s, vec2(i, j));
    } else if (uFilter == kCssmPoisson16 || uFilter == kCssmPoisson20) {
        n = uFilter == kCssmPoisson16 ? 16 : 20;
        // n taps need about n texels under the disk: r = sqrt(n / π), with room to spare.
        float radius = uRadiusTexels > 0.0 ? uRadiusTexels : 1.5 * sqrt(float(n) / 3.14159);
        mat2 rot = pixelRotation();
        for (int i = 0; i < n; ++i) sum += passes(s, poissonTap(i, rot, radius));
    } else if (uFilter == kCssmRandom30) {
        n = 30;
        float radius = uRadiusTexels > 0.0 ? uRadiusTexels : 1.5 * sqrt(float(n) / 3.14159);
        for (int i = 0; i < n; ++i) sum += passes(s, randomDiskTap(i, radius));
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
    if (uSeparateOpaque != 0) return compareAt(s, vec2(0.0), 0.0) * coloured;
    return coloured;
}
