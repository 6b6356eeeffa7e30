#version 450 core
// Shadow volume of one triangle with its neighbours (Crow 1977): for a triangle facing the
// light, a side quad on every silhouette edge (the neighbour faces away, or there is none),
// extruded away from the light, and for z-fail the caps: the triangle itself (light cap) and its
// projection (dark cap). Faces point out of the volume (counter-clockwise from outside), which
// is what the stencil's front/back operations count.
//
// Open, non-manifold or inconsistently wound meshes (uBothSides = 1): every triangle casts, a
// triangle facing away taken reversed, as the ray tracer sees a surface from either side. Each
// triangle's volume is then closed on its own, and the stencil count is how many of them hold
// the pixel: non-zero is shadow. A side two neighbours share is left out only where their
// volumes' sides there cancel (they run the edge opposite ways once turned to the light), the
// way Stich, Wächter and Keller handle non-closed models (GPU Gems 3, ch. 11, "multiplicity").
#include "src/shadows/volumes/volume_clip.glsl"
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 18) out;
// What VolumeCache captures by transform feedback (in world space, each strip as triangles) to
// draw again through later frames' cameras with volume_kept.vert.
layout(xfb_buffer = 0, xfb_offset = 0) out vec4 gWorld;
layout(xfb_buffer = 0, xfb_offset = 16) out float gNudge;
in int vIndex[];
uniform int uBothSides;
uniform mat4 uViewProj;
uniform vec4 uLight;  // xyz position, w = 1; or the direction light travels, w = 0
uniform int uEmit;    // bit 0: the sides; bit 1: light and dark caps (z-fail, or a capture of caps alone)
uniform float uExtrusion;  // beyond the scene's far side; 0: to infinity (w = 0)
uniform vec4 uFarPlane;  // the plane (n, w) the volume ends on, past every receiver (VolumeExtent); n = 0: none

vec3 awayFromLight(vec3 p) { return uLight.w > 0.5 ? p - uLight.xyz : uLight.xyz; }

// A vertex pushed away from the light. At infinity (w = 0) is the textbook form, but clipping
// triangles that reach infinity costs the rasteriser enough precision that the volume's sides
// land up to a pixel off where they cut a receiver; a finite extrusion past every receiver
// (depth clamp keeps it from the far plane) is exact.
vec4 extruded(vec3 p) {
    vec3 d = awayFromLight(p);
    if (uExtrusion <= 0.0) return vec4(d, 0.0);
    // The volume ends on a plane past every receiver its caster shadows, so the dark cap, flat on
    // it, stays out of the scene. Every ray from the caster crosses it outwards (along > 0).
    float along = dot(uFarPlane.xyz, d);
    if (along > 0.0) return vec4(p + d * max((uFarPlane.w - dot(uFarPlane.xyz, p)) / along, 0.0), 1.0);
    return vec4(p + normalize(d) * uExtrusion, 1.0);
}

vec3 v[6];

// Twice the area corners (i, j, k) of v[] show the light, signed: > 0 when (i, j, k) winds
// counter-clockwise seen from the light. Taken with the corners in vertex-index order and the
// permutation's sign applied, so every invocation that meets the same three corners (the
// triangle's own, and its neighbour's on a shared edge) gets the same number to the bit, with
// `precise` keeping the compiler from contracting it differently at each call. Invocations that
// disagreed about a nearly edge-on triangle would leave a side without its twin: a streak. (On
// llvmpipe, street.json and construction.json score the same without the ordering; it is a
// guard for drivers that round or fuse differently per call site.)
float facing(int i, int j, int k) {
    bool odd = false;
    if (vIndex[i] > vIndex[j]) { int t = i; i = j; j = t; odd = !odd; }
    if (vIndex[j] > vIndex[k]) { int t = j; j = k; k = t; odd = !odd; }
    if (vIndex[i] > vIndex[j]) { int t = i; i = j; j = t; odd = !odd; }
    precise float f = dot(cross(v[j] - v[i], v[k] - v[i]), -awayFromLight(v[i]));
    return odd ? -f : f;
}

void emitNudged(vec4 worldOrDirection, float nudge) {
    gWorld = worldOrDirection;
    gNudge = nudge;
    gl_Position = volumeClip(uViewProj, worldOrDirection, nudge);
    EmitVertex();
}
void emit(vec4 worldOrDirection) { emitNudged(worldOrDirection, 0.0); }
void emitCap(vec3 world) { emitNudged(vec4(world, 1.0), 1.0); }  // the light cap (volume_clip.glsl)

void main() {
    for (int i = 0; i < 6; ++i) v[i] = gl_in[i].gl_Position.xyz;
    const float own = facing(0, 2, 4);
    if (own == 0.0 || (uBothSides == 0 && own < 0.0)) return;  // edge-on, welded flat, or (closed mesh) facing away
    const bool reversed = own < 0.0;
    for (int e = 0; e < 6 && (uEmit & 1) != 0; e += 2) {
        const int a = e, b = (e + 2) % 6;
        // The neighbour, wound (a, n, b) as a consistent mesh winds it: facing the light the
        // same way as this triangle, the two volumes' sides on this edge run opposite ways and
        // cancel. A border's "neighbour" is this triangle reversed, which never cancels.
        const float neighbour = facing(a, e + 1, b);
        if ((neighbour > 0.0 && own > 0.0) || (neighbour < 0.0 && own < 0.0)) continue;
        const int from = reversed ? b : a, to = reversed ? a : b;
        emit(vec4(v[from], 1.0));
        emit(extruded(v[from]));
        emit(vec4(v[to], 1.0));
        emit(extruded(v[to]));
        EndPrimitive();
    }
    if ((uEmit & 2) == 0) return;
    const int second = reversed ? 4 : 2, third = reversed ? 2 : 4;
    emitCap(v[0]);
    emitCap(v[second]);
    emitCap(v[third]);
    EndPrimitive();
    emit(extruded(v[0]));
    emit(extruded(v[third]));
    emit(extruded(v[second]));
    EndPrimitive();
}
