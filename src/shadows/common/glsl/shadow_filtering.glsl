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
    vec3 surface;    // 2D: the receiver point itself, no bias nor normal offset: (u, v, window depth)
    vec3 tangent, bitangent;  // cube: one texel step in direction space
    float texelWorld;         // world size of one texel at the receiver
    float resolution;         // texels across the map
    vec2 depthSlope;          // receiver-plane depth change per texel (2D, Isidoro 2006)
    vec2 uvDx, uvDy;          // screen-space derivatives of the 2D coordinates (for mipmapped moments)
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
    s.surface = surface.xyz / surface.w;
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
    s.uvDx = dx.xy;
    s.uvDy = dy.xy;
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

// Hardware comparison at an offset of `texels` (plus a depth offset, e.g. receiver-plane).
float compareAt(ShadowSite s, vec2 texels, float depthOffset) {
    if (s.cube) return shadowCompareCube(s.slot, s.coord + s.tangent * texels.x + s.bitangent * texels.y, s.depth + depthOffset);
    return shadowCompare2D(s.slot, vec3(s.coord.xy + texels / s.resolution, s.depth + depthOffset));
}

// Raw (window-space) depth stored at an offset of `texels`.
float rawDepthAt(ShadowSite s, vec2 texels) {
    if (s.cube) return shadowRawLodCube(s.slot, s.coord + s.tangent * texels.x + s.bitangent * texels.y).r;
    return shadowRawLod2D(s.slot, s.coord.xy + texels / s.resolution).r;
}

// The translucent tint behind the nearest translucent layer (the colour map of Nápravník 2020).
vec3 tintAt(ShadowSite s) {
    return s.cube ? shadowTintBehindCube(s.slot, s.coord, s.depth) : shadowTintBehind2D(s.slot, s.coord.xy, s.depth);
}

// Linear depth in [0, 1] between the light's near and far planes, from window depth.
float linearShadowDepth(int light, float windowDepth) {
    LightData L = uLights[light];
    if (!lightPerspective(light)) return windowDepth;
    return perspectiveLinearDepth(windowDepth, L.positionNear.w, L.directionFar.w);
}

// World distance along the light's axis, from window depth.
float worldShadowDepth(int light, float windowDepth) {
    LightData L = uLights[light];
    float n = L.positionNear.w, f = L.directionFar.w;
    if (!lightPerspective(light)) return n + windowDepth * (f - n);
    return perspectiveViewDepth(windowDepth, n, f);
}
