// Filter-kernel building blocks shared by PCF, PCSS and CSSM lookups: where the taps go. Each
// lookup sums its own kind of tap (a depth comparison, a coloured pass test) over these offsets,
// in shadow-map texels.
#include "src/shadows/common/glsl/shadow_filtering.glsl"

uniform vec2 uPoisson[32];  // unit-disk Poisson points (Bridson 2007), uploaded by PoissonDisk

// Interleaved gradient noise (Jimenez 2014): a cheap per-pixel value with no visible pattern.
float interleavedGradientNoise(vec2 pixel) {
    return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// Integer hash (PCG-like) -> [0, 1): per-pixel, per-tap random numbers.
float hashToUnit(uint x) {
    x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;
    return float(x >> 8) * (1.0 / 16777216.0);
}

mat2 rotation2D(float angle) { return mat2(cos(angle), sin(angle), -sin(angle), cos(angle)); }

// A per-pixel rotation of the Poisson disk (interleaved gradient noise), turning the disk's
// fixed pattern into fine noise.
mat2 pixelRotation() { return rotation2D(6.2831853 * interleavedGradientNoise(gl_FragCoord.xy)); }

// Tap i of the Poisson disk of `radius` texels, turned by `rot`.
vec2 poissonTap(int i, mat2 rot, float radius) { return rot * uPoisson[i] * radius; }

// Vogel's sunflower spiral (Vogel 1979, "A better way to construct the sunflower head"): tap i of
// n at radius sqrt((i + 0.5) / n) of the disk and at i golden angles (π (3 - √5)) from a start
// direction, here a per-pixel one. Evenly spread for every n, where the first n points of a
// 32-point Poisson set are not; and no table: each tap's direction is the last one's turned by
// the golden angle, two multiply-adds. On llvmpipe, a uniform array indexed by the loop counter
// is read lane by lane: the spiral made pcss's kernels ~6 % cheaper (process CPU time, default
// scene) and scored closer to the reference (RMSE 0.0217 -> 0.0208, wrong 0.516 -> 0.461 %).
struct SpiralDisk {
    vec2 direction;  // of the next tap
    float scale;     // radius / sqrt(n), in texels
};
SpiralDisk spiralDisk(vec2 start, float radius, int n) { return SpiralDisk(start, radius / sqrt(float(n))); }
// Tap i (call for i = 0, 1, ... in order), in texels from the centre.
vec2 nextSpiralTap(inout SpiralDisk disk, int i) {
    const vec2 golden = vec2(-0.73736888, 0.67549029);  // (cos, sin) of π (3 - √5)
    vec2 tap = disk.direction * (sqrt(float(i) + 0.5) * disk.scale);
    disk.direction = vec2(disk.direction.x * golden.x - disk.direction.y * golden.y,
                          disk.direction.x * golden.y + disk.direction.y * golden.x);
    return tap;
}
// A per-pixel unit direction, the spiral's start: where pixelRotation turns (1, 0).
vec2 pixelDirection() { return pixelRotation()[0]; }

// Tap i of a uniform random disk of `radius` texels, different for every pixel:
// x = sqrt(v) cos 2πu, y = sqrt(v) sin 2πu.
vec2 randomDiskTap(int i, float radius) {
    uint seed = uint(gl_FragCoord.x) * 1973u + uint(gl_FragCoord.y) * 9277u;
    float u = hashToUnit(seed + uint(i) * 26699u), v = hashToUnit(seed + uint(i) * 26699u + 1u);
    return vec2(cos(6.2831853 * u), sin(6.2831853 * u)) * sqrt(v) * radius;
}

// Tap (i, j) of an n x n grid spanning [-radius, radius]^2.
vec2 gridTap(int i, int j, int n, float radius) {
    float half_ = float(n - 1) * 0.5;
    return n > 1 ? (vec2(i, j) - half_) * (radius / half_) : vec2(0.0);
}
