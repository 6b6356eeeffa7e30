// Percentage-closer soft shadows (Fernando 2005): search for blockers, estimate the penumbra by
// similar triangles, w = (d_receiver - d_blocker) * w_light / d_blocker, then PCF that wide.
// Directional lights have an angular size: w = (d_receiver - d_blocker) * 2 tan(θ/2).
// Both kernels are Vogel spirals (kernels.glsl) turned per pixel, not the Poisson set.
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

// What the search and the filter can only end with, where the receiver's tile bounds show it: 1
// (lit) or 0 (shadowed); -1 where the taps must run. No texel of the search region lies nearer
// than the tile's plane allows, so any blockers found average at least that far, and the filter
// is at most as wide as that nearest blocker makes it. Lit when no search texel can be a
// blocker, or when every texel within that widest filter lies behind the receiver (a slope or a
// curved caster finds itself as blockers, yet its narrow filter passes); shadowed when every
// texel of the tile lies in front. The lookup then returns tint or 0, exactly as the taps would.
float searchOutcome(ShadowSite s, int light, float lightSize, float receiver, float texelScale, float searchTexels) {
    float planeAtP, farthest;
    vec2 g;
    if (!tileAround(s, searchTexels, planeAtP, g, farthest)) return -1.0;
    float slope = abs(g.x) + abs(g.y);
    float nearest = planeAtP - slope * (searchTexels + 0.5 + 1e-3);  // no search texel lies nearer
    if (nearest >= s.depth + 1e-6) return 1.0;  // no blocker
    // 1.01, 1e-3: the rounding of the blockers' mean and of the radius.
    float widest = clamp(0.5 * penumbraTexels(light, lightSize, receiver, worldShadowDepth(light, clamp(nearest, 0.0, 1.0)), texelScale),
                         0.5, uMaxRadiusTexels) * 1.01 + 1e-3;
    if (widest > searchTexels) return -1.0;  // the filter may read past the tile's texels
    if (planeAtP - slope * (widest + 0.5 + 1e-3) >= s.depth + 1e-6) return 1.0;
    // Every texel in front: every search tap a blocker, every filter tap shadowed. A reference
    // past 1 may be clamped to 1 by the sampler: "in front" needs depths below 1.
    return farthest < s.depth - 1e-6 && farthest < 1.0 ? 0.0 : -1.0;
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
    // Where the tile bounds show how the search and filter end (depth_tiles.glsl), both loops break
    // before their first tap.
    float agreed = searchOutcome(s, light, lightSize, receiver, texelScale, searchTexels);
    // Both spirals start from the same per-pixel direction.
    vec2 start = pixelDirection();
    SpiralDisk searchDisk = spiralDisk(start, searchTexels, uBlockerSamples);
    float blockerSum = 0.0;
    int blockers = 0;
    for (int i = 0; i < uBlockerSamples; ++i) {
        if (agreed >= 0.0) break;
        float d = rawDepthAt(s, nextSpiralTap(searchDisk, i));
        if (d < s.depth) {
            blockerSum += worldShadowDepth(light, d);
            ++blockers;
        }
    }
    if (agreed < 0.0 && blockers == 0) return plainMapTint(s, NdotL);

    // 2. Penumbra estimate from the average blocker depth; 3. PCF of that width.
    float blocker = blockerSum / float(blockers);
    float radius = clamp(0.5 * penumbraTexels(light, lightSize, receiver, blocker, texelScale), 0.5, uMaxRadiusTexels);
    float lit = 0.0;
    // The bounds again, over the filter the blockers found ask for: every tap may still agree.
    float filterAgreed = agreed >= 0.0 ? agreed : tapsAgree(s, radius, vec2(0.0));
    SpiralDisk filterDisk = spiralDisk(start, radius, uFilterTaps);
    for (int i = 0; i < uFilterTaps; ++i) {
        if (filterAgreed >= 0.0) { lit = filterAgreed * float(uFilterTaps); break; }
        lit += compareAt(s, nextSpiralTap(filterDisk, i), 0.0);
    }
    return lit / float(uFilterTaps) * plainMapTint(s, NdotL);
}
