#version 450 core
// Debug overlay: a light's depth map (grey, contrast-stretched) or colour map (Nápravník 2020's
// third phase, Mátl 2013 fig. 5.2).
#include "../common/color.glsl"
in vec2 vUv;
layout(binding = 0) uniform sampler2D uImage;
layout(binding = 1) uniform sampler2DArray uLayers;
uniform int uIsDepth;
uniform int uLayer;  // >= 0: show this layer of uLayers instead of uImage
layout(location = 0) out vec4 outColor;
void main() {
    vec4 v = uLayer >= 0 ? texture(uLayers, vec3(vUv, float(uLayer))) : texture(uImage, vUv);
    vec3 c = uIsDepth != 0 ? vec3(pow(v.r, 4.0)) : v.rgb;
    outColor = vec4(linearToSrgb(c), 1.0);
}
