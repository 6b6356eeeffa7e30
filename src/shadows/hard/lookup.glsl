// Hard shadow-map lookup (Williams 1978) with the translucent tint of Nápravník 2020.
#include "src/shadows/common/glsl/shadow_coord.glsl"
#include "src/shadows/common/glsl/shadow_samplers.glsl"

vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    int slot = lightShadowSlot(light);
    if (slot < 0) return vec3(1.0);
    ShadowCoord sc = shadowCoord(light, P, N, NdotL);
    if (!sc.inside) return vec3(1.0);
    if (lightType(light) == kLightPoint)
        return shadowCompareCube(slot, sc.uv, sc.depth) * shadowTintBehindCube(slot, sc.uv, sc.depth);
    return shadowCompare2D(slot, vec3(sc.uv.xy, sc.depth)) * shadowTintBehind2D(slot, sc.uv.xy, sc.depth);
}
