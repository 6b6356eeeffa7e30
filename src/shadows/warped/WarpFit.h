#pragma once
// View-dependent warped shadow maps for a directional light, the geometry (pure math, no GL):
//   LiSPSM (Wimmer, Scherzer & Purgathofer 2004): a perspective warp whose axis lies in the
//     shadow-map plane, along the view direction projected onto it; the light stays directional.
//   PSM (Stamminger & Drettakis 2002): the shadow map taken in the camera's post-perspective
//     space, where the sun becomes a point light (in front of or behind the viewer) or stays
//     directional (light parallel to the image plane).
// Both are fitted to a body B = (camera or tile sub-frustum) ∩ scene bounds, extruded towards
// the light to keep every caster that can shadow it.
#include "scene/Camera.h"
#include "scene/Light.h"
#include "scene/Mesh.h"

#include <array>
#include <glm/glm.hpp>
#include <vector>

namespace penumbra::shadows {

// Where the scene is: its bounds (casters reach to their edge) and, when known, each object's
// bounds, so the body hugs what is there rather than the air in the scene's box (a tall tower
// far away must not make the body start at the camera).
struct WarpScene {
    scene::Bounds bounds;
    std::vector<scene::Bounds> objects;  // empty: the body is the frustum ∩ `bounds`
    WarpScene() = default;
    WarpScene(const scene::Bounds& b) : bounds(b) {}  // NOLINT: a box is a scene of one box
};

struct WarpedView {
    glm::mat4 viewProj{1.0f};      // world -> clip of the shadow map
    glm::mat4 shadowMatrix{1.0f};  // world -> [0,1]^3 texture space (after the divide by w)
    // World half-space the caster pass keeps (dot(plane, P) >= 0): geometry behind a warp's
    // projection centre would wrap through infinity into the map.
    glm::vec4 clipPlane{0.0f, 0.0f, 0.0f, 1.0f};
    float n = 0.0f;         // LiSPSM: distance of the projection centre from the body
    float sinGamma = 0.0f;  // sine of the angle between view and light directions
    bool uniform = false;   // fell back to a plain orthographic fit (degenerate angles)
    bool inverted = false;  // PSM: the sun behind the viewer, the inverted projection
    bool pointInPostPerspective = false;  // PSM: the light became a point light
    bool valid = false;     // false: the body is empty (the camera sees nothing of the scene)
};

// What a warped view is fitted to: B, the part of the (sub-)frustum where the scene is, and B
// extruded towards the light to the scene's edge (every caster that can shadow B lies in it).
struct WarpBody {
    std::vector<glm::vec3> visible, casters;
    glm::vec3 axis{0.0f, 0.0f, -1.0f};  // the frustum's axis
};
// False when the frustum sees nothing of the scene.
bool makeWarpBody(const scene::Light& sun, const glm::mat4& cameraViewProj, const WarpScene& scene, WarpBody& body);
// The room makeWarpBody gives every object's box in a scene of box `sceneBounds`: flat objects (a
// ground plane) have boxes of zero thickness, which clipping would whittle down to nothing in
// rounding.
glm::vec3 warpBodyMargin(const scene::Bounds& sceneBounds);

// `points` and, for each, where the ray towards the light leaves `box` (the casters' reach).
std::vector<glm::vec3> extrudeTowardLight(const std::vector<glm::vec3>& points, const glm::vec3& toLight,
                                          const scene::Bounds& box);

// Projection of tile (col, row) of a cols x rows grid over the camera's image (row 0 at the
// bottom), the sub-frustum Plachý 2012's slave cameras used (§3.5).
glm::mat4 tileProjection(const scene::Camera& camera, float aspect, int cols, int rows, int col, int row, float far);

struct LispsmOptions {
    float nScale = 1.0f;          // multiplies n_opt (1: Wimmer's optimum)
    float minSinGamma = 0.05f;    // below this the warp degenerates: plain orthographic fit
    bool nearFromCamera = false;  // z_n: the camera's near plane instead of the body's nearest point
};

// LiSPSM for the (sub-)frustum `cameraViewProj` seen from `camera`.
WarpedView fitLispsm(const scene::Light& sun, const scene::Camera& camera, const glm::mat4& cameraViewProj,
                     const WarpScene& scene, const LispsmOptions& options = {});

// PSM for the same. `minNear` bounds the virtual camera's near plane from below, as a share of
// the body's depth: the slide-back that keeps every caster in front of the virtual camera.
WarpedView fitPsm(const scene::Light& sun, const scene::Camera& camera, const glm::mat4& cameraViewProj,
                  const WarpScene& scene, float minNear = 0.02f);

// Both fitted to a body made already (makeWarpBody), for a caller that needs the body too.
WarpedView fitLispsm(const scene::Light& sun, const scene::Camera& camera, const WarpBody& body, const LispsmOptions& options);
WarpedView fitPsm(const scene::Light& sun, const scene::Camera& camera, const WarpBody& body, float minNear);

// Held views, as the plain sun's box (LightSpace.h, kBoxSlack) and the cascades hold theirs, so
// that a moving camera has the warped maps drawn every few frames instead of every frame:
// `view` with `room` to spare around its body, its clip-space image shrunk by 1 + room about its
// centre (across the map and in depth).
WarpedView withRoom(WarpedView view, float room);
// Whether `held` (last frame's view) still serves this frame's `body`: every point of the body and
// of its extrusion lies in its clip volume and in front of its clip plane, and nowhere on B are its
// texels more than `coarser` times those of `fitted`, this frame's own fit.
bool warpedViewHolds(const WarpedView& held, const WarpedView& fitted, const WarpBody& body, const glm::vec3& lightDirection,
                     float coarser);
// This frame's view, from its own fit to `body` and last frame's view (null: none, e.g. the first
// frame): last frame's while it holds with its texels at most kHeldCoarser those of the fit (as the
// plain box's); else the fit with kBoxSlack of room; without last frame's, the fit itself, so a
// single frame is as it was.
WarpedView followWarpedView(const WarpedView& fitted, const WarpedView* last, const WarpBody& body, const glm::vec3& lightDirection);

// Two unit directions across a light, perpendicular to it and to each other: where a texel is
// measured (WarpedTexelGauge).
struct AcrossLight {
    explicit AcrossLight(const glm::vec3& lightDirection);
    glm::vec3 e1, e2;
};

// The world size of one shadow-map texel at P, measured across the light (the coarser of two
// perpendicular directions): 1 / (resolution * |d uv / d P|) through the projective map. Made
// once for a loop over many points of one map, the two directions taken through the matrix once:
// the fits measure every corner of the camera's body (the 98k grid's 2,420; psm's fit 1.30 ->
// 1.07 ms a frame), Renderer::flatCasterNeeds asks WarpedShadowMap::shadowReachTexelsWithin of
// each receiver.
class WarpedTexelGauge {
public:
    WarpedTexelGauge(const glm::mat4& shadowMatrix, const AcrossLight& across, int resolution);
    float at(const glm::vec3& P) const;

private:
    glm::mat4 s_;
    glm::vec4 se1_, se2_;
    float resolution_;
};
// The same at one point.
float warpedTexelWorld(const glm::mat4& shadowMatrix, const glm::vec3& P, const glm::vec3& lightDirection, int resolution);

}  // namespace penumbra::shadows
