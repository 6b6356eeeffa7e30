#version 450 core
// Sample distribution shadow maps' reduction (Lauritzen, Salvi & Lefohn 2011, §4.1): the nearest
// and farthest depth the camera's pre-pass covered, reduced on the GPU so that the CPU reads two
// words instead of the whole depth image. Window depths lie in [0, 1], where a float's bits order
// as the float does, so uint atomics take the min and max exactly.
// Each invocation scans a kBlock x kBlock block of texels in registers, and a group of 8 x 8 covers
// 128 x 128 texels with 64 shared atomics: llvmpipe runs a group's invocations in turns, and on it
// one invocation per texel took 1.4-2.1 ms for a 640 x 360 pre-pass, blocks of 8 x 8 texels 0.94,
// of 16 x 16 0.76, against 0.85 for reading the image back and scanning it on the CPU.
layout(local_size_x = 8, local_size_y = 8) in;
const int kBlock = 16;

layout(binding = 0) uniform sampler2D uDepth;  // the pre-pass's depth, compare mode off
layout(std430, binding = 0) buffer Bounds {
    uint nearestBits;   // cleared to the bits of 1.0
    uint farthestBits;  // cleared to 0
};

shared uint sNearest, sFarthest;

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        sNearest = floatBitsToUint(1.0);
        sFarthest = 0u;
    }
    barrier();
    ivec2 size = textureSize(uDepth, 0);
    ivec2 first = ivec2(gl_GlobalInvocationID.xy) * kBlock;
    uint nearest = floatBitsToUint(1.0), farthest = 0u;
    for (int y = 0; y < kBlock; ++y)
        for (int x = 0; x < kBlock; ++x) {
            ivec2 p = first + ivec2(x, y);
            if (any(greaterThanEqual(p, size))) continue;
            float d = texelFetch(uDepth, p, 0).r;
            if (d < 1.0) {  // 1.0: the cleared far plane, nothing drawn
                uint bits = floatBitsToUint(abs(d));  // abs: -0.0 would order after every positive depth
                nearest = min(nearest, bits);
                farthest = max(farthest, bits);
            }
        }
    if (nearest <= farthest) {
        atomicMin(sNearest, nearest);
        atomicMax(sFarthest, farthest);
    }
    barrier();
    // One global atomic per group, not per texel.
    if (gl_LocalInvocationIndex == 0u && sNearest <= sFarthest) {
        atomicMin(nearestBits, sNearest);
        atomicMax(farthestBits, sFarthest);
    }
}
