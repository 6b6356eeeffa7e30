#include "bench/FloorRenderer.h"

#include "gl/PassState.h"
#include "gpu/ShaderContract.h"
#include "shadows/LightSpace.h"

#include <stdexcept>

namespace penumbra::bench {

FloorRenderer::FloorRenderer(const scene::Scene& scene, Mode mode, int shadowResolution)
    : scene_(scene), mode_(mode), resolution_(shadowResolution), gpu_(scene) {
    if (scene.lights.empty()) throw std::invalid_argument("the floor passes need a scene with at least one light");
    depthProgram_ = gl::Program::build({.vertex = "src/bench/glsl/floor_depth.vert", .fragment = "src/bench/glsl/floor_depth.frag"});
    if (mode != Mode::DepthOnly)
        lambertProgram_ = gl::Program::build({.vertex = "src/bench/glsl/floor.vert",
                                              .fragment = "src/bench/glsl/floor_lambert.frag",
                                              .defines = {std::string("SHADOWED ") + (mode == Mode::Lambert ? "1" : "0")}});
    depth_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, resolution_, resolution_);
    depth_.setDepthCompare(true);  // as compare_: a shadow sampler reads it right with or without the sampler object
    depthFbo_.attach(GL_DEPTH_ATTACHMENT, depth_);
    depthFbo_.setNoColor();
    depthFbo_.checkComplete("floor depth map");
}

void FloorRenderer::render(float time, const scene::Camera& camera, int width, int height) {
    if (width != width_ || height != height_) {
        colour_ = gl::Texture::create2D(GL_RGBA8, width, height);
        cameraDepth_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, width, height);
        cameraFbo_ = gl::Framebuffer::colourAndDepth(colour_, cameraDepth_, "floor camera target");
        width_ = width;
        height_ = height;
    }
    const GLuint target = cameraFbo_.id();
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const scene::Light& light = scene_.lights.front();
    const shadows::LightSpace space = shadows::computeLightSpace(light, resolution_, scene_.boundsAt(time), camera, aspect);
    const std::vector<render::Draw> draws = gpu_.draws(time, camera.position);

    // No program current before the clears below: one deleted by a renderer case run before this
    // one would stay current, and NVIDIA validates it on a clear (a debug-output warning there).
    glUseProgram(0);
    timer_.beginFrame(frame_++);
    timer_.begin(render::Pass::Shadow);
    triangles_ = 0;
    if (mode_ != Mode::Unshadowed) {
        gl::ScopedPassState state(gl::PassState::depthOnly());
        depthFbo_.beginDepthPass(resolution_, resolution_);
        depthProgram_.set("uViewProj", space.viewProj[0]);
        for (const render::Draw& d : draws)
            if (d.castsShadow) {
                // Solids' back faces culled in both passes, as the renderer culls them: the floor
                // must not draw more than the renderer does. Both projections keep GL's winding.
                render::cullBackFacesOfSolid(d, true, space.viewProj[0]);
                gpu_.draw(d, depthProgram_);
                triangles_ += d.triangles;
            }
    }
    timer_.end(render::Pass::Shadow);

    timer_.begin(render::Pass::Opaque);
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, width, height);
    const float clear[4] = {0.05f, 0.06f, 0.08f, 1.0f}, farDepth = 1.0f;
    glClearNamedFramebufferfv(target, GL_COLOR, 0, clear);
    if (mode_ != Mode::DepthOnly) {
        gl::ScopedPassState state(gl::PassState::depthOnly());
        glClearNamedFramebufferfv(target, GL_DEPTH, 0, &farDepth);
        // The renderer's unit for 2D shadow maps: unit 0 is where GpuScene::draw binds a diffuse texture.
        depth_.bind(gpu::kUnitShadow2D);
        compare_.bind(gpu::kUnitShadow2D);
        lambertProgram_.set("uShadowMap", gpu::kUnitShadow2D);
        const glm::mat4 viewProj = camera.projection(aspect) * camera.view();
        lambertProgram_.set("uViewProj", viewProj);
        lambertProgram_.set("uShadowMatrix", shadows::kClipToTexture * space.viewProj[0]);
        const glm::vec3 toLight = light.type == scene::Light::Type::Directional ? -light.direction : glm::normalize(light.position);
        lambertProgram_.set("uToLight", glm::normalize(toLight));
        lambertProgram_.set("uBias", 0.002f);
        for (const render::Draw& d : draws)
            if (d.visible && !d.translucent) {
                render::cullBackFacesOfSolid(d, true, viewProj);
                gpu_.draw(d, lambertProgram_);
            }
        gl::Sampler::unbind(gpu::kUnitShadow2D);
        glUseProgram(0);  // likewise for whatever clears next
    }
    timer_.end(render::Pass::Opaque);
    timer_.endFrame();
}

}  // namespace penumbra::bench
