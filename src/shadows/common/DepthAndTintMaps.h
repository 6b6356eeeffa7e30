#pragma once
// Per-light storage most shadow-map techniques share: an opaque-caster depth map (2D or cube)
// and a transmittance ("tint") map of translucent casters in front of it (seed 001's
// per-light colour buffer). Reallocated when a light's resolution changes; both are
// re-rendered every frame.
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Sampler.h"
#include "gl/Texture.h"
#include "shadows/ShadowTechnique.h"

#include <vector>

namespace penumbra::shadows {

class DepthAndTintMaps {
public:
    struct LightMaps {
        int resolution = 0;
        bool cube = false;
        gl::Texture depth;  // DEPTH_COMPONENT32F, hardware compare enabled
        gl::Texture tint;   // RGBA16F: rgb transmittance, a nearest translucent depth
        // Per face (6 for cubes): depth only for the opaque pass (llvmpipe then never touches
        // the colour tiles), depth + colour for the translucent pass.
        std::vector<gl::Framebuffer> depthFaces, tintFaces;
    };

    // `withTint` false: opaque depth only (techniques that handle translucency themselves).
    explicit DepthAndTintMaps(bool withTint = true);
    void render(const ShadowFrame& frame);
    // Binds each light's maps to the units of its slot (see shaders/common/bindings.glsl); with
    // `rawDepth` the depth map is also bound, without comparison, to the raw units.
    void bind(bool rawDepth = false) const;
    // Shadow slot per light (-1: none) in the order the renderer gives lights; also in the light UBO.
    static std::vector<int> slots(const std::vector<scene::Light>& lights);
    // The directional light view-dependent techniques (cascades, LiSPSM, PSM) take over; -1: none.
    static int firstShadowedSun(const std::vector<scene::Light>& lights);
    std::size_t memoryBytes() const;
    std::vector<DebugView> debugViews() const;
    void setFiltering(GLenum filter);  // GL_NEAREST (hard) or GL_LINEAR (hardware 2x2 PCF)

    std::size_t lightCount() const { return slots_.size(); }
    int slot(std::size_t light) const { return slots_[light]; }
    // The unit where light `light`'s raw depth, or a technique's own map in its place, is bound.
    GLuint rawUnit(std::size_t light) const;
    const LightMaps& maps(std::size_t light) const { return maps_[light]; }
    const gl::Program& depthProgram() const { return depthProgram_; }  // opaque casters -> depth

private:
    void ensure(std::size_t light, int resolution, bool cube);
    std::vector<LightMaps> maps_;
    std::vector<int> slots_;
    std::vector<bool> cube_;
    gl::Program depthProgram_, tintProgram_;
    gl::Sampler rawSampler_{GL_NEAREST, GL_NEAREST};  // reads depth maps without comparison
    GLenum filter_ = GL_NEAREST;
    bool withTint_ = true;
};

}  // namespace penumbra::shadows
