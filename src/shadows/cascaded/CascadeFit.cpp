#include "shadows/cascaded/CascadeFit.h"

#include "shadows/LightSpace.h"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::shadows {

std::vector<float> cascadeSplits(float n, float f, int m, float lambda) {
    std::vector<float> c(static_cast<std::size_t>(m) + 1);
    for (int i = 0; i <= m; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(m);
        const float logarithmic = n * std::pow(f / n, t), uniform = n + (f - n) * t;
        c[static_cast<std::size_t>(i)] = lambda * logarithmic + (1.0f - lambda) * uniform;
    }
    c.front() = n;
    c.back() = f;
    return c;
}

Cascade fitCascade(const scene::Light& light, const scene::Camera& camera, float aspect, float splitNear, float splitFar,
                   const scene::Bounds& sceneBounds, int res, bool stabilize) {
    const glm::vec3 dir = light.direction;
    // A light view through the world origin: only its orientation matters; positions are
    // expressed in it so that texel snapping is relative to a fixed grid.
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f), dir, anyPerpendicular(dir));
    const auto corners = frustumCorners(glm::perspective(glm::radians(camera.fovDeg), aspect, splitNear, splitFar) * camera.view());

    glm::vec2 lo, hi;
    if (stabilize) {
        glm::vec3 centre(0.0f);
        for (const auto& c : corners) centre += c / 8.0f;
        float radius = 0.0f;
        for (const auto& c : corners) radius = std::max(radius, glm::length(c - centre));
        radius = std::ceil(radius * 16.0f) / 16.0f;  // quantised: rounding noise must not resize the box
        const float texel = 2.0f * radius / static_cast<float>(res);
        glm::vec2 centreLs = glm::vec2(view * glm::vec4(centre, 1.0f));
        centreLs = glm::floor(centreLs / texel) * texel;  // whole texels: the grid never slides
        lo = centreLs - radius;
        hi = centreLs + radius;
    } else {
        lo = glm::vec2(std::numeric_limits<float>::max());
        hi = glm::vec2(std::numeric_limits<float>::lowest());
        for (const auto& c : corners) {
            const glm::vec2 p = glm::vec2(view * glm::vec4(c, 1.0f));
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    }
    const scene::Bounds ls = sceneBounds.transformed(view);
    const float margin = 1e-3f * std::max(glm::length(sceneBounds.extent()), 1.0f);
    Cascade c;
    c.splitNear = splitNear;
    c.splitFar = splitFar;
    c.depthNear = -ls.max.z - margin;
    c.depthFar = -ls.min.z + margin;
    c.viewProj = glm::ortho(lo.x, hi.x, lo.y, hi.y, c.depthNear, c.depthFar) * view;
    c.shadowMatrix = kClipToTexture * c.viewProj;
    c.texelWorld = std::max(hi.x - lo.x, hi.y - lo.y) / static_cast<float>(res);
    return c;
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

std::vector<glm::vec3> frustumInsideBox(const glm::mat4& viewProj, const scene::Bounds& box) {
    std::vector<glm::vec3> points;
    if (box.empty()) return points;
    // Gribb & Hartmann: the clip volume's planes are w +- x, w +- y, w +- z of the matrix's rows.
    const glm::mat4 t = glm::transpose(viewProj);
    const std::array<glm::vec4, 6> frustum{t[3] + t[0], t[3] - t[0], t[3] + t[1], t[3] - t[1], t[3] + t[2], t[3] - t[2]};
    const std::array<glm::vec4, 6> boxPlanes{glm::vec4(1, 0, 0, -box.min.x), glm::vec4(-1, 0, 0, box.max.x),
                                             glm::vec4(0, 1, 0, -box.min.y), glm::vec4(0, -1, 0, box.max.y),
                                             glm::vec4(0, 0, 1, -box.min.z), glm::vec4(0, 0, -1, box.max.z)};
    clippedEdges(frustumCorners(viewProj), boxPlanes, points);
    clippedEdges(box.corners(), frustum, points);
    return points;
}

}  // namespace penumbra::shadows
