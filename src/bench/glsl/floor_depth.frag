#version 450 core
// Bare depth-only raster: no outputs, no samplers (declaring one slows llvmpipe's draw submission).
void main() {}
