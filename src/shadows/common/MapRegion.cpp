#include "shadows/common/MapRegion.h"

namespace penumbra::shadows {

TexelRect texelRect(std::span<const glm::vec3> points, const glm::mat4& viewProj, int resolution) {
    if (points.empty()) return TexelRect(0);
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& p : points) {
        const glm::vec4 c = viewProj * glm::vec4(p, 1.0f);
        if (c.w <= 1e-6f) return {0, 0, resolution, resolution};
        const glm::vec2 ndc = glm::vec2(c) / c.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    const glm::vec2 first = glm::floor((glm::clamp(lo, -1.0f, 1.0f) * 0.5f + 0.5f) * float(resolution)) - 1.0f;
    const glm::vec2 last = glm::ceil((glm::clamp(hi, -1.0f, 1.0f) * 0.5f + 0.5f) * float(resolution)) + 1.0f;
    return glm::clamp(TexelRect(first.x, first.y, last.x, last.y), 0, resolution);
}

TexelRect texelRect(const scene::Bounds& bounds, const glm::mat4& viewProj, int resolution) {
    if (bounds.empty()) return TexelRect(0);
    return texelRect(bounds.corners(), viewProj, resolution);
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
