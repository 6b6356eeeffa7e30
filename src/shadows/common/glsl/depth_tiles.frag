#version 450 core
// Level 0 of DepthTileBounds, one tile: over the tile's texels and kDepthTileBorder more on every side
// (clamped to the map as a tap's lookup is, at the unclamped texel's position), a plane under
// every depth, d >= g . c + a with c the texel's centre relative to the tile's corner, and the
// farthest depth. g is the tile's slope across its middle row and column: any g gives a true
// bound (a is the minimum for that g); the right one, on a plane, gives a tight one.
// kDepthTile + 2 kDepthTileBorder must be even: the texels are read 2 x 2 at a time.
#include "src/gpu/ShaderContract.h"
layout(binding = 0) uniform sampler2D uDepth;  // raw depth: a sampler without comparison
layout(location = 0) out vec4 outBounds;       // (a, g.x, g.y, farthest)

float depthAt(ivec2 texel) { return texelFetch(uDepth, clamp(texel, ivec2(0), textureSize(uDepth, 0) - 1), 0).r; }

void main() {
    ivec2 corner = kDepthTile * ivec2(gl_FragCoord.xy);
    const int middle = kDepthTile / 2, last = kDepthTile - 1;
    vec2 g = vec2(depthAt(corner + ivec2(last, middle)) - depthAt(corner + ivec2(0, middle)),
                  depthAt(corner + ivec2(middle, last)) - depthAt(corner + ivec2(middle, 0))) / float(last);
    float a = 2.0, farthest = 0.0;  // depths lie in [0, 1]
    // 2 x 2 texels per gather (half the cost per texel of texelFetch on llvmpipe): texels (x, y)
    // to (x + 1, y + 1) from the tile's corner, in textureGather's order, centres at c + the offsets.
    vec4 around = 0.5 * vec4(g.y - g.x, g.x + g.y, g.x - g.y, -g.x - g.y);
    vec2 size = vec2(textureSize(uDepth, 0));
    for (int y = -kDepthTileBorder; y < kDepthTile + kDepthTileBorder; y += 2)
        for (int x = -kDepthTileBorder; x < kDepthTile + kDepthTileBorder; x += 2) {
            vec2 c = vec2(x, y) + 1.0;  // the point between the 4 texels' centres
            vec4 d = textureGather(uDepth, (vec2(corner) + c) / size, 0);
            vec4 below = d - (dot(g, c) + around);
            a = min(a, min(min(below.x, below.y), min(below.z, below.w)));
            farthest = max(farthest, max(max(d.x, d.y), max(d.z, d.w)));
        }
    outBounds = vec4(a, g, farthest);
}
