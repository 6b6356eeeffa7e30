// Per-light data (std140 uniform block, binding 0), mirrored by render/LightBlock.h.
#include "bindings.glsl"

#define LIGHT_DIRECTIONAL 0
#define LIGHT_SPOT 1
#define LIGHT_POINT 2
#define LIGHT_PROJECTOR 3

struct LightData {
    mat4 shadowMatrix;   // world -> shadow texture space [0,1]^3 (directional, spot, projector)
    vec4 colorType;      // rgb: radiance (colour * intensity); w: LIGHT_*
    vec4 positionNear;   // xyz: position; w: shadow near plane
    vec4 directionFar;   // xyz: direction light travels; w: shadow far plane
    vec4 cone;           // x: cos(outer half-angle); y: cos(inner); z: projector slot; w: shadow slot (-1: none)
    vec4 shadow;         // x: bias, y: slope bias, z: normal offset (all in shadow texels); w: texel scale
    vec4 misc;           // x: 1 if perspective; y: resolution; z: light size (world units)
};

layout(std140, binding = 0) uniform LightBlock {
    ivec4 uLightCount;   // x: number of lights
    LightData uLights[MAX_LIGHTS];
};

int lightType(int i) { return int(uLights[i].colorType.w); }
