// Screen-mask techniques (shadow volumes, planar projected shadows): each light's visibility from
// its screen mask at this pixel; coloured tint from translucent casters, and surfaces the camera
// pre-pass did not see (glass), come from the shared shadow maps.
#include "src/shadows/common/glsl/shadow_filtering.glsl"
#include "src/shadows/common/glsl/screen_mask.glsl"

vec3 shadowVisibility(int light, vec3 P, vec3 N, float NdotL) {
    ShadowSite site = shadowSite(light, P, N, NdotL);
    vec3 tint = plainMapTint(site, NdotL);
    float v = screenMaskVisibility(light);
    if (v < 0.0) return site.inside ? compareAt(site, vec2(0.0), 0.0) * tint : vec3(1.0);
    return v * tint;
}
