#version 450 core
// Shadow volume of one triangle with its neighbours (Crow 1977): for a triangle facing the
// light, a side quad on every silhouette edge (the neighbour faces away, or there is none),
// extruded to infinity (w = 0), and for z-fail the caps: the triangle itself (light cap) and its
// projection to infinity (dark cap). Faces point out of the volume (counter-clockwise from
// outside), which is what the stencil's front/back operations count.
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 18) out;
uniform mat4 uViewProj;
uniform vec4 uLight;  // xyz position, w = 1; or the direction light travels, w = 0
uniform int uCaps;    // 1: emit light and dark caps (z-fail)
uniform float uExtrusion;  // beyond the scene's far side; 0: to infinity (w = 0)

vec3 awayFromLight(vec3 p) { return uLight.w > 0.5 ? p - uLight.xyz : uLight.xyz; }

// A vertex pushed away from the light. At infinity (w = 0) is the textbook form, but clipping
// triangles that reach infinity costs the rasteriser enough precision that the volume's sides
// land up to a pixel off where they cut a receiver; a finite extrusion past every receiver
// (depth clamp keeps it from the far plane) is exact.
vec4 extruded(vec3 p) {
    vec3 d = awayFromLight(p);
    return uExtrusion > 0.0 ? vec4(p + normalize(d) * uExtrusion, 1.0) : vec4(d, 0.0);
}

bool facesLight(vec3 a, vec3 b, vec3 c) { return dot(cross(b - a, c - a), -awayFromLight(a)) > 0.0; }

void emit(vec4 worldOrDirection) { gl_Position = uViewProj * worldOrDirection; EmitVertex(); }

// The light cap lies on the caster's own lit surface: nudged a little deeper (in window depth)
// it fails the depth test there, as the dark cap does, and the two cancel. Sides are not nudged,
// so the shadow's edge on a receiver stays exact.
void emitCap(vec3 world) {
    gl_Position = uViewProj * vec4(world, 1.0);
    gl_Position.z += 2e-5 * gl_Position.w;
    EmitVertex();
}

void main() {
    vec3 v[6];
    for (int i = 0; i < 6; ++i) v[i] = gl_in[i].gl_Position.xyz;
    if (!facesLight(v[0], v[2], v[4])) return;
    for (int e = 0; e < 6; e += 2) {
        vec3 a = v[e], b = v[(e + 2) % 6], neighbour = v[e + 1];
        if (facesLight(a, neighbour, b)) continue;  // shared with a lit neighbour: not a silhouette
        emit(vec4(a, 1.0));
        emit(extruded(a));
        emit(vec4(b, 1.0));
        emit(extruded(b));
        EndPrimitive();
    }
    if (uCaps == 0) return;
    emitCap(v[0]);
    emitCap(v[2]);
    emitCap(v[4]);
    EndPrimitive();
    emit(extruded(v[0]));
    emit(extruded(v[4]));
    emit(extruded(v[2]));
    EndPrimitive();
}
