// Screen-space visibility (ScreenShadowMask): one R8 layer per light, read at this pixel, where
// this fragment is the surface the camera pre-pass saw. Anything else (glass in front of it)
// answers -1 and the caller falls back to the shadow map.
#include "shaders/common/depth.glsl"

layout(binding = kUnitScreenShadow) uniform sampler2DArray uScreenMask;
layout(binding = kUnitScreenDepth) uniform sampler2D uScreenMaskDepth;
uniform vec2 uScreenMaskDepthRange;  // camera near, far

float screenMaskVisibility(int light) {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float n = uScreenMaskDepthRange.x, f = uScreenMaskDepthRange.y;
    float seen = perspectiveViewDepth(texelFetch(uScreenMaskDepth, pixel, 0).r, n, f);
    float here = perspectiveViewDepth(gl_FragCoord.z, n, f);
    if (abs(seen - here) > 1e-3 * here + 1e-4) return -1.0;
    return texelFetch(uScreenMask, ivec3(pixel, light), 0).r;
}
