#version 450 core
// End of frame: distance fog towards the background before the far plane (Nápravník 2020, "Mlha";
// compiled in with FOG, see render/Renderer.cpp), clamp (no tone mapping) and sRGB encoding.
#include "../common/color.glsl"
in vec2 vUv;
layout(binding = 0) uniform sampler2D uHdr;
layout(binding = 1) uniform sampler2D uDepth;
// The camera's perspective (glm::perspective) inverted for one pixel: window depth d lies at view
// depth uViewDepth.x / (d + uViewDepth.y), and the pixel's ray leaves at (ndc.xy * uRaySlope, -1)
// in view space. Measured on llvmpipe (default scene, 1280x720): inverting the whole projection
// matrix per pixel cost 2.1 ms of a 7 ms resolve.
uniform vec2 uViewDepth;
uniform vec2 uRaySlope;
uniform vec3 uBackground;
uniform vec2 uFog;        // start, end distances from the camera
uniform int uEncodeSrgb;  // 0: pass linear values through (debug channels)
uniform int uOwnPixelsOnly;  // 1: keep the target where another renderer owns the pixel (alpha 0)
layout(location = 0) out vec4 outColor;

void main() {
    vec4 hdr = texture(uHdr, vUv);
    if (uOwnPixelsOnly != 0 && hdr.a < 0.5) discard;
    vec3 color = hdr.rgb;
#ifdef FOG
    float depth = texture(uDepth, vUv).r;
    if (depth < 1.0) {
        vec2 ray = (vUv * 2.0 - 1.0) * uRaySlope;
        float distance = uViewDepth.x / (depth + uViewDepth.y) * sqrt(1.0 + dot(ray, ray));
        color = mix(color, uBackground, smoothstep(uFog.x, uFog.y, distance));
    }
#endif
    outColor = vec4(uEncodeSrgb != 0 ? linearToSrgb(color) : color, 1.0);
}
