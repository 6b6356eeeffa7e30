// Hard shadow-map lookup (Williams 1978) with the translucent tint of Nápravník 2020.
#include "src/shadows/common/glsl/shadow_filtering.glsl"

vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    int slot = lightShadowSlot(light);
    if (slot < 0) return vec3(1.0);
#if defined(MATERIAL_TRANSLUCENT) && !(defined(SCENE_TRANSLUCENT_CASTERS) && SCENE_TRANSLUCENT_CASTERS == 0)
    // Translucent receivers take their own layers out of the tint (tintAt), which needs the
    // receiver's plane: the site, with its derivatives, in this program only.
    ShadowSite s = shadowSite(light, P, N, NdotL);
    return s.inside ? compareAt(s, vec2(0.0), 0.0) * tintAt(s) : vec3(1.0);
#else
    ShadowCoord sc = shadowCoord(light, P, N, NdotL);
    if (!sc.inside) return vec3(1.0);
    if (lightType(light) == kLightPoint)
        return shadowCompareCube(slot, sc.uv, sc.depth) * shadowTintBehindCube(slot, sc.uv, sc.depth);
    return shadowCompare2D(slot, vec3(sc.uv.xy, sc.depth)) * shadowTintBehind2D(slot, sc.uv.xy, sc.depth);
#endif
}
