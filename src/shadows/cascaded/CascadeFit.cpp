#include "shadows/cascaded/CascadeFit.h"

#include "shadows/LightSpace.h"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <glm/gtc/matrix_access.hpp>
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
                   const scene::Bounds& sceneBounds, int res, bool stabilize, const Cascade* previous) {
    const glm::vec3 dir = light.direction;
    // A light view through the world origin: only its orientation matters; positions are
    // expressed in it so that texel snapping is relative to a fixed grid.
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f), dir, anyPerpendicular(dir));
    const auto corners = frustumCorners(glm::perspective(glm::radians(camera.fovDeg), aspect, splitNear, splitFar) * camera.view());

    glm::vec2 lo, hi, boxCentre(0.0f);
    float half = 0.0f;
    if (stabilize) {
        glm::vec3 centre(0.0f);
        for (const auto& c : corners) centre += c / 8.0f;
        float radius = 0.0f;
        for (const auto& c : corners) radius = std::max(radius, glm::length(c - centre));
        radius = std::ceil(radius * 16.0f) / 16.0f;  // quantised: rounding noise must not resize the box
        const glm::vec2 centreLs = glm::vec2(view * glm::vec4(centre, 1.0f));
        const float moved = std::ceil(radius * (1.0f + kBoxSlack) * 16.0f) / 16.0f;
        const bool holds = previous && previous->direction == dir && previous->halfSize >= radius && previous->halfSize <= moved &&
                           glm::all(glm::lessThanEqual(glm::abs(centreLs - previous->centre),
                                                       glm::vec2(previous->halfSize - radius + 2.0f * previous->halfSize / static_cast<float>(res))));
        if (holds) {
            half = previous->halfSize;
            boxCentre = previous->centre;
        } else {
            half = previous ? moved : radius;
            const float texel = 2.0f * half / static_cast<float>(res);
            boxCentre = glm::floor(centreLs / texel) * texel;  // whole texels: the grid never slides
        }
        lo = boxCentre - half;
        hi = boxCentre + half;
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
    c.centre = boxCentre;
    c.halfSize = half;
    c.direction = dir;
    return c;
}

std::vector<glm::vec4> columnPlanes(const std::vector<glm::vec3>& points, const glm::mat4& viewProj, int resolution, float marginTexels) {
    std::vector<glm::vec2> p;
    p.reserve(points.size());
    for (const glm::vec3& w : points) p.emplace_back(viewProj * glm::vec4(w, 1.0f));
    std::sort(p.begin(), p.end(), [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (p.size() < 3) return {};
    // Andrew's monotone chain: the hull counter-clockwise, no collinear points.
    const auto turn = [](const glm::vec2& o, const glm::vec2& a, const glm::vec2& b) {
        return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    };
    std::vector<glm::vec2> hull(2 * p.size());
    std::size_t k = 0;
    for (const glm::vec2& q : p) {
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], q) <= 0.0f) --k;
        hull[k++] = q;
    }
    for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && turn(hull[k - 2], hull[k - 1], p[i]) <= 0.0f) --k;
        hull[k++] = p[i];
    }
    hull.resize(k - 1);
    if (hull.size() < 3) return {};
    // Clip x and y are affine in P (orthographic): n . (x, y) <= n . a + margin is a world plane
    // holding the light's direction.
    const glm::vec4 x = glm::row(viewProj, 0), y = glm::row(viewProj, 1);
    const float margin = 2.0f * marginTexels / static_cast<float>(resolution);
    std::vector<glm::vec4> planes;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const glm::vec2 a = hull[i], b = hull[(i + 1) % hull.size()];
        const glm::vec2 n = glm::normalize(glm::vec2(b.y - a.y, a.x - b.x));  // outward
        planes.push_back(glm::vec4(0.0f, 0.0f, 0.0f, glm::dot(n, a) + margin) - (n.x * x + n.y * y));
    }
    return planes;
}

}  // namespace penumbra::shadows
