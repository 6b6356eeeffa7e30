#pragma once
// Sample distribution shadow maps' first step (Lauritzen, Salvi & Lefohn 2011): the nearest and
// farthest visible depth of this frame, from a camera depth pre-pass, so the cascades split only
// the depth range that holds visible surfaces instead of [near, far]. The depth is reduced to its
// min and max on the GPU (depth_bounds.comp): the fit waits for two words, not for a depth image
// read back and scanned on the CPU.
#include "gl/Buffer.h"
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
    // (nearest, farthest) window depth the pre-pass covered; nearest > farthest when it covered none.
    std::pair<float, float> reduce(glm::ivec2 size);

    gl::Texture depth_;
    gl::Framebuffer target_;
    glm::ivec2 size_{0};
    DepthCasterProgram program_;
    gl::Program reduce_;   // depth_bounds.comp
    gl::Buffer bounds_;    // its two words: the nearest and farthest depth's bits
};

}  // namespace penumbra::shadows
