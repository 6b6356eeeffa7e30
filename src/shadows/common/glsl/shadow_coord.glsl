// Where a surface point lands in its light's shadow map, with the bias knobs applied
// (constant, slope-scaled and normal-offset bias). All three are in
// units of the world size of one shadow texel at the receiver, so their defaults hold at any
// scene scale and map resolution.
#include "shaders/common/lights.glsl"

struct ShadowCoord {
    vec3 uv;       // 2D lights: texture coordinates (xy) ; point lights: direction from the light
    float depth;   // reference depth for the comparison, bias already subtracted
    bool inside;   // false when the point falls outside the map
};

// Distance along the light's view axis (perspective lights) that sets the texel footprint.
float lightViewDepth(int light, vec3 P) {
    LightData L = uLights[light];
    vec3 d = P - L.positionNear.xyz;
    if (lightType(light) == kLightPoint) { vec3 a = abs(d); return max(a.x, max(a.y, a.z)); }
    return dot(d, L.directionFar.xyz);
}

float shadowTexelWorldSize(int light, vec3 P) {
    float scale = uLights[light].shadow.w;
    return lightPerspective(light) ? scale * max(lightViewDepth(light, P), 1e-4) : scale;
}

// Window-space depth of a perspective projection at view depth d (GL, near n, far f).
float perspectiveWindowDepth(float d, float n, float f) { return f / (f - n) - f * n / ((f - n) * d); }

// The light's type (point or not, perspective or not) is a constant in a lighting program
// specialised to the scene's lights (render/LightingProgram.h), so the branches below fold:
// measured 2-3 ms of hard's 37 ms opaque pass on llvmpipe (98k-triangle grid, 1280x720).
ShadowCoord shadowCoord(int light, vec3 P, vec3 N, float NdotL) {
    LightData L = uLights[light];
    float texel = shadowTexelWorldSize(light, P);
    float cosTheta = clamp(NdotL, 1e-3, 1.0);
    float tanTheta = min(sqrt(1.0 - cosTheta * cosTheta) / cosTheta, 10.0);
    float worldBias = texel * (L.shadow.x + L.shadow.y * tanTheta);
    vec3 Po = P + N * (L.shadow.z * texel);   // normal offset

    float n = L.positionNear.w, f = L.directionFar.w;
    ShadowCoord sc;
    if (lightType(light) == kLightPoint) {
        float d = lightViewDepth(light, Po);
        // d(depth)/d(distance) = f n / ((f - n) d^2) converts the world bias to depth units.
        sc.uv = Po - L.positionNear.xyz;
        sc.depth = perspectiveWindowDepth(d, n, f) - worldBias * f * n / ((f - n) * d * d);
        sc.inside = d > n && d < f;
        return sc;
    }
    vec4 s = L.shadowMatrix * vec4(Po, 1.0);
    sc.uv = lightPerspective(light) ? s.xyz / s.w : s.xyz;
    if (lightPerspective(light)) {
        float d = max(lightViewDepth(light, Po), 1e-4);
        sc.depth = sc.uv.z - worldBias * f * n / ((f - n) * d * d);
        sc.inside = s.w > 0.0 && all(greaterThanEqual(sc.uv, vec3(0.0))) && all(lessThanEqual(sc.uv, vec3(1.0)));
    } else {
        sc.depth = sc.uv.z - worldBias / (f - n);   // orthographic depth is linear in distance
        sc.inside = all(greaterThanEqual(sc.uv.xy, vec2(0.0))) && all(lessThanEqual(sc.uv.xy, vec2(1.0)));
    }
    return sc;
}
