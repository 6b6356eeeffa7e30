#version 450 core
// The still casters' depth copied back into a layer of a layered shadow map (LayeredDepthMap),
// texel for texel, by a draw rather than glCopyImageSubData: llvmpipe runs a copy on the calling
// thread after waiting for every queued draw that touches either texture, a stall in the middle
// of the shadow pass where a draw is queued as any other.
layout(binding = 0) uniform sampler2DArray uStill;
uniform int uLayer;
void main() { gl_FragDepth = texelFetch(uStill, ivec3(ivec2(gl_FragCoord.xy), uLayer), 0).r; }
