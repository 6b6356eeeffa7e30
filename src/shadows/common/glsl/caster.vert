#version 450 core
// Shadow casters seen from a light (depth and transmittance passes).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

uniform mat4 uModel;
uniform mat4 uLightViewProj;

out vec2 vUv;

void main() {
    vUv = aUv;
    gl_Position = uLightViewProj * uModel * vec4(aPosition, 1.0);
}
