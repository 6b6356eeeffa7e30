#version 450 core
// DepthAndTintMaps::TintAlpha::FarthestAround, after the tint pass: the least drawn alpha (1 - the
// farthest translucent layer's depth, transmit.frag's second output) over each texel's 3 x 3
// neighbourhood, into the tint map's alpha (blending keeps its rgb). Each 2 x 2 footprint of a
// bilinear fetch lies inside the neighbourhood of every texel it blends, so the fetched alpha is
// at most the least of those four: a conservative "behind every layer there" test in one fetch.
// Map edges clamp, as the lookup's sampler does. Cube faces: a fetch near a face's edge blends the next
// face's texels, which this face cannot see, so edge texels near a layer of this face get 0 ("a
// layer may be in front"), and the lookup counts texels there instead. (Only near a layer: the
// bound is then a function of the drawn alpha alone, the same however much of the tint was
// redrawn, and texels far from every layer keep the white of "no layer".)
layout(binding = 0) uniform sampler2D uDrawn;  // the drawn alpha of one face
uniform int uCubeFace;
layout(location = 0) out vec4 outBound;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec2 size = vec2(textureSize(uDrawn, 0));
    // Four gathers at the corners around texel p read its 3 x 3 neighbourhood (clamped at the
    // map's edges, as the lookup's sampler is): 4 fetches where texel by texel took 9.
    vec4 bounds = min(min(textureGather(uDrawn, vec2(p) / size, 0), textureGather(uDrawn, vec2(p + ivec2(1, 0)) / size, 0)),
                      min(textureGather(uDrawn, vec2(p + ivec2(0, 1)) / size, 0), textureGather(uDrawn, vec2(p + ivec2(1)) / size, 0)));
    float bound = min(min(bounds.x, bounds.y), min(bounds.z, bounds.w));
    ivec2 last = textureSize(uDrawn, 0) - 1;
    bool edge = any(equal(p, ivec2(0))) || any(equal(p, last));
    outBound = vec4(0.0, 0.0, 0.0, uCubeFace != 0 && edge && bound < 1.0 ? 0.0 : bound);
}
