#pragma once
// Where each light's shadow map looks: view-projection matrices, depth range and the world size
// of one shadow-map texel. Shared by every technique; computed once per light per frame.
#include "scene/Camera.h"
#include "scene/Light.h"
#include "scene/Mesh.h"

#include <array>
#include <glm/glm.hpp>
#include <vector>

namespace penumbra::shadows {

struct LightSpace {
    scene::Light::Type type = scene::Light::Type::Directional;
    int resolution = 2048;
    bool perspective = false;
    float near = 0.0f, far = 1.0f;  // depth range of the projection(s)
    // World size of one texel: at unit distance along the view axis when perspective,
    // everywhere when orthographic.
    float texelScale = 0.0f;
    int faceCount = 1;                      // 6 for point lights (cube map)
    std::array<glm::mat4, 6> viewProj{};    // world -> clip, per face
    glm::mat4 shadowMatrix{1.0f};           // world -> [0,1]^3 texture space (2D lights)
    // Directional lights: the light's view (world -> light space; x and y depend on its rotation
    // alone) and the box's corner and size across the light in it (x, y: lo; z, w: size), which
    // the next frame's fit may keep.
    glm::mat4 lightView{1.0f};
    glm::vec4 box{0.0f};
};

// Directional lights get an orthographic box that holds every caster in the scene bounds and,
// across the light, only what the camera frustum can see (casters behind receivers along the
// light stay in, since they lie in the same light-space column). Spot and projector lights use
// their cone; point lights the six cube faces.
// `previous` (may be null): the same light's space last frame. A directional light then keeps
// last frame's box across the light, per axis, while it still holds what the camera sees and is
// at most one size step larger than a fit would be; when it must move, the new box leaves
// kBoxSlack of room around the view, so that a moving camera moves it (and has its map drawn
// whole) every few frames instead of every frame. Without `previous`, the tight fit.
LightSpace computeLightSpace(const scene::Light& light, int resolution, const scene::Bounds& sceneBounds,
                             const scene::Camera& camera, float aspect, const LightSpace* previous = nullptr);

// The room a moved directional box leaves around the view, as a share of the view's extent per axis.
extern const float kBoxSlack;
// How much coarser a held view's texels may be than this frame's own fit: a step of the size
// ladder (2^(1/8)) and kBoxSlack. The sun box's bound (computeLightSpace), and the rule of the
// held warped views (followWarpedView).
extern const float kHeldCoarser;

// ShadowTechnique::shadowReachTexels of one compare on the light's plain map at the receiver's own
// texel (hard's; other lights' lookups in cascaded and the warped maps): that texel and the tint's.
inline constexpr float kPlainCompareReachTexels = 2.0f;

// ShadowTechnique::shadowReachTexels of a lookup that compares one texel of a map of its own
// (cascades, warped views) at the receiver's own depth: the renderer pads each caster's shadow by
// that + the normal offset + 2 texels of the light's plain map (`plainTexel`, LightSpace::texelScale;
// Renderer::addShadowReach), and the lookup needs the texel it reads, the normal offset and the
// same 2 of rounding in its own map's coarsest texel (at least the plain compare's,
// kPlainCompareReachTexels). Rounded up to a
// power of two, so that the renderer's memo of footprints keeps its keys while those maps move.
float reachInPlainTexels(float coarsestTexel, float plainTexel, float normalOffset);

// Maps clip space [-1,1]^3 to texture space [0,1]^3.
extern const glm::mat4 kClipToTexture;

// A unit axis not parallel to `d` (the up vector of a view along d).
glm::vec3 anyPerpendicular(const glm::vec3& d);

// World-space corners of the clip volume of `viewProj` (bit 0: x, 1: y, 2: z; set = +1).
std::array<glm::vec3, 8> frustumCorners(const glm::mat4& viewProj);

// The points where the convex frustum of `viewProj` (world -> clip, e.g. one cascade's camera
// slice) and `box` meet: each one's edges clipped to the other. Every vertex of the intersection
// lies on an edge of one of the two (it is where three faces meet, two of them of the same
// solid), so these points span it; none when the two do not meet.
std::vector<glm::vec3> frustumInsideBox(const glm::mat4& viewProj, const scene::Bounds& box);
// The same against one frustum made once (its corners take a matrix inverse): for many boxes.
struct Frustum {
    explicit Frustum(const glm::mat4& viewProj);
    std::array<glm::vec3, 8> corners;
    std::array<glm::vec4, 6> planes;
};
std::vector<glm::vec3> frustumInsideBox(const Frustum& frustum, const scene::Bounds& box);

// The six view matrices of a cube map, in GL's face order (+X, -X, +Y, -Y, +Z, -Z).
std::array<glm::mat4, 6> cubeFaceViews(const glm::vec3& position);

}  // namespace penumbra::shadows
