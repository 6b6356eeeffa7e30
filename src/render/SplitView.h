#pragma once
// Two renderers of one scene side by side in one frame (issue 13, "compare in one window"): the
// columns left of the divider come from one technique (or parameter set), those right of it from
// the other. Each side keeps its own shadow maps and timers; both shade only their own columns.
#include "render/Renderer.h"

#include <memory>

namespace penumbra::render {

// The column of a divider at `share` (0..1) of `width`.
int dividerColumn(float share, int width);
// One split frame: `left` on the columns left of the divider at `share` of the width, `right` on
// the others, and the divider painted as the white columns either side of it. SplitView and the
// window (which owns its renderers itself) both draw through it.
void renderSplit(Renderer& left, Renderer& right, float share, float time, const scene::Camera& camera, int width, int height,
                 GLuint targetFramebuffer);

class SplitView {
public:
    // `left` and `right`: the two sides' options (technique, parameters); the scene is shared.
    SplitView(scene::Scene& scene, const RenderOptions& left, const RenderOptions& right);

    // The frame of `width` x `height` with the divider at column dividerColumn(width), drawn as
    // the white columns either side of it.
    void render(float time, const scene::Camera& camera, int width, int height, GLuint targetFramebuffer);
    int dividerColumn(int width) const { return render::dividerColumn(divider_, width); }
    void setDivider(float share);  // share of the width left of the divider, kept within [0, 1]
    float divider() const { return divider_; }
    void swap() { std::swap(left_, right_); }  // the key that swaps the halves
    Renderer& left() { return *left_; }
    Renderer& right() { return *right_; }

private:
    std::unique_ptr<Renderer> left_, right_;
    float divider_ = 0.5f;
};

}  // namespace penumbra::render
