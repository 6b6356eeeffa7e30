#version 450 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;

// The camera depth pre-pass (caster.vert) and the lighting pass (lighting.vert) must put every
// vertex at the same depth, bit for bit (Renderer::drawDepthFirst).
invariant gl_Position;

uniform mat4 uModel;
uniform mat4 uViewProj;

out VertexOut {
    vec3 worldPos;
    vec3 normal;
    vec2 uv;
} vOut;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vOut.worldPos = world.xyz;
    vOut.normal = transpose(inverse(mat3(uModel))) * aNormal;
    vOut.uv = aUv;
    gl_Position = uViewProj * world;
}
