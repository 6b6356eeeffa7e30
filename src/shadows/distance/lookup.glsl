// The "Fresnel effect of shadows" of seed document 001 (a small coloured-light engine): the shadow softens with the caster-receiver distance.
// Three 3x3 kernels, each summing to 9, chosen by that distance:
//   near [0 0 0; 0 9 0; 0 0 0], middle [.5 .5 .5; .5 5 .5; .5 .5 .5], far all ones.
#include "src/shadows/common/glsl/shadow_filtering.glsl"

uniform float uNearDistance;   // world units: below this the near kernel
uniform float uFarDistance;    // above this the far kernel
uniform float uSpacingTexels;  // distance between the 3x3 taps

vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    ShadowSite s = shadowSite(light, P, N, NdotL);
    if (!s.inside) return vec3(1.0);
    // Nearest caster over the 3x3 footprint gives the caster-receiver distance.
    float nearest = s.depth;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) nearest = min(nearest, rawDepthAt(s, vec2(i, j) * uSpacingTexels));
    float distance = worldShadowDepth(light, s.depth) - worldShadowDepth(light, nearest);
    float centre = distance < uNearDistance ? 9.0 : (distance < uFarDistance ? 5.0 : 1.0);
    float ring = distance < uNearDistance ? 0.0 : (distance < uFarDistance ? 0.5 : 1.0);
    float lit = 0.0;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i)
            lit += ((i == 0 && j == 0) ? centre : ring) * compareAt(s, vec2(i, j) * uSpacingTexels, 0.0);
    return lit / 9.0 * plainMapTint(s, NdotL);
}
