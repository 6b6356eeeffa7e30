#include "shadows/common/MapRegion.h"

namespace penumbra::shadows {

TexelRect texelRect(const scene::Bounds& bounds, const glm::mat4& viewProj, int resolution) {
    if (bounds.empty()) return TexelRect(0);
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 c = viewProj * glm::vec4((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                                                 (i & 4) ? bounds.max.z : bounds.min.z, 1.0f);
        if (c.w <= 1e-6f) return {0, 0, resolution, resolution};
        const glm::vec2 ndc = glm::vec2(c) / c.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    const glm::vec2 first = glm::floor((glm::clamp(lo, -1.0f, 1.0f) * 0.5f + 0.5f) * float(resolution)) - 1.0f;
    const glm::vec2 last = glm::ceil((glm::clamp(hi, -1.0f, 1.0f) * 0.5f + 0.5f) * float(resolution)) + 1.0f;
    return glm::clamp(TexelRect(first.x, first.y, last.x, last.y), 0, resolution);
}

void clearColourIn(GLuint framebuffer, const TexelRect& rect, const glm::vec4& colour) {
    if (isEmpty(rect)) return;
    glEnable(GL_SCISSOR_TEST);
    glScissor(rect.x, rect.y, rect.z - rect.x, rect.w - rect.y);
    glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, &colour.x);
    glDisable(GL_SCISSOR_TEST);
}

}  // namespace penumbra::shadows
