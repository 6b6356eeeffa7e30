// Cascaded / parallel-split shadow maps (Zhang et al. 2006) for the sun; other lights use the
// plain hard lookup. The cascade is chosen by view depth (or by the first box that contains the
// point), and blended with the next one near the split so the border does not show.
#include "src/shadows/common/glsl/shadow_filtering.glsl"

layout(binding = kUnitLayered) uniform sampler2DArrayShadow uCascades;
uniform int uCascadeLight;        // index of the cascaded light, -1: none
uniform int uCascadeCount;
uniform float uCascadeSplits[9];  // view-space distances
uniform mat4 uCascadeMatrix[8];   // world -> [0,1]^3
uniform vec3 uCascadeTexel[8];    // x: texel world size, y: depth range (far - near)
uniform mat4 uCascadeCameraView;
uniform float uCascadeBlend;      // share of each cascade blended into the next
const int kCascadeSelect = CASCADE_SELECT;  // 0 by depth, 1 by projection (lookupDefines)
uniform int uCascadeDebug;        // 1: tint each cascade

float sampleCascade(int c, int light, vec3 P, vec3 N, float NdotL) {
    LightData L = uLights[light];
    float texel = uCascadeTexel[c].x;
    float cosTheta = clamp(NdotL, 1e-3, 1.0);
    float tanTheta = min(sqrt(1.0 - cosTheta * cosTheta) / cosTheta, 10.0);
    float worldBias = texel * (L.shadow.x + L.shadow.y * tanTheta);
    vec4 s = uCascadeMatrix[c] * vec4(P + N * (L.shadow.z * texel), 1.0);
    if (any(lessThan(s.xy, vec2(0.0))) || any(greaterThan(s.xy, vec2(1.0)))) return 1.0;
    return texture(uCascades, vec4(s.xy, float(c), s.z - worldBias / uCascadeTexel[c].y));
}

bool insideCascade(int c, vec3 P) {
    vec4 s = uCascadeMatrix[c] * vec4(P, 1.0);
    return all(greaterThan(s.xy, vec2(0.01))) && all(lessThan(s.xy, vec2(0.99)));
}

// Whether `light` is the cascaded one. A program specialised to the light layout knows it at
// compile time (SCENE_SUN_LIGHT is the renderer's ShadowSlots::sun, the light renderMaps takes),
// so the other lights' lookups hold no cascade code and the sun's no plain-map fetch: llvmpipe
// runs both sides of a uniform branch for every pixel.
#ifdef SCENE_SUN_LIGHT
bool cascadedLight(int light) { return light == SCENE_SUN_LIGHT; }
#else
bool cascadedLight(int light) { return light == uCascadeLight; }
#endif

const vec3 kCascadeTints[8] = vec3[](vec3(1.0, 0.6, 0.6), vec3(0.6, 1.0, 0.6), vec3(0.6, 0.6, 1.0), vec3(1.0, 1.0, 0.5),
                                     vec3(1.0, 0.5, 1.0), vec3(0.5, 1.0, 1.0), vec3(1.0, 0.8, 0.5), vec3(0.8, 0.8, 0.8));

vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    ShadowSite site = shadowSite(light, P, N, NdotL);
    if (!cascadedLight(light)) return site.inside ? compareAt(site, vec2(0.0), 0.0) * plainMapTint(site, NdotL) : vec3(1.0);
    float depth = -(uCascadeCameraView * vec4(P, 1.0)).z;
    int c = uCascadeCount;
    for (int i = 0; i < uCascadeCount; ++i) {
        bool chosen = kCascadeSelect == 0 ? depth < uCascadeSplits[i + 1] : insideCascade(i, P);
        if (chosen) { c = i; break; }
    }
    if (c >= uCascadeCount) return plainMapTint(site, NdotL);  // beyond the last split: lit
    float lit = sampleCascade(c, light, P, N, NdotL);
    // Blend into the next cascade over the last uCascadeBlend of this one.
    float start = uCascadeSplits[c + 1] - uCascadeBlend * (uCascadeSplits[c + 1] - uCascadeSplits[c]);
    if (c + 1 < uCascadeCount && depth > start && uCascadeBlend > 0.0)
        // Clamped: chosen by projection, a point may lie in cascade c's box beyond its split,
        // where the unclamped weight left [0, 1] and the visibility with it.
        lit = mix(lit, sampleCascade(c + 1, light, P, N, NdotL), clamp((depth - start) / (uCascadeSplits[c + 1] - start), 0.0, 1.0));
    vec3 result = lit * plainMapTint(site, NdotL);
    return uCascadeDebug != 0 ? result * kCascadeTints[c] : result;
}
