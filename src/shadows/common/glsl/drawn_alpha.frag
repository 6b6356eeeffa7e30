#version 450 core
// DepthAndTintMaps::TintAlpha::FarthestAround, step 1: the alpha the tint pass drew (1 - the
// farthest translucent layer's depth) into a map of its own, where farthest_around.frag reads
// it. Kept across frames: a redraw of part of the tint bounds the texels around that part again
// from the drawn alpha of their neighbours, redrawn or not.
layout(binding = 0) uniform sampler2D uTint;  // one face of the tint map
layout(location = 0) out float outDrawn;
void main() { outDrawn = texelFetch(uTint, ivec2(gl_FragCoord.xy), 0).a; }
