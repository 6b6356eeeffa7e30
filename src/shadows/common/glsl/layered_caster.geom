#version 450 core
// Layered rendering: one invocation per layer (cascade, tile) writes gl_Layer; triangles wholly
// outside a layer's x/y range are culled here (casters culled per layer). Depth is not culled:
// casters in front of a layer's box still shadow it. Each layer may also clip away a world
// half-space (uLayerClip, kept where dot(plane, P) >= 0): warped maps (PSM, LiSPSM) must not see
// geometry behind their projection centre, which would wrap around through infinity.
layout(triangles, invocations = 16) in;
layout(triangle_strip, max_vertices = 3) out;
uniform mat4 uLayerViewProj[16];
uniform vec4 uLayerClip[16];
uniform int uLayerCount;
in vec2 vsUv[];
out vec2 vUv;
void main() {
    int layer = gl_InvocationID;
    if (layer >= uLayerCount) return;
    vec4 p[3];
    for (int i = 0; i < 3; ++i) p[i] = uLayerViewProj[layer] * gl_in[i].gl_Position;
    for (int axis = 0; axis < 2; ++axis) {
        if (p[0][axis] > p[0].w && p[1][axis] > p[1].w && p[2][axis] > p[2].w) return;
        if (p[0][axis] < -p[0].w && p[1][axis] < -p[1].w && p[2][axis] < -p[2].w) return;
    }
    for (int i = 0; i < 3; ++i) {
        gl_Layer = layer;
        gl_Position = p[i];
        gl_ClipDistance[0] = dot(uLayerClip[layer], gl_in[i].gl_Position);
        vUv = vsUv[i];
        EmitVertex();
    }
    EndPrimitive();
}
