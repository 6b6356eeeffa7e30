#include "shadows/LightSpace.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::shadows {

using scene::Light;

const glm::mat4 kClipToTexture = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));

glm::vec3 anyPerpendicular(const glm::vec3& d) {
    return std::abs(d.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

std::array<glm::vec3, 8> frustumCorners(const glm::mat4& viewProj) {
    const glm::mat4 invViewProj = glm::inverse(viewProj);
    std::array<glm::vec3, 8> corners{};
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 ndc{(i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f, 1.0f};
        const glm::vec4 w = invViewProj * ndc;
        corners[static_cast<std::size_t>(i)] = glm::vec3(w) / w.w;
    }
    return corners;
}

namespace {

// Cyrus-Beck: the part of segment [a, b] in every half-space dot(plane, (p, 1)) >= 0.
bool clipSegment(glm::vec3& a, glm::vec3& b, const std::array<glm::vec4, 6>& planes) {
    float t0 = 0.0f, t1 = 1.0f;
    for (const glm::vec4& plane : planes) {
        const float da = glm::dot(plane, glm::vec4(a, 1.0f)), db = glm::dot(plane, glm::vec4(b, 1.0f));
        if (da < 0.0f && db < 0.0f) return false;
        if (da < 0.0f) t0 = std::max(t0, da / (da - db));
        else if (db < 0.0f) t1 = std::min(t1, da / (da - db));
        if (t0 > t1) return false;
    }
    const glm::vec3 d = b - a;
    b = a + d * t1;
    a = a + d * t0;
    return true;
}

// Each edge of the solid with these corners, clipped to the planes; the ends that remain.
void clippedEdges(const std::array<glm::vec3, 8>& corners, const std::array<glm::vec4, 6>& planes, std::vector<glm::vec3>& out) {
    for (int i = 0; i < 8; ++i)
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (i & bit) continue;
            glm::vec3 a = corners[static_cast<std::size_t>(i)], b = corners[static_cast<std::size_t>(i | bit)];
            if (!clipSegment(a, b, planes)) continue;
            out.push_back(a);
            out.push_back(b);
        }
}

}  // namespace

// Gribb & Hartmann: the clip volume's planes are w +- x, w +- y, w +- z of the matrix's rows.
Frustum::Frustum(const glm::mat4& viewProj) : corners(frustumCorners(viewProj)) {
    const glm::mat4 t = glm::transpose(viewProj);
    planes = {t[3] + t[0], t[3] - t[0], t[3] + t[1], t[3] - t[1], t[3] + t[2], t[3] - t[2]};
}

std::vector<glm::vec3> frustumInsideBox(const glm::mat4& viewProj, const scene::Bounds& box) {
    return box.empty() ? std::vector<glm::vec3>{} : frustumInsideBox(Frustum(viewProj), box);
}

std::vector<glm::vec3> frustumInsideBox(const Frustum& frustum, const scene::Bounds& box) {
    std::vector<glm::vec3> points;
    if (box.empty()) return points;
    points.reserve(48);  // two ends of each solid's 12 edges
    const std::array<glm::vec4, 6> boxPlanes{glm::vec4(1, 0, 0, -box.min.x), glm::vec4(-1, 0, 0, box.max.x),
                                             glm::vec4(0, 1, 0, -box.min.y), glm::vec4(0, -1, 0, box.max.y),
                                             glm::vec4(0, 0, 1, -box.min.z), glm::vec4(0, 0, -1, box.max.z)};
    clippedEdges(frustum.corners, boxPlanes, points);
    clippedEdges(box.corners(), frustum.planes, points);
    return points;
}

// Against shimmer and crawling as the camera moves (cf. Valient, "Stable rendering of cascaded
// shadow maps", ShaderX6; CascadeFit.h): the box's size per axis only takes values on a ladder
// of 2^(1/8) steps, so it stays put while the view changes a little, and its corner sits on a
// grid of kSnapTexels texels fixed in light space, so the map's content moves by whole texels,
// and CSSM's stratified tiles (caster.frag, 8 x 8 texels) stay on the same world-space texels.
// Costs up to 9 % + 8 texels of resolution per axis; a held box (`previous`) up to a ladder step
// and kBoxSlack more. Measured on scenes/park.json's camera path (llvmpipe, 64 frames at 60 fps):
// the box moved in 4 frames instead of 45, its texels 4.6 % coarser on average; slack 1/32 gave 7
// moves, 1/8 gave 3 (docs/measurements.md, stop 56).
constexpr float kSnapTexels = 8.0f;
constexpr float kSizeSteps = 8.0f;  // ladder steps per doubling
const float kBoxSlack = 1.0f / 16.0f;
const float kHeldCoarser = std::exp2(1.0f / kSizeSteps) * (1.0f + kBoxSlack);

float reachInPlainTexels(float coarsestTexel, float plainTexel, float normalOffset) {
    if (!(plainTexel > 0.0f)) return -1.0f;
    const float ratio = std::max(coarsestTexel / plainTexel, 1.0f), offset = std::max(normalOffset, 0.0f);
    return std::exp2(std::ceil(std::log2(std::max(ratio * (offset + 3.0f) - offset - 2.0f, kPlainCompareReachTexels))));
}

namespace {

float snapStep(float size, int res) { return size / static_cast<float>(res) * kSnapTexels; }

// The least size on the ladder that holds `wanted` and `steps` snapping steps more.
float ladderSize(float wanted, int res, float steps) {
    float size = std::exp2(std::ceil(std::log2(wanted) * kSizeSteps) / kSizeSteps);
    while (size < wanted + steps * snapStep(size, res)) size *= std::exp2(1.0f / kSizeSteps);
    return size;
}

// One axis of the box: [lo, lo + size) holding [wantLo, wantHi].
struct AxisBox {
    float lo, size;
};

// The tight fit: the corner snapped below wantLo (one step of room for it).
AxisBox tightAxis(float wantLo, float wantHi, int res) {
    const float size = ladderSize(wantHi - wantLo, res, 1.0f);
    const float step = snapStep(size, res);
    return {std::floor(wantLo / step) * step, size};
}

// With last frame's axis: kept while it holds the view and is at most one ladder step larger than
// a moved box would be; else moved, with kBoxSlack of the view's extent as room, the view in its
// middle (two steps of room for the snapped corner).
AxisBox followingAxis(float wantLo, float wantHi, int res, AxisBox last) {
    const float wanted = wantHi - wantLo;
    const float size = ladderSize(wanted * (1.0f + kBoxSlack), res, 2.0f);
    const bool holds = last.lo <= wantLo && last.lo + last.size >= wantHi;
    if (holds && last.size <= size * std::exp2(1.0f / kSizeSteps) * 1.0001f) return last;
    const float step = snapStep(size, res);
    return {std::floor((0.5f * (wantLo + wantHi) - 0.5f * size) / step) * step, size};
}

}  // namespace

static LightSpace directional(const Light& light, int res, const scene::Bounds& bounds, const scene::Camera& camera,
                              float aspect, const LightSpace* previous) {
    LightSpace ls;
    const glm::vec3 center = bounds.center();
    const float radius = std::max(glm::length(bounds.extent()) * 0.5f, 1e-3f);
    // The view's axis passes through the world origin, so that light-space x, y (and the
    // snapping grid below) do not move when animated objects move the scene's centre.
    const glm::vec3 axisPoint = light.direction * glm::dot(center, light.direction);
    const glm::mat4 view = glm::lookAt(axisPoint - light.direction * radius * 2.0f, axisPoint, anyPerpendicular(light.direction));

    const scene::Bounds sceneLs = bounds.transformed(view);
    // What the camera can see, no further than the scene reaches.
    const float farDistance = std::min(camera.far, glm::length(camera.position - center) + radius);
    scene::Bounds viewLs;
    for (const auto& c : frustumCorners(glm::perspective(glm::radians(camera.fovDeg), aspect, camera.near,
                                                       std::max(farDistance, camera.near * 2.0f)) * camera.view()))
        viewLs.add(glm::vec3(view * glm::vec4(c, 1.0f)));
    glm::vec2 lo = glm::max(glm::vec2(sceneLs.min), glm::vec2(viewLs.min));
    glm::vec2 hi = glm::min(glm::vec2(sceneLs.max), glm::vec2(viewLs.max));
    if (lo.x >= hi.x || lo.y >= hi.y) {  // camera looks away from everything: cover the scene
        lo = glm::vec2(sceneLs.min);
        hi = glm::vec2(sceneLs.max);
    }
    // A small margin so that geometry on the box faces is not clipped.
    const float margin = 1e-3f * radius;
    lo -= margin;
    hi += margin;
    const bool follow = previous && previous->type == Light::Type::Directional && previous->resolution == res &&
                        glm::mat3(previous->lightView) == glm::mat3(view) && previous->box.z > 0.0f;
    for (int axis = 0; axis < 2; ++axis) {
        const AxisBox b = follow ? followingAxis(lo[axis], hi[axis], res, {previous->box[axis], previous->box[axis + 2]})
                                 : tightAxis(lo[axis], hi[axis], res);
        lo[axis] = b.lo;
        hi[axis] = b.lo + b.size;
        ls.box[axis] = b.lo;
        ls.box[axis + 2] = b.size;
    }
    ls.lightView = view;
    const float zNear = -sceneLs.max.z - margin, zFar = -sceneLs.min.z + margin;
    const glm::mat4 proj = glm::ortho(lo.x, hi.x, lo.y, hi.y, zNear, zFar);
    ls.type = Light::Type::Directional;
    ls.resolution = res;
    ls.perspective = false;
    ls.near = zNear;
    ls.far = zFar;
    ls.texelScale = std::max(hi.x - lo.x, hi.y - lo.y) / static_cast<float>(res);
    ls.viewProj[0] = proj * view;
    ls.shadowMatrix = kClipToTexture * ls.viewProj[0];
    return ls;
}

static LightSpace cone(const Light& light, int res) {
    LightSpace ls;
    const float fov = glm::radians(light.angleDeg);
    const glm::mat4 view = glm::lookAt(light.position, light.position + light.direction, anyPerpendicular(light.direction));
    ls.type = light.type;
    ls.resolution = res;
    ls.perspective = true;
    ls.near = light.near;
    ls.far = light.range;
    ls.texelScale = 2.0f * std::tan(fov * 0.5f) / static_cast<float>(res);
    ls.viewProj[0] = glm::perspective(fov, 1.0f, light.near, light.range) * view;
    ls.shadowMatrix = kClipToTexture * ls.viewProj[0];
    return ls;
}

std::array<glm::mat4, 6> cubeFaceViews(const glm::vec3& p) {
    // GL cube map conventions (OpenGL 4.5 spec table 8.19).
    return {glm::lookAt(p, p + glm::vec3(1, 0, 0), glm::vec3(0, -1, 0)),
            glm::lookAt(p, p + glm::vec3(-1, 0, 0), glm::vec3(0, -1, 0)),
            glm::lookAt(p, p + glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)),
            glm::lookAt(p, p + glm::vec3(0, -1, 0), glm::vec3(0, 0, -1)),
            glm::lookAt(p, p + glm::vec3(0, 0, 1), glm::vec3(0, -1, 0)),
            glm::lookAt(p, p + glm::vec3(0, 0, -1), glm::vec3(0, -1, 0))};
}

static LightSpace point(const Light& light, int res) {
    LightSpace ls;
    ls.type = Light::Type::Point;
    ls.resolution = res;
    ls.perspective = true;
    ls.near = light.near;
    ls.far = light.range;
    ls.faceCount = 6;
    ls.texelScale = 2.0f / static_cast<float>(res);
    const glm::mat4 proj = glm::perspective(glm::radians(90.0f), 1.0f, light.near, light.range);
    const auto views = cubeFaceViews(light.position);
    for (std::size_t f = 0; f < 6; ++f) ls.viewProj[f] = proj * views[f];
    return ls;
}

LightSpace computeLightSpace(const Light& light, int resolution, const scene::Bounds& bounds,
                             const scene::Camera& camera, float aspect, const LightSpace* previous) {
    switch (light.type) {
        case Light::Type::Directional: return directional(light, resolution, bounds, camera, aspect, previous);
        case Light::Type::Spot:
        case Light::Type::Projector: return cone(light, resolution);
        case Light::Type::Point: return point(light, resolution);
    }
    return {};
}

}  // namespace penumbra::shadows
