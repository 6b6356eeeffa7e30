#version 450 core
// Casters flattened onto the receiver plane along the light's rays (Blinn 1988).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
uniform mat4 uModel;
uniform mat4 uViewProj;
uniform mat4 uFlatten;  // PlanarFit.h: M = (P·L) I - L Pᵀ
uniform vec4 uPlane;    // receiver plane, the light on its positive side
uniform vec4 uLight;    // homogeneous light
uniform int uNaive;     // 1: divide by w before projecting (casters behind the light then cast)
out vec2 vUv;
out float vAbovePlane;  // caster's height over the plane
out float vBelowLight;  // light's height minus the caster's (point lights), > 0 between them
void main() {
    vUv = aUv;
    vec4 world = uModel * vec4(aPosition, 1.0);
    vAbovePlane = dot(uPlane, world);
    vBelowLight = uLight.w > 0.5 ? dot(uPlane, uLight) - vAbovePlane : 1.0;
    vec4 flattened = uFlatten * world;
    if (uNaive != 0) flattened /= flattened.w;
    gl_Position = uViewProj * flattened;
}
