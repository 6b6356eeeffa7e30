#version 450 core
// DepthAndTintMaps::TintAlpha::FarthestAround, step 1: the least tint alpha (1 - the farthest
// translucent layer's depth) over each texel's 3 x 3 neighbourhood. Each 2 x 2 footprint of a
// bilinear fetch lies inside the neighbourhood of every texel it blends, so the fetched alpha is
// at most the least of those four: a conservative "behind every layer there" test in one fetch.
// Map edges clamp, as the lookup's sampler does. Cube faces: a fetch near a face's edge blends the next
// face's texels, which this face cannot see, so edge texels get 0 ("a layer may be in front"),
// and the lookup counts texels there instead.
layout(binding = 0) uniform sampler2D uTint;  // one face of the tint map
uniform int uCubeFace;
layout(location = 0) out float outBound;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 size = vec2(textureSize(uTint, 0));
    // Four gathers at the corners around texel p read its 3 x 3 neighbourhood (clamped at the
    // map's edges, as the lookup's sampler is): 4 fetches where texel by texel took 9.
    vec4 bounds = min(min(textureGather(uTint, vec2(p) / size, 3), textureGather(uTint, vec2(p + ivec2(1, 0)) / size, 3)),
                      min(textureGather(uTint, vec2(p + ivec2(0, 1)) / size, 3), textureGather(uTint, vec2(p + ivec2(1)) / size, 3)));
    float bound = min(min(bounds.x, bounds.y), min(bounds.z, bounds.w));
    ivec2 last = textureSize(uTint, 0) - 1;
    bool edge = any(equal(p, ivec2(0))) || any(equal(p, last));
    outBound = uCubeFace != 0 && edge ? 0.0 : bound;
}
