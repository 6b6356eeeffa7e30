#version 450 core
// The floor's depth-only raster: position in, clip position out, nothing else to set up.
layout(location = 0) in vec3 aPosition;

uniform mat4 uModel;
uniform mat4 uViewProj;

void main() { gl_Position = uViewProj * (uModel * vec4(aPosition, 1.0)); }
