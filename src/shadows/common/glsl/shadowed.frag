#version 450 core
// Writes "shadowed" (0) into a screen shadow mask layer; the stencil test picks the pixels.
out vec4 fragColor;
void main() { fragColor = vec4(0.0); }
