#include "render/SplitView.h"

#include <algorithm>
#include <cmath>

namespace penumbra::render {

SplitView::SplitView(scene::Scene& scene, const RenderOptions& left, const RenderOptions& right)
    : left_(std::make_unique<Renderer>(scene, left)), right_(std::make_unique<Renderer>(scene, right)) {}

int dividerColumn(float share, int width) {
    return std::clamp(static_cast<int>(std::lround(share * static_cast<float>(width))), 0, width);
}

void SplitView::setDivider(float share) { divider_ = std::clamp(share, 0.0f, 1.0f); }

void SplitView::render(float time, const scene::Camera& camera, int width, int height, GLuint target) {
    renderSplit(*left_, *right_, divider_, time, camera, width, height, target);
}

void renderSplit(Renderer& left, Renderer& right, float share, float time, const scene::Camera& camera, int width, int height,
                 GLuint target) {
    const int column = dividerColumn(share, width);
    left.render(time, camera, width, height, target, {0, column});
    right.render(time, camera, width, height, target, {column, width});
    if (column <= 0 || column >= width) return;
    const float white[4] = {1, 1, 1, 1};
    glEnable(GL_SCISSOR_TEST);
    glScissor(column - 1, 0, 2, height);
    glClearNamedFramebufferfv(target, GL_COLOR, 0, white);
    glDisable(GL_SCISSOR_TEST);
}

}  // namespace penumbra::render
