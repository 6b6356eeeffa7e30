#pragma once
// Where the coloured shadow of a translucent caster can fall, so that the camera's opaque pass
// shades everything else with a lighting program that reads no tint at all (RECEIVER_UNTINTED:
// every tint fetch folds to white, and CSSM's coloured term with its fallback loop goes). llvmpipe
// runs a shader's every fetch and loop body for every pixel whatever a pixel decides, so only a
// program without the code spares its cost (issue 15: "no tint lookup where no translucent caster
// can reach"; issue 11: CSSM at the cost of the plain map).
//
// Per light and translucent caster, the footprint is the part of the receiver's box inside the
// caster's shadow volume: the prism (directional) or pyramid from the light (perspective) through
// the caster's box, padded by the texels a lookup reads around its own. A receiver drawn with few
// triangles is split on the screen: the footprints' rectangles with the full program, the rest
// with the untinted one (scissored draws, each pixel in exactly one rectangle), so that a big
// floor pays for coloured shadows only where they may fall.
#include "gpu/ShaderContract.h"
#include "scene/Mesh.h"

#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace penumbra::render {

// A caster's or receiver's box: its mesh bounds under its model matrix (a rotated pane's is far
// thinner than its world box), or a world box.
struct OrientedBox {
    using Corners = std::array<glm::vec3, 8>;  // in scene::Bounds::corner's order
    OrientedBox(const scene::Bounds& world);   // NOLINT: a world box is an oriented box
    OrientedBox(const scene::Bounds& local, const glm::mat4& model);
    Corners corners;
    bool empty = true;
};

// The quarters of `box` across its two longest sides under `model` (in the world).
std::array<scene::Bounds, 4> quarters(const scene::Bounds& box, const glm::mat4& model);

// What `cut` keeps of the world box `box`, cell by cell: quarters of quarters, `levels` deep (up
// to 4^levels cells), each finest cell's kept box passed to `emit`; a cell `cut` keeps nothing of
// is not divided further. Their union holds what `cut` keeps of `box`, far tighter than one box
// does where that is no box (a footprint along a caster's foot, a projector's trapezoid on a floor).
template <class Cut, class Emit>
void cellsOf(const Cut& cut, const scene::Bounds& box, int levels, Emit&& emit) {
    const scene::Bounds part = cut(OrientedBox(box));
    if (part.empty()) return;
    if (levels == 0) {
        emit(part);
        return;
    }
    for (const scene::Bounds& q : quarters(box, glm::mat4(1.0f))) cellsOf(cut, q, levels - 1, emit);
}

// The part of `receiver` (a world box, or a turned pane's own box) that light `light` may tint
// through a translucent caster inside `caster`: the world box of the receiver's points whose ray
// from the light passes
// within `padTexels` texels (of LightData::shadow.w; per unit distance for perspective lights) of
// the caster's box. Each face of the receiver's box is clipped by the volume's planes, so the box
// is exact up to the padding and conservative. Empty when the receiver lies off the caster's
// shadow. (Receivers between the light and the caster count as reached: a lookup may extrapolate
// the receiver's depth past its own.)
scene::Bounds tintFootprint(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver, float padTexels);

// The part of `receiver` that light `light` may shadow through any caster inside `caster`, opaque
// or translucent: tintFootprint's box. It holds the receiver's points whose ray from the light
// passes within `padTexels` texels of the caster's box, on either side of it, so it does not depend
// on how the lookup compares depths. Off every other caster's, a receiver's lookup reads the map
// where it holds the receiver itself or what lies behind it (Renderer's shadow reach).
inline scene::Bounds shadowFootprint(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver,
                                     float padTexels) {
    return tintFootprint(light, caster, receiver, padTexels);
}

// shadowFootprint for an opaque caster: the part of it that does not lie clearly in front of the
// caster's part above the receiver, as the light sees them (the cut of tintFootprintNotInFront,
// with SideTolerance::Surface: the normal offset may move a lookup away from the light). An opaque
// caster wholly behind a receiver's point puts nothing in front of it in the map. `depthReach`:
// how much deeper than its receiver's biased depth a lookup may compare, in window depth
// (ShadowTechnique::shadowReachDepth: the receiver-plane taps' clamp).
scene::Bounds opaqueShadowFootprint(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver, float padTexels,
                                    float depthReach);

// Whether a flat opaque caster in `plane` (world; unit normal, offset) leaves every point of
// `receiver` lit under a directional light: the receiver lies on the light's side of the plane by
// more than a lookup reaches. A point h above the plane (along its normal) sees the plane, s to its
// side across the light, at least (h - s sin t) / cos t deeper (t: the light's angle to the normal).
// The pad (world: pad texels of the light's plain map) holds the normal offset o, which may move
// the lookup towards the plane, and the taps' reach a across the light, along each axis of the map
// (s up to sqrt(2) a): h over o + sqrt(2) a sin t <= pad max(1, sqrt(2) sin t), plus the depth
// reach and the surface tolerance, keeps every compare on the lit side.
// Under a spot, projector or point light (its eye on one side of the plane), the receiver on the
// eye's side: a tap's ray passes a point at most s = 2 pad texels (z texelScale wide at view depth
// z) beside a receiver point, so at least h - s above the plane, and meets the plane no nearer than
// h - s further on, at least (h - s) cos a deeper in view depth (a: the ray's angle to the map's
// axis; cos a >= 1/sqrt(3) on a cube face). h over s plus twice the depth reach (window depth
// turned into view depth at the receiver's deepest corner) over cos a keeps it lit.
bool flatCasterShadowsNone(const gpu::LightData& light, const glm::vec4& plane, const OrientedBox& receiver, float padTexels,
                           float depthReach);

// How near a receiver may come to a caster's layers before it counts as on their side: a lookup
// that compares its biased depth with the layers (Lookup: an opaque receiver's tint product, whose
// bias lands it in front of its geometry), or one that places the receiver by its own surface
// (Surface: a translucent receiver's builds, which divide its own layers out where they are the
// farthest, within 2^-12 of its depth, or read no other layer at all).
enum class SideTolerance { Lookup, Surface };

// The part of tintFootprint's box whose points may lie not clearly behind every layer of the
// caster as the light sees them: within the farthest light depth of the caster's part in the
// receiver's shadow volume (the caster above it) plus, with SideTolerance::Lookup, the distance
// a lookup may land in front of its receiver (the light's bias knobs) and the tint test's
// tolerance. Elsewhere in the footprint a receiver is behind every layer around it, where CSSM's
// lookup takes the tint map's product and its fallback loop is never due
// (ShadowTechnique::behindLayersBuild). A half-space along the light's direction or axis cuts the
// receiver (a box around a point light).
scene::Bounds tintFootprintNotBehind(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver,
                                     float padTexels, SideTolerance tolerance = SideTolerance::Lookup);

// The part of tintFootprint's box whose points may lie not clearly in front of every layer of the
// caster: beyond the least light depth of the caster's part in the receiver's shadow volume, less
// the same tolerance. Elsewhere in the footprint the caster's layers all lie behind the receiver,
// so they put no colour on it: a translucent receiver there is reached by no layer but its own
// (ShadowTechnique::ownLayersBuild). Point lights: short of the caster is a box around the light
// (a cube map's depth is the largest axis distance), so the footprint's parts in the six
// half-spaces beyond its faces (until stop 62 the whole footprint).
scene::Bounds tintFootprintNotInFront(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver,
                                      float padTexels, SideTolerance tolerance = SideTolerance::Surface);

// Both of the above at once, as far as asked (`notBehind`, `notInFront`; a side not asked for
// stays empty): they share the caster's volume and its depth range above the receiver.
struct TintSides {
    scene::Bounds notBehind, notInFront;
    bool empty() const { return notBehind.empty() && notInFront.empty(); }
};
TintSides tintFootprintSides(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver, float padTexels,
                             SideTolerance tolerance, bool notBehind, bool notInFront);

// The part of `receiver` that light `light` can light at all: for a projector or a spot light the
// part inside its frustum's four side planes (lighting.frag's incidentRadiance is exactly 0
// outside them: a projector's picture stops at the frame's edge, a spot's cone lies inside its
// square frustum); the whole box for other lights. Empty where the light reaches none of it.
scene::Bounds lightReach(const gpu::LightData& light, const OrientedBox& receiver);

// What the renderer keeps per receiver, caster and light across frames (render/FrameMemo.h): the
// tint footprint and, once it has been on screen, its cells (world boxes, from cellsOf or the
// translucent receivers' both sides). Neither depends on the camera, except through a sun's map
// that follows the view; their screen rectangles do, and those are taken anew each frame.
struct FootprintCells {
    scene::Bounds footprint;
    bool celled = false;  // the cells below are worked out
    std::vector<scene::Bounds> notBehind, notInFront;
};

// A pixel rectangle [x0, x1) x [y0, y1).
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool contains(const PixelRect& r) const { return r.x0 >= x0 && r.y0 >= y0 && r.x1 <= x1 && r.y1 <= y1; }
    PixelRect intersected(const PixelRect& r) const;
};

// The pixels of a `width` x `height` view that `box` may cover through `viewProj` (world to
// clip), a pixel's margin around them; the whole view when the box reaches behind the eye.
PixelRect screenRect(const scene::Bounds& box, const glm::mat4& viewProj, int width, int height);

// `area` cut into disjoint rectangles, each wholly inside or wholly outside the union of
// `covered`: the grid of every rectangle's edges, its cells merged along rows and then across
// rows of the same runs.
struct RectPartition {
    std::vector<PixelRect> inside, outside;
};
RectPartition partition(const PixelRect& area, const std::vector<PixelRect>& covered);

}  // namespace penumbra::render
