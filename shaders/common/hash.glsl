// The PCG-style integer hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering": their
// recommendation, pcg). Shared by the per-fragment random numbers (random.glsl) and the casters'
// placement hash (caster.vert), which cssm/caster.frag's stratified ξ keys its layers by.
uint pcgHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
