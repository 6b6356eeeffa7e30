#version 450 core
// DepthAndTintMaps::TintAlpha::FarthestAround, step 2: farthest_around.frag's bound into the
// tint map's alpha (MIN-blended there, rgb kept; the bound never exceeds the texel's own alpha).
layout(binding = 0) uniform sampler2D uAround;
layout(location = 0) out vec4 outAlpha;
void main() { outAlpha = vec4(1.0, 1.0, 1.0, texelFetch(uAround, ivec2(gl_FragCoord.xy), 0).r); }
