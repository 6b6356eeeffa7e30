#include "shadows/warped/WarpFit.h"

#include "shadows/LightSpace.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_access.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace penumbra::shadows {

namespace {

glm::vec3 unproject(const glm::mat4& inverse, const glm::vec3& ndc) {
    const glm::vec4 w = inverse * glm::vec4(ndc, 1.0f);
    return glm::vec3(w) / w.w;
}

// The axis of a (possibly off-axis) frustum: the ray through the centre of its image.
glm::vec3 frustumAxis(const glm::mat4& viewProj) {
    const glm::mat4 inv = glm::inverse(viewProj);
    return glm::normalize(unproject(inv, {0, 0, 1}) - unproject(inv, {0, 0, -1}));
}

scene::Bounds boundsOf(const std::vector<glm::vec3>& points, const glm::mat4& m, bool divide) {
    scene::Bounds b;
    for (const auto& p : points) {
        const glm::vec4 q = m * glm::vec4(p, 1.0f);
        b.add(divide ? glm::vec3(q) / q.w : glm::vec3(q));
    }
    return b;
}

// The orthographic box around `b` (a light view's coordinates, light travelling along -z).
glm::mat4 orthoAround(const scene::Bounds& b) {
    const glm::vec3 margin = 1e-3f * glm::max(b.extent(), glm::vec3(1e-4f));
    return glm::ortho(b.min.x - margin.x, b.max.x + margin.x, b.min.y - margin.y, b.max.y + margin.y,
                      -b.max.z - margin.z, -b.min.z + margin.z);
}

WarpedView finish(WarpedView w, const glm::mat4& viewProj) {
    w.viewProj = viewProj;
    w.shadowMatrix = kClipToTexture * viewProj;
    w.valid = true;
    return w;
}

}  // namespace

// A thousandth of the scene.
glm::vec3 warpBodyMargin(const scene::Bounds& sceneBounds) { return glm::vec3(1e-3f * glm::length(sceneBounds.extent())); }

bool makeWarpBody(const scene::Light& sun, const glm::mat4& cameraViewProj, const WarpScene& scene, WarpBody& body) {
    const Frustum camera(cameraViewProj);
    if (scene.objects.empty()) body.visible = frustumInsideBox(camera, scene.bounds);
    const glm::vec3 margin = warpBodyMargin(scene.bounds);
    for (scene::Bounds box : scene.objects) {
        box.min -= margin;
        box.max += margin;
        const auto part = frustumInsideBox(camera, box);
        body.visible.insert(body.visible.end(), part.begin(), part.end());
    }
    if (body.visible.empty()) return false;
    body.casters = extrudeTowardLight(body.visible, -glm::normalize(sun.direction), scene.bounds);
    body.axis = frustumAxis(cameraViewProj);
    return true;
}

WarpedView withRoom(WarpedView view, float room) {
    const float s = 1.0f / (1.0f + room);
    return finish(view, glm::scale(glm::mat4(1.0f), glm::vec3(s)) * view.viewProj);
}

bool warpedViewHolds(const WarpedView& held, const WarpedView& fitted, const WarpBody& body, const glm::vec3& lightDirection,
                     float coarser) {
    if (!held.valid || !fitted.valid) return false;
    for (const glm::vec3& p : body.casters) {  // the visible points come first in it
        const glm::vec4 c = held.viewProj * glm::vec4(p, 1.0f);
        if (c.w <= 0.0f || glm::any(glm::greaterThan(glm::abs(glm::vec3(c)), glm::vec3(c.w)))) return false;
        if (glm::dot(held.clipPlane, glm::vec4(p, 1.0f)) < 0.0f) return false;
    }
    // The resolution cancels out of the ratio.
    const AcrossLight across(lightDirection);
    const WarpedTexelGauge heldTexel(held.shadowMatrix, across, 1), fittedTexel(fitted.shadowMatrix, across, 1);
    for (const glm::vec3& p : body.visible)
        if (heldTexel.at(p) > coarser * fittedTexel.at(p)) return false;
    return true;
}

std::vector<glm::vec3> extrudeTowardLight(const std::vector<glm::vec3>& points, const glm::vec3& toLight,
                                          const scene::Bounds& box) {
    std::vector<glm::vec3> out(points);
    for (const auto& p : points) {
        float t = std::numeric_limits<float>::max();
        for (int a = 0; a < 3; ++a) {
            if (std::abs(toLight[a]) < 1e-8f) continue;
            const float wall = toLight[a] > 0.0f ? box.max[a] : box.min[a];
            t = std::min(t, (wall - p[a]) / toLight[a]);
        }
        if (t > 0.0f && t < std::numeric_limits<float>::max()) out.push_back(p + toLight * t);
    }
    return out;
}

glm::mat4 tileProjection(const scene::Camera& camera, float aspect, int cols, int rows, int col, int row, float far) {
    const float top = camera.near * std::tan(glm::radians(camera.fovDeg) * 0.5f), right = top * aspect;
    const float w = 2.0f * right / static_cast<float>(cols), h = 2.0f * top / static_cast<float>(rows);
    const float l = -right + w * static_cast<float>(col), b = -top + h * static_cast<float>(row);
    return glm::frustum(l, l + w, b, b + h, camera.near, far);
}

WarpedView fitLispsm(const scene::Light& sun, const scene::Camera& camera, const glm::mat4& cameraViewProj,
                     const WarpScene& scene, const LispsmOptions& options) {
    WarpBody body;
    return makeWarpBody(sun, cameraViewProj, scene, body) ? fitLispsm(sun, camera, body, options) : WarpedView{};
}

WarpedView fitLispsm(const scene::Light& sun, const scene::Camera& camera, const WarpBody& body, const LispsmOptions& options) {
    WarpedView w;
    const glm::vec3 d = glm::normalize(sun.direction);
    const float cosGamma = glm::dot(body.axis, d);
    w.sinGamma = std::sqrt(std::max(0.0f, 1.0f - cosGamma * cosGamma));
    w.uniform = w.sinGamma < options.minSinGamma;
    // Light space: looking along the light, +y the view axis projected onto the map's plane.
    const glm::vec3 up = w.uniform ? anyPerpendicular(d) : glm::normalize(body.axis - cosGamma * d);
    const glm::mat4 lightView = glm::lookAt(camera.position, camera.position + d, up);
    if (w.uniform) return finish(w, orthoAround(boundsOf(body.casters, lightView, false)) * lightView);

    // Wimmer 2004, §5.2: n_opt = (z_n + sqrt(z_f z_n)) / sin γ with z_n, z_f the near and far
    // distances of the body seen along the view axis, here measured in the warp's y extent.
    const scene::Bounds ls = boundsOf(body.visible, lightView, false);
    float nearDist = std::numeric_limits<float>::max();
    for (const auto& p : body.visible) nearDist = std::min(nearDist, glm::dot(p - camera.position, body.axis));
    nearDist = std::max(nearDist, camera.near);
    if (options.nearFromCamera) nearDist = camera.near;
    const float depth = std::max(ls.max.y - ls.min.y, 1e-4f);
    const float zn = nearDist / w.sinGamma, zf = zn + depth * w.sinGamma;
    w.n = options.nScale * (zn + std::sqrt(zf * zn)) / w.sinGamma;
    if (w.n > 1e3f * depth) {  // the warp has flattened out: n -> infinity is the uniform map
        w.uniform = true;
        return finish(w, orthoAround(boundsOf(body.casters, lightView, false)) * lightView);
    }
    const float n = w.n, f = n + depth;
    const glm::vec3 centre(0.0f, ls.min.y - n, 0.0f);  // projection centre, behind the body along y
    // Perspective along +y: y' = a y + b, w' = y maps y in [n, f] to [-1, 1]; x and z keep
    // their values, so light rays (lines along z) stay parallel: the light stays directional.
    glm::mat4 warp(1.0f);
    warp[1][1] = (f + n) / (f - n);
    warp[3][1] = -2.0f * f * n / (f - n);
    warp[1][3] = 1.0f;
    warp[3][3] = 0.0f;
    const glm::mat4 m = warp * glm::translate(glm::mat4(1.0f), -centre) * lightView;
    glm::vec4 plane = glm::row(lightView, 1);
    plane.w -= centre.y + 0.1f * n;  // keep y > centre + n/10: nothing of the body is lost
    w.clipPlane = plane;
    return finish(w, orthoAround(boundsOf(body.casters, m, true)) * m);
}

WarpedView fitPsm(const scene::Light& sun, const scene::Camera& camera, const glm::mat4& cameraViewProj,
                  const WarpScene& scene, float minNear) {
    WarpBody body;
    return makeWarpBody(sun, cameraViewProj, scene, body) ? fitPsm(sun, camera, body, minNear) : WarpedView{};
}

WarpedView fitPsm(const scene::Light& sun, const scene::Camera& camera, const WarpBody& body, float minNear) {
    WarpedView w;
    const glm::vec3 v = body.axis;
    auto depthOf = [&](const glm::vec3& p) { return glm::dot(p - camera.position, v); };
    float visibleNear = std::numeric_limits<float>::max(), visibleFar = 0.0f, casterNear = visibleNear, casterFar = 0.0f;
    for (const auto& p : body.visible) {
        visibleNear = std::min(visibleNear, depthOf(p));
        visibleFar = std::max(visibleFar, depthOf(p));
    }
    for (const auto& p : body.casters) {
        casterNear = std::min(casterNear, depthOf(p));
        casterFar = std::max(casterFar, depthOf(p));
    }
    // The virtual camera (Stamminger & Drettakis §4.2, Kozlov 2004): its near plane pushed to
    // the nearest visible point (bounded below to limit the warp), then slid back until every
    // caster that can shadow the body lies in front of it.
    const float nearTarget = std::max({camera.near, visibleNear, minNear * visibleFar});
    const float slide = std::max(0.0f, nearTarget - casterNear);
    const glm::vec3 eye = camera.position - v * slide;
    const float nearV = std::max(casterNear + slide, nearTarget), farV = std::max(casterFar + slide, nearV * 1.01f);
    const glm::vec3 camUp = std::abs(glm::dot(camera.up, v)) < 0.99f ? camera.up : anyPerpendicular(v);
    const glm::mat4 pp = glm::perspective(glm::radians(90.0f), 1.0f, nearV, farV) * glm::lookAt(eye, eye + v, camUp);
    w.clipPlane = glm::vec4(v, -glm::dot(v, eye) - 0.5f * nearV);  // in front of the virtual near plane / 2

    // The sun in post-perspective space: a point (w != 0) or still a direction (w = 0).
    const glm::vec4 light = pp * glm::vec4(-glm::normalize(sun.direction), 0.0f);
    std::vector<glm::vec3> q;
    for (const auto& p : body.casters) {
        const glm::vec4 h = pp * glm::vec4(p, 1.0f);
        q.push_back(glm::vec3(h) / h.w);
    }
    scene::Bounds qb;
    for (const auto& p : q) qb.add(p);
    const glm::vec3 centre = qb.center();
    if (std::abs(light.w) < 1e-3f * glm::length(glm::vec3(light))) {  // parallel to the image plane
        const glm::vec3 dir = glm::normalize(glm::vec3(light));
        const glm::mat4 view = glm::lookAt(centre + dir, centre, anyPerpendicular(dir));
        return finish(w, orthoAround(boundsOf(q, view, false)) * view * pp);
    }
    w.pointInPostPerspective = true;
    w.inverted = light.w < 0.0f;  // the sun behind the viewer
    const glm::vec3 lp = glm::vec3(light) / light.w;
    // Look from the light's image at the body's centre, unless the body then spans more than
    // ~150°: the image lies just beyond the far plane (z_ndc = (f+n)/(f-n), the plane at infinity)
    // when the sun is near the view axis, and only the axis along -z keeps every point in front.
    glm::vec3 axis = glm::normalize(centre - lp);
    for (const auto& p : q)
        if (glm::dot(glm::normalize(p - lp), axis) < 0.26f) {
            axis = glm::vec3(0.0f, 0.0f, -1.0f);
            break;
        }
    const glm::mat4 view = glm::lookAt(lp, lp + axis, anyPerpendicular(axis));
    float dmin = std::numeric_limits<float>::max(), dmax = 0.0f;
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const auto& p : q) {
        const glm::vec3 e = glm::vec3(view * glm::vec4(p, 1.0f));
        const float dist = std::max(-e.z, 1e-6f);
        dmin = std::min(dmin, dist);
        dmax = std::max(dmax, dist);
        lo = glm::min(lo, glm::vec2(e) / dist);
        hi = glm::max(hi, glm::vec2(e) / dist);
    }
    const float nearL = dmin * 0.99f, farL = dmax * 1.01f;
    lo -= 1e-3f * (hi - lo);
    hi += 1e-3f * (hi - lo);
    // Inverted case: the occluders of a point lie farther from the light's image than the point
    // itself (its rays pass through infinity), so the map keeps the farthest surface: near and
    // far swap, depth falls with distance, and the usual "stored < receiver" test still holds.
    const float zFront = w.inverted ? farL : nearL, zBack = w.inverted ? nearL : farL;
    const glm::mat4 proj = glm::frustum(lo.x * zFront, hi.x * zFront, lo.y * zFront, hi.y * zFront, zFront, zBack);
    return finish(w, proj * view * pp);
}

WarpedView followWarpedView(const WarpedView& fitted, const WarpedView* last, const WarpBody& body, const glm::vec3& lightDirection) {
    if (!last || !fitted.valid) return fitted;
    return warpedViewHolds(*last, fitted, body, lightDirection, kHeldCoarser) ? *last : withRoom(fitted, kBoxSlack);
}

AcrossLight::AcrossLight(const glm::vec3& lightDirection) {
    const glm::vec3 d = glm::normalize(lightDirection);
    e1 = glm::normalize(glm::cross(d, anyPerpendicular(d)));
    e2 = glm::cross(d, e1);
}

float warpedTexelWorld(const glm::mat4& s, const glm::vec3& P, const glm::vec3& lightDirection, int resolution) {
    return WarpedTexelGauge(s, AcrossLight(lightDirection), resolution).at(P);
}

WarpedTexelGauge::WarpedTexelGauge(const glm::mat4& s, const AcrossLight& across, int resolution)
    : s_(s), se1_(s * glm::vec4(across.e1, 0.0f)), se2_(s * glm::vec4(across.e2, 0.0f)), resolution_(static_cast<float>(resolution)) {}

float WarpedTexelGauge::at(const glm::vec3& P) const {
    const glm::vec4 h = s_ * glm::vec4(P, 1.0f);
    const glm::vec2 uv = glm::vec2(h) / h.w;
    float gain = std::numeric_limits<float>::max();
    for (const glm::vec4& se : {se1_, se2_})  // d(uv)/dP · e = (S_xy e - uv S_w e) / w
        gain = std::min(gain, glm::length((glm::vec2(se) - uv * se.w) / h.w));
    return 1.0f / (resolution_ * std::max(gain, 1e-12f));
}

}  // namespace penumbra::shadows
