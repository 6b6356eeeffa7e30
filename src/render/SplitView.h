#pragma once
// Two renderers of one scene side by side in one frame (issue 13, "compare in one window"): the
// columns left of the divider come from one technique (or parameter set), those right of it from
// the other. Each side keeps its own shadow maps and timers; both shade only their own columns.
#include "render/Renderer.h"

#include <memory>

namespace penumbra::render {

// Paints the divider of a split frame: the two pixel columns either side of `column`, white.
void drawDivider(GLuint targetFramebuffer, int column, int width, int height);

class SplitView {
public:
    // `left` and `right`: the two sides' options (technique, parameters); the scene is shared.
    SplitView(scene::Scene& scene, const RenderOptions& left, const RenderOptions& right);

    // The frame of `width` x `height` with the divider at column dividerColumn(width), drawn as
    // the white columns either side of it.
    void render(float time, const scene::Camera& camera, int width, int height, GLuint targetFramebuffer);
    int dividerColumn(int width) const;
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
