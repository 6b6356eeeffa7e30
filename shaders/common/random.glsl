// Per-fragment random numbers for stochastic shadow maps (Mátl 2013 §5.1: speed and artifacts
// depend on the generator). Seeded by the fragment's light-space position *and depth*, so that
// stacked layers decorrelate and the result does not depend on draw order, plus a per-frame value.
//   kRandomPcg: PCG-style integer hash (Jarzynski & Olano 2020's recommendation for GPU hashing)
//   kRandomSinFract: the classic fract(sin(dot(p, k)) * 43758.5453): cheap, but float precision makes it
//      repeat and band for large arguments
#include "src/gpu/ShaderContract.h"
#include "hash.glsl"

uniform int uRandomGenerator;  // kRandom*
uniform int uFrameSeed;  // frame counter (non-negative)

// Uniform in [0, 1), `stream` selects an independent sequence (e.g. one per colour channel).
float fragmentRandom(uint stream) {
    uvec3 p = uvec3(gl_FragCoord.xy, floatBitsToUint(gl_FragCoord.z));
    if (uRandomGenerator == kRandomSinFract) {
        vec3 q = vec3(gl_FragCoord.xy, gl_FragCoord.z * 4096.0) + float(stream) * 17.0 + float(uFrameSeed % 1024) * 0.37;
        float x = dot(q, vec3(12.9898, 78.233, 37.719));
        // Reduced to [0, 2pi) first: a GPU's sine unit loses precision far from 0 (on an H100,
        // sin of x ~ 1e5 moved the mean of xi so far that black nylon read 0.786 instead of 0.75).
        return fract(sin(x - 6.2831853 * floor(x * 0.15915494)) * 43758.5453);
    }
    uint h = pcgHash(p.x ^ pcgHash(p.y ^ pcgHash(p.z ^ pcgHash(stream ^ pcgHash(uint(uFrameSeed))))));
    return float(h >> 8) * (1.0 / 16777216.0);
}
