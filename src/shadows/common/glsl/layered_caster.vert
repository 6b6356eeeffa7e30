#version 450 core
// Casters into every layer of a LayeredDepthMap at once: the geometry shader instances each triangle per layer.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
uniform mat4 uModel;
out vec2 vsUv;
void main() {
    vsUv = aUv;
    gl_Position = uModel * vec4(aPosition, 1.0);  // world space; projected per layer
}
