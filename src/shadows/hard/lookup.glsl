// Hard shadow-map lookup (Williams 1978) with the translucent tint of Nápravník 2020.
#include "src/shadows/common/glsl/shadow_filtering.glsl"

vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    int slot = lightShadowSlot(light);
    if (slot < 0) return vec3(1.0);
#if defined(MATERIAL_TRANSLUCENT) && !(defined(SCENE_TRANSLUCENT_CASTERS) && SCENE_TRANSLUCENT_CASTERS == 0)
    // Translucent receivers take their own layers out of the tint (tintAt), which needs the
    // receiver's plane: the site, with its derivatives, in this program only.
    ShadowSite s = shadowSite(light, P, N, NdotL);
    // RECEIVER_UNTINTED: every other translucent layer around this receiver lies behind it, or none
    // is there (render/TintReach.h, tintFootprintNotInFront), and its own layers are known
    // (Draw::ownLayersKnown): the only layers in front of it are its own, read from no map
    // (plainMapTint). Else every other layer in front (RECEIVER_BEHIND_LAYERS: the whole lookup's
    // division is that build already), layers on both sides, or own layers not known: the whole
    // lookup. Where another layer lies behind a solid, the farthest layer at its texels is not its
    // own and its own cannot be divided out: the untinted build has no such case.
    return s.inside ? compareAt(s, vec2(0.0), 0.0) * plainMapTint(s, NdotL) : vec3(1.0);
#else
    ShadowCoord sc = shadowCoord(light, P, N, NdotL);
    if (!sc.inside) return vec3(1.0);
    if (lightType(light) == kLightPoint)
        return shadowCompareCube(slot, sc.uv, sc.depth) * shadowTintBehindCube(slot, sc.uv, sc.depth);
    return shadowCompare2D(slot, vec3(sc.uv.xy, sc.depth)) * shadowTintBehind2D(slot, sc.uv.xy, sc.depth);
#endif
}
