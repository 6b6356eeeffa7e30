#pragma once
// The floor the bench measures every technique against: the same triangles drawn the least
// expensive way a shadowed frame can be drawn, with none of the renderer's generality. Like the
// renderer, it culls solids' back faces (render::Draw::solid) in both passes.
// - DepthOnly: one depth-only raster of every caster into the first light's map.
// - Lambert: that, then one camera pass of Lambert times one sampler2DShadow lookup into RGBA8.
// - Unshadowed: the camera pass of Lambert alone, no map: the floor of a shadowless frame.
// Timed with the renderer's own query ring (Shadow and Opaque passes), so ratios are like for like.
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Sampler.h"
#include "gl/Texture.h"
#include "render/FrameTimer.h"
#include "render/GpuScene.h"
#include "scene/Scene.h"

namespace penumbra::bench {

class FloorRenderer {
public:
    enum class Mode { DepthOnly, Lambert, Unshadowed };  // the order of bench::kFloors (Bench.h)
    // Uses the scene's first light (a directional one's box, a spot's cone; a point light's
    // first cube face). Throws InputError-like std::invalid_argument when the scene has no light.
    FloorRenderer(const scene::Scene& scene, Mode mode, int shadowResolution);

    // Draws into its own RGBA8 + depth target of width x height (framebuffer()).
    void render(float time, const scene::Camera& camera, int width, int height);
    GLuint framebuffer() const { return cameraFbo_.id(); }
    render::FrameTimer& timer() { return timer_; }
    std::size_t shadowMemoryBytes() const { return mode_ == Mode::Unshadowed ? 0 : depth_.memoryBytes(); }
    std::size_t trianglesPerFrame() const { return triangles_; }

private:
    const scene::Scene& scene_;
    Mode mode_;
    int resolution_;
    render::GpuScene gpu_;
    gl::Program depthProgram_, lambertProgram_;
    gl::Texture depth_;
    gl::Framebuffer depthFbo_;
    gl::Texture colour_, cameraDepth_;
    gl::Framebuffer cameraFbo_;
    int width_ = 0, height_ = 0;
    gl::Sampler compare_{GL_LINEAR, GL_LINEAR, true};
    render::FrameTimer timer_;
    std::uint64_t frame_ = 0;
    std::size_t triangles_ = 0;
};

}  // namespace penumbra::bench
