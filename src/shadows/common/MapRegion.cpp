#include "shadows/common/MapRegion.h"

#include "shadows/ShadowTechnique.h"

#include <array>
#include <cmath>

namespace penumbra::shadows {

namespace {

// Clip-space w below which a point counts as at or behind a perspective light's eye.
constexpr float kEyeW = 1e-6f;

// The texels of a map of `resolution` under the NDC rectangle [lo, hi], one texel of margin.
TexelRect texelsOf(glm::vec2 lo, glm::vec2 hi, int resolution) {
    const glm::vec2 first = glm::floor((glm::clamp(lo, -1.0f, 1.0f) * 0.5f + 0.5f) * float(resolution)) - 1.0f;
    const glm::vec2 last = glm::ceil((glm::clamp(hi, -1.0f, 1.0f) * 0.5f + 0.5f) * float(resolution)) + 1.0f;
    return glm::clamp(TexelRect(first.x, first.y, last.x, last.y), 0, resolution);
}

}  // namespace

TexelRect texelRect(std::span<const glm::vec3> points, const glm::mat4& viewProj, int resolution) {
    if (points.empty()) return TexelRect(0);
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& p : points) {
        const glm::vec4 c = viewProj * glm::vec4(p, 1.0f);
        if (c.w <= kEyeW) return {0, 0, resolution, resolution};
        const glm::vec2 ndc = glm::vec2(c) / c.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    return texelsOf(lo, hi, resolution);
}

glm::ivec4 CasterMap::texelsNear(std::span<const std::array<glm::vec3, 8>> boxes, const glm::mat4& viewProj, float pad) const {
    TexelRect near(0);
    for (const auto& corners : boxes) near = unite(near, texelRect(corners, viewProj, resolution));
    const int padTexels = static_cast<int>(std::ceil(pad * texelsPerLightTexel));
    return intersection(grown(near, glm::ivec2(padTexels), resolution), texels);
}

glm::ivec4 CasterMap::united(const glm::ivec4& a, const glm::ivec4& b) { return unite(a, b); }

// A perspective light sees only the box's part in front of its eye: a convex solid whose corners
// are the box's corners there and the points where the box's edges cross the eye's plane. A
// perspective projection keeps that solid convex, so those corners' projections bound its texels.
// Points on the eye's plane project to infinity, which the clamp takes to the map's edge. A box
// wholly behind the eye (the sky side of a point light's cube) covers no texel.
TexelRect texelRect(const scene::Bounds& bounds, const glm::mat4& viewProj, int resolution) {
    if (bounds.empty()) return TexelRect(0);
    std::array<glm::vec4, 8> clip{};
    for (int i = 0; i < 8; ++i) clip[static_cast<std::size_t>(i)] = viewProj * glm::vec4(bounds.corner(i), 1.0f);
    glm::vec2 lo(1e9f), hi(-1e9f);
    bool any = false;
    const auto add = [&](const glm::vec4& c) {
        const glm::vec2 ndc = glm::vec2(c) / c.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
        any = true;
    };
    for (std::size_t i = 0; i < 8; ++i) {
        const bool front = clip[i].w > kEyeW;
        if (front) add(clip[i]);
        for (std::size_t bit : {1u, 2u, 4u}) {  // the edges to corners whose index differs in one bit
            const std::size_t j = i ^ bit;
            if (j < i || front == (clip[j].w > kEyeW)) continue;
            glm::vec4 crossing = glm::mix(clip[i], clip[j], (kEyeW - clip[i].w) / (clip[j].w - clip[i].w));
            crossing.w = kEyeW;
            add(crossing);
        }
    }
    return any ? texelsOf(lo, hi, resolution) : TexelRect(0);
}

glm::mat4 cropTo(const TexelRect& rect, int resolution) {
    // The rectangle's NDC span [a, b] per axis goes to [-1, 1]: x' = (2 x - (a + b) w) / (b - a).
    const glm::vec2 a = glm::vec2(rect.x, rect.y) / float(resolution) * 2.0f - 1.0f;
    const glm::vec2 b = glm::vec2(rect.z, rect.w) / float(resolution) * 2.0f - 1.0f;
    glm::mat4 crop(1.0f);
    crop[0][0] = 2.0f / (b.x - a.x);
    crop[1][1] = 2.0f / (b.y - a.y);
    crop[3][0] = -(a.x + b.x) / (b.x - a.x);
    crop[3][1] = -(a.y + b.y) / (b.y - a.y);
    return crop;
}

ScopedScissor::ScopedScissor(const TexelRect& rect, bool enable) : enabled_(enable) {
    if (!enabled_) return;
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect.x, rect.y, rect.z - rect.x, rect.w - rect.y);
}

ScopedScissor::~ScopedScissor() {
    if (enabled_) glDisable(GL_SCISSOR_TEST);
}

void clearColourIn(GLuint framebuffer, const TexelRect& rect, const glm::vec4& colour, GLint drawBuffer) {
    if (isEmpty(rect)) return;
    const ScopedScissor scissor(rect);
    glClearNamedFramebufferfv(framebuffer, GL_COLOR, drawBuffer, &colour.x);
}

}  // namespace penumbra::shadows
