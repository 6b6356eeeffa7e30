#version 450 core
// End of frame for the float target: distance fog (compiled in with FOG, see
// render/Renderer.cpp), clamp (no tone mapping) and sRGB encoding.
#include "../common/color.glsl"
#include "../common/fog.glsl"
in vec2 vUv;
layout(binding = 0) uniform sampler2D uHdr;
layout(binding = 1) uniform sampler2D uDepth;
uniform int uEncodeSrgb;  // 0: pass linear values through (debug channels)
uniform int uOwnPixelsOnly;  // 1: keep the target where another renderer owns the pixel (alpha 0)
layout(location = 0) out vec4 outColor;

void main() {
    vec4 hdr = texture(uHdr, vUv);
    if (uOwnPixelsOnly != 0 && hdr.a < 0.5) discard;
    vec3 color = hdr.rgb;
#ifdef FOG
    float depth = texture(uDepth, vUv).r;
    if (depth < 1.0) color = mix(color, uBackground, fogAmount(cameraDistance(depth, vUv)));
#endif
    outColor = vec4(uEncodeSrgb != 0 ? linearToSrgb(color) : color, 1.0);
}
