#include "render/TintReach.h"

#include "util/PerspectiveDepth.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace penumbra::render {

namespace {

// A half-space: points with dot(n, x) + d >= 0.
struct Plane {
    glm::vec3 n;
    float d;
    float at(const glm::vec3& x) const { return glm::dot(n, x) + d; }
};

// A convex polygon of a box face clipped by up to seven planes (4 + 7 vertices), or of a plane's
// quad clipped by a box's six faces, its world box's six and six planes (each clip adds at most
// one vertex; the section of the two boxes has at most 12 sides, the planes add 6).
struct Polygon {
    std::array<glm::vec3, 24> v;
    int n = 0;
};

// Sutherland-Hodgman: `poly` cut to its part inside `plane` (no allocation: this runs per
// receiver, light, caster, cell and face every frame). Each vertex's distance is taken once, and
// a polygon wholly inside, the common case, is left as it is. With insideAll's test of the
// corners first, the footprints' CPU time per frame (stats.json tint_shading cpu_ms, medians of
// 10 frames) fell from 2.39-2.44 to 1.25-1.57 ms on the glass scene, 0.70 to 0.47 on the default.
void clip(Polygon& poly, const Plane& plane) {
    std::array<float, 24> f;
    bool allInside = true;
    for (int i = 0; i < poly.n; ++i) {
        f[static_cast<std::size_t>(i)] = plane.at(poly.v[static_cast<std::size_t>(i)]);
        allInside = allInside && f[static_cast<std::size_t>(i)] >= 0.0f;
    }
    if (allInside) return;
    Polygon out;
    for (int i = 0; i < poly.n; ++i) {
        const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>((i + 1) % poly.n);
        if (f[a] >= 0.0f) out.v[static_cast<std::size_t>(out.n++)] = poly.v[a];
        if ((f[a] >= 0.0f) != (f[b] >= 0.0f))  // signs differ: f[a] != f[b]
            out.v[static_cast<std::size_t>(out.n++)] = poly.v[a] + (poly.v[b] - poly.v[a]) * (f[a] / (f[a] - f[b]));
    }
    poly = out;
}

// A unit vector across d (render/ may not include shadows/LightSpace.h, whose anyPerpendicular
// is the same idea: tests/architecture/include_boundaries.cmake).
glm::vec3 perpendicular(const glm::vec3& d) {
    return glm::normalize(glm::cross(d, std::abs(d.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
}

// A hexahedron's faces, corners in Bounds::corner's order, each a cycle.
constexpr int kFaces[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};

// Every vertex of the part of the hexahedron `box` (corners in Bounds::corner's order: a box or
// its affine image) inside every plane, face by face (Sutherland-Hodgman). With the apex where
// the planes meet, these are all the vertices of the convex intersection but those inside `box`
// on a plane that does not pass through the apex.
template <class Visit>
void visitFaces(const OrientedBox::Corners& box, std::span<const Plane> planes, Visit&& visit) {
    for (const auto& face : kFaces) {
        Polygon poly;
        for (int c : face) poly.v[static_cast<std::size_t>(poly.n++)] = box[static_cast<std::size_t>(c)];
        for (const Plane& plane : planes) {
            if (poly.n == 0) break;
            clip(poly, plane);
        }
        for (int i = 0; i < poly.n; ++i) visit(poly.v[static_cast<std::size_t>(i)]);
    }
}

// The planes of a hexahedron's faces (corners in Bounds::corner's order), facing in and moved out
// by a hair of its size for rounding; a face without area (a flat box's sides) gives none.
int facePlanes(const OrientedBox::Corners& box, std::array<Plane, 6>& out) {
    glm::vec3 centre(0.0f);
    for (const glm::vec3& c : box) centre += c * 0.125f;
    const float slack = 1e-4f * glm::length(box[7] - box[0]) + 1e-6f;
    int count = 0;
    for (const auto& face : kFaces) {
        const glm::vec3 a = box[static_cast<std::size_t>(face[0])];
        glm::vec3 n = glm::cross(box[static_cast<std::size_t>(face[1])] - a, box[static_cast<std::size_t>(face[3])] - a);
        const float length = glm::length(n);
        if (length < 1e-12f) continue;
        n /= length;
        if (glm::dot(n, centre - a) < 0.0f) n = -n;
        out[static_cast<std::size_t>(count++)] = Plane{n, slack - glm::dot(n, a)};
    }
    return count;
}

// The world box of the part of `oriented` inside every plane. Every vertex of the (convex)
// intersection lies on a face of the box, or is `apex`, or lies on `cut` (one of `planes`, not
// through the apex). The apex and the cut are taken within the world box around `oriented`
// (conservative: a light inside that box but outside a turned receiver's own counts as inside).
scene::Bounds insideAll(const OrientedBox& oriented, std::span<const Plane> planes, const glm::vec3* apex, const Plane* cut = nullptr) {
    scene::Bounds receiver;
    for (const glm::vec3& c : oriented.corners) receiver.add(c);
    // Wholly outside one plane: nothing; wholly inside every plane: all of it (the box is convex).
    bool inside = true;
    for (const Plane& plane : planes) {
        int in = 0;
        for (const glm::vec3& c : oriented.corners) in += plane.at(c) >= 0.0f ? 1 : 0;
        if (in == 0) return {};
        inside = inside && in == 8;
    }
    if (inside) return receiver;
    scene::Bounds out;
    visitFaces(oriented.corners, planes, [&](const glm::vec3& v) { out.add(v); });
    if (apex && glm::all(glm::greaterThanEqual(*apex, receiver.min)) && glm::all(glm::lessThanEqual(*apex, receiver.max)) &&
        std::all_of(planes.begin(), planes.end(), [&](const Plane& p) { return p.at(*apex) >= 0.0f; }))
        out.add(*apex);
    if (cut) {
        // The cut's own cross-section: a quad on its plane, wider than the box, clipped by the
        // box's faces and every plane.
        const glm::vec3 n = glm::normalize(cut->n), c = receiver.center();
        const glm::vec3 onPlane = c - n * (cut->at(c) / glm::length(cut->n));
        const glm::vec3 e1 = perpendicular(n) * (glm::length(receiver.max - receiver.min) + 1.0f), e2 = glm::cross(n, e1);
        Polygon poly;
        poly.n = 4;
        poly.v = {onPlane - e1 - e2, onPlane + e1 - e2, onPlane + e1 + e2, onPlane - e1 + e2};
        for (int a = 0; a < 3 && poly.n > 0; ++a) {
            glm::vec3 axis(0.0f);
            axis[a] = 1.0f;
            clip(poly, Plane{axis, -receiver.min[a]});
            if (poly.n > 0) clip(poly, Plane{-axis, receiver.max[a]});
        }
        // A turned receiver's own faces too: its world box holds mostly air (a thin pane), which
        // the cut's cross-section would otherwise span.
        std::array<Plane, 6> faces;
        const int faceCount = facePlanes(oriented.corners, faces);
        for (int f = 0; f < faceCount && poly.n > 0; ++f) clip(poly, faces[static_cast<std::size_t>(f)]);
        for (const Plane& plane : planes) {
            if (poly.n == 0) break;
            if (&plane != cut) clip(poly, plane);
        }
        for (int i = 0; i < poly.n; ++i) out.add(poly.v[static_cast<std::size_t>(i)]);
    }
    if (out.empty()) return out;
    return scene::Bounds{glm::max(out.min, receiver.min), glm::min(out.max, receiver.max)};  // rounding of the cuts
}

// A convex hull of at most N points, held in place: the footprints run per caster and light each
// frame, and keep off the heap as Polygon does.
template <std::size_t N>
struct Hull {
    std::array<glm::vec2, 2 * N> v;  // the monotone chain's working room
    std::size_t n = 0;
};

// The convex hull of `points`, counter-clockwise, without points within `tolerance` of a side
// (Andrew's monotone chain); fewer than 3 points where they lie on a line.
template <std::size_t N>
Hull<N> convexHull(std::array<glm::vec2, N> points, float tolerance) {
    std::sort(points.begin(), points.end(), [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    const auto turnsLeft = [tolerance](const glm::vec2& o, const glm::vec2& a, const glm::vec2& b) {
        const glm::vec2 e = a - o, f = b - o;
        return e.x * f.y - e.y * f.x > tolerance * glm::length(f - e);
    };
    Hull<N> out;
    auto& hull = out.v;
    std::size_t k = 0;
    for (std::size_t i = 0; i < N; ++i) {  // lower chain
        while (k >= 2 && !turnsLeft(hull[k - 2], hull[k - 1], points[i])) --k;
        hull[k++] = points[i];
    }
    for (std::size_t i = N - 1, lower = k + 1; i-- > 0;) {  // upper chain
        while (k >= lower && !turnsLeft(hull[k - 2], hull[k - 1], points[i])) --k;
        hull[k++] = points[i];
    }
    out.n = k > 1 ? k - 1 : k;  // the last point is the first
    return out;
}

// The shadow volume of a caster with corners `caster`, padded by `padTexels`: up to five planes
// (a sun's prism: four) and the apex where they meet (perspective lights). False when it is
// unbounded: a caster reaching beside or behind the light (a point light inside a glass ball).
struct ShadowVolume {
    std::array<Plane, 7> planes;  // a sun's silhouette has up to six sides; room for one more: a cut
    int count = 0;
    bool hasApex = false;
    glm::vec3 apex{0.0f};
};
bool shadowVolume(const gpu::LightData& light, const OrientedBox::Corners& caster, float padTexels, ShadowVolume& out) {
    const float texelScale = light.shadow.w;
    if (static_cast<int>(light.colorType.w) == gpu::kLightDirectional) {
        // The caster's shadow: the prism along d over its box's silhouette (the convex hull of its
        // corners seen along d, up to six sides), each side moved out by texels of texelScale (the
        // same width everywhere in an orthographic map). A rectangle around the silhouette in an
        // arbitrary frame across d held up to twice its area, and a floor's cut of it more.
        const glm::vec3 d = glm::normalize(glm::vec3(light.directionFar));
        const glm::vec3 u = perpendicular(d), v = glm::cross(d, u);
        const float pad = padTexels * texelScale;
        std::array<glm::vec2, 8> q;
        glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
        for (std::size_t i = 0; i < caster.size(); ++i) {
            q[i] = glm::vec2(glm::dot(u, caster[i]), glm::dot(v, caster[i]));
            lo = glm::min(lo, q[i]);
            hi = glm::max(hi, q[i]);
        }
        const auto hull = convexHull(q, 1e-6f * std::max(hi.x - lo.x, hi.y - lo.y));
        if (hull.n >= 3 && hull.n <= 6) {
            out.count = 0;
            for (std::size_t i = 0; i < hull.n; ++i) {
                const glm::vec2 a = hull.v[i], e = hull.v[(i + 1) % hull.n] - a;
                const glm::vec2 outward = glm::normalize(glm::vec2(e.y, -e.x));  // counter-clockwise hull
                const glm::vec3 n = outward.x * u + outward.y * v;
                out.planes[static_cast<std::size_t>(out.count++)] = Plane{-n, glm::dot(outward, a) + pad};
            }
            return true;
        }
        out.planes = {{{u, pad - lo.x}, {-u, hi.x + pad}, {v, pad - lo.y}, {-v, hi.y + pad}}};
        out.count = 4;
        return true;
    }
    // Perspective lights (spot, projector, point): the pyramid from the light through the
    // caster's box, in the projective coordinates (s, t) = (u, v)·(x - p) / a·(x - p) of an axis a
    // through the box's centre, padded by texels of texelScale per unit distance (a texel spans at
    // most that angle, dθ = ds cos²θ: hence the 1 + tan² on the pad).
    const glm::vec3 p = glm::vec3(light.positionNear);
    glm::vec3 centre(0.0f);
    for (const glm::vec3& c : caster) centre += c * 0.125f;
    if (glm::length(centre - p) <= 1e-6f) return false;
    const glm::vec3 a = glm::normalize(centre - p), u = perpendicular(a), v = glm::cross(a, u);
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const glm::vec3& c : caster) {
        const float w = glm::dot(a, c - p);
        if (w <= 1e-3f * glm::length(c - p)) return false;
        const glm::vec2 q(glm::dot(u, c - p) / w, glm::dot(v, c - p) / w);
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    const float tan2 = std::max(lo.x * lo.x, hi.x * hi.x) + std::max(lo.y * lo.y, hi.y * hi.y);
    const float pad = padTexels * texelScale * (1.0f + tan2);
    lo -= pad;
    hi += pad;
    // s >= lo.x: (u - lo.x a)·(x - p) >= 0, and so on; w > 0 in front of the light.
    const auto through = [&](const glm::vec3& n) { return Plane{n, -glm::dot(n, p)}; };
    out.planes = {through(u - lo.x * a), through(hi.x * a - u), through(v - lo.y * a), through(hi.y * a - v), through(a)};
    out.count = 5;
    out.hasApex = true;
    out.apex = p;
    return true;
}

// tintFootprint, with the receiver cut further by `limit` when it is given (a half-space).
// The part of `receiver` inside the caster's shadow volume (`volume`; nullptr: unbounded, all of
// it), cut further by `limit` when it is given (a half-space).
scene::Bounds footprintIn(const ShadowVolume* volume, const OrientedBox& receiver, const Plane* limit) {
    if (!volume) return insideAll(receiver, {}, nullptr);  // all of it may be tinted
    ShadowVolume v = *volume;
    if (limit) v.planes[static_cast<std::size_t>(v.count++)] = *limit;
    const std::span<const Plane> planes(v.planes.data(), static_cast<std::size_t>(v.count));
    return insideAll(receiver, planes, v.hasApex ? &v.apex : nullptr, limit ? &planes.back() : nullptr);
}

// tintFootprint.
scene::Bounds footprint(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver, float padTexels) {
    if (caster.empty || receiver.empty) return {};
    ShadowVolume volume;
    return footprintIn(shadowVolume(light, caster.corners, padTexels, volume) ? &volume : nullptr, receiver, nullptr);
}

// The least and largest `depthOf` over the part of `caster` inside the shadow volume of
// `receiver` (the caster's points on rays that pass within the padding of the receiver); empty
// (least > largest) when there is none. Only that part can put a layer near the rays to the
// receiver, so a small receiver, a cell of a floor, compares with the part of the caster above
// it, not with its farthest corner anywhere.
struct DepthRange {
    float least = std::numeric_limits<float>::max(), most = std::numeric_limits<float>::lowest();
    bool empty() const { return least > most; }
};
template <class Depth>
DepthRange depthsAbove(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver, float padTexels, Depth&& depthOf) {
    DepthRange range;
    const auto keep = [&](const glm::vec3& v) {
        const float d = depthOf(v);
        range.least = std::min(range.least, d);
        range.most = std::max(range.most, d);
    };
    ShadowVolume volume;
    if (!shadowVolume(light, receiver.corners, padTexels, volume)) {
        for (const glm::vec3& c : caster.corners) keep(c);
        return range;
    }
    // The apex (the light) lies outside the caster: the faces' vertices are all that count.
    visitFaces(caster.corners, std::span<const Plane>(volume.planes.data(), static_cast<std::size_t>(volume.count)), keep);
    return range;
}

// SideTolerance as distance along the light: world distance for a directional light, a
// relative scale of depth for a perspective one. Lookup: how far in front of its geometry a
// lookup may land (the constant bias, the slope bias at shadow_coord.glsl's tan θ cap of 10 and
// the normal offset), 2 texels for the rasterised layers' and the comparison's rounding, and the
// tint tests' tolerance (2^-10 of the depth range, or of 1 - window depth, about 2^-10 of the
// view depth z), given 4 times over. Surface: the normal offset, which may turn a lookup from the
// light, the 2 texels of rounding, and 2^-12 of depth (ownLayersFrom's 2^-12 and its quarter texel).
float sideMargin(const gpu::LightData& light, SideTolerance kind) {
    const bool lookup = kind == SideTolerance::Lookup;
    const float texels = (lookup ? light.shadow.x + 10.0f * light.shadow.y : 0.0f) + light.shadow.z + 2.0f;
    const float tolerance = lookup ? 1.0f / 256.0f : 1.0f / 4096.0f;
    if (static_cast<int>(light.colorType.w) == gpu::kLightDirectional)
        return texels * light.shadow.w + (light.directionFar.w - light.positionNear.w) * tolerance;
    return 2.0f * (texels * light.shadow.w + tolerance);
}

// The view depth of a perspective light (spot, projector, a point light's cube face) whose window
// depth is `windowReach` short of view depth z's; 0 where that is before the near plane.
float perspectiveDepthNearer(const gpu::LightData& light, float z, float windowReach) {
    const float n = light.positionNear.w, f = light.directionFar.w;
    const float window = util::perspectiveWindowDepth(n, f, z) - windowReach;
    return window > 0.0f ? util::perspectiveViewDepth(n, f, window) : 0.0f;
}

// tintFootprintSides, the near side's limit first moved nearer the light by `depthReach` of window
// depth (how much deeper than its receiver a lookup may compare).
TintSides footprintSides(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver, float padTexels,
                         SideTolerance tolerance, float depthReach, bool notBehind, bool notInFront) {
    TintSides sides;
    if (caster.empty || receiver.empty || !(notBehind || notInFront)) return sides;
    ShadowVolume casterVolume;
    const ShadowVolume* volume = shadowVolume(light, caster.corners, padTexels, casterVolume) ? &casterVolume : nullptr;
    const glm::vec3 p = glm::vec3(light.positionNear);
    const float margin = sideMargin(light, tolerance);
    const int type = static_cast<int>(light.colorType.w);
    if (type == gpu::kLightPoint) {
        // A cube map's depth is the largest axis distance: the points within a limit form a box.
        const DepthRange range = depthsAbove(light, caster, receiver, padTexels, [&](const glm::vec3& c) {
            const glm::vec3 q = glm::abs(c - p);
            return std::max(q.x, std::max(q.y, q.z));
        });
        if (range.empty()) return sides;
        if (notInFront) {
            // Short of the caster is the box of half-size `limit` around the light; beyond it lies
            // the union of six half-spaces, one per axis and side: the footprint's part in each.
            // (A cube face's depth is a perspective view depth along its axis.)
            const float least = depthReach > 0.0f ? perspectiveDepthNearer(light, range.least, depthReach) : range.least;
            const float limit = least / (1.0f + margin);
            for (int axis = 0; axis < 3; ++axis)
                for (const float side : {-1.0f, 1.0f}) {
                    glm::vec3 normal(0.0f);
                    normal[axis] = side;  // side * (x - p) >= limit along the axis
                    const Plane cut{normal, -side * p[axis] - limit};
                    sides.notInFront.add(footprintIn(volume, receiver, &cut));
                }
        }
        if (!notBehind) return sides;
        const float limit = (1.0f + margin) * range.most;
        scene::Bounds world;  // (a turned receiver: its world box, conservatively)
        for (const glm::vec3& c : receiver.corners) world.add(c);
        const scene::Bounds within{glm::max(world.min, p - limit), glm::min(world.max, p + limit)};
        if (glm::all(glm::lessThanEqual(within.min, within.max))) sides.notBehind = footprintIn(volume, within, nullptr);
        return sides;
    }
    // Orthographic depth is linear in distance along d; a perspective light's texel and tolerance
    // grow with its depth z, so the limit is the caster's depth scaled.
    const glm::vec3 d = glm::normalize(glm::vec3(light.directionFar));
    const bool directional = type == gpu::kLightDirectional;
    const DepthRange range = depthsAbove(light, caster, receiver, padTexels, [&](const glm::vec3& c) {
        return directional ? glm::dot(d, c) : glm::dot(d, c - p);
    });
    if (range.empty()) return sides;
    const float origin = directional ? 0.0f : glm::dot(d, p);
    // Depth z(x) = d·x - origin: beyond keeps z <= most + margin, short keeps z >= least - margin.
    if (notBehind) {
        const float limit = directional ? range.most + margin : range.most * (1.0f + margin);
        const Plane cut{-d, origin + limit};
        sides.notBehind = footprintIn(volume, receiver, &cut);
    }
    if (notInFront) {
        const float n = light.positionNear.w, f = light.directionFar.w;
        float least = range.least;
        if (depthReach > 0.0f && directional) least -= depthReach * (f - n);
        if (depthReach > 0.0f && !directional) least = perspectiveDepthNearer(light, least, depthReach);
        const float limit = directional ? least - margin : least / (1.0f + margin);
        const Plane cut{d, -origin - limit};
        sides.notInFront = footprintIn(volume, receiver, &cut);
    }
    return sides;
}

}  // namespace

// tintFootprint cut to the points that may lie beyond the caster's depth range above the
// receiver (notBehind) and short of it (notInFront), widened by sideMargin: the half-space on the
// far side of its largest depth, or on the near side of its least. The caster's volume and depth
// range serve both cuts; a side not asked for stays empty.
TintSides tintFootprintSides(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver, float padTexels,
                             SideTolerance tolerance, bool notBehind, bool notInFront) {
    return footprintSides(light, caster, receiver, padTexels, tolerance, 0.0f, notBehind, notInFront);
}

// flatCasterShadowsNone for a spot, projector or point light: `n`, `offset` the unit plane.
static bool flatCasterShadowsNoneSeenFrom(const gpu::LightData& light, glm::vec3 n, float offset, const OrientedBox& receiver,
                                          float padTexels, float depthReach) {
    const glm::vec3 eye(light.positionNear);
    const float near = light.positionNear.w, far = light.directionFar.w;
    const float eyeHeight = glm::dot(n, eye) + offset;
    if (std::abs(eyeHeight) < 1e-4f * far) return false;  // the eye in the plane: neither side is clearly lit
    if (eyeHeight < 0.0f) n = -n, offset = -offset;
    const bool cube = static_cast<int>(light.colorType.w) == gpu::kLightPoint;
    const glm::vec3 axis = glm::normalize(glm::vec3(light.directionFar));
    float lowest = std::numeric_limits<float>::max(), deepest = 0.0f, leastCos = cube ? 1.0f / std::sqrt(3.0f) : 1.0f;
    for (const glm::vec3& c : receiver.corners) {
        const glm::vec3 v = c - eye;
        const float z = cube ? std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z))) : glm::dot(v, axis);
        if (z <= near) return false;  // at or behind the map's near plane: not bounded here
        lowest = std::min(lowest, glm::dot(n, c) + offset);
        deepest = std::max(deepest, z);
        if (!cube) leastCos = std::min(leastCos, z / glm::length(v));  // a cone holds the box if it holds its corners
    }
    float reach = 0.0f;  // view depth a compare may reach past the deepest corner
    if (depthReach > 0.0f) {
        const float reached = util::perspectiveViewDepth(near, far, util::perspectiveWindowDepth(near, far, deepest) + depthReach);
        if (!std::isfinite(reached)) return false;  // it may compare past the far plane
        reach = reached - deepest;
    }
    const float margin = 2.0f * padTexels * light.shadow.w * deepest + 2.0f * reach / leastCos + deepest / 4096.0f;
    return lowest > margin;
}

bool flatCasterShadowsNone(const gpu::LightData& light, const glm::vec4& plane, const OrientedBox& receiver, float padTexels,
                           float depthReach) {
    if (receiver.empty) return false;
    glm::vec3 n(plane);
    float offset = plane.w;
    const float length = glm::length(n);
    if (length <= 0.0f) return false;
    n /= length;
    offset /= length;
    if (static_cast<int>(light.colorType.w) != gpu::kLightDirectional)
        return flatCasterShadowsNoneSeenFrom(light, n, offset, receiver, padTexels, depthReach);
    const glm::vec3 d = glm::normalize(glm::vec3(light.directionFar));
    const float facing = -glm::dot(n, d);  // cos t, on the normal's side
    if (std::abs(facing) < 1e-3f) return false;  // edge-on to the light: neither side is clearly lit
    if (facing < 0.0f) n = -n, offset = -offset;
    const float range = light.directionFar.w - light.positionNear.w;
    // The normal offset and the taps' reach across the light share the pad; a tap a across the
    // light, along x or y of the map (so up to sqrt(2) a in all), stands for a point up to
    // sqrt(2) a sin t nearer the plane.
    const float sinT = std::sqrt(std::max(0.0f, 1.0f - facing * facing));
    const float margin = padTexels * light.shadow.w * std::max(1.0f, std::sqrt(2.0f) * sinT) + std::max(depthReach, 0.0f) * range +
                         range / 4096.0f;
    return std::all_of(receiver.corners.begin(), receiver.corners.end(),
                       [&](const glm::vec3& c) { return glm::dot(n, c) + offset > margin; });
}

scene::Bounds opaqueShadowFootprint(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver, float padTexels,
                                    float depthReach) {
    return footprintSides(light, caster, receiver, padTexels, SideTolerance::Surface, depthReach, false, true).notInFront;
}

OrientedBox::OrientedBox(const scene::Bounds& world) : corners(world.corners()), empty(world.empty()) {}

OrientedBox::OrientedBox(const scene::Bounds& local, const glm::mat4& model) : empty(local.empty()) {
    for (int i = 0; i < 8; ++i) corners[static_cast<std::size_t>(i)] = glm::vec3(model * glm::vec4(local.corner(i), 1.0f));
}

std::array<scene::Bounds, 4> quarters(const scene::Bounds& box, const glm::mat4& model) {
    glm::vec3 size = box.max - box.min;
    for (int k = 0; k < 3; ++k) size[k] *= glm::length(glm::vec3(model[k]));
    const int a = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
    const int b = a == 0 ? (size.y >= size.z ? 1 : 2) : a == 1 ? (size.x >= size.z ? 0 : 2) : (size.x >= size.y ? 0 : 1);
    const float midA = 0.5f * (box.min[a] + box.max[a]), midB = 0.5f * (box.min[b] + box.max[b]);
    std::array<scene::Bounds, 4> quarter;
    for (std::size_t i = 0; i < 4; ++i) {
        scene::Bounds& c = quarter[i];
        c = box;
        (i & 1 ? c.min[a] : c.max[a]) = midA;
        (i & 2 ? c.min[b] : c.max[b]) = midB;
    }
    return quarter;
}

scene::Bounds lightReach(const gpu::LightData& light, const OrientedBox& receiver) {
    const int type = static_cast<int>(light.colorType.w);
    if (receiver.empty || (type != gpu::kLightProjector && type != gpu::kLightSpot)) {
        scene::Bounds all;
        if (!receiver.empty)
            for (const glm::vec3& c : receiver.corners) all.add(c);
        return all;
    }
    // s = shadowMatrix * (P, 1); lit only where 0 <= s.x <= s.w and 0 <= s.y <= s.w (which also
    // puts P in front of the light, s.w >= 0): four half-spaces through the light's position.
    const glm::mat4 m = glm::transpose(light.shadowMatrix);  // rows of the matrix as columns
    const glm::vec4 u = m[0], v = m[1], w = m[3];
    const auto plane = [](const glm::vec4& r) { return Plane{glm::vec3(r), r.w}; };
    const std::array<Plane, 4> sides{plane(u), plane(w - u), plane(v), plane(w - v)};
    const glm::vec3 apex(light.positionNear);
    return insideAll(receiver, sides, &apex);
}

scene::Bounds tintFootprint(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver, float padTexels) {
    return footprint(light, caster, receiver, padTexels);
}

scene::Bounds tintFootprintNotBehind(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver,
                                     float padTexels, SideTolerance tolerance) {
    return tintFootprintSides(light, caster, receiver, padTexels, tolerance, true, false).notBehind;
}

scene::Bounds tintFootprintNotInFront(const gpu::LightData& light, const OrientedBox& caster, const OrientedBox& receiver,
                                      float padTexels, SideTolerance tolerance) {
    return tintFootprintSides(light, caster, receiver, padTexels, tolerance, false, true).notInFront;
}


PixelRect PixelRect::intersected(const PixelRect& r) const {
    PixelRect i{std::max(x0, r.x0), std::max(y0, r.y0), std::min(x1, r.x1), std::min(y1, r.y1)};
    return i.empty() ? PixelRect{} : i;
}

PixelRect screenRect(const scene::Bounds& box, const glm::mat4& viewProj, int width, int height) {
    const PixelRect view{0, 0, width, height};
    if (box.empty()) return {};
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    // The corners' clip coordinates as the minimum corner's plus the box's edges along x, y, z
    // (viewProj's columns scaled): one product instead of eight (scenes/street.json's split takes
    // tens of thousands of these a frame).
    const glm::vec3 size = box.max - box.min;
    const glm::vec4 origin = viewProj * glm::vec4(box.min, 1.0f), ex = viewProj[0] * size.x, ey = viewProj[1] * size.y,
                    ez = viewProj[2] * size.z;
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 clip = origin + (i & 1 ? ex : glm::vec4(0.0f)) + (i & 2 ? ey : glm::vec4(0.0f)) + (i & 4 ? ez : glm::vec4(0.0f));
        if (clip.w <= 1e-5f) return view;  // behind the eye: its projection is unbounded
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    const auto pixel = [](float ndc, int size) { return (ndc * 0.5f + 0.5f) * static_cast<float>(size); };
    // Far outside the view, clamp before converting (an int cannot hold every float).
    const auto low = [&](float ndc, int size) { return static_cast<int>(std::floor(std::clamp(pixel(ndc, size), -1.0f, size + 1.0f))) - 1; };
    const auto high = [&](float ndc, int size) { return static_cast<int>(std::ceil(std::clamp(pixel(ndc, size), -1.0f, size + 1.0f))) + 1; };
    return PixelRect{low(lo.x, width), low(lo.y, height), high(hi.x, width), high(hi.y, height)}.intersected(view);
}

RectPartition partition(const PixelRect& area, const std::vector<PixelRect>& covered) {
    RectPartition out;
    if (area.empty()) return out;
    std::vector<int> xs{area.x0, area.x1}, ys{area.y0, area.y1};
    std::vector<PixelRect> cut;
    for (const PixelRect& c : covered) {
        const PixelRect r = c.intersected(area);
        if (r.empty()) continue;
        cut.push_back(r);
        xs.insert(xs.end(), {r.x0, r.x1});
        ys.insert(ys.end(), {r.y0, r.y1});
    }
    for (std::vector<int>* v : {&xs, &ys}) {
        std::sort(v->begin(), v->end());
        v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    // Runs of equal cells along each row band; a run continues the one above it when the band
    // below repeats it exactly (same columns, same side).
    struct Run {
        PixelRect rect;
        bool inside;
    };
    std::vector<Run> done, open;
    for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
        std::vector<Run> band;
        for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
            const PixelRect cell{xs[i], ys[j], xs[i + 1], ys[j + 1]};
            const bool inside = std::any_of(cut.begin(), cut.end(), [&](const PixelRect& r) { return r.contains(cell); });
            if (!band.empty() && band.back().inside == inside) band.back().rect.x1 = cell.x1;
            else band.push_back({cell, inside});
        }
        std::vector<Run> next;
        for (Run& r : band) {
            const auto above = std::find_if(open.begin(), open.end(), [&](const Run& o) {
                return o.inside == r.inside && o.rect.x0 == r.rect.x0 && o.rect.x1 == r.rect.x1;
            });
            if (above != open.end()) {
                r.rect.y0 = above->rect.y0;
                open.erase(above);
            }
            next.push_back(r);
        }
        done.insert(done.end(), open.begin(), open.end());
        open = std::move(next);
    }
    done.insert(done.end(), open.begin(), open.end());
    for (const Run& r : done) (r.inside ? out.inside : out.outside).push_back(r.rect);
    return out;
}

}  // namespace penumbra::render
