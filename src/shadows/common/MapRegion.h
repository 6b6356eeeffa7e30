#pragma once
// Rectangles of texels in a square shadow map: where a set of casters can have written, so that
// clears and per-texel passes (CSSM's tile reduction) touch only that part of the map. For the
// plain tint map the scissored clear measured no faster on llvmpipe (default scene, shadow pass
// 11.2-11.7 ms either way: the pane's tint draw, ~3.3 ms, is the cost), but no frame clears more
// than the casters can have written.
#include "scene/Mesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>

#include <epoxy/gl.h>

namespace penumbra::shadows {

// (x0, y0, x1, y1), exclusive; empty when x0 >= x1 or y0 >= y1.
using TexelRect = glm::ivec4;

inline bool isEmpty(const TexelRect& r) { return r.x >= r.z || r.y >= r.w; }

// The smallest rectangle holding both (either may be empty).
inline TexelRect unite(const TexelRect& a, const TexelRect& b) {
    if (isEmpty(a)) return b;
    if (isEmpty(b)) return a;
    return {glm::min(a.x, b.x), glm::min(a.y, b.y), glm::max(a.z, b.z), glm::max(a.w, b.w)};
}

// `r` widened by `by` texels on each side (x and y apart), clamped to a square map of `size`.
inline TexelRect grown(const TexelRect& r, glm::ivec2 by, int size) {
    if (isEmpty(r)) return r;
    return glm::clamp(TexelRect(r.x - by.x, r.y - by.y, r.z + by.x, r.w + by.y), 0, size);
}

// The texels of a map `factor` times coarser that hold any of `r`'s (mip levels, downsampled maps).
inline TexelRect coarser(const TexelRect& r, int factor, int coarseSize) {
    if (isEmpty(r)) return r;
    return glm::clamp(TexelRect(r.x / factor, r.y / factor, (r.z + factor - 1) / factor, (r.w + factor - 1) / factor), 0,
                      coarseSize);
}

// The texels in both (empty if none).
inline TexelRect intersection(const TexelRect& a, const TexelRect& b) {
    return {glm::max(a.x, b.x), glm::max(a.y, b.y), glm::min(a.z, b.z), glm::min(a.w, b.w)};
}

// The texels of a square map of `resolution` that `bounds` can cover through `viewProj`, one
// texel of margin around them: of a box that reaches behind a perspective light's eye, its part
// in front (nothing when it lies wholly behind).
TexelRect texelRect(const scene::Bounds& bounds, const glm::mat4& viewProj, int resolution);
// The same for any set of points (empty when there are none; the whole map when one lies behind
// a perspective light's eye, where its projection would flip).
TexelRect texelRect(std::span<const glm::vec3> points, const glm::mat4& viewProj, int resolution);

// Which texels of a map computed from one face of a depth map (moments, min/max depth tiles) must
// be computed again this frame. All of them, unless `key` (the face's still casters' digest with
// whatever else the derived map depends on; 0: unknown) is the one it was last computed from:
// then only where the animated casters were last frame and are now (DepthAndTintMaps::movingTexels).
class DerivedTexels {
public:
    TexelRect changed(std::uint64_t key, const TexelRect& moving, int resolution) {
        const TexelRect redo = key != 0 && key == holds_ ? unite(moving_, moving) : TexelRect(0, 0, resolution, resolution);
        holds_ = key;
        moving_ = moving;
        return redo;
    }

private:
    std::uint64_t holds_ = 0;
    TexelRect moving_{0};
};

// Clip space cut down to `rect` of a square map of `resolution`: cropTo(rect) * viewProj culls
// what cannot reach those texels (the part of x and y in clip space; depth is left alone).
glm::mat4 cropTo(const TexelRect& rect, int resolution);

// Scissor test on `rect` for the scope's draws and clears (none when `enable` is false).
class ScopedScissor {
public:
    explicit ScopedScissor(const TexelRect& rect, bool enable = true);
    ~ScopedScissor();
    ScopedScissor(const ScopedScissor&) = delete;
    ScopedScissor& operator=(const ScopedScissor&) = delete;

private:
    bool enabled_;
};

// Clears draw buffer `drawBuffer` of `framebuffer` to `colour` inside `rect` only (nothing if empty).
void clearColourIn(GLuint framebuffer, const TexelRect& rect, const glm::vec4& colour, GLint drawBuffer = 0);

}  // namespace penumbra::shadows
