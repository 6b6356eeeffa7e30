#version 450 core
// Level k > 0 of DepthTileBounds from level k - 1: a tile's texels and border are those of the
// 4 x 4 finer tiles around its 2 x 2 (each with its own border), so over each of them
// d >= g_c . (x - o_c) + a_c, and the tile's plane g (the mean of its 2 x 2 children's) lies
// under that by the minimum of (g_c - g) . (x - o) over the child's box of texel centres.
// A tile whose neighbourhood leaves the map gets bounds that never agree (a lookup there runs its
// kernel): past the map the taps read clamped texels no finer tile holds.
#include "src/gpu/ShaderContract.h"
layout(binding = 0) uniform sampler2D uFiner;  // a view of level k - 1 alone: no feedback loop
uniform int uLevel;                            // k
uniform int uFinerTiles;                       // tiles across the map at level k - 1
layout(location = 0) out vec4 outBounds;       // (a, g.x, g.y, farthest)

void main() {
    ivec2 tile = ivec2(gl_FragCoord.xy);
    float finerSide = float(kDepthTile << (uLevel - 1)), finerBorder = finerSide - float(kDepthTileInset);
    ivec2 first = 2 * tile - 1;
    if (any(lessThan(first, ivec2(0))) || any(greaterThan(first + 3, ivec2(uFinerTiles - 1)))) {
        outBounds = vec4(-4.0, 0.0, 0.0, 1.0);
        return;
    }
    vec2 g = vec2(0.0);
    for (int y = 1; y <= 2; ++y)
        for (int x = 1; x <= 2; ++x) g += 0.25 * texelFetch(uFiner, first + ivec2(x, y), 0).yz;
    float a = 2.0, farthest = 0.0;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            vec4 child = texelFetch(uFiner, first + ivec2(x, y), 0);
            // The child's corner and box of texel centres, relative to this tile's corner.
            vec2 corner = vec2(x - 1, y - 1) * finerSide;
            vec2 mid = corner + 0.5 * finerSide, half_ = vec2(0.5 * finerSide + finerBorder - 0.5);
            vec2 dg = child.yz - g;
            // g_c . (x - o_c) + a_c - g . (x - o) = dg . (x - o) + a_c - g_c . corner
            float under = child.x - dot(child.yz, corner) + dot(dg, mid) - dot(abs(dg), half_);
            a = min(a, under);
            farthest = max(farthest, child.w);
        }
    outBounds = vec4(a, g, farthest);
}
