// Warped shadow maps (LiSPSM, PSM), one per screen tile, for the sun; other lights use the plain
// hard lookup. The map's texel size varies across it, so the bias is applied in world space:
// the receiver moves towards the light by (bias + slope * tan θ) texels and along its normal by
// normal_offset texels, each texel measured at the receiver through the projective map.
#include "src/shadows/common/glsl/shadow_filtering.glsl"

layout(binding = kUnitLayered) uniform sampler2DArrayShadow uWarped;
uniform int uWarpedLight;        // index of the warped light, -1: none
uniform mat4 uWarpedMatrix[16];  // world -> [0,1]^3 (after the divide by w), per tile
uniform ivec2 uWarpedGrid;       // cols, rows
uniform mat4 uWarpedCameraViewProj;
uniform float uWarpedResolution;
uniform int uWarpedDebug;        // 1: tint each tile

// World size of one texel at P: 1 / (resolution * |d uv / d P|) across the light, the coarser of
// two directions (WarpFit.cpp, warpedTexelWorld).
float warpedTexelWorld(mat4 S, vec3 P, vec3 lightDir) {
    vec4 h = S * vec4(P, 1.0);
    vec2 uv = h.xy / h.w;
    vec3 e1 = normalize(cross(lightDir, abs(lightDir.y) < 0.99 ? vec3(0, 1, 0) : vec3(1, 0, 0)));
    vec3 e2 = cross(lightDir, e1);
    vec4 s1 = S * vec4(e1, 0.0), s2 = S * vec4(e2, 0.0);
    float gain = min(length((s1.xy - uv * s1.w) / h.w), length((s2.xy - uv * s2.w) / h.w));
    return 1.0 / (uWarpedResolution * max(gain, 1e-12));
}

const int kWarpedTiles = WARPED_TILES;  // cols x rows (lookupDefines)

// The screen tile of P, whose map it reads. Measured on llvmpipe (default scene, lispsm): the
// search and the dynamically indexed matrix cost 3.5 ms of a 34 ms opaque pass, so one map
// (1 x 1) skips both at compile time.
int warpedTile(vec3 P) {
    if (kWarpedTiles == 1) return 0;
    vec4 c = uWarpedCameraViewProj * vec4(P, 1.0);
    vec2 ndc = c.w > 0.0 ? c.xy / c.w : vec2(0.0);
    ivec2 cell = clamp(ivec2(floor((ndc * 0.5 + 0.5) * vec2(uWarpedGrid))), ivec2(0), uWarpedGrid - 1);
    return cell.y * uWarpedGrid.x + cell.x;
}

// Whether `light` is the warped one: a compile-time answer in a program specialised to the light
// layout (as cascadedLight in cascaded/lookup.glsl).
#ifdef SCENE_SUN_LIGHT
bool warpedLight(int light) { return light == SCENE_SUN_LIGHT; }
#else
bool warpedLight(int light) { return light == uWarpedLight; }
#endif

const vec3 kTileTints[4] = vec3[](vec3(1.0, 0.6, 0.6), vec3(0.6, 1.0, 0.6), vec3(0.6, 0.6, 1.0), vec3(1.0, 1.0, 0.5));

vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    ShadowSite site = shadowSite(light, P, N, NdotL);
    vec3 tint = plainMapTint(site, NdotL);
    if (!warpedLight(light)) return site.inside ? compareAt(site, vec2(0.0), 0.0) * tint : vec3(1.0);
    LightData L = uLights[light];
    vec3 toLight = -normalize(L.directionFar.xyz);
    int tile = warpedTile(P);
    mat4 S = uWarpedMatrix[tile];
    float texel = warpedTexelWorld(S, P, -toLight);
    float cosTheta = clamp(NdotL, 1e-3, 1.0);
    float tanTheta = min(sqrt(1.0 - cosTheta * cosTheta) / cosTheta, 10.0);
    vec3 biased = P + toLight * (texel * (L.shadow.x + L.shadow.y * tanTheta)) + N * (L.shadow.z * texel);
    vec4 h = S * vec4(biased, 1.0);
    vec3 s = h.xyz / h.w;
    float lit = 1.0;
    if (h.w > 0.0 && all(greaterThan(s.xy, vec2(0.0))) && all(lessThan(s.xy, vec2(1.0))))
        lit = texture(uWarped, vec4(s.xy, float(tile), s.z));
    vec3 result = lit * tint;
    return uWarpedDebug != 0 ? result * kTileTints[tile % 4] : result;
}
