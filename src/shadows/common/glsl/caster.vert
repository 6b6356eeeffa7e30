#version 450 core
// Shadow casters seen from a light (depth and transmittance passes).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

// The camera depth pre-pass (caster.vert) and the lighting pass (lighting.vert) must put every
// vertex at the same depth, bit for bit (Renderer::drawDepthFirst).
invariant gl_Position;

uniform mat4 uModel;
uniform mat4 uLightViewProj;
// World half-space kept when GL_CLIP_DISTANCE0 is on (dot(plane, P) >= 0): warped maps (PSM,
// LiSPSM) must not see geometry behind their projection centre, which would wrap around through
// infinity. Ignored while the clip distance is disabled.
uniform vec4 uClipPlane = vec4(0.0, 0.0, 0.0, 1.0);

out vec2 vUv;
#ifdef CASTER_OBJECT_HASH
// A hash of the caster's placement, the same for every vertex of a draw: CSSM's stratified ξ
// (cssm/caster.frag) keys its layers by it. Hashed here, once per vertex, rather than in every
// fragment (measured, glass scene: the four hashes were ~1/4 of the ξ's cost).
#include "shaders/common/hash.glsl"
flat out uint vObject;
#endif

void main() {
    vUv = aUv;
#ifdef CASTER_OBJECT_HASH
    uvec4 placement = floatBitsToUint(uModel[3]) ^ floatBitsToUint(uModel[0]) ^ floatBitsToUint(uModel[1]);
    vObject = pcgHash(placement.x ^ pcgHash(placement.y ^ pcgHash(placement.z ^ pcgHash(floatBitsToUint(uModel[2].x)))));
#endif
    vec4 world = uModel * vec4(aPosition, 1.0);
    gl_ClipDistance[0] = dot(uClipPlane, world);
    gl_Position = uLightViewProj * world;
}
