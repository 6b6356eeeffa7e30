#version 450 core
// Layered rendering: one invocation per cascade writes gl_Layer; triangles wholly outside a
// cascade's box are culled here (casters culled per cascade).
layout(triangles, invocations = 8) in;
layout(triangle_strip, max_vertices = 3) out;
uniform mat4 uCascadeViewProj[8];
uniform int uCascadeCount;
in vec2 vsUv[];
out vec2 vUv;
void main() {
    if (gl_InvocationID >= uCascadeCount) return;
    vec4 p[3];
    for (int i = 0; i < 3; ++i) p[i] = uCascadeViewProj[gl_InvocationID] * gl_in[i].gl_Position;
    // Outside when all three vertices lie beyond the same side of the box (x, y); depth is not
    // culled, casters in front of the box still shadow it.
    for (int axis = 0; axis < 2; ++axis) {
        if (p[0][axis] > p[0].w && p[1][axis] > p[1].w && p[2][axis] > p[2].w) return;
        if (p[0][axis] < -p[0].w && p[1][axis] < -p[1].w && p[2][axis] < -p[2].w) return;
    }
    for (int i = 0; i < 3; ++i) {
        gl_Layer = gl_InvocationID;
        gl_Position = p[i];
        vUv = vsUv[i];
        EmitVertex();
    }
    EndPrimitive();
}
