#pragma once
// A frame is a list of passes: shadow maps (the technique's), opaque surfaces, translucent
// surfaces back to front, then resolve (fog, clamp, sRGB) and debug overlays; or the surfaces are
// shaded straight into 8-bit sRGB, fog included, and nothing is resolved (render/SrgbTarget.h).
// Each pass is timed with a GPU timer query.
#include "gl/Buffer.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Sampler.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "render/CasterQueries.h"
#include "render/FrameMemo.h"
#include "render/FrameTimer.h"
#include "render/GpuScene.h"
#include "render/LightingProgram.h"
#include "render/PlaceholderTextures.h"
#include "render/SrgbTarget.h"
#include "render/TintReach.h"
#include "render/Transparency.h"
#include "scene/Scene.h"
#include "shadows/ShadowTechnique.h"

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace penumbra::render {

// Debug channels (linear floats, nearest opaque surface only): a light's shadow visibility,
// the G-buffer, a light's unshadowed contribution and the ambient term. The shaded opaque image
// equals Ambient + sum over lights of Contribution * Visibility.
enum class OutputMode { Shaded = 0, Visibility = 1, WorldPosition = 2, Normal = 3, Contribution = 4, Ambient = 5 };

// Pixel columns [first, last) of a frame; last < 0: to the right edge.
struct Columns {
    int first = 0, last = -1;
};

// How a frame is rendered: the one set of options every front-end (window, render, compare,
// bench) fills, through one CLI helper (app/RenderOptionsCli.h).
struct RenderOptions {
    std::string technique;     // "" = the scene's `technique`, else "hard"
    int shadowResolution = 0;  // > 0 overrides every light's own resolution
    bool debugOverlay = false;
    OutputMode output = OutputMode::Shaded;
    int debugLight = 0;  // which light OutputMode::Visibility shows
    // Debug channels (output != Shaded) show the nearest surface, translucent ones too, where by
    // default they show the nearest opaque one: `compare --translucent-receivers`.
    bool debugTranslucent = false;
    // Technique parameters as text ("radius_texels" = "3", "filter" = "cross13",
    // "stabilize" = "true"); names a technique lacks are ignored unless strictParameters is set
    // (then they are an error naming the known ones).
    shadows::ParameterValues parameters;
    bool strictParameters = false;
    TransparencyMode transparency = TransparencyMode::SortedObjects;
    int peelLayers = 4;  // depth peeling: layers kept
    // Most anisotropic samples per lookup of the scene's textures and projector pictures. 1
    // (trilinear) by default, as bgfx, Filament and osg sample: measured on llvmpipe (default
    // scene, 1280x720) 8x doubled the opaque pass (40 -> 88 ms) and the shadow pass (17 -> 30 ms).
    int anisotropy = 1;
    // Keep the depth that still (unanimated) casters leave in a light's map while the light, its
    // map and those casters stay put, and redraw only what moves (shadows::ShadowFrame). false
    // redraws every map every frame: the bare per-frame cost, for peer comparisons.
    bool reuseStillCasters = true;
    // Keep a directional light's box across frames while it still holds what the camera sees, and
    // move it with room to spare (shadows::computeLightSpace's `previous`): a moving camera then
    // has the sun's map drawn whole every few frames instead of every frame, at up to one size
    // step and kBoxSlack of its resolution. false fits the box to each frame's view alone
    // (`--refit-sun-box`); the first frame, and any single frame, is fitted so either way.
    bool holdSunBox = true;
    // Cut mesh parts of 32768 triangles or more into clusters that each shadow pass culls against
    // its cascade, layer or cube face (render/MeshClusters.h). false draws such parts whole: the
    // same maps, for measuring what the clusters save. Read when the Renderer is made.
    bool clusterCasters = true;
    // Draw the opaque surfaces' depth first (the alpha-tested casters' program, camera as the
    // light), then shade with depth writes off: the lighting shader runs once per visible pixel
    // instead of once per fragment. Pays where overdraw is high and shading dear (a GPU, the
    // dragon, PCSS); on llvmpipe's default scene it cost more than it saved. Same pixels.
    bool depthPrepass = false;
    // Cull the back faces of solids (Draw::solid) in the camera's opaque passes and in the depth
    // maps of every light: the same pixels and maps at less raster work, but for a few silhouette
    // texels where a polygon offset pushes a front face seen edge-on behind the back face next to
    // it. false draws both faces everywhere, for measuring what culling saves (`--both-faces`).
    bool cullSolidBackFaces = true;
    // Seed 002's "-sh 6": a technique per region was asked for, so a scene without regions is an
    // error rather than one technique everywhere (render/RegionView.h, drawsByRegion).
    bool requireRegions = false;
    // Shade opaque receivers, or the screen rectangles of their pixels, that no translucent
    // caster's coloured shadow can reach with a lighting program that reads no tint
    // (render/TintReach.h): the same pixels, less shading where colour cannot fall. false gives
    // every receiver the whole lookup (`--tint-everywhere`), for measuring what it saves.
    bool tintOnlyWhereReached = true;
    // Shade the screen rectangles of a receiver's pixels that a projector or spot light cannot
    // reach (outside its frustum: render/TintReach.h, lightReach) with a lighting program that
    // leaves that light out: the same pixels, without its picture and shadow lookup there. false
    // (`--light-everywhere`) shades every light everywhere, for measuring what it saves.
    bool lightOnlyWhereReached = true;
    // Shade the screen rectangles of an opaque receiver that no other caster's shadow volume reaches
    // (render/TintReach.h, shadowFootprint) with a lighting program that leaves that light's shadow
    // lookup out, where the technique bounds how far its lookup reads (ShadowTechnique::
    // shadowReachTexels): the same pixels, without the lookup where it would answer 1. false
    // (`--shadow-everywhere`) looks every shadow up on every pixel, for measuring what it saves.
    bool shadowOnlyWhereCast = true;
    // Leave out of a light's maps the flat opaque casters whose shadow can fall on no other surface
    // (a ground under everything), and draw one carrying a few still casters only around them,
    // with those techniques; with moment maps (but MSM) a ground only around the shadows on it
    // and what it shadows (ShadowTechnique::filterReachTexels): the same pixels, less of the maps
    // drawn (Renderer::flatCasterNeeds). false (`--every-caster`) draws every caster whole.
    bool onlyCastersThatShadow = true;
    // Shade into a 32-bit float target and resolve it into the output in a pass of its own (fog,
    // clamp, sRGB): what readLinear() reads. false shades straight into the output as 8-bit sRGB
    // (render/SrgbTarget.h) wherever the frame allows it (shaded output, sorted transparency):
    // the same picture to within rounding, without the resolve pass. The front-ends turn it off
    // unless asked (`--float-target`); tests and `compare`, which read floats, keep it.
    bool floatTarget = true;
};

// The technique `options` asks for on `scene`: its own, else the scene's, else "hard".
std::string chosenTechnique(const RenderOptions& options, const scene::Scene& scene);

class Renderer {
public:
    // `scene` must outlive the renderer; lights may be edited between frames.
    Renderer(scene::Scene& scene, RenderOptions options = {});

    // Throws std::invalid_argument (unknown name) or gl::ShaderError; the old technique stays
    // active when the new one fails.
    void setTechnique(const std::string& name);
    void setOutputMode(OutputMode mode, int debugLight = 0);
    // Debug channels show the nearest surface strictly behind `nearest`'s window depth (a depth
    // texture of the frame's size, from cameraDepth() of a frame drawn from the same camera): the
    // surface seen through the nearest translucent one (compare --behind-glass). nullptr: the
    // nearest surface, as usual. Shaded frames ignore it.
    void showBehind(const gl::Texture* nearest) { behind_ = nearest; }
    // The last frame's camera depth (window depth, GL_DEPTH_COMPONENT32F, the frame's size).
    const gl::Texture& cameraDepth() const { return depth_; }
    // Anisotropic filtering of the scene's textures, 1-16 (RenderOptions::anisotropy).
    void setAnisotropy(int anisotropy);
    // Seed 002's combined technique (render/RegionView.h): `own[i]` says whether this renderer
    // shades object i. The others are drawn into depth alone, so they still hide what lies behind
    // them. With `ownPixelsOnly` the output keeps just the pixels whose nearest opaque surface is
    // one of its own and leaves the rest of the target as it was; otherwise every pixel is written
    // (the others' as background). Translucent objects are drawn by every renderer, over whichever
    // surface owns the pixel. Empty `own` (the default): every object is its own.
    void setReceivers(std::vector<bool> own, bool ownPixelsOnly);
    // Rebuilds every program from the shader files as they are now (live editing): the
    // technique (keeping its current parameter values) and the renderer's own passes. All or
    // nothing: on a compile error nothing changes, the last good programs keep drawing, and the
    // error is returned ("file:line: ..."); "" on success.
    std::string reloadShaders();
    RenderOptions& options() { return options_; }
    scene::Scene& scene() { return scene_; }
    const shadows::ShadowTechnique& technique() const { return *technique_; }
    shadows::ShadowTechnique& technique() { return *technique_; }

    // Renders the frame at `time` into `targetFramebuffer` (0: the window) of width x height.
    // A 0x0 size (minimised window) renders nothing. `columns` limits the camera passes and the
    // output to the pixel columns [first, last) of the frame (split view: render/SplitView.h);
    // shadow maps are always whole.
    void render(float time, const scene::Camera& camera, int width, int height, GLuint targetFramebuffer,
                Columns columns = {});

    // GPU times per pass come from a ring of timer queries, a few frames late (render/FrameTimer.h).
    // The newest finished frame's, without waiting:
    const PassTimes& lastTimes() const { return timer_.latest(); }
    // Waits for the last rendered frame's times (for callers that have synchronised anyway).
    const PassTimes& waitForTimes() { return timer_.waitForAll().gpu; }
    // The query ring itself: every finished frame's times, calibration (benchmarks).
    FrameTimer& frameTimer() { return timer_; }
    std::uint64_t framesRendered() const { return frameIndex_; }
    // Triangles drawn into shadow maps in the last frame, per light (all passes and faces).
    const std::vector<std::size_t>& shadowTriangles() const { return shadowTriangles_; }
    // Where each light's map looked in the last frame.
    const std::vector<shadows::LightSpace>& lightSpaces() const { return lastSpaces_; }
    // Go on from `other`'s last frame (RenderOptions::holdSunBox): a renderer made beside another
    // mid-way (the split view's second side) then holds the same sun's box as it.
    void holdSunBoxOf(const Renderer& other) { lastSpaces_ = other.lastSpaces_; }
    // How the last frame shaded its opaque draws where translucent casters may tint them
    // (RenderOptions::tintOnlyWhereReached, render/TintReach.h): draws with the whole lookup, with
    // the untinted program, with the behind-layers one, and draws split on the screen between them
    // (rectangles of each); translucent draws with the own-layers build, whole or split; and the
    // CPU time the choice took.
    struct TintShading {
        std::size_t whole = 0, untinted = 0, behindLayers = 0, split = 0, tintedRects = 0, untintedRects = 0, behindLayersRects = 0;
        std::size_t translucentUntinted = 0, translucentBehindLayers = 0, translucentSplit = 0;  // translucent receivers (ShadowTechnique::ownLayersBuild)
        double cpuMs = 0.0;  // the footprints and rectangles' CPU time (render/TintReach.h)
        std::size_t unlitPieces = 0;  // pieces drawn with a light left out (addLightReach), both passes
        std::size_t unshadowedPieces = 0;  // pieces drawn with a light's shadow lookup left out (addShadowReach)
        // Tint footprints (per receiver, caster and light) and lights' reaches (per draw and light),
        // each with its cells, worked out this frame rather than kept from the last (FrameMemo: a
        // still scene works out none after its first frame but a sun's when the camera moves, as
        // the sun's map follows the view).
        std::size_t footprintsMade = 0;
    };
    const TintShading& tintShading() const { return tintShading_; }
    std::size_t shadowMemoryBytes() const { return technique_->memoryBytes(); }
    // The last frame's linear HDR colour (before fog and sRGB), RGBA floats, bottom row first.
    // Throws std::logic_error where that frame was shaded into 8-bit sRGB (RenderOptions::floatTarget).
    std::vector<float> readLinear() const;
    int effectiveResolution(const scene::Light& light) const;

private:
    void ensureTargets(int width, int height, bool floatTarget);
    // What every pass of one frame reads: the camera, the frame's draws (GpuScene::draws order), the
    // lights' spaces and their uniform block.
    struct FrameInputs {
        float time;
        const scene::Camera& camera;
        float aspect;
        int width, height;
        glm::mat4 cameraViewProj;
        std::vector<Draw> draws;
        scene::Bounds bounds;                     // every object at `time`
        std::vector<shadows::LightSpace> spaces;  // one per light
        gpu::LightBlock block{};
        bool translucentCasters = false;
    };
    // The frame's inputs, the light block uploaded and the lighting programs made for its layout.
    FrameInputs prepareFrame(float time, const scene::Camera& camera, int width, int height);
    void renderShadowMaps(const FrameInputs& frame);
    void drawCasters(const CasterQueries& casters, shadows::DrawPrograms programs, const shadows::CasterSelection& selection);
    void renderCameraPasses(const FrameInputs& frame, GLuint target, Columns columns);
    // How each opaque draw is shaded where translucent casters may tint it (render/TintReach.h).
    struct TintedPixels {
        TintLookup lookup = TintLookup::Whole;  // of the whole draw, unless it is split
        // A split draw's pixels in disjoint rectangles, per the lookup they need (TintLookup's
        // order), of at least two kinds; empty when the draw is not split.
        std::array<std::vector<PixelRect>, 3> rects;
        bool split() const { return !rects[0].empty() || !rects[1].empty() || !rects[2].empty(); }
    };
    // Where each light whose frustum bounds its light (a projector, a spot) reaches a draw's
    // pixels (render/TintReach.h, lightReach): the light's bit and that rectangle of the draw's own.
    // Or, with `shadowOnly`, where the light's shadow may fall on them (addShadowReach): outside,
    // the light is shaded without its lookup.
    struct LightReach {
        unsigned bit = 0;
        std::vector<PixelRect> rects;  // the light (its shadow) reaches no pixel of the draw outside these
        bool shadowOnly = false;
    };
    struct DrawReach {
        PixelRect own;                   // the draw's pixels
        std::vector<LightReach> lights;  // the lights that miss some of them; empty: none left out
    };
    struct TintSplit {
        std::vector<TintedPixels> draws;  // per draw; empty: every draw whole
        PixelRect area;                   // the camera passes' pixels
        bool scissored = false;           // a column range scissors them (render's `columns`)
        std::vector<DrawReach> reach;     // per draw (addLightReach); empty: every light everywhere
    };
    // A rectangle of a draw's pixels, the lookup it needs, the lights that reach none of it and
    // those whose shadows reach none of it.
    struct Piece {
        PixelRect rect;
        TintLookup lookup = TintLookup::Whole;
        unsigned unlit = 0, unshadowed = 0;
    };
    // The frame's receivers cut into pieces (splitByTint, addLightReach, addShadowReach), tallied
    // into tintShading_; `scissored`: a column range scissors the camera passes.
    TintSplit splitReceivers(const FrameInputs& frame, PixelRect area, bool scissored);
    void clearCameraTarget(GLuint framebuffer, int width, int height);
    void drawTranslucentPass(const FrameInputs& frame, const TintSplit& split, const std::function<void()>& throughSrgbView);
    // `area`: the pixels of the width x height frame the camera passes draw (a column range).
    TintSplit splitByTint(const std::vector<Draw>& draws, const gpu::LightBlock& block, const glm::mat4& viewProj, int width, int height,
                          PixelRect area) const;
    TintShading tally(const TintSplit& split, const std::vector<Draw>& draws) const;
    // RenderOptions::lightOnlyWhereReached: the reach of every projector and spot light per draw.
    void addLightReach(TintSplit& split, const std::vector<Draw>& draws, const gpu::LightBlock& block, const glm::mat4& viewProj,
                       int width, int height) const;
    // The technique's reach flatCasterNeeds judges flat parts by, in texels of the light's map,
    // with its reach in depth (negative: both sides of a caster count); `filtered`: its
    // filterReachTexels, else its shadowReachTexels and shadowReachDepth.
    struct FlatCasterReach {
        float texels, depth;
        bool filtered;
    };
    FlatCasterReach flatCasterReach() const;
    // (Kept, and answered again, while nothing it depends on changed.)
    const std::vector<FlatCasterNeed>& flatCasterNeeds(const std::vector<Draw>& draws, const gpu::LightBlock& block) const;
    mutable std::uint64_t flatCasterNeedsKey_ = 0;  // flatCasterNeeds' last answer and what it was of
    mutable std::vector<FlatCasterNeed> flatCasterNeeds_;
    // What it asked the technique's shadowReachTexelsWithin (a light, a receiver's draw, the answer),
    // under views of reachViewsDigest flatCasterViews_.
    struct FlatCasterReachAsked {
        int light;
        std::size_t draw;
        float reach;
    };
    mutable std::vector<FlatCasterReachAsked> flatCasterAsked_;
    mutable std::uint64_t flatCasterViews_ = 0;
    // RenderOptions::shadowOnlyWhereCast: per opaque draw and shadowed light, where shadows may fall.
    void addShadowReach(TintSplit& split, const std::vector<Draw>& draws, const gpu::LightBlock& block, const glm::mat4& viewProj,
                        int width, int height) const;
    // The pieces a draw is drawn in: the tint split's rectangles, or its own, each cut by the
    // lights' reach; empty where the draw is drawn whole with `lookup` and every light.
    std::vector<Piece> piecesOf(const TintSplit* split, std::size_t draw) const;
    void drawPieces(const Draw& d, const std::vector<Piece>& pieces, const TintSplit& split);
    void drawSurfaces(const std::vector<Draw>& draws, bool translucent, const scene::Camera& camera, float aspect,
                      const TintSplit* split = nullptr);
    void drawDepthFirst(const std::vector<Draw>& draws, const scene::Camera& camera, float aspect);
    bool ownObject(std::size_t object) const { return ownObjects_.empty() || (object < ownObjects_.size() && ownObjects_[object]); }
    void useLightLayout(std::vector<std::string> layout);
    std::vector<std::string> lightingDefines(const shadows::ShadowTechnique& technique) const;
    void drawDebugLines(const scene::Camera& camera, float aspect);
    // A lighting program's uniforms and its technique's lookup, before a pass draws with it.
    void prepareLighting(const gl::Program& program, bool translucent, const scene::Camera& camera, float aspect);
    // The texture units every lighting program of a pass reads besides the technique's maps
    // (placeholders, projector pictures, the debug and fog depths): context state, bound once a pass.
    void bindLightingUnits() const;
    // A debug channel looks behind the surface showBehind chose.
    bool showsBehind() const { return behind_ && options_.output != OutputMode::Shaded; }
    LightingPrograms buildLighting(const shadows::ShadowTechnique& technique, std::vector<std::string> defines) const;
    void resolve(GLuint target, int width, int height, const scene::Camera& camera, float aspect);
    void setFogUniforms(const gl::Program& program, const scene::Camera& camera, float aspect) const;
    bool shadesIntoSrgb() const;
    bool fogInShading() const;
    // `layout` and the output's defines: FOG_IN_SHADING where the lighting shader applies the fog
    // (shadesIntoSrgb), DEBUG_OUTPUT for a debug channel.
    std::vector<std::string> withOutputDefines(std::vector<std::string> layout) const;
    void drawOverlay(GLuint target, int width, int height);
    void releaseBoundTextures();

    scene::Scene& scene_;
    RenderOptions options_;
    GpuScene gpu_;
    std::unique_ptr<shadows::ShadowTechnique> technique_;
    LightingPrograms lighting_;
    gl::Program resolve_, foggedResolve_, overlay_, lines_;
    TintShading tintShading_;
    // The world boxes behind the split and the lights' reach, per receiver, caster and light
    // (render/FrameMemo.h): kept while those stay put.
    mutable FrameMemo<FootprintCells> footprintCells_;
    mutable FrameMemo<std::vector<scene::Bounds>> reachCells_;
    mutable FrameMemo<std::vector<scene::Bounds>> shadowCells_;  // per receiver, caster and light (addShadowReach)
    std::vector<bool> ownObjects_;  // setReceivers; empty: all
    bool ownPixelsOnly_ = false;
    // Depth of the pre-pass / of another renderer's objects: the shadow passes' caster programs,
    // with the camera as the "light" (built on first use).
    std::optional<shadows::DepthCasterProgram> depthFirst_;
    std::vector<std::string> lightLayout_;      // the light layout's defines (render/LightingProgram.h)
    std::vector<std::string> lightingDefines_;  // what lighting_ was built with: the layout's and the technique's
    gl::Buffer lineVertices_;
    gl::VertexArray lineVao_;
    std::unique_ptr<OrderIndependentTransparency> oit_;  // built on first use, per technique
    PlaceholderTextures placeholders_;  // on every lighting unit the technique leaves empty
    gl::Buffer lightBlock_;
    gl::VertexArray emptyVao_;
    gl::Sampler overlaySampler_{GL_LINEAR, GL_LINEAR};  // reads depth maps without comparison
    // Float HDR colour (made for frames that resolve it) + depth; 32-bit so that debug channels
    // (positions) keep their precision.
    gl::Texture hdr_, depth_;
    const gl::Texture* behind_ = nullptr;  // showBehind
    gl::Framebuffer hdrFbo_;
    SrgbTarget srgb_;  // where the frame goes when it skips the float target
    bool srgbFrame_ = false;  // the last frame did
    const gl::Texture* fogDepth_ = nullptr;  // during the translucent pass: the opaque depth its fog reads
    gl::Texture releaseColour_;  // releaseBoundTextures's 1x1 target
    gl::Framebuffer releaseTarget_;
    int targetW_ = 0, targetH_ = 0;
    shadows::ShadowSlots slots_;  // this frame's shadow slots and sun
    std::vector<shadows::LightSpace> lastSpaces_;  // last frame's, per light (RenderOptions::holdSunBox reads them)
    std::vector<std::size_t> shadowTriangles_;
    FrameTimer timer_;
    std::uint32_t frameIndex_ = 0;
};

}  // namespace penumbra::render
