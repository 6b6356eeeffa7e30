#include "render/SplitView.h"

#include <algorithm>
#include <cmath>

namespace penumbra::render {

SplitView::SplitView(scene::Scene& scene, const RenderOptions& left, const RenderOptions& right)
    : left_(std::make_unique<Renderer>(scene, left)), right_(std::make_unique<Renderer>(scene, right)) {}

int SplitView::dividerColumn(int width) const {
    return std::clamp(static_cast<int>(std::lround(divider_ * static_cast<float>(width))), 0, width);
}

void SplitView::setDivider(float share) { divider_ = std::clamp(share, 0.0f, 1.0f); }

void SplitView::render(float time, const scene::Camera& camera, int width, int height, GLuint target) {
    const int column = dividerColumn(width);
    left_->render(time, camera, width, height, target, {0, column});
    right_->render(time, camera, width, height, target, {column, width});
    drawDivider(target, column, width, height);
}

void drawDivider(GLuint target, int column, int width, int height) {
    if (column <= 0 || column >= width) return;
    const float white[4] = {1, 1, 1, 1};
    glEnable(GL_SCISSOR_TEST);
    glScissor(column - 1, 0, 2, height);
    glClearNamedFramebufferfv(target, GL_COLOR, 0, white);
    glDisable(GL_SCISSOR_TEST);
}

}  // namespace penumbra::render
