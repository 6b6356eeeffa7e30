#include "render/Renderer.h"

#include "gl/Debug.h"
#include "gl/PassState.h"
#include "gpu/ShaderContract.h"
#include "render/LightBlock.h"
#include "render/LightingProgram.h"
#include "render/MeshClusters.h"
#include "util/Digest.h"
#include "util/Log.h"
#include "util/Srgb.h"

#include <algorithm>
#include <chrono>
#include <span>
#include <stdexcept>
#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::render {

std::string chosenTechnique(const RenderOptions& options, const scene::Scene& scene) {
    if (!options.technique.empty()) return options.technique;
    return scene.technique.empty() ? "hard" : scene.technique;
}

static void configure(shadows::ShadowTechnique& technique, const RenderOptions& options) {
    const auto unknown = shadows::applyParameters(technique.parameters(), options.parameters);
    if (!options.strictParameters || unknown.empty()) return;
    std::string known;
    for (const auto& p : technique.parameters()) known += (known.empty() ? "" : ", ") + p.name;
    throw std::invalid_argument("technique '" + technique.name() + "' has no parameter '" + unknown.front() +
                                "'; its parameters: " + (known.empty() ? "none" : known));
}

static gl::Program fullscreenProgram(const char* fragment, std::vector<std::string> defines = {}) {
    return gl::Program::build({.vertex = "shaders/passes/fullscreen.vert", .fragment = fragment, .defines = std::move(defines)});
}

// The renderer's own passes (resolve, debug overlay, debug lines), built together so that a live
// reload replaces all of them or none.
// The resolve comes with and without fog: llvmpipe runs the code under a uniform `if` whatever
// the uniform says (measured: a fog-less scene paid 5 ms of a 31 ms frame for fog it never drew).
struct PassPrograms {
    gl::Program resolve, foggedResolve, overlay, lines;
};
static PassPrograms buildPassPrograms() {
    return {fullscreenProgram("shaders/passes/resolve.frag"), fullscreenProgram("shaders/passes/resolve.frag", {"FOG 1"}),
            fullscreenProgram("shaders/passes/overlay.frag"),
            gl::Program::build({.vertex = "shaders/passes/lines.vert", .fragment = "shaders/passes/lines.frag"})};
}

// The light layout the first frame will have (slots depend on the lights alone), so that the
// constructor builds, and checks, the program that frame uses.
static std::vector<std::string> initialLightLayout(const std::vector<scene::Light>& lights, bool translucentCasters) {
    const shadows::ShadowSlots slots = shadows::ShadowSlots::assign(lights);
    return lightLayoutDefines(packLights(lights, std::vector<shadows::LightSpace>(lights.size()), slots), slots.sun, translucentCasters);
}

// The faces a solid turns away from a pass drawn through `viewProj`, which keeps only the nearest
// depth (shadows::CasterSelection::nearestDepthOnly). GL tells front from back by the winding
// in window space. For x -> M x / w the Jacobian's determinant is det(M) / w^4, and clipping keeps
// w > 0 only, so the sign of det(M) says for every drawn triangle whether M keeps the world's
// winding: GL's own projections (glm::perspective, glm::ortho) turn the right-handed world into
// left-handed NDC, det < 0, and the world's counter-clockwise front faces stay counter-clockwise
// on screen. A transform with det > 0 mirrors them (GL_FRONT is then the face turned away); a
// degenerate one (a flattening projection) has no back.
static GLenum facesTurnedAway(const glm::mat4& viewProj) {
    const float det = glm::determinant(viewProj);
    const float scale = glm::length(viewProj[0]) * glm::length(viewProj[1]) * glm::length(viewProj[2]) * glm::length(viewProj[3]);
    if (!(std::abs(det) > 1e-6f * scale)) return GL_NONE;
    return det < 0.0f ? GL_BACK : GL_FRONT;
}

// Whether any tint pass has something to draw (SCENE_TRANSLUCENT_CASTERS).
static bool anyTranslucentCaster(const std::vector<Draw>& draws) {
    return std::any_of(draws.begin(), draws.end(), [](const Draw& d) { return d.castsShadow && d.translucent; });
}

Renderer::Renderer(scene::Scene& scene, RenderOptions options)
    : scene_(scene), options_(std::move(options)), gpu_(scene, static_cast<float>(options_.anisotropy), options_.clusterCasters), lightBlock_(sizeof(gpu::LightBlock), nullptr) {
    if (scene_.lights.size() > static_cast<std::size_t>(gpu::kMaxLights))
        throw std::invalid_argument("the scene has " + std::to_string(scene_.lights.size()) + " lights; at most " +
                                    std::to_string(gpu::kMaxLights) + " are supported");
    int projectors = 0, shadowed2D = 0, shadowedCube = 0;
    for (const auto& l : scene_.lights) {
        projectors += l.type == scene::Light::Type::Projector;
        if (l.shadow.enabled) (l.type == scene::Light::Type::Point ? shadowedCube : shadowed2D) += 1;
    }
    if (projectors > gpu::kMaxProjectors)
        throw std::invalid_argument("the scene has " + std::to_string(projectors) + " projectors; at most " +
                                    std::to_string(gpu::kMaxProjectors) + " are supported");
    if (shadowed2D > gpu::kMaxShadow2D || shadowedCube > gpu::kMaxShadowCube)
        log::warn("{}: {} directional/spot/projector and {} point lights cast shadows; only the first {} and {} will "
                  "(set \"shadow\": {\"enabled\": false} on the others to silence this)",
                  scene_.source.string(), shadowed2D, shadowedCube, gpu::kMaxShadow2D, gpu::kMaxShadowCube);
    options_.technique = chosenTechnique(options_, scene_);
    technique_ = shadows::createTechnique(options_.technique);
    configure(*technique_, options_);
    lightLayout_ = withOutputDefines(initialLightLayout(scene_.lights, anyTranslucentCaster(gpu_.draws(0.0f, scene_.camera.position))));
    lightingDefines_ = lightingDefines(*technique_);
    lighting_ = buildLighting(*technique_, lightingDefines_);
    PassPrograms passes = buildPassPrograms();
    resolve_ = std::move(passes.resolve);
    foggedResolve_ = std::move(passes.foggedResolve);
    overlay_ = std::move(passes.overlay);
    lines_ = std::move(passes.lines);
    releaseColour_ = gl::Texture::create2D(GL_RGBA8, 1, 1);  // made now: a soak counts live GL objects
    releaseTarget_ = gl::Framebuffer::colourOnly(releaseColour_, -1, "texture release draw");
}

void Renderer::setTechnique(const std::string& name) {
    auto technique = shadows::createTechnique(name);
    configure(*technique, options_);
    std::vector<std::string> defines = lightingDefines(*technique);
    LightingPrograms lighting = buildLighting(*technique, defines);
    technique_ = std::move(technique);
    lighting_ = std::move(lighting);
    lightingDefines_ = std::move(defines);
    oit_.reset();  // its lighting variants include the old technique's lookup
    options_.technique = name;
    releaseBoundTextures();
}

// llvmpipe holds the textures of the last draw's texture units until a later draw binds others,
// though they are deleted: a technique's maps would outlive it until the next frame's first draw.
// A draw that rasterises nothing, with a program that samples only the renderer's own targets,
// hands them back now. (The float target's resolve pass did so at the end of every frame.)
// Into a 1x1 target of its own, and the framebuffers bound before are bound again: a window's UI
// may draw after a technique change in its panel.
void Renderer::releaseBoundTextures() {
    GLint drawBound = 0, readBound = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawBound);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readBound);
    gl::unbindTextureUnits(gpu::kLightingUnits);
    releaseTarget_.bind();
    {
        const gl::ScopedPassState scope(gl::PassState::fullscreen());
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, 0, 0);
        resolve_.use();
        emptyVao_.bind();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDisable(GL_SCISSOR_TEST);
    }
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawBound));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readBound));
}

std::string Renderer::reloadShaders() {
    try {
        auto technique = shadows::createTechnique(technique_->name());
        shadows::ParameterValues current;
        for (const auto& p : technique_->parameters()) current.emplace_back(p.name, p.text());
        shadows::applyParameters(technique->parameters(), current);
        std::vector<std::string> defines = lightingDefines(*technique);
        LightingPrograms lighting = buildLighting(*technique, defines);
        PassPrograms passes = buildPassPrograms();
        technique_ = std::move(technique);
        lighting_ = std::move(lighting);
        lightingDefines_ = std::move(defines);
        resolve_ = std::move(passes.resolve);
        foggedResolve_ = std::move(passes.foggedResolve);
        overlay_ = std::move(passes.overlay);
        lines_ = std::move(passes.lines);
        oit_.reset();  // rebuilt from the new files on first use
        depthFirst_.reset();
        releaseBoundTextures();  // the old technique's maps, as setTechnique hands them back
        return "";
    } catch (const std::exception& e) {
        return e.what();
    }
}

void Renderer::setOutputMode(OutputMode mode, int debugLight) {
    options_.output = mode;
    options_.debugLight = debugLight;
}

void Renderer::setAnisotropy(int anisotropy) {
    options_.anisotropy = std::clamp(anisotropy, 1, 16);
    gpu_.setAnisotropy(static_cast<float>(options_.anisotropy));
}

int Renderer::effectiveResolution(const scene::Light& light) const {
    return options_.shadowResolution > 0 ? options_.shadowResolution : light.shadow.resolution;
}

// The float colour target only for frames that resolve it: a frame shaded into sRGB never needs
// it (14.7 MB at 1280x720, 133 MB at 3840x2160).
void Renderer::ensureTargets(int w, int h, bool floatTarget) {
    if (w != targetW_ || h != targetH_) {
        depth_ = gl::Texture::create2D(GL_DEPTH_COMPONENT32F, w, h);
        depth_.setFilter(GL_NEAREST, GL_NEAREST);
        hdr_ = {};
        hdrFbo_ = {};
        targetW_ = w;
        targetH_ = h;
    }
    if (!floatTarget || hdr_.id() != 0) return;
    hdr_ = gl::Texture::create2D(GL_RGBA32F, w, h);
    hdr_.setFilter(GL_NEAREST, GL_NEAREST);
    hdrFbo_ = gl::Framebuffer::colourAndDepth(hdr_, depth_, "main colour target");
}

// One frame: its set-up (draws, light spaces, the light block, the programs for its light layout),
// the lights' shadow maps, then the camera's passes (opaque, translucent, resolve).
void Renderer::render(float time, const scene::Camera& camera, int width, int height, GLuint target, Columns columns) {
    if (width <= 0 || height <= 0) return;  // minimised: nothing to draw into
    srgbFrame_ = shadesIntoSrgb();
    ensureTargets(width, height, !srgbFrame_);
    const FrameInputs frame = prepareFrame(time, camera, width, height);
    // Every pass declares its state; between passes GL's initial state holds (no culling:
    // planes and panes are single-sided geometry seen from both sides).
    gl::applyPassState({});
    timer_.beginFrame(frameIndex_);
    renderShadowMaps(frame);
    renderCameraPasses(frame, target, columns);
    // No program of this renderer's stays current: a frame shaded straight into sRGB ends on a
    // lighting program, whose textures go with the renderer, and a driver may check the current
    // program at the caller's next clear (see gl::unbindTextureUnits).
    glUseProgram(0);
    timer_.endFrame();
}

Renderer::FrameInputs Renderer::prepareFrame(float time, const scene::Camera& camera, int width, int height) {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    FrameInputs frame{time, camera, aspect, width, height, camera.projection(aspect) * camera.view(), gpu_.draws(time, camera.position)};
    const std::vector<Draw>& draws = frame.draws;
    // Light spaces for this frame: objects move, so the directional fit follows them; a sun's box
    // is held from last frame's while it still holds the view (RenderOptions::holdSunBox).
    frame.bounds = scene_.boundsAt(time);
    std::vector<shadows::LightSpace>& spaces = frame.spaces;
    if (!options_.holdSunBox || lastSpaces_.size() != scene_.lights.size()) lastSpaces_.clear();
    for (std::size_t i = 0; i < scene_.lights.size(); ++i)
        spaces.push_back(shadows::computeLightSpace(scene_.lights[i], effectiveResolution(scene_.lights[i]), frame.bounds, camera,
                                                    aspect, lastSpaces_.empty() ? nullptr : &lastSpaces_[i]));
    lastSpaces_ = spaces;
    slots_ = shadows::ShadowSlots::assign(scene_.lights);
    frame.block = packLights(scene_.lights, spaces, slots_);
    const gpu::LightBlock& block = frame.block;
    lightBlock_.update(0, sizeof(block), &block);
    lightBlock_.bindBase(GL_UNIFORM_BUFFER, gpu::kLightBlockBinding);
    // A material made translucent at run time rebuilds the programs once (useLightLayout).
    frame.translucentCasters = anyTranslucentCaster(draws);
    useLightLayout(withOutputDefines(lightLayoutDefines(block, slots_.sun, frame.translucentCasters)));
    return frame;
}

// The lights' maps (the technique's passes), with the frame's casters offered through
// shadows::ShadowFrame: which a pass selects, where in its map they write, and their draws.
void Renderer::renderShadowMaps(const FrameInputs& in) {
    const std::vector<Draw>& draws = in.draws;
    const gpu::LightBlock& block = in.block;
    const scene::Camera& camera = in.camera;
    const glm::mat4& cameraViewProj = in.cameraViewProj;
    const float time = in.time, aspect = in.aspect;
    const int width = in.width, height = in.height;
    gl::DebugGroup group("shadow maps");
    timer_.begin(Pass::Shadow);
    shadows::ShadowFrame frame;
    frame.lights = &scene_.lights;
    frame.lightSpaces = &in.spaces;
    frame.slots = &slots_;
    frame.frameIndex = frameIndex_++;
    frame.camera = &camera;
    frame.aspect = aspect;
    frame.sceneBounds = in.bounds;
    frame.surfaceBounds = [&] {
        std::vector<scene::Bounds> boxes;
        for (const Draw& d : draws) gpu_.addSurfaceBounds(d, boxes);
        return boxes;
    };
    frame.reuseStillCasters = options_.reuseStillCasters;
    frame.holdSunBox = options_.holdSunBox;
    frame.translucentCasters = in.translucentCasters;
    frame.drawSurfaces = [&](shadows::DrawPrograms programs, int onlyObject) {
        for (const Draw& d : draws)
            if (d.visible && !d.translucent && (onlyObject < 0 || d.object == static_cast<std::size_t>(onlyObject))) {
                cullBackFacesOfSolid(d, options_.cullSolidBackFaces, cameraViewProj);  // seen from the camera, as drawSurfaces is
                gpu_.draw(d, programs.of(*d.material));
            }
        glDisable(GL_CULL_FACE);
    };
    frame.scene = &scene_;
    frame.time = time;
    frame.viewport = {width, height};
    // The views fitted first: flatCasterNeeds asks for the reach of this frame's maps.
    technique_->fitToView(frame);
    shadowTriangles_.assign(scene_.lights.size(), 0);
    const CasterQueries casters(draws, flatCasterNeeds(draws, block), gpu_, block, flatCasterReach().texels);
    frame.casterBounds = [&](const shadows::CasterSelection& selection) { return casters.bounds(selection); };
    frame.casterTexels = [&](const shadows::CasterSelection& selection) { return casters.texels(selection); };
    frame.casterBoxes = [&](const shadows::CasterSelection& selection) { return casters.boxes(selection); };
    frame.casterDigest = [&](const shadows::CasterSelection& selection) { return casters.digest(selection); };
    frame.drawCasters = [&](shadows::DrawPrograms programs, const shadows::CasterSelection& selection) {
        drawCasters(casters, programs, selection);
    };
    technique_->renderMaps(frame);
    timer_.end(Pass::Shadow);
}

// A caster pass's draws: the selection's casters, back faces of solids culled where only the
// nearest depth counts, a ground carrying casters scissored to where their lookups read it; the
// triangles drawn counted per light.
void Renderer::drawCasters(const CasterQueries& casters, shadows::DrawPrograms programs, const shadows::CasterSelection& selection) {
    if (selection.lightViewProj) {
        programs.plain->set("uLightViewProj", *selection.lightViewProj);
        programs.textured->set("uLightViewProj", *selection.lightViewProj);
    }
    const GLenum away = options_.cullSolidBackFaces && selection.nearestDepthOnly && selection.lightViewProj
                            ? facesTurnedAway(*selection.lightViewProj) : GL_NONE;
    glCullFace(away == GL_NONE ? GL_BACK : away);
    const glm::mat4 through = selection.lightViewProj.value_or(glm::mat4(1.0f));
    for (const Draw& d : casters.draws()) {
        if (!casters.selected(d, selection)) continue;
        cullBackFacesOfSolid(d, away != GL_NONE, through);
        const auto draw = [&] {
            return selection.cull ? gpu_.drawInside(d, programs.of(*d.material), *selection.cull, selection.cullPlanes)
                                  : (gpu_.draw(d, programs.of(*d.material)), d.triangles);
        };
        // A ground carrying casters, drawn only where their lookups read it (flatCasterNeeds):
        // near the still ones, and apart near the moving ones, so that each rectangle
        // depends on its casters alone.
        const NearCasters* near = selection.map && selection.lightViewProj ? casters.nearOf(d, selection) : nullptr;
        std::size_t drawn = 0;
        if (!near) {
            drawn = draw();
        } else {
            glEnable(GL_SCISSOR_TEST);
            for (const glm::ivec4& t : {casters.nearTexels(near->still, selection), casters.nearTexels(near->moving, selection)}) {
                if (t.x >= t.z || t.y >= t.w) continue;
                glScissor(t.x, t.y, t.z - t.x, t.w - t.y);
                drawn += draw();
            }
            const glm::ivec4 t = selection.map->texels;  // the pass's own scissor back
            glScissor(t.x, t.y, t.z - t.x, t.w - t.y);
            if (!selection.map->scissored) glDisable(GL_SCISSOR_TEST);
        }
        if (selection.light >= 0 && static_cast<std::size_t>(selection.light) < shadowTriangles_.size())
            shadowTriangles_[static_cast<std::size_t>(selection.light)] += drawn;
    }
    glCullFace(GL_BACK);
    glDisable(GL_CULL_FACE);  // as the pass set it (PassState::cullFace is false in every caster pass)
}

// The camera's passes: opaque surfaces (after the tint split and the lights' and shadows' reach
// chose each draw's programs), translucent ones, then the resolve into `target`.
void Renderer::renderCameraPasses(const FrameInputs& in, GLuint target, Columns columns) {
    const std::vector<Draw>& draws = in.draws;
    const scene::Camera& camera = in.camera;
    const float aspect = in.aspect;
    const int width = in.width, height = in.height;
    // A column range scissors every camera pass, clears included, and the output.
    const int first = std::clamp(columns.first, 0, width), last = columns.last < 0 ? width : std::clamp(columns.last, first, width);
    const bool partial = first > 0 || last < width;
    if (partial) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(first, 0, last - first, height);
    }
    const TintSplit tintSplit = splitReceivers(in, PixelRect{first, 0, last, height}, partial);
    const GLuint frameFbo = srgbFrame_ ? srgb_.begin(target, width, height, depth_) : hdrFbo_.id();
    // An sRGB frame's opaque surfaces write its bytes unblended, their shader encoding sRGB itself
    // (ENCODE_SRGB_IN_SHADER, SrgbTarget::bytesFramebuffer). What blends over them (translucent
    // surfaces, debug lines) draws through the sRGB view, which GL encodes and blends in linear.
    // The clear goes with the opaque pass: llvmpipe runs each framebuffer binding's commands as
    // a scene of its own, and a clear alone in one costs a store and a load of every tile.
    const GLuint opaqueFbo = srgbFrame_ ? srgb_.bytesFramebuffer() : frameFbo;
    bool srgbView = false;
    const auto throughSrgbView = [&] {
        if (!srgbFrame_ || srgbView) return;
        glBindFramebuffer(GL_FRAMEBUFFER, frameFbo);
        glEnable(GL_FRAMEBUFFER_SRGB);
        srgbView = true;
    };
    clearCameraTarget(opaqueFbo, width, height);
    {
        gl::DebugGroup group("opaque");
        timer_.begin(Pass::Opaque);
        drawDepthFirst(draws, camera, aspect);
        drawSurfaces(draws, false, camera, aspect, &tintSplit);
        if (options_.debugOverlay) {
            throughSrgbView();  // linear colours
            drawDebugLines(camera, aspect);
        }
        timer_.end(Pass::Opaque);
    }
    drawTranslucentPass(in, tintSplit, throughSrgbView);
    {
        gl::DebugGroup group("resolve");
        timer_.begin(Pass::Post);
        if (srgbFrame_) {
            glDisable(GL_FRAMEBUFFER_SRGB);
            srgb_.finish(target, width, height);
        } else {
            resolve(target, width, height, camera, aspect);
        }
        if (options_.debugOverlay) drawOverlay(target, width, height);
        timer_.end(Pass::Post);
    }
    if (partial) glDisable(GL_SCISSOR_TEST);
}

// Each receiver's pieces for this frame's camera passes (TintSplit): the tint split, then the
// lights' and their shadows' reach; the choice's tally and CPU time go to tintShading_.
Renderer::TintSplit Renderer::splitReceivers(const FrameInputs& in, PixelRect area, bool scissored) {
    const auto splitStart = std::chrono::steady_clock::now();
    footprintCells_.nextFrame();
    reachCells_.nextFrame();
    shadowCells_.nextFrame();
    TintSplit split = splitByTint(in.draws, in.block, in.cameraViewProj, in.width, in.height, area);
    split.scissored = scissored;
    addLightReach(split, in.draws, in.block, in.cameraViewProj, in.width, in.height);
    addShadowReach(split, in.draws, in.block, in.cameraViewProj, in.width, in.height);
    tintShading_ = tally(split, in.draws);
    tintShading_.footprintsMade = footprintCells_.madeThisFrame() + reachCells_.madeThisFrame() + shadowCells_.madeThisFrame();
    tintShading_.cpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - splitStart).count();
    return split;
}

// The camera target cleared: the background, far depth.
void Renderer::clearCameraTarget(GLuint fbo, int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, width, height);
    // Alpha 1 marks a pixel a surface of this renderer covers (debug channels: any surface; region
    // views: its own, setReceivers); the shaded background is 1 too unless another renderer owns it.
    const bool shaded = options_.output == OutputMode::Shaded;
    glm::vec4 clear = shaded ? glm::vec4(scene_.background, ownPixelsOnly_ ? 0.0f : 1.0f) : glm::vec4(0.0f);
    if (srgbFrame_) clear = glm::vec4(util::linearToSrgb(glm::vec3(clear)), clear.a);
    // NVIDIA validates the current program's samplers on a clear: another engine's program, still
    // current though deleted, must not be judged against this frame's texture units.
    glUseProgram(0);
    glClearNamedFramebufferfv(fbo, GL_COLOR, 0, &clear.x);
    const float farDepth = 1.0f;
    glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &farDepth);
}

// Translucent surfaces over the opaque frame: sorted and blended (through the sRGB view when the
// frame is sRGB), or one of the order-independent modes into the float target.
void Renderer::drawTranslucentPass(const FrameInputs& in, const TintSplit& tintSplit, const std::function<void()>& throughSrgbView) {
    gl::DebugGroup group("translucent");
    timer_.begin(Pass::Translucent);
    // Debug channels show the nearest opaque surface, or with debugTranslucent the nearest
    // surface (drawSurfaces: depth-tested and written, not blended).
    const bool shaded = options_.output == OutputMode::Shaded;
    const TransparencyMode mode = options_.transparency;
    const std::vector<Draw>& draws = in.draws;
    if (shaded ? isSorted(mode) : options_.debugTranslucent) {
        const bool anyTranslucent = std::any_of(draws.begin(), draws.end(), [](const Draw& d) { return d.visible && d.translucent; });
        if (anyTranslucent) throughSrgbView();
        fogDepth_ = fogInShading() && anyTranslucent ? &srgb_.opaqueDepthCopy(depth_) : nullptr;
        drawSurfaces(draws, true, in.camera, in.aspect, &tintSplit);
        fogDepth_ = nullptr;
    } else if (shaded) {
        if (!oit_) oit_ = std::make_unique<OrderIndependentTransparency>(technique_->lookupShader(), lightingDefines_);
        bindLightingUnits();
        oit_->render(mode, options_.peelLayers, gpu_, draws,
                     [&](const gl::Program& p) { prepareLighting(p, true, in.camera, in.aspect); }, hdrFbo_, depth_, in.width,
                     in.height);
    }
    timer_.end(Pass::Translucent);
}

// Lights added, removed, retyped or shadowed differently change the layout the lighting
// programs are specialised to, and a technique parameter may change its lookup's compile-time
// choices: rebuild them (rare; a compile costs ~0.1-1 s on llvmpipe).
void Renderer::useLightLayout(std::vector<std::string> layout) {
    lightLayout_ = std::move(layout);
    std::vector<std::string> defines = lightingDefines(*technique_);
    if (defines == lightingDefines_) return;
    lighting_ = buildLighting(*technique_, defines);
    lightingDefines_ = std::move(defines);
    oit_.reset();
}

LightingPrograms Renderer::buildLighting(const shadows::ShadowTechnique& technique, std::vector<std::string> defines) const {
    bool anyTextured = false;
    for (const auto& object : scene_.objects)
        for (const auto& part : scene_.meshes[static_cast<std::size_t>(object.mesh)].parts)
            anyTextured = anyTextured || scene_.material(object, part).diffuseTexture >= 0;
    return {technique.lookupShader(), std::move(defines), anyTextured};
}

std::vector<std::string> Renderer::lightingDefines(const shadows::ShadowTechnique& technique) const {
    std::vector<std::string> defines = lightLayout_;
    for (auto& d : technique.lookupDefines()) defines.push_back(std::move(d));
    return defines;
}

// The technique's world-space lines (cascade frusta, ...), depth-tested against the scene.
void Renderer::drawDebugLines(const scene::Camera& camera, float aspect) {
    const auto lines = technique_->debugLines();
    if (lines.empty()) return;
    std::vector<glm::vec3> vertices;  // position, colour, interleaved
    for (const auto& l : lines) vertices.insert(vertices.end(), {l.a, l.color, l.b, l.color});
    const std::size_t bytes = vertices.size() * sizeof(glm::vec3);
    if (lineVertices_.size() < bytes) {
        lineVertices_ = gl::Buffer(bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
        glVertexArrayVertexBuffer(lineVao_.id(), 0, lineVertices_.id(), 0, 2 * sizeof(glm::vec3));
        lineVao_.attribute(0, 0, 3, 0);
        lineVao_.attribute(1, 0, 3, sizeof(glm::vec3));
    }
    lineVertices_.update(0, bytes, vertices.data());
    lines_.set("uViewProj", camera.projection(aspect) * camera.view());
    lines_.use();
    lineVao_.bind();
    gl::PassState state = gl::PassState::depthOnly();
    state.depthFunc = GL_LEQUAL;
    const gl::ScopedPassState scope(state);
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(vertices.size() / 2));
}

void Renderer::prepareLighting(const gl::Program& program, bool translucent, const scene::Camera& camera, float aspect) {
    program.set("uViewProj", camera.projection(aspect) * camera.view());
    program.set("uCameraPos", camera.position);
    program.set("uAmbient", scene_.ambient);
    program.set("uTranslucentPass", translucent ? 1 : 0);
    program.set("uOutputMode", static_cast<int>(options_.output));
    program.set("uDebugLight", options_.debugLight);
    program.set("uShowBehind", showsBehind() ? 1 : 0);
    if (fogInShading()) setFogUniforms(program, camera, aspect);
    technique_->bindLookup(program);
}

void Renderer::bindLightingUnits() const {
    placeholders_.bindAll();
    if (showsBehind()) behind_->bind(gpu::kUnitBehindDepth);
    if (fogDepth_) fogDepth_->bind(gpu::kUnitOpaqueDepth);
    int projector = 0;
    for (const auto& light : scene_.lights)
        if (light.type == scene::Light::Type::Projector && projector < gpu::kMaxProjectors)
            gpu_.image(light.image).bind(gpu::kUnitProjector + static_cast<unsigned>(projector++));
}

// Parts of up to this many triangles are split on the screen (drawn once per rectangle): llvmpipe
// transforms every vertex of a draw however little of it the scissor keeps.
static constexpr std::size_t kSplitTriangles = 4096;
// Beyond this many rectangles a receiver is split around the footprints' bounding rectangle alone.
// (The glass scene's floor, split three ways, takes 61: 11 whole, 28 behind layers, 22 untinted.)
static constexpr std::size_t kMostSplitDraws = 128;
// Receivers covering less of the frame than this keep the whole lookup.
static constexpr double kLeastSwitchedShare = 0.03;
static constexpr double kLeastSwitchedTranslucentShare = 0.005;
// Levels of quarters (cellsOf) whose reach rectangles bound a projector's or spot's light on a
// draw cheap to repeat (addLightReach): up to 8 x 8 cells.
static constexpr int kReachLevels = 3;
// The same for a receiver's shadow footprints (addShadowReach): up to 4 x 4 cells. They are made
// per caster, not per bounded light: at 8 x 8 the default scene's split took 0.68 ms of CPU per
// frame, at 4 x 4 0.36 (0.11 without the shadow reach), the ground's skipped rectangles a little
// smaller.
static constexpr int kShadowReachLevels = 2;

// The pixels of `area` that draw `d` may cover, or none where they are under `leastShare` of the
// width x height frame: a small receiver stays with one program. On llvmpipe each switch between
// programs costs more than a few thousand pixels' lookups save (scenes/street.json, 190 draws:
// hard's opaque pass 88 against 67-69 ms when every draw chose).
static PixelRect switchedRect(const Draw& d, const glm::mat4& viewProj, int width, int height, const PixelRect& area, double leastShare) {
    const PixelRect own = screenRect(d.worldBounds, viewProj, width, height).intersected(area);
    const double ownArea = double(own.x1 - own.x0) * double(own.y1 - own.y0);
    return own.empty() || ownArea < leastShare * double(width) * double(height) ? PixelRect{} : own;
}

namespace {

// The grid the not-behind rectangles are grown to (pixels).
constexpr int kSnap = 32;

// The union of `rects` grown to a grid of kSnap pixels, within `own`, as few rectangles: the grid
// cells any of them touches, in runs along each row of cells, a run continuing the one above it
// where it spans the same cells. The footprints' cells come many and overlapping (thousands over
// scenes/street.json's ground, where keeping only rectangles no other one contains took 2 ms a
// frame).
std::vector<PixelRect> snapped(const PixelRect& own, const std::vector<PixelRect>& rects) {
    if (own.empty() || rects.empty()) return {};
    const int cx0 = own.x0 / kSnap, cy0 = own.y0 / kSnap, cols = (own.x1 + kSnap - 1) / kSnap - cx0,
              rows = (own.y1 + kSnap - 1) / kSnap - cy0;
    std::vector<char> touched(static_cast<std::size_t>(cols * rows), 0);
    for (const PixelRect& r : rects) {
        const PixelRect in = r.intersected(own);
        if (in.empty()) continue;
        for (int y = in.y0 / kSnap; y <= (in.y1 - 1) / kSnap; ++y)
            for (int x = in.x0 / kSnap; x <= (in.x1 - 1) / kSnap; ++x) touched[static_cast<std::size_t>((y - cy0) * cols + x - cx0)] = 1;
    }
    std::vector<PixelRect> runs;
    std::vector<std::size_t> above, current;  // indices into runs of the last row's runs, this row's
    for (int y = 0; y < rows; ++y) {
        current.clear();
        for (int x = 0; x < cols;) {
            if (!touched[static_cast<std::size_t>(y * cols + x)]) {
                ++x;
                continue;
            }
            const int first = x;
            while (x < cols && touched[static_cast<std::size_t>(y * cols + x)]) ++x;
            const PixelRect run = PixelRect{(cx0 + first) * kSnap, (cy0 + y) * kSnap, (cx0 + x) * kSnap, (cy0 + y + 1) * kSnap}.intersected(own);
            const auto same = std::find_if(above.begin(), above.end(), [&](std::size_t i) { return runs[i].x0 == run.x0 && runs[i].x1 == run.x1; });
            if (same != above.end()) {
                runs[*same].y1 = run.y1;
                current.push_back(*same);
            } else {
                current.push_back(runs.size());
                runs.push_back(run);
            }
        }
        above.swap(current);
    }
    return runs;
}

using RectsByLookup = std::array<std::vector<PixelRect>, 3>;  // TintLookup's order

// `own` cut by `first`: its pixels on the `settledInside` side of it take lookup `settled`, the
// others are cut again by `second` into `inSecond` and `offSecond`.
RectsByLookup cutTwice(const PixelRect& own, const std::vector<PixelRect>& first, bool settledInside, TintLookup settled,
                       const std::vector<PixelRect>& second, TintLookup inSecond, TintLookup offSecond) {
    RectsByLookup rects;
    RectPartition byFirst = partition(own, first);
    rects[static_cast<int>(settled)] = std::move(settledInside ? byFirst.inside : byFirst.outside);
    for (const PixelRect& r : settledInside ? byFirst.outside : byFirst.inside) {
        RectPartition bySecond = partition(r, second);
        auto &in = rects[static_cast<int>(inSecond)], &off = rects[static_cast<int>(offSecond)];
        in.insert(in.end(), bySecond.inside.begin(), bySecond.inside.end());
        off.insert(off.end(), bySecond.outside.begin(), bySecond.outside.end());
    }
    return rects;
}

// An opaque receiver's `own` in disjoint rectangles per lookup: the pixels some not-behind
// footprint may cover take the whole lookup, the rest of the footprints' pixels the behind-layers
// build, the others none.
RectsByLookup rectsByLookup(const PixelRect& own, const std::vector<PixelRect>& notBehind, const std::vector<PixelRect>& tinted) {
    return cutTwice(own, snapped(own, notBehind), true, TintLookup::Whole, tinted, TintLookup::BehindLayers, TintLookup::Untinted);
}

// A translucent receiver's: pixels where every other layer lies behind it (off every not-in-front
// footprint) take the build for its own layers alone (Untinted), the rest where every other layer
// lies in front of it (off every not-behind footprint) the build that divides its own layers out
// of their product (BehindLayers), and pixels that may have layers on both sides the whole lookup.
RectsByLookup translucentRectsByLookup(const PixelRect& own, const std::vector<PixelRect>& notBehind,
                                       const std::vector<PixelRect>& notInFront) {
    return cutTwice(own, snapped(own, notInFront), false, TintLookup::Untinted, snapped(own, notBehind), TintLookup::Whole,
                    TintLookup::BehindLayers);
}

// The boxes `cut` gives (tintFootprintNotBehind, tintFootprintNotInFront) for the parts of `box`
// under `model` (a world box under the identity, or a turned receiver's own): the box's own when
// the cut leaves nothing of it or at the finest level, else those of its quarters across its two
// longest sides (in the world). Where a receiver is not behind a caster is a strip at the caster's
// foot or across it, whose box may span the whole footprint; halving around it keeps the rest
// behind (8 x 8 cells at most). A translucent receiver's cells are of its own box, 8 x 8 too: a
// cell's depth span along the light (a pane turned from it) sets how near another pane may come
// before the cell counts as beside it. Glass scene, cssm2: the green pane's pixels that keep the
// whole lookup 11,008 with 4 x 4 cells, 3,008 with 8 x 8 (4,928 with 8 x 8 only for the
// not-in-front cells). The split's CPU time per frame (stats.json tint_shading cpu_ms, medians of
// 10 frames at 640 x 360): 1.64-1.67 ms with both sides cut in one descent (sideCellsOf), 1.79-1.81
// cut apart, 1.07 before the not-in-front cells; the not-behind cells at 4 x 4 saved 0.1 ms and
// gave a strip of the red pane back to the whole lookup.
constexpr int kFinestLevel = 3, kFinestTranslucentLevel = 3;
// How far from its texel an opaque receiver's behind-layers test reads the tint map: the bilinear
// fetch's texel, and one for rounding.
constexpr float kBehindTestReachTexels = 2.0f;

// A translucent receiver's cells, both sides at once (tintFootprintSides), each side as far down
// as it is not empty.
template <class Emit>
void sideCellsOf(const gpu::LightData& light, const OrientedBox& caster, const scene::Bounds& box, const glm::mat4& model, float pad,
                 int level, bool notBehind, bool notInFront, Emit&& emit) {
    const TintSides sides = tintFootprintSides(light, caster, OrientedBox(box, model), pad, SideTolerance::Surface, notBehind, notInFront);
    if (sides.empty()) return;
    if (level == kFinestTranslucentLevel) {
        emit(sides);
        return;
    }
    for (const scene::Bounds& q : quarters(box, model))
        sideCellsOf(light, caster, q, model, pad, level + 1, !sides.notBehind.empty(), !sides.notInFront.empty(), emit);
}

// The screen rectangles of a receiver's footprints (tinted), and of their parts that may be not
// behind the caster (notBehind; the footprints themselves without a behind-layers build) and, for
// a translucent receiver, not in front of it (notInFront), within `own`, over every shadowed light
// and translucent caster.
struct ReceiverFootprints {
    std::vector<PixelRect> tinted, notBehind, notInFront;
};
// The non-empty screen rectangles of world boxes `parts` within `own`, appended to `rects`.
void appendOnScreen(std::vector<PixelRect>& rects, std::span<const scene::Bounds> parts, const PixelRect& own,
                    const glm::mat4& viewProj, int width, int height) {
    for (const scene::Bounds& part : parts) {
        const PixelRect rect = screenRect(part, viewProj, width, height).intersected(own);
        if (!rect.empty()) rects.push_back(rect);
    }
}

// A translucent receiver's cells are its own box's (a thin pane's world box holds mostly air); an
// opaque one's those of its footprint's world box. The footprints and their cells are world boxes
// that depend on the receiver, the caster and the light alone: `memo` keeps them across frames
// (the clipping that makes them was most of the split's CPU time), and only their screen
// rectangles are taken anew. A sun's map follows the view (LightSpace), so its footprints are
// made again when the camera moves; a spot's, a projector's and a point light's are not.
ReceiverFootprints footprintsOf(const Draw& d, const PixelRect& own, const std::vector<OrientedBox>& casters,
                                const gpu::LightBlock& block, float reach, bool behindBuild, const glm::mat4& viewProj, int width,
                                int height, FrameMemo<FootprintCells>& memo) {
    const OrientedBox receiver(d.meshBounds, d.model);
    ReceiverFootprints f;
    const auto addOnScreen = [&](std::vector<PixelRect>& rects, const std::vector<scene::Bounds>& parts) {
        appendOnScreen(rects, parts, own, viewProj, width, height);
    };
    for (int l = 0; l < block.count.x; ++l) {
        const gpu::LightData& light = block.lights[l];
        if (light.cone.w < 0.0f) continue;  // casts no shadow, so no colour either
        const float pad = lookupPadTexels(reach, light);
        // Whether an opaque receiver is behind every layer is the behind-layers build's test alone
        // (colouredByTint's behindEveryLayer: the bilinear tint at its texel, 2 x 2 texels), so
        // only casters that reach those texels count there; the whole lookup's reach (`pad`)
        // decides only whether any tint is read at all.
        const float behindPad = kBehindTestReachTexels + light.shadow.z + 2.0f;
        for (const OrientedBox& caster : casters) {
            bool made = false;
            FootprintCells& cells =
                memo.at(util::Digest().add(light, caster.corners, d.meshBounds, d.model, d.translucent, pad, behindPad).value(), made);
            if (made) cells.footprint = tintFootprint(light, caster, receiver, pad);
            const PixelRect r = screenRect(cells.footprint, viewProj, width, height).intersected(own);
            if (r.empty()) continue;
            f.tinted.push_back(r);
            if (!behindBuild) {
                f.notBehind.push_back(r);
                continue;
            }
            if (!cells.celled) {
                if (d.translucent) {
                    sideCellsOf(light, caster, d.meshBounds, d.model, pad, 0, true, true, [&](const TintSides& sides) {
                        if (!sides.notBehind.empty()) cells.notBehind.push_back(sides.notBehind);
                        if (!sides.notInFront.empty()) cells.notInFront.push_back(sides.notInFront);
                    });
                } else {
                    cellsOf([&](const OrientedBox& cell) { return tintFootprintNotBehind(light, caster, cell, behindPad); },
                            cells.footprint, kFinestLevel, [&](const scene::Bounds& part) { cells.notBehind.push_back(part); });
                }
                cells.celled = true;
            }
            addOnScreen(f.notBehind, cells.notBehind);
            addOnScreen(f.notInFront, cells.notInFront);
        }
    }
    return f;
}

// The pixels of disjoint rectangles.
double pixelsOf(const std::vector<PixelRect>& rects) {
    double sum = 0.0;
    for (const PixelRect& r : rects) sum += double(r.x1 - r.x0) * double(r.y1 - r.y0);
    return sum;
}

// The bounding rectangle of `rects`, alone (empty when they are).
std::vector<PixelRect> bounding(const std::vector<PixelRect>& rects) {
    if (rects.empty()) return {};
    PixelRect all = rects.front();
    for (const PixelRect& r : rects) all = {std::min(all.x0, r.x0), std::min(all.y0, r.y0), std::max(all.x1, r.x1), std::max(all.y1, r.y1)};
    return {all};
}

}  // namespace

Renderer::TintSplit Renderer::splitByTint(const std::vector<Draw>& draws, const gpu::LightBlock& block, const glm::mat4& viewProj,
                                          int width, int height, PixelRect area) const {
    TintSplit split;
    split.area = area;
    const float reach = technique_->tintReachTexels();
    // Without translucent casters every program reads no tint already (SCENE_TRANSLUCENT_CASTERS 0).
    // The visibility output is split as the shaded picture is, so that `compare` scores the pixels
    // a user sees (translucent receivers' builds differ from the whole lookup at rims); the other
    // outputs read no shadow.
    const bool readsShadows = options_.output == OutputMode::Shaded || options_.output == OutputMode::Visibility;
    if (!options_.tintOnlyWhereReached || reach < 0.0f || !readsShadows || !anyTranslucentCaster(draws)) return split;
    const bool behindBuild = technique_->behindLayersBuild();
    // Translucent receivers too, where the lookup has a build for those only their own layers
    // reach, and the pass draws each object whole (not sorted by triangle, not order-independent).
    const bool translucentReceivers = technique_->ownLayersBuild() && options_.transparency == TransparencyMode::SortedObjects;
    std::vector<OrientedBox> casters;
    std::vector<std::size_t> casterDraws;
    for (std::size_t i = 0; i < draws.size(); ++i)
        if (draws[i].translucent && draws[i].castsShadow) {
            casters.emplace_back(draws[i].meshBounds, draws[i].model);
            casterDraws.push_back(i);
        }
    split.draws.resize(draws.size());
    for (std::size_t i = 0; i < draws.size(); ++i) {
        const Draw& d = draws[i];
        if (!d.visible || !ownObject(d.object)) continue;  // another renderer shades it (RegionView)
        if (d.translucent && !(translucentReceivers && d.ownLayersKnown)) continue;
        // A translucent receiver's whole lookup costs far more per pixel than an opaque one's.
        const PixelRect own =
            switchedRect(d, viewProj, width, height, area, d.translucent ? kLeastSwitchedTranslucentShare : kLeastSwitchedShare);
        if (own.empty()) continue;
        // A translucent receiver's own layers are the lookup's to divide out: only the others count.
        std::vector<OrientedBox> others;
        if (d.translucent)
            for (std::size_t c = 0; c < casters.size(); ++c)
                if (casterDraws[c] != i) others.push_back(casters[c]);
        const ReceiverFootprints f = footprintsOf(d, own, d.translucent ? others : casters, block, reach, behindBuild || d.translucent,
                                                  viewProj, width, height, footprintCells_);
        TintedPixels& t = split.draws[i];
        const auto rectCount = [&] {
            std::size_t count = 0;
            for (const auto& r : t.rects) count += r.size();
            return count;
        };
        if (d.translucent) {
            // Every other layer behind it, or none there: the layers in front of it are its own
            // (Untinted). Every other layer in front of it: they are in the tint's product with its
            // own, which the lookup divides out (BehindLayers). Layers on both sides: the whole.
            if (f.notInFront.empty()) {
                t.lookup = TintLookup::Untinted;
                continue;
            }
            if (d.triangles > kSplitTriangles) {
                if (f.notBehind.empty()) t.lookup = TintLookup::BehindLayers;
                continue;
            }
            t.rects = translucentRectsByLookup(own, f.notBehind, f.notInFront);
            if (rectCount() > kMostSplitDraws) t.rects = translucentRectsByLookup(own, bounding(f.notBehind), bounding(f.notInFront));
        } else {
            if (f.tinted.empty()) {
                t.lookup = TintLookup::Untinted;
                continue;
            }
            if (f.notBehind.empty() && d.triangles > kSplitTriangles) t.lookup = TintLookup::BehindLayers;
            if (d.triangles > kSplitTriangles) continue;  // whole (or behind layers), unsplit
            t.rects = rectsByLookup(own, f.notBehind, f.tinted);
            if (rectCount() > kMostSplitDraws) t.rects = rectsByLookup(own, bounding(f.notBehind), bounding(f.tinted));
            // Behind-layers rectangles covering little of the frame are not worth their draws and
            // program switches (scenes/street.json: 21 receivers split three ways, cssm2's opaque pass
            // 91 against 85-87 ms): those pixels keep the whole lookup.
            if (pixelsOf(t.rects[static_cast<int>(TintLookup::BehindLayers)]) < kLeastSwitchedShare * double(width) * double(height))
                t.rects = rectsByLookup(own, f.tinted, f.tinted);
        }
        // All of one kind: the draw is not split after all.
        const auto kinds = std::count_if(t.rects.begin(), t.rects.end(), [](const auto& r) { return !r.empty(); });
        if (kinds != 1) continue;
        for (int l = 0; l < 3; ++l)
            if (!t.rects[static_cast<std::size_t>(l)].empty()) t.lookup = static_cast<TintLookup>(l);
        t.rects = {};
    }
    return split;
}

Renderer::TintShading Renderer::tally(const TintSplit& split, const std::vector<Draw>& draws) const {
    TintShading t;
    for (std::size_t i = 0; i < draws.size(); ++i) {
        if (!draws[i].visible || !ownObject(draws[i].object)) continue;
        static const TintedPixels whole;
        const TintedPixels& pixels = split.draws.empty() ? whole : split.draws[i];
        if (draws[i].translucent) {
            t.translucentSplit += pixels.split() ? 1 : 0;
            t.translucentUntinted += !pixels.split() && pixels.lookup == TintLookup::Untinted ? 1 : 0;
            t.translucentBehindLayers += !pixels.split() && pixels.lookup == TintLookup::BehindLayers ? 1 : 0;
            continue;
        }
        if (pixels.split()) {
            ++t.split;
            t.tintedRects += pixels.rects[static_cast<int>(TintLookup::Whole)].size();
            t.untintedRects += pixels.rects[static_cast<int>(TintLookup::Untinted)].size();
            t.behindLayersRects += pixels.rects[static_cast<int>(TintLookup::BehindLayers)].size();
        } else if (pixels.lookup == TintLookup::Whole) {
            ++t.whole;
        } else {
            ++(pixels.lookup == TintLookup::Untinted ? t.untinted : t.behindLayers);
        }
    }
    return t;
}

// Lights whose frustum bounds their light: a projector's picture stops at its frame, a spot's
// cone lies inside its square frustum (lightReach). Elsewhere they add exactly 0, yet llvmpipe
// runs their picture sample and shadow lookup, masked, for every pixel: measured on the default
// scene, whose projector lights the screen and the ground before it, the projector was half the
// opaque pass (none 32 -> 15.5 ms, hard 48 -> 25, pcss 99 -> 48 with it left out everywhere).
void Renderer::addLightReach(TintSplit& split, const std::vector<Draw>& draws, const gpu::LightBlock& block,
                             const glm::mat4& viewProj, int width, int height) const {
    if (!options_.lightOnlyWhereReached || options_.output != OutputMode::Shaded) return;  // debug channels show every light
    std::vector<int> bounded;
    for (int l = 0; l < block.count.x; ++l) {
        const int type = static_cast<int>(block.lights[l].colorType.w);
        if (type == gpu::kLightProjector || type == gpu::kLightSpot) bounded.push_back(l);
    }
    if (bounded.empty()) return;
    split.reach.resize(draws.size());
    for (std::size_t i = 0; i < draws.size(); ++i) {
        const Draw& d = draws[i];
        if (!d.visible || !ownObject(d.object)) continue;
        // Translucent pieces blend once per pixel only when each object is drawn whole in turn.
        if (d.translucent && options_.transparency != TransparencyMode::SortedObjects) continue;
        const PixelRect own = switchedRect(d, viewProj, width, height, split.area, kLeastSwitchedShare);
        if (own.empty()) continue;
        const OrientedBox box(d.meshBounds, d.model);
        DrawReach& reach = split.reach[i];
        reach.own = own;
        for (int l : bounded) {
            const gpu::LightData& light = block.lights[l];
            // The lit world boxes, kept across frames (footprintsOf). A draw cheap to repeat is
            // bounded cell by cell: a floor's reach is the light's trapezoid on it, where one box
            // gave the trapezoid's bounding rectangle.
            const bool byCells = d.triangles <= kSplitTriangles;
            bool made = false;
            std::vector<scene::Bounds>& lit = reachCells_.at(util::Digest().add(light, box.corners, byCells).value(), made);
            if (made) {
                const scene::Bounds whole = lightReach(light, box);
                const auto add = [&lit](const scene::Bounds& part) { lit.push_back(part); };
                if (!whole.empty()) {
                    if (byCells) cellsOf([&](const OrientedBox& cell) { return lightReach(light, cell); }, whole, kReachLevels, add);
                    else add(whole);
                }
            }
            std::vector<PixelRect> rects;
            appendOnScreen(rects, lit, own, viewProj, width, height);
            // Grown to the tint split's grid, the cells' rectangles merge into few pieces.
            rects = snapped(own, rects);
            if (!rects.empty() && partition(own, rects).outside.empty()) continue;  // every pixel may be lit
            reach.lights.push_back({1u << static_cast<unsigned>(l), std::move(rects)});
        }
    }
}

Renderer::FlatCasterReach Renderer::flatCasterReach() const {
    const float filtered = technique_->filterReachTexels();
    // A filtered lookup averages depths on both sides of the receiver's: no side is safe.
    if (filtered >= 0.0f) return {filtered, -1.0f, true};
    return {technique_->shadowReachTexels(), technique_->shadowReachDepth(), false};
}

const std::vector<FlatCasterNeed>& Renderer::flatCasterNeeds(const std::vector<Draw>& draws, const gpu::LightBlock& block) const {
    const auto [reach, depthReach, filtered] = flatCasterReach();
    if (!options_.onlyCastersThatShadow || reach < 0.0f) {  // every caster drawn whole
        flatCasterNeedsKey_ = 0;
        flatCasterNeeds_.assign(draws.size(), FlatCasterNeed{});
        return flatCasterNeeds_;
    }
    // Kept while no part moved and the lights, their offsets and the reach stayed
    // (scenes/street.json: 1.0-1.1 ms a frame for its 215 parts on llvmpipe's machine, 0.75-0.97
    // when a part's first receiver ended the search).
    util::Digest digest;
    digest.add(reach, depthReach, filtered, block);
    for (const scene::Light& light : scene_.lights) digest.add(light.shadow.polygonOffset);
    for (const Draw& d : draws) digest.add(d.object, d.mesh, d.part, d.model, d.translucent, d.castsShadow, d.moving);
    // Per light and draw, the reach of the lookups at that draw's surfaces where less: the maps read
    // there may be finer than the frame's coarsest (cascades near the camera, warped texels near
    // the warp's near plane), and a flat part's shadow is judged against each receiver by the reach
    // of its own lookups (the osgShadow grid under lispsm: 59 of its 100 objects read at most 8
    // plain texels away, against 64 over the whole view, and its ground left the map). A filtered
    // lookup's reach (filterReachTexels) holds everywhere alike. Asked only where it may decide
    // (flatCasterShadowsNone passes with the finest reach, not with the frame's), and remembered:
    // with the rest unchanged, the answer is kept while those same questions get the same answers
    // (a moving camera refits the views every frame).
    const auto reachWithin = [&](const FlatCasterReachAsked& asked) {
        return std::max(0.0f, std::min(reach, technique_->shadowReachTexelsWithin(asked.light, draws[asked.draw].worldBounds)));
    };
    const std::uint64_t views = technique_->reachViewsDigest();
    if (digest.value() == flatCasterNeedsKey_ && flatCasterNeeds_.size() == draws.size() &&
        (views == flatCasterViews_ ||
         std::all_of(flatCasterAsked_.begin(), flatCasterAsked_.end(), [&](const auto& a) { return reachWithin(a) == a.reach; }))) {
        flatCasterViews_ = views;
        return flatCasterNeeds_;
    }
    std::vector<FlatCasterNeed> needs(draws.size());
    std::vector<FlatCasterReachAsked> asked;
    std::vector<float> receiverReach(static_cast<std::size_t>(block.count.x) * draws.size(), -1.0f);
    const auto reachAt = [&](int light, std::size_t receiver) {
        float& at = receiverReach[static_cast<std::size_t>(light) * draws.size() + receiver];
        if (at < 0.0f) {
            FlatCasterReachAsked question{light, receiver, 0.0f};
            at = question.reach = reachWithin(question);
            asked.push_back(question);
        }
        return at;
    };
    std::vector<OrientedBox> boxes;  // each draw's, once: every caster and light tests them all
    boxes.reserve(draws.size());
    for (const Draw& d : draws) boxes.emplace_back(d.meshBounds, d.model);
    // Past this many receivers a part is drawn whole (its rectangles, one for the still receivers
    // and one for the moving, would leave little out). A filtered lookup's ground counts every
    // opaque caster over it too: under a field of objects (the osgShadow grid's 100 spheres and
    // tori) their rectangle still leaves the ground's far parts out (grid, vsm, every map redrawn:
    // blur 6.2 -> 2.4 ms, shadow pass 1.24 -> 1.08x floor-depth's by glFinish wall clocks); so does
    // lispsm's ground there, near the 41 far objects its coarse texels reach (shadow pass 1.24 ->
    // 1.03x hard's). Evaluating every receiver costs scenes/construction.json 0.2 ms (0.075 with
    // 8) in frames where something moved.
    const std::size_t mostNear = 256;
    for (std::size_t c = 0; c < draws.size(); ++c) {
        const Draw& d = draws[c];
        // A solid's inner faces, seen from inside, are lit through it: only flat parts qualify.
        if (!d.castsShadow || d.translucent || !d.selfShadowFree || d.solid) continue;
        const OrientedBox& caster = boxes[c];
        // Its plane in the world (planes map by the inverse transpose); Mesh::partPlane's flatness
        // tolerance (1e-4 of the part's size) lies within flatCasterShadowsNone's surface tolerance.
        std::optional<glm::vec4> plane;
        if (d.plane) plane = glm::transpose(glm::inverse(d.model)) * *d.plane;
        FlatCasterNeed& need = needs[c];
        for (int l = 0; l < block.count.x; ++l) {
            const gpu::LightData& light = block.lights[l];
            if (light.cone.w < 0.0f) continue;  // no map
            // A point light's cube faces: a part's own texels count in its own lookups there (pcss
            // finds them in its blocker search, and its narrow filter does not always pass them):
            // over a ground and a floating sphere, 3 of 153,600 pixels changed without them.
            if (static_cast<int>(light.colorType.w) == gpu::kLightPoint) continue;
            const float framePad = lookupPadTexels(reach, light);
            const glm::vec2 offset = scene_.lights[static_cast<std::size_t>(l)].shadow.polygonOffset;
            const float opaqueReach = offset.x >= 0.0f && offset.y >= 0.0f ? depthReach : -1.0f;
            NearCasters shadowed;
            bool whole = false;  // a receiver that moves (but with a filtered lookup), or too many of them
            for (std::size_t r = 0; r < draws.size() && !whole; ++r) {
                if (r == c) continue;
                const OrientedBox& receiver = boxes[r];
                // (An offset that pulls the caster's depths towards the light voids the plane's side.)
                const auto shadowsNone = [&](float padTexels) {
                    return plane && opaqueReach >= 0.0f && flatCasterShadowsNone(light, *plane, receiver, padTexels, opaqueReach);
                };
                if (shadowsNone(framePad)) continue;
                // A receiver within the finest lookup's reach of the plane (one resting on a ground)
                // is judged by the frame's reach: its own would hardly leave the part out.
                const bool asks = !filtered && shadowsNone(lookupPadTexels(0.0f, light));
                const float receiverReach = asks ? reachAt(l, r) : reach;
                const float pad = receiverReach < reach ? lookupPadTexels(receiverReach, light) : framePad;
                if (pad < framePad && shadowsNone(pad)) continue;
                const bool shadows = !(opaqueReach >= 0.0f ? opaqueShadowFootprint(light, caster, receiver, pad, opaqueReach)
                                                           : shadowFootprint(light, caster, receiver, pad))
                                          .empty();
                // A filtered lookup on the part itself averages its depth with those of the
                // opaque casters shadowing it: it stays in the map around their shadows too.
                const bool shadowedBy = filtered && draws[r].castsShadow && !draws[r].translucent &&
                                        !shadowFootprint(light, receiver, caster, pad).empty();
                if (!shadows && !shadowedBy) continue;
                // A light's kept still map holds the part as drawn for the receivers of that frame;
                // moment maps redraw every caster where the moving ones are and were.
                (draws[r].moving ? shadowed.moving : shadowed.still).push_back(receiver.corners);
                whole = (draws[r].moving && !filtered) || shadowed.still.size() + shadowed.moving.size() > mostNear;
            }
            if (shadowed.empty()) {
                need.nothing |= 1u << static_cast<unsigned>(l);
            } else if (!whole) {
                need.near.resize(static_cast<std::size_t>(block.count.x));
                need.near[static_cast<std::size_t>(l)] = std::move(shadowed);
            }
        }
    }
    flatCasterNeedsKey_ = digest.value();
    flatCasterViews_ = views;
    flatCasterAsked_ = std::move(asked);
    flatCasterNeeds_ = std::move(needs);
    return flatCasterNeeds_;
}

// Where no other caster's shadow volume reaches an opaque receiver, a light's map holds the
// receiver itself (one that shadows none of its own lit points: Draw::selfShadowFree) or what lies
// behind it, and its lookup answers exactly 1; yet llvmpipe runs that lookup, masked, for every
// pixel. The receiver's pixels off every caster's footprint (render/TintReach.h: padded by the
// technique's shadowReachTexels and the normal offset, then, where less, by its
// shadowReachTexelsWithin that footprint's box: a pixel nearer the caster than the reach of the
// maps it reads lies within both pads; an opaque caster's on the side of it away
// from the light, within the lookup's shadowReachDepth, a translucent one's on both sides) are
// shaded with a build that leaves the lookup out. Measured on the default scene: see
// docs/measurements.md, stops 53, 54 and 58.
void Renderer::addShadowReach(TintSplit& split, const std::vector<Draw>& draws, const gpu::LightBlock& block,
                              const glm::mat4& viewProj, int width, int height) const {
    const float reach = technique_->shadowReachTexels(), depthReach = technique_->shadowReachDepth();
    // Debug channels show every lookup (compare scores the visibility output as it always was).
    if (!options_.shadowOnlyWhereCast || reach < 0.0f || options_.output != OutputMode::Shaded) return;
    // Every caster the maps hold, seen or not, with the digest of its box (the memo's keys combine
    // digests: a scene of 190 draws hashed the light and both boxes anew for every pair, 4 ms a frame).
    struct Caster {
        std::size_t draw;
        OrientedBox box;
        std::uint64_t key;
        bool opaque;  // in the depth map alone, at its surface's depth (no tint, no layers)
    };
    std::vector<Caster> casters;
    for (std::size_t i = 0; i < draws.size(); ++i)
        if (draws[i].castsShadow) {
            const OrientedBox box(draws[i].meshBounds, draws[i].model);
            casters.push_back({i, box, util::Digest().add(box.corners).value(), !draws[i].translucent});
        }
    std::vector<std::uint64_t> lightKeys;
    for (int l = 0; l < block.count.x; ++l) lightKeys.push_back(util::Digest().add(block.lights[l]).value());
    for (std::size_t i = 0; i < draws.size(); ++i) {
        const Draw& d = draws[i];
        if (!d.visible || d.translucent || !ownObject(d.object)) continue;
        const PixelRect own = switchedRect(d, viewProj, width, height, split.area, kLeastSwitchedShare);
        if (own.empty()) continue;
        const OrientedBox receiver(d.meshBounds, d.model);
        const std::uint64_t receiverKey = util::Digest().add(receiver.corners).value();
        const bool byCells = d.triangles <= kSplitTriangles;
        // A solid seen from inside, or cut open by the near plane, shows faces lit through itself.
        const bool selfShadowFree = d.selfShadowFree && (!d.solid || !nearPlaneMayCut(viewProj, d.worldBounds));
        for (int l = 0; l < block.count.x; ++l) {
            const gpu::LightData& light = block.lights[l];
            if (light.cone.w < 0.0f) continue;  // no map, no lookup
            const float pad = lookupPadTexels(reach, light);
            // A polygon offset that pulls depths towards the light could put a caster in front of
            // its own box in the map: then its volume counts on both sides of it.
            const glm::vec2 offset = scene_.lights[static_cast<std::size_t>(l)].shadow.polygonOffset;
            const float opaqueReach = offset.x >= 0.0f && offset.y >= 0.0f ? depthReach : -1.0f;
            std::vector<PixelRect> rects;
            for (const Caster& c : casters) {
                if (c.draw == i && selfShadowFree) continue;
                const OrientedBox& caster = c.box;
                // Opaque casters shadow only what lies behind them (not clearly in front of their
                // box, within the lookup's depth reach); translucent ones tint through CSSM's and
                // the tint maps' layer tests, whose reach in depth is not bounded here.
                const float casterReach = c.opaque ? opaqueReach : -1.0f;
                const auto footprint = [&](const OrientedBox& receiverPart, float padTexels) {
                    return casterReach >= 0.0f ? opaqueShadowFootprint(light, caster, receiverPart, padTexels, casterReach)
                                               : shadowFootprint(light, caster, receiverPart, padTexels);
                };
                // The whole footprint first, then its cells (if any): the whole's screen rectangle
                // alone where it is no wider and no taller than two cells of the grid, which its
                // cells' could not beat by much (scenes/street.json: 190 casters).
                const auto partsPaddedBy = [&](float padTexels) -> const std::vector<scene::Bounds>& {
                    bool made = false;
                    std::vector<scene::Bounds>& parts = shadowCells_.at(
                        util::Digest().add(lightKeys[static_cast<std::size_t>(l)], c.key, receiverKey, padTexels, casterReach, byCells).value(),
                        made);
                    if (made) {
                        const auto padded = [&](const OrientedBox& receiverPart) { return footprint(receiverPart, padTexels); };
                        const scene::Bounds whole = padded(receiver);
                        const auto add = [&parts](const scene::Bounds& part) { parts.push_back(part); };
                        if (!whole.empty()) {
                            add(whole);
                            if (byCells) cellsOf(padded, whole, kShadowReachLevels, add);
                        }
                    }
                    return parts;
                };
                const std::vector<scene::Bounds>* found = &partsPaddedBy(pad);
                // Padded by the reach of the maps read within that footprint's box, where less.
                if (!found->empty()) {
                    const float near = technique_->shadowReachTexelsWithin(l, found->front());
                    if (near >= 0.0f && near < reach) found = &partsPaddedBy(near + light.shadow.z + 2.0f);
                }
                const std::vector<scene::Bounds>& parts = *found;
                if (parts.empty()) continue;
                const PixelRect whole = screenRect(parts.front(), viewProj, width, height).intersected(own);
                if (whole.empty()) continue;
                if (parts.size() == 1 || (whole.x1 - whole.x0 <= 2 * kSnap && whole.y1 - whole.y0 <= 2 * kSnap)) {
                    rects.push_back(whole);
                    continue;
                }
                appendOnScreen(rects, std::span<const scene::Bounds>(parts).subspan(1), own, viewProj, width, height);  // its cells
            }
            rects = snapped(own, rects);
            if (!rects.empty() && partition(own, rects).outside.empty()) continue;  // shadows may fall on every pixel
            if (split.reach.empty()) split.reach.resize(draws.size());
            split.reach[i].own = own;
            split.reach[i].lights.push_back({1u << static_cast<unsigned>(l), std::move(rects), true});
        }
    }
}

std::vector<Renderer::Piece> Renderer::piecesOf(const TintSplit* split, std::size_t draw) const {
    if (!split) return {};
    const TintedPixels* tinted = draw < split->draws.size() ? &split->draws[draw] : nullptr;
    const DrawReach* reach = draw < split->reach.size() && !split->reach[draw].lights.empty() ? &split->reach[draw] : nullptr;
    std::vector<Piece> pieces;
    if (tinted && tinted->split()) {
        for (int l = 0; l < 3; ++l)
            for (const PixelRect& r : tinted->rects[static_cast<std::size_t>(l)]) pieces.push_back({r, static_cast<TintLookup>(l), 0});
    } else if (reach) {
        pieces.push_back({reach->own, tinted ? tinted->lookup : TintLookup::Whole, 0});
    }
    if (!reach) return pieces;
    const std::vector<Piece> uncut = pieces;
    std::vector<Piece> cut;
    // Beyond this many, the draws cost more than the lights left out save (as kMostSplitDraws).
    constexpr std::size_t kMostPieces = 2 * kMostSplitDraws;
    for (const LightReach& light : reach->lights) {
        cut.clear();
        for (const Piece& p : pieces) {
            const RectPartition byLight = partition(p.rect, light.rects);
            for (const PixelRect& r : byLight.inside) cut.push_back({r, p.lookup, p.unlit, p.unshadowed});
            for (const PixelRect& r : byLight.outside)
                cut.push_back({r, p.lookup, p.unlit | (light.shadowOnly ? 0u : light.bit), p.unshadowed | (light.shadowOnly ? light.bit : 0u)});
        }
        if (light.shadowOnly && cut.size() > kMostPieces) continue;  // that shadow looked up everywhere instead
        pieces.swap(cut);
    }
    if (pieces.size() > kMostPieces) return uncut;
    for (Piece& p : pieces) p.unshadowed &= ~p.unlit;  // a light left out has no lookup: one build for both
    return pieces;
}

// Each pixel in one piece, drawn with the lookup it needs and without the lights that miss it.
// The pieces are disjoint rectangles, so their order is free: each build is prepared once (its
// uniforms, texture and program) and draws all of its pieces.
void Renderer::drawPieces(const Draw& d, const std::vector<Piece>& pieces, const TintSplit& split) {
    glEnable(GL_SCISSOR_TEST);
    std::vector<bool> drawn(pieces.size(), false);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        if (drawn[i]) continue;
        const gl::Program& program = lighting_.of(*d.material, d.translucent, pieces[i].lookup, pieces[i].unlit, pieces[i].unshadowed);
        gpu_.prepare(d, program);
        for (std::size_t j = i; j < pieces.size(); ++j) {
            const Piece& p = pieces[j];
            if (drawn[j] || p.lookup != pieces[i].lookup || p.unlit != pieces[i].unlit || p.unshadowed != pieces[i].unshadowed) continue;
            drawn[j] = true;
            glScissor(p.rect.x0, p.rect.y0, p.rect.x1 - p.rect.x0, p.rect.y1 - p.rect.y0);
            gpu_.drawPrepared(d);
            if (p.unlit != 0) ++tintShading_.unlitPieces;
            if (p.unshadowed != 0) ++tintShading_.unshadowedPieces;
        }
    }
    if (split.scissored) glScissor(split.area.x0, split.area.y0, split.area.x1 - split.area.x0, split.area.y1 - split.area.y0);
    else glDisable(GL_SCISSOR_TEST);
}

void Renderer::drawSurfaces(const std::vector<Draw>& draws, bool translucent, const scene::Camera& camera, float aspect,
                            const TintSplit* split) {
    const auto drawn = [&](const Draw& d) {
        return d.translucent == translucent && d.visible && (translucent || ownObject(d.object));
    };
    const TintedPixels whole;
    const auto tintOf = [&](std::size_t i) -> const TintedPixels& {
        return !split || split->draws.empty() ? whole : split->draws[i];
    };
    std::vector<std::vector<Piece>> pieces(draws.size());
    std::vector<const gl::Program*> used;  // by this pass: built and prepared before it draws
    const auto use = [&](const gl::Program& p) {
        if (std::find(used.begin(), used.end(), &p) == used.end()) used.push_back(&p);
    };
    for (std::size_t i = 0; i < draws.size(); ++i)
        if (drawn(draws[i])) {
            pieces[i] = piecesOf(split, i);
            if (pieces[i].empty()) use(lighting_.of(*draws[i].material, draws[i].translucent, tintOf(i).lookup));
            for (const Piece& p : pieces[i]) use(lighting_.of(*draws[i].material, draws[i].translucent, p.lookup, p.unlit, p.unshadowed));
        }
    bindLightingUnits();
    for (const gl::Program* p : used) prepareLighting(*p, translucent, camera, aspect);
    gl::PassState state = gl::PassState::depthOnly();
    state.depthFunc = GL_LEQUAL;
    if (translucent && options_.output == OutputMode::Shaded) {
        state.withBlend(overTransmittance());
        state.depthWrite = false;
    } else if (options_.depthPrepass) {
        state.depthWrite = false;  // the pre-pass wrote it; unwritten, early tests survive the alpha test's discard
    }
    const gl::ScopedPassState scope(state);
    const bool byTriangle = translucent && options_.transparency == TransparencyMode::SortedTriangles;
    const glm::mat4 viewProj = camera.projection(aspect) * camera.view();
    for (std::size_t i = 0; i < draws.size(); ++i) {
        const Draw& d = draws[i];
        if (!drawn(d)) continue;
        if (!translucent) cullBackFacesOfSolid(d, options_.cullSolidBackFaces, viewProj);  // translucent solids show their far side through the near one
        if (!pieces[i].empty()) {
            drawPieces(d, pieces[i], *split);
            continue;
        }
        const gl::Program& program = lighting_.of(*d.material, d.translucent, tintOf(i).lookup);
        if (byTriangle) gpu_.drawTrianglesSorted(d, program, camera.position);
        else gpu_.draw(d, program);
    }
}

void Renderer::setReceivers(std::vector<bool> own, bool ownPixelsOnly) {
    ownObjects_ = std::move(own);
    ownPixelsOnly_ = ownPixelsOnly;
}

// Opaque surfaces into depth only (alpha-tested texels stay holes) before the lighting pass: the
// objects another renderer shades, which hide this renderer's own where they are in front, and
// with RenderOptions::depthPrepass this renderer's own too. caster.vert computes gl_Position as
// lighting.vert does, both `invariant`, so the lighting pass's LEQUAL test passes exactly the
// nearest surface.
void Renderer::drawDepthFirst(const std::vector<Draw>& draws, const scene::Camera& camera, float aspect) {
    if (ownObjects_.empty() && !options_.depthPrepass) return;
    if (!depthFirst_) depthFirst_.emplace();
    const glm::mat4 viewProj = camera.projection(aspect) * camera.view();
    depthFirst_->set("uLightViewProj", viewProj);
    const shadows::DrawPrograms programs = *depthFirst_;
    gl::PassState state = gl::PassState::depthOnly();
    state.colorWrite = glm::bvec4(false);
    const gl::ScopedPassState scope(state);
    for (const Draw& d : draws)
        if (d.visible && !d.translucent && (options_.depthPrepass || !ownObject(d.object))) {
            cullBackFacesOfSolid(d, options_.cullSolidBackFaces, viewProj);
            gpu_.draw(d, programs.of(*d.material));
        }
}

// shaders/common/fog.glsl's uniforms.
void Renderer::setFogUniforms(const gl::Program& program, const scene::Camera& camera, float aspect) const {
    // clip z = P22 z + P32, clip w = -z: the view depth -z at window depth d is
    // P32 / (2d - 1 + P22) = (P32 / 2) / (d + (P22 - 1) / 2); x / -z = ndc.x / P00, likewise y.
    const glm::mat4 projection = camera.projection(aspect);
    program.set("uViewDepth", glm::vec2(projection[3][2] * 0.5f, (projection[2][2] - 1.0f) * 0.5f));
    program.set("uRaySlope", glm::vec2(1.0f / projection[0][0], 1.0f / projection[1][1]));
    program.set("uBackground", scene_.background);
    program.set("uFog", glm::vec2(scene_.fog.start, scene_.fog.end));
}

// The frame goes straight into 8-bit sRGB (render/SrgbTarget.h) unless it must be read back as
// floats, shows a debug channel (linear values), keeps another renderer's pixels (the resolve's
// discard) or composites transparency in passes of its own onto the float target.
bool Renderer::shadesIntoSrgb() const {
    return !options_.floatTarget && options_.output == OutputMode::Shaded && !ownPixelsOnly_ && isSorted(options_.transparency);
}

// The lighting shader applies the fog (FOG_IN_SHADING) where no resolve pass will.
bool Renderer::fogInShading() const { return shadesIntoSrgb() && scene_.fog.enabled; }

// ENCODE_SRGB_IN_SHADER where the opaque pass writes sRGB bytes itself (SrgbTarget::bytesFramebuffer),
// FOG_IN_SHADING where the lighting shader applies the fog, DEBUG_OUTPUT where it writes a debug
// channel instead of the shaded colour. Shaded builds hold no debug code: llvmpipe ran the
// channels' uniform tests and their per-light bookkeeping for every fragment (measured, default
// scene, none, hard and cssm2: about 1-2 ms of a 40-60 ms opaque pass; 98k grid, none: 0.8 of 31 ms).
std::vector<std::string> Renderer::withOutputDefines(std::vector<std::string> layout) const {
    if (shadesIntoSrgb()) layout.emplace_back("ENCODE_SRGB_IN_SHADER");
    if (fogInShading()) layout.emplace_back("FOG_IN_SHADING");
    if (options_.output != OutputMode::Shaded) layout.emplace_back("DEBUG_OUTPUT");
    return layout;
}

void Renderer::resolve(GLuint target, int width, int height, const scene::Camera& camera, float aspect) {
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    glViewport(0, 0, width, height);
    const gl::ScopedPassState scope(gl::PassState::fullscreen());
    const bool shaded = options_.output == OutputMode::Shaded;
    const gl::Program& program = shaded && scene_.fog.enabled ? foggedResolve_ : resolve_;
    setFogUniforms(program, camera, aspect);
    program.set("uEncodeSrgb", shaded ? 1 : 0);
    program.set("uOwnPixelsOnly", ownPixelsOnly_ ? 1 : 0);
    hdr_.bind(0);
    depth_.bind(1);
    program.use();
    emptyVao_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void Renderer::drawOverlay(GLuint target, int width, int height) {
    const auto views = technique_->debugViews();
    const int size = std::max(64, std::min(width, height) / 4);
    int x = 8;
    glBindFramebuffer(GL_FRAMEBUFFER, target);
    const gl::ScopedPassState scope(gl::PassState::fullscreen());
    overlay_.use();
    emptyVao_.bind();
    overlaySampler_.bind(0);
    overlaySampler_.bind(1);
    for (const auto& view : views) {
        const bool layered = view.target == GL_TEXTURE_2D_ARRAY;
        if ((view.target != GL_TEXTURE_2D && !layered) || x + size > width) continue;
        glViewport(x, 8, size, size);
        glBindTextureUnit(layered ? 1 : 0, view.texture);
        overlay_.set("uIsDepth", view.depth ? 1 : 0);
        overlay_.set("uLayer", layered ? view.layer : -1);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        x += size + 8;
    }
    gl::Sampler::unbind(0);
    gl::Sampler::unbind(1);
    glViewport(0, 0, width, height);
}

std::vector<float> Renderer::readLinear() const {
    if (srgbFrame_)
        throw std::logic_error("Renderer::readLinear: the last frame was shaded into 8-bit sRGB; RenderOptions::floatTarget keeps the float target");
    if (hdr_.id() == 0) return {};  // no frame drawn yet
    std::vector<float> pixels(static_cast<std::size_t>(targetW_) * targetH_ * 4);
    glGetTextureImage(hdr_.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(pixels.size() * sizeof(float)), pixels.data());
    return pixels;
}

}  // namespace penumbra::render
