#version 450 core
// Puts order-independent translucency over the opaque frame with the same dual-source blend as
// the painter's path: dst = dst * transmit + colour.
//   mode 0 weighted blended: colour = (Σ C w / Σ a w) * (1 - mean(T)), transmit = Π T (exact)
//   mode 1 depth peeling: layers front to back, colour = Σ_i C_i Π_{j<i} T_j, transmit = Π T
//   mode 2 dual depth peeling: front layers as mode 1, back layers (farthest first) composited
//          back to front, then seen through the front ones
in vec2 vUv;
layout(binding = 0) uniform sampler2D uAccum;        // weighted: Σ C w, Σ a w
layout(binding = 1) uniform sampler2D uTransmit;     // weighted: Π T
layout(binding = 2) uniform sampler2DArray uLayerColour;
layout(binding = 3) uniform sampler2DArray uLayerTransmit;
layout(binding = 4) uniform sampler2DArray uBackColour;
layout(binding = 5) uniform sampler2DArray uBackTransmit;
uniform int uMode;
uniform int uLayers;
layout(location = 0, index = 0) out vec4 outColor;
layout(location = 0, index = 1) out vec4 outTransmit;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    if (uMode == 0) {
        vec4 accum = texelFetch(uAccum, p, 0);
        vec3 T = texelFetch(uTransmit, p, 0).rgb;
        vec3 average = accum.rgb / max(accum.a, 1e-5);
        outColor = vec4(average * (1.0 - dot(T, vec3(1.0 / 3.0))), 1.0);
        outTransmit = vec4(T, 1.0);
        return;
    }
    vec3 colour = vec3(0.0), T = vec3(1.0);
    for (int i = 0; i < uLayers; ++i) {
        colour += T * texelFetch(uLayerColour, ivec3(p, i), 0).rgb;
        T *= texelFetch(uLayerTransmit, ivec3(p, i), 0).rgb;
    }
    if (uMode == 2) {
        vec3 back = vec3(0.0), backT = vec3(1.0);
        for (int i = 0; i < uLayers; ++i) {  // i = 0 is the farthest layer
            vec3 t = texelFetch(uBackTransmit, ivec3(p, i), 0).rgb;
            back = back * t + texelFetch(uBackColour, ivec3(p, i), 0).rgb;
            backT *= t;
        }
        colour += T * back;
        T *= backT;
    }
    outColor = vec4(colour, 1.0);
    outTransmit = vec4(T, 1.0);
}
