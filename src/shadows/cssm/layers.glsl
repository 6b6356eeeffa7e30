// What a texel of a coloured stochastic shadow map says about its layers (tiles.frag,
// nearest_layer.frag): alpha holds the nearest translucent layer's depth, each channel the
// nearest depth written for it (1: none), under MIN blending.

// Per channel: 1 where a layer behind the nearest one wrote λ. A channel the nearest layer wrote
// holds exactly its depth, alpha.
vec3 writtenBehind(vec4 texel) {
    return vec3(lessThan(texel.rgb, vec3(1.0))) * vec3(notEqual(texel.rgb, vec3(texel.a)));
}
