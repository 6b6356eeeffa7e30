#pragma once
// Sample distribution shadow maps' first step (Lauritzen, Salvi & Lefohn 2011): the nearest and
// farthest visible depth of this frame, from a camera depth pre-pass, so the cascades split only
// the depth range that holds visible surfaces instead of [near, far].
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "shadows/ShadowTechnique.h"

#include <optional>
#include <utility>

namespace penumbra::shadows {

class DepthBounds {
public:
    // View distances (min, max) of the visible opaque surfaces; nullopt when nothing is visible.
    std::optional<std::pair<float, float>> measure(const ShadowFrame& frame);

private:
    gl::Texture depth_;
    gl::Framebuffer target_;
    glm::ivec2 size_{0};
    DepthCasterProgram program_;
};

}  // namespace penumbra::shadows
