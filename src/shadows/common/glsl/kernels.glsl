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
