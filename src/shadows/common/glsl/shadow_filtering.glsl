// Building blocks of filtered shadow lookups: one light's map seen around a receiver point,
// with taps addressed in shadow-map texels for 2D maps and cube maps alike.
#include "shadow_coord.glsl"
#include "shadow_samplers.glsl"
#include "shaders/common/depth.glsl"

struct ShadowSite {
    int light;
    int slot;
    bool cube;
    bool inside;
    vec3 coord;      // 2D: (u, v, reference depth); cube: direction from the light
    float depth;     // reference depth (window space), bias applied
    vec3 surface;    // the receiver point itself, no bias nor normal offset: 2D (u, v, window depth); cube: relative to the light
    vec3 tangent, bitangent;  // cube: one texel step in direction space
    float texelWorld;         // world size of one texel at the receiver
    float resolution;         // texels across the map
    vec2 depthSlope;          // receiver-plane depth change per texel (2D, Isidoro 2006)
    // Cube maps: the receiver's plane (through the lookup point, relative to the light) and the
    // bias already subtracted from `depth`, for per-tap receiver-plane depths.
    vec3 planePoint, planeNormal;
    float near, far, depthBias;
};

// Must run in uniform control flow (it takes screen-space derivatives).
ShadowSite shadowSite(int light, vec3 P, vec3 N, float NdotL) {
    LightData L = uLights[light];
    ShadowSite s;
    s.light = light;
    s.slot = lightShadowSlot(light);
    s.cube = lightType(light) == kLightPoint;
    ShadowCoord sc = shadowCoord(light, P, N, NdotL);
    s.inside = sc.inside && s.slot >= 0;
    s.coord = s.cube ? sc.uv : vec3(sc.uv.xy, sc.depth);
    s.depth = sc.depth;
    vec4 surface = L.shadowMatrix * vec4(P, 1.0);  // folds away in lookups that never read it
    s.surface = s.cube ? P - L.positionNear.xyz : surface.xyz / surface.w;
    s.texelWorld = shadowTexelWorldSize(light, P);
    float res = L.misc.y;
    s.resolution = res;
    vec3 dir = normalize(sc.uv);
    vec3 helper = abs(dir.y) < 0.99 ? vec3(0, 1, 0) : vec3(1, 0, 0);
    // A cube face texel spans 2 d / res world units at view depth d = the major axis.
    float cubeTexel = 2.0 * max(abs(sc.uv.x), max(abs(sc.uv.y), abs(sc.uv.z))) / res;
    s.tangent = normalize(cross(helper, dir)) * cubeTexel;
    s.bitangent = normalize(cross(dir, s.tangent)) * cubeTexel;
    // Receiver-plane depth bias: depth as a linear function of (u, v) across the pixel.
    vec3 dx = dFdx(vec3(sc.uv.xy, sc.depth)), dy = dFdy(vec3(sc.uv.xy, sc.depth));
    mat2 J = mat2(dx.x, dy.x, dx.y, dy.y);  // rows: d(uv)/dx, d(uv)/dy
    float det = determinant(J);
    vec2 slopeUv = abs(det) > 1e-12 ? inverse(J) * vec2(dx.z, dy.z) : vec2(0.0);
    s.depthSlope = s.cube ? vec2(0.0) : slopeUv / res;
    s.planePoint = sc.uv;  // cube: offset lookup point minus the light position
    s.planeNormal = N;
    s.near = L.positionNear.w;
    s.far = L.directionFar.w;
    s.depthBias = s.cube ? perspectiveWindowDepth(lightViewDepth(light, L.positionNear.xyz + sc.uv), s.near, s.far) - sc.depth : 0.0;
    return s;
}

// The receiver's own depth at a tap `texels` away, extrapolated along its plane (receiver-plane
// depth bias; Isidoro 2006 for 2D maps, an exact ray-plane intersection for cube faces), so wide
// kernels do not shadow sloped receivers with themselves. Clamped against grazing planes.
float cubeReceiverDepth(ShadowSite s, vec3 d);

float tapReceiverDepth(ShadowSite s, vec2 texels) {
    if (!s.cube) return s.depth + clamp(dot(s.depthSlope, texels), -0.01, 0.01);
    return cubeReceiverDepth(s, s.coord + s.tangent * texels.x + s.bitangent * texels.y);
}

// The receiver's depth where its plane meets the light's ray along direction `d` (cube maps).
float cubeReceiverDepth(ShadowSite s, vec3 d) {
    float denom = dot(d, s.planeNormal);
    float k = abs(denom) > 1e-8 ? dot(s.planePoint, s.planeNormal) / denom : 1.0;
    if (k <= 0.0) return s.depth;
    vec3 q = abs(d * k);
    float depth = perspectiveWindowDepth(max(q.x, max(q.y, q.z)), s.near, s.far) - s.depthBias;
    return clamp(depth, s.depth - 0.01, s.depth + 0.01);
}

// Cube-map texel addressing (OpenGL 4.5 table 8.19): the face a direction selects, and its
// (s, t) in [0, 1]; cubeFaceDirection inverts it for a face and (s, t).
vec3 cubeFaceCoord(vec3 d, out int face) {
    vec3 a = abs(d);
    if (a.x >= a.y && a.x >= a.z) { face = d.x > 0.0 ? 0 : 1; return vec3((vec2(d.x > 0.0 ? -d.z : d.z, -d.y) / a.x + 1.0) * 0.5, a.x); }
    if (a.y >= a.z) { face = d.y > 0.0 ? 2 : 3; return vec3((vec2(d.x, d.y > 0.0 ? d.z : -d.z) / a.y + 1.0) * 0.5, a.y); }
    face = d.z > 0.0 ? 4 : 5;
    return vec3((vec2(d.z > 0.0 ? d.x : -d.x, -d.y) / a.z + 1.0) * 0.5, a.z);
}
vec3 cubeFaceDirection(int face, vec2 st) {
    vec2 c = st * 2.0 - 1.0;  // (sc, tc) with |ma| = 1
    if (face == 0) return vec3(1.0, -c.y, -c.x);
    if (face == 1) return vec3(-1.0, -c.y, c.x);
    if (face == 2) return vec3(c.x, 1.0, c.y);
    if (face == 3) return vec3(c.x, -1.0, -c.y);
    if (face == 4) return vec3(c.x, -c.y, 1.0);
    return vec3(-c.x, -c.y, -1.0);
}

// Hardware comparison at an offset of `texels` (plus a depth offset, e.g. receiver-plane). A
// receiver's plane extrapolated past the far plane (a floor grazing a light's range) would fail
// LEQUAL against the cleared 1.0, a shadow from nothing: float depth maps do not clamp the
// reference (GL 4.5 §8.23.1), so it is clamped here.
float compareAt(ShadowSite s, vec2 texels, float depthOffset) {
    float reference = min(s.depth + depthOffset, 1.0);
    if (s.cube) return shadowCompareCube(s.slot, s.coord + s.tangent * texels.x + s.bitangent * texels.y, reference);
    return shadowCompare2D(s.slot, vec3(s.coord.xy + texels / s.resolution, reference));
}

// Raw (window-space) depth stored at an offset of `texels`.
float rawDepthAt(ShadowSite s, vec2 texels) {
    if (s.cube) return shadowRawLodCube(s.slot, s.coord + s.tangent * texels.x + s.bitangent * texels.y).r;
    return shadowRawLod2D(s.slot, s.coord.xy + texels / s.resolution).r;
}

// Linear depth in [0, 1] between the light's near and far planes, from window depth.
float linearShadowDepth(int light, float windowDepth) {
    LightData L = uLights[light];
    if (!lightPerspective(light)) return windowDepth;
    return perspectiveLinearDepth(windowDepth, L.positionNear.w, L.directionFar.w);
}

// Translucent receivers: per texel of the tint map, how many of the receiver's own layers the tint
// there holds, where every other layer there lies in front of the receiver; dividing them out of
// the tint (throughOwnLayers) leaves the light that reaches the receiver:
//  0: every layer at the texel lies in front of the receiver (beyond its rim, as the light sees
//     it): the product as it is;
//  1: the texel's farthest layer is the receiver's own surface: a pane behind another, a solid's
//     far side behind its near side;
//  2: the receiver is where light enters a closed part (uClosedPart), no entry lies behind it at
//     the texel, but a layer does: the face the light leaves that solid by, of the same material
//     (solids that neither nest nor intersect): a glass block's lit face behind a pane;
// -1: not known (a layer behind the receiver that is not its own).
// The farthest layer and entry are the tint pass's fp32 drawn alpha (DepthAndTintMaps); "is the
// receiver" means on its surface, extended along its plane to the texel centre: within 2^-12 of
// its linear depth and a quarter texel's slope (the rasterised depth of a tessellated surface).
// From the farthest layers' and entries' window depths, the receiver's linear depth at each texel
// centre and its change per texel:
vec4 ownLayersFrom(ShadowSite s, vec4 farthest, vec4 entry, vec4 linearSurface, float perTexel) {
    vec4 linearFarthest, linearEntry;
    for (int i = 0; i < 4; ++i) {
        linearFarthest[i] = linearShadowDepth(s.light, farthest[i]);
        linearEntry[i] = linearShadowDepth(s.light, entry[i]);
    }
    vec4 margin = vec4(linearSurface.y / 4096.0 + 0.25 * perTexel + 1e-7);
    bvec4 last = lessThan(abs(linearFarthest - linearSurface), margin), lastEntry = lessThan(abs(linearEntry - linearSurface), margin);
    bvec4 allInFront = lessThan(linearFarthest, linearSurface - margin);
    // The farthest layer is the farthest entry itself where both channels hold the same fragment's
    // depth: the receiver alone (a closed part whose exit an opaque surface hides, or an open one).
    // Where it differs, an exit lies behind, by any distance: the own one of a closed part (also
    // by its rim, where the light leaves through a side a hair behind the lit face).
    vec4 behindEntry = mix(vec4(uClosedPart != 0 ? 2.0 : -1.0), vec4(1.0), equal(farthest, entry));
    return mix(mix(mix(vec4(-1.0), vec4(0.0), allInFront), vec4(1.0), last), behindEntry, lastEntry);
}

// Whether the receiver's `layers` own layers are known and let enough of each channel through to
// divide by (a channel they stop almost wholly would magnify the tint's rounding), and the light
// through its own layers' tint with them divided out.
vec3 ownTransmittance(float layers) {
    return layers > 1.5 ? receiverTransmittance * receiverTransmittance : layers > 0.5 ? receiverTransmittance : vec3(1.0);
}
bool ownLayersDividable(float layers) { return layers >= 0.0 && all(greaterThanEqual(ownTransmittance(layers), vec3(1.0 / 1024.0))); }
vec3 throughOwnLayers(vec3 tint, float layers) { return min(tint / max(ownTransmittance(layers), vec3(1.0 / 1024.0)), vec3(1.0)); }

// Point lights: the window depth of the receiver's own plane (through the unbiased point, `surface`)
// along direction `d` from the light, within 0.01 of the point's own (grazing planes).
float cubeSurfaceDepth(ShadowSite s, vec3 d) {
    vec3 a = abs(s.surface);
    float own = perspectiveWindowDepth(max(a.x, max(a.y, a.z)), s.near, s.far);
    float denom = dot(d, s.planeNormal);
    float k = abs(denom) > 1e-8 ? dot(s.surface, s.planeNormal) / denom : -1.0;
    if (k <= 0.0) return own;
    vec3 q = abs(d * k);
    return clamp(perspectiveWindowDepth(max(q.x, max(q.y, q.z)), s.near, s.far), own - 0.01, own + 0.01);
}
// The receiver's linear depth at the centre of the texel `offset` texels from `centre` (in texels,
// on cube face `face`), along its plane.
float linearSurfaceAt(ShadowSite s, vec2 centre, int face, vec2 offset) {
    if (s.cube) return linearShadowDepth(s.light, cubeSurfaceDepth(s, cubeFaceDirection(face, (centre + offset) / s.resolution)));
    return linearShadowDepth(s.light, s.surface.z + clamp(dot(centre + offset - s.surface.xy * s.resolution, s.depthSlope), -0.01, 0.01));
}
// Where the lookup lands on its map, in texels (on cube face `face`).
vec2 lookupTexel(ShadowSite s, out int face) {
    face = 0;
    return s.cube ? cubeFaceCoord(s.coord, face).xy * s.resolution : s.coord.xy * s.resolution;
}

// The own layers at the 2 x 2 texels around the lookup (gather order; `texel`: where it lands,
// `centre`: between the four, in texels), and (bilinearThroughOwnLayers) the tint there weighed
// bilinearly after the division, so that a receiver's rim, where texels with and without
// its own layer meet, is exact too. A texel whose layers are not known gives its product where the
// receiver is behind its nearest layer (tint alpha, NearestLayer: pcf-bilinear) or its farthest
// (FarthestLayer: CSSM), else 1.
vec4 ownLayersAround(ShadowSite s, out vec2 texel, out vec2 centre) {
    int face;
    texel = lookupTexel(s, face);
    centre = floor(texel - 0.5) + 1.0;  // between the 2 x 2
    const vec4 dx = vec4(-0.5, 0.5, 0.5, -0.5), dy = vec4(0.5, 0.5, -0.5, -0.5);  // gather order
    vec4 linearSurface;
    for (int i = 0; i < 4; ++i) linearSurface[i] = linearSurfaceAt(s, centre, face, vec2(dx[i], dy[i]));
    float perTexel = abs(linearSurface.y - linearSurface.x) + abs(linearSurface.y - linearSurface.z);
    vec4 farthest, entry;
    if (s.cube) shadowDrawnGatherCube(s.slot, s.coord, farthest, entry);
    else shadowDrawnGather2D(s.slot, centre / s.resolution, farthest, entry);
    return ownLayersFrom(s, farthest, entry, linearSurface, perTexel);
}
vec3 bilinearThroughOwnLayers(ShadowSite s) {
    vec2 texel, centre;
    vec4 own = ownLayersAround(s, texel, centre);
    mat4 tint = s.cube ? shadowTintGatherCube(s.slot, s.coord) : shadowTintGather2D(s.slot, centre / s.resolution);
    vec2 f = texel - (centre - 0.5);  // the upper texels' weights in x, y
    vec4 weights = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));  // gather order
    vec3 sum = vec3(0.0);
    for (int i = 0; i < 4; ++i) {
        vec3 product = vec3(tint[0][i], tint[1][i], tint[2][i]);
        bool divide = ownLayersDividable(own[i]);
        sum += weights[i] * (divide ? throughOwnLayers(product, own[i]) : tintBehind(vec4(product, tint[3][i]), s.depth));
    }
    return sum;
}

// The light a translucent receiver's own layers let through to it: none of a flat part's lies in
// front of it; a convex solid's entry face lies in front of each point where the light leaves it
// (its outward normal turned from the light), once. `NdotL`: with the normal turned to the camera,
// as lighting.frag lights both faces.
vec3 ownLayersInFront(float NdotL) {
    float outwardNdotL = gl_FrontFacing ? NdotL : -NdotL;
    return uClosedPart != 0 && outwardNdotL < 0.0 ? receiverTransmittance : vec3(1.0);
}

// The centre of the texel the lookup lands in, in texels (on cube face `face`): the texel nearest
// filtering reads.
vec2 landingTexel(ShadowSite s, out int face) { return clamp(floor(lookupTexel(s, face)), vec2(0.0), vec2(s.resolution - 1.0)) + 0.5; }
// The own layers at that texel alone (`centre`, in texels, on face `face`; nearest filtering): one
// fetch where ownLayersAround's 2 x 2 take two gathers. Measured on llvmpipe, glass scene, hard's
// translucent pass: 13.8 ms against 17.0 ms with the 2 x 2 (9.9 ms with no division; the receiver
// plane's derivatives are 1.6 ms of the rest).
float ownLayersAtTexel(ShadowSite s, vec2 centre, int face) {
    vec2 drawn = s.cube ? shadowDrawnCube(s.slot, cubeFaceDirection(face, centre / s.resolution)) : shadowDrawnFetch2D(s.slot, ivec2(centre));
    float linearSurface = linearSurfaceAt(s, centre, face, vec2(0.0));
    float perTexel = abs(linearSurfaceAt(s, centre, face, vec2(1.0, 0.0)) - linearSurface) +
                     abs(linearSurfaceAt(s, centre, face, vec2(0.0, 1.0)) - linearSurface);
    return ownLayersFrom(s, drawn.xxxx, drawn.yyyy, vec4(linearSurface), perTexel).x;
}
// The tint of the texel the lookup lands in, read at its centre so that the map's filtering,
// nearest or linear, returns that texel alone; `light` is that tint with the receiver's own layers
// there divided out, and the result whether they are known (else `tint` serves the caller's way).
bool landingTintThroughOwnLayers(ShadowSite s, out vec3 light, out vec4 tint) {
    int face;
    vec2 texel = landingTexel(s, face), centre = texel / s.resolution;
    tint = s.cube ? shadowTintCube(s.slot, cubeFaceDirection(face, centre)) : shadowTint2D(s.slot, centre);
    float layers = ownLayersAtTexel(s, texel, face);
    light = throughOwnLayers(tint.rgb, layers);
    return ownLayersDividable(layers);
}

// The plain tint (NearestLayer) for a translucent receiver: the product with its own layers
// divided out where ownLayersFrom knows them, at the texel the tint is read from (nearest
// filtering) or at each of the 2 x 2 (SHADOW_TINT_LINEAR, pcf-bilinear). Elsewhere (an unknown
// layer behind the receiver) the product of every layer behind whose nearest the receiver lies,
// as before: the deterministic map cannot tell which layers lie in front. Measured on the glass
// scene (compare --translucent-receivers): see the README's glass paragraph.
vec3 tintThroughOwnLayers(ShadowSite s) {
#ifdef SHADOW_TINT_LINEAR
    return bilinearThroughOwnLayers(s);
#else
    vec3 light;
    vec4 tint;
    return landingTintThroughOwnLayers(s, light, tint) ? light : tintBehind(tint, s.depth);
#endif
}

// The translucent tint behind the nearest translucent layer (the colour map of Nápravník 2020).
vec3 tintAt(ShadowSite s) {
#if defined(MATERIAL_TRANSLUCENT) && !(defined(SCENE_TRANSLUCENT_CASTERS) && SCENE_TRANSLUCENT_CASTERS == 0)
    return tintThroughOwnLayers(s);
#else
    return s.cube ? shadowTintBehindCube(s.slot, s.coord, s.depth) : shadowTintBehind2D(s.slot, s.coord.xy, s.depth);
#endif
}

// Light reaching a translucent receiver, bounded by its own layers in front, per channel. Light
// reaching a closed part's side turned from the light has crossed one of its own entry faces at
// least, and every layer only takes light away: the truth is at most ownLayersInFront, so the bound
// can only bring an answer nearer it. It mends the whole lookup on a thin pane's far side, whose
// lookup the bias lands in front of the pane's near side, so that it read no layer (1) where the
// truth is t (compare --behind-glass, stop 62): plainMapTint's and CSSM's (cssm/lookup.glsl).
vec3 atMostOwnLayersInFront(vec3 light, float NdotL) {
#if defined(MATERIAL_TRANSLUCENT) && !(defined(SCENE_TRANSLUCENT_CASTERS) && SCENE_TRANSLUCENT_CASTERS == 0)
    return min(light, ownLayersInFront(NdotL));
#else
    return light;
#endif
}

// The tint at a site of the light's plain map (hard's lookup, and those whose depth compare reads
// maps of their own: cascades, warped views): white off the map; a translucent receiver that no
// other layer's tint reaches (RECEIVER_UNTINTED: the renderer's tint split) gets only its own
// layers in front, read from no map.
vec3 plainMapTint(ShadowSite s, float NdotL) {
    if (!s.inside) return vec3(1.0);
#if defined(MATERIAL_TRANSLUCENT) && defined(RECEIVER_UNTINTED) && !(defined(SCENE_TRANSLUCENT_CASTERS) && SCENE_TRANSLUCENT_CASTERS == 0)
    return ownLayersInFront(NdotL);
#else
    return atMostOwnLayersInFront(tintAt(s), NdotL);
#endif
}

// World distance along the light's axis, from window depth.
float worldShadowDepth(int light, float windowDepth) {
    LightData L = uLights[light];
    float n = L.positionNear.w, f = L.directionFar.w;
    if (!lightPerspective(light)) return n + windowDepth * (f - n);
    return perspectiveViewDepth(windowDepth, n, f);
}
