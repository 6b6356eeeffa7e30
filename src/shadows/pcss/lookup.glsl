// Percentage-closer soft shadows (Fernando 2005): search for blockers, estimate the penumbra by
// similar triangles, w = (d_receiver - d_blocker) * w_light / d_blocker, then PCF that wide.
// Directional lights have an angular size: w = (d_receiver - d_blocker) * 2 tan(θ/2).
#include "src/shadows/common/glsl/kernels.glsl"
#include "src/shadows/common/glsl/depth_tiles.glsl"

uniform int uBlockerSamples;
uniform int uFilterTaps;
uniform float uLightSizeDefault;   // world units, for local lights without a size
uniform float uSunAngleDefault;    // degrees, for directional lights without a size
uniform float uMaxRadiusTexels;    // clamp on search and filter radius (cost bound)

// Penumbra width in texels at the receiver for a blocker at world depth `blocker`.
float penumbraTexels(int light, float lightSize, float receiver, float blocker, float texelScale) {
    if (lightType(light) == kLightDirectional)
        return (receiver - blocker) * 2.0 * tan(radians(lightSize) * 0.5) / texelScale;
    // Width at the receiver in world units, over the world size of a texel there.
    return lightSize * (receiver - blocker) / max(blocker, 1e-4) / (texelScale * receiver);
}

vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    ShadowSite s = shadowSite(light, P, N, NdotL);
    if (!s.inside) return vec3(1.0);
    LightData L = uLights[light];
    bool directional = lightType(light) == kLightDirectional;
    float lightSize = L.misc.z > 0.0 ? L.misc.z : (directional ? uSunAngleDefault : uLightSizeDefault);
    float texelScale = L.shadow.w;
    float receiver = worldShadowDepth(light, s.depth);
    float near = L.positionNear.w;

    // 1. Blocker search over the region through which the receiver sees the light: as wide as the
    //    penumbra a blocker at the near plane would cast.
    float searchTexels = clamp(0.5 * penumbraTexels(light, lightSize, receiver, directional ? receiver - 0.25 * (receiver - near) : near, texelScale),
                               1.0, uMaxRadiusTexels);
    // Lit where the tile bounds show no texel of the search region in front of the receiver: no
    // blocker, so both loops break before their first tap (depth_tiles.glsl). Measured on llvmpipe,
    // default scene: the opaque pass XX.
    float agreed = tapsAgree(s, searchTexels, vec2(0.0)) == 1.0 ? 1.0 : -1.0;
    mat2 rot = pixelRotation();
    float blockerSum = 0.0;
    int blockers = 0;
    for (int i = 0; i < uBlockerSamples; ++i) {
        if (agreed >= 0.0) break;
        float d = rawDepthAt(s, poissonTap(i, rot, searchTexels));
        if (d < s.depth) {
            blockerSum += worldShadowDepth(light, d);
            ++blockers;
        }
    }
    if (agreed < 0.0 && blockers == 0) return tintAt(s);

    // 2. Penumbra estimate from the average blocker depth; 3. PCF of that width.
    float blocker = blockerSum / float(blockers);
    float radius = clamp(0.5 * penumbraTexels(light, lightSize, receiver, blocker, texelScale), 0.5, uMaxRadiusTexels);
    float lit = 0.0;
    for (int i = 0; i < uFilterTaps; ++i) {
        if (agreed >= 0.0) { lit = float(uFilterTaps); break; }
        lit += compareAt(s, poissonTap(i, rot, radius), 0.0);
    }
    return lit / float(uFilterTaps) * tintAt(s);
}
