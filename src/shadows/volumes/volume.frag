#version 450 core
// Shadow volumes only count in the stencil buffer.
void main() {}
