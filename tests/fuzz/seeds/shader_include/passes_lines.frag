#version 450 core
in vec3 vColor;
layout(location = 0) out vec4 fragColor;
void main() { fragColor = vec4(vColor * 4.0, 1.0); }  // HDR target: bright enough to read after tone mapping
