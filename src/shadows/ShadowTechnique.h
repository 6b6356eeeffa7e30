#pragma once
// One shadow technique = data (its maps) + passes (renderMaps) + a GLSL lookup that the
// lighting shader includes as "shadow_lookup.glsl", defining
//     vec3 shadowVisibility(int light, vec3 worldPos, vec3 worldNormal, float NdotL);
// (rgb: coloured visibility, 1 = fully lit). Adding a technique = a folder here + one line in
// Registry.cpp.
//
// This header is the whole seam between render/ and shadows/: render/ includes nothing else of
// shadows/, and shadows/ includes nothing of render/ (tests/cli/include_boundaries.cmake checks
// both). What both sides must agree on in GLSL (units, limits, the light block) lives in
// gpu/ShaderContract.h.
#include "gl/Program.h"
#include "scene/Camera.h"
#include "scene/Scene.h"
#include "shadows/LightSpace.h"
#include "shadows/Parameter.h"
#include "shadows/ShadowSlots.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace penumbra::shadows {

// Which casters a pass wants. Opaque casters block; translucent ones (coverage < 1 or
// transmission > 0) tint (McGuire & Enderton 2011).
enum class Casters { Opaque, Translucent };

// Which casters by motion: animated objects (`Moving`) or the others (`Still`), whose transforms
// change only when someone edits the scene.
enum class Motion { Any, Still, Moving };

// The square map a depth pass draws (CasterSelection::map).
struct CasterMap {
    int resolution = 0;
    glm::ivec4 texels{0};    // (x0, y0, x1, y1), exclusive: what the pass draws, its scissor if `scissored`
    bool scissored = false;  // else the scissor test is off
    // This map's texels per texel of its light's plain map (LightSpace::resolution) where both
    // see through the same light space (moments at half resolution: 1/2), so that a reach in the
    // light's texels is this many of its own; 1 for maps of their own (cascades, warped views).
    float texelsPerLightTexel = 1.0f;
    // The pass draws every caster again wherever moving ones are and were (moment maps' changed
    // texels), so a ground may follow moving casters too: drawn near them, its texels there
    // counting as theirs (ShadowFrame::casterTexels). Else a ground near a moving caster is whole.
    bool followsMovingCasters = false;
    // The texels of this pass within `pad` texels of its light's plain map of what world boxes
    // (their 8 corners each) seen through `viewProj` cover: the union of each box's bounding texels
    // (the whole map where a corner lies behind the eye), grown by the pad (MapRegion.cpp). Empty
    // where no box is.
    glm::ivec4 texelsNear(std::span<const std::array<glm::vec3, 8>> boxes, const glm::mat4& viewProj, float pad) const;
    // The smallest rectangle holding both (MapRegion's unite; either may be empty).
    static glm::ivec4 united(const glm::ivec4& a, const glm::ivec4& b);
};

// Which casters one shadow pass draws. Casters whose world bounds lie wholly outside the clip
// volume of `cull` (a light's view-projection, one cube face's, ...) are skipped: a caster
// outside a light's view volume cannot shadow anything inside it. nullopt draws every caster
// (passes that project casters elsewhere, layered passes that cull per layer themselves).
// The triangles drawn are counted for light `light` (-1: not counted).
// `lightViewProj`: the world-to-clip transform the casters are drawn through; drawCasters sets it
// as the programs' uLightViewProj (nullopt: the caller sets what its programs need).
// `nearestDepthOnly`: the pass keeps only the nearest depth. Along any ray the nearest surface of
// a solid (render::Draw::solid) is one of its front faces, so such a pass culls the faces a solid
// turns away from lightViewProj: the map is the same, at about half the raster work. Passes that
// flatten casters, or colour them through every face, draw both faces.
// `map`: the map a depth pass draws through lightViewProj, where it draws one view of one
// (nullopt: drawCasters draws each caster whole). With it, a ground carrying other casters is
// drawn only where their lookups read it (render::Renderer::flatCasterNeeds).
struct CasterSelection {
    Casters casters = Casters::Opaque;
    std::optional<glm::mat4> cull;
    int light = -1;
    Motion motion = Motion::Any;
    std::optional<glm::mat4> lightViewProj;
    bool nearestDepthOnly = false;
    std::optional<CasterMap> map;
    // World planes (dot(plane, P) >= 0 inside): a caster wholly outside any one is left out. A
    // cascade's: the column along the light over the receivers it is read for.
    std::vector<glm::vec4> cullPlanes;
};

// The program each caster draw uses: `plain` for materials whose texture the pass need not
// read, `textured` for the others. Depth passes read it only for an alpha test (materials with a
// cutoff, MASK) and keep the test's `discard` out of `plain`: a fragment stage that may discard
// costs llvmpipe its early depth write for every fragment (measured, default scene: hard's
// shadow pass 16.5 -> 11.3 ms). Passes that weigh light by coverage (the tint's transmittance)
// read the texture's alpha for any textured material (`coverageFromTexture`), and `plain` leaves
// the sample out: llvmpipe samples under a false uniform branch all the same (measured, default
// scene with every map redrawn: hard's shadow pass 61-63 -> 35-37 ms, the glass's tint in the
// projector's 2048^2 map). A single program converts to both.
struct DrawPrograms {
    DrawPrograms(const gl::Program& both) : plain(&both), textured(&both) {}  // NOLINT: implicit by design
    DrawPrograms(const gl::Program& plainProgram, const gl::Program& texturedProgram, bool coverageFromTexture)
        : plain(&plainProgram), textured(&texturedProgram), coverageFromTexture(coverageFromTexture) {}
    const gl::Program& of(const scene::Material& m) const {
        return m.alphaCutoff > 0.0f || (coverageFromTexture && m.diffuseTexture >= 0) ? *textured : *plain;
    }
    const gl::Program* plain;
    const gl::Program* textured;
    bool coverageFromTexture = false;
};

// A caster program's two builds for DrawPrograms. Uniforms set here reach both.
class CasterProgramPair {
public:
    CasterProgramPair(const gl::ProgramDesc& plain, const gl::ProgramDesc& textured, bool coverageFromTexture);
    template <class T>
    void set(const char* name, const T& value) const {
        plain_.set(name, value);
        textured_.set(name, value);
    }
    operator DrawPrograms() const { return {plain_, textured_, coverageFromTexture_}; }  // NOLINT: implicit by design

private:
    gl::Program plain_, textured_;
    bool coverageFromTexture_;
};

// Opaque casters into depth alone (shadows/common/glsl/depth.frag): an empty fragment stage for
// most materials, the alpha test for alpha-tested ones (see DrawPrograms for why they differ).
// The shadow passes draw casters with it, and the renderer its camera depth pre-pass
// (render/Renderer.cpp).
class DepthCasterProgram : public CasterProgramPair {
public:
    DepthCasterProgram();
};

// Translucent casters' transmittance into a tint map (shadows/common/glsl/transmit.frag): a build
// without the texture for untextured materials (see DrawPrograms).
class TintCasterProgram : public CasterProgramPair {
public:
    TintCasterProgram();
};

// What the renderer gives a technique for one frame.
struct ShadowFrame {
    const std::vector<scene::Light>* lights = nullptr;
    const std::vector<LightSpace>* lightSpaces = nullptr;  // one per light
    const ShadowSlots* slots = nullptr;                    // this frame's slots and sun, one per light
    // Draws the selected casters, each with its material's program of `programs` bound (uModel,
    // uLightViewProj when the selection names it, and material uniforms are set, the diffuse
    // texture is on unit 0); the caller sets any other matrix its programs read.
    std::function<void(DrawPrograms programs, const CasterSelection& selection)> drawCasters;
    // The world bounds of the casters `drawCasters` would draw for `selection` (empty: none), so
    // that passes over a map can be limited to where those casters can have written.
    std::function<scene::Bounds(const CasterSelection& selection)> casterBounds;
    // The texels of `selection.map` (which it must name, with lightViewProj) that those casters
    // can write: each one's bounding texels, a ground drawn only near its casters' scissor.
    std::function<glm::ivec4(const CasterSelection& selection)> casterTexels;
    // The same casters' world bounds one by one (a box per drawn part), for passes that must know
    // which caster lies in front of which (DepthAndTintMaps' tint over the still depth).
    std::function<std::vector<scene::Bounds>(const CasterSelection& selection)> casterBoxes;
    // A digest of what `drawCasters` would draw for `selection`: which parts, their transforms
    // and the materials' alpha tests. Equal digests in two frames mean equal depth written, so a
    // map of still casters can be kept (DepthAndTintMaps). Never 0.
    std::function<std::uint64_t(const CasterSelection& selection)> casterDigest;
    // false: every map is redrawn every frame (`--redraw-shadow-maps`: the bare per-frame cost).
    bool reuseStillCasters = true;
    // Hold a directional light's boxes across frames while they hold the view (the renderer's
    // RenderOptions::holdSunBox; cascades keep theirs as the plain map's LightSpace does).
    bool holdSunBox = true;
    // Some object casts a shadow through a translucent material (the lookups' SCENE_TRANSLUCENT_CASTERS).
    bool translucentCasters = true;
    // Draws the visible opaque surfaces (every one, or only object `onlyObject` when >= 0), each
    // with its material's program of `programs` bound: depth pre-passes and receiver masks of
    // screen-space techniques. Through the camera's view-projection only: solids' back faces are
    // culled as in the camera's own passes.
    std::function<void(DrawPrograms programs, int onlyObject)> drawSurfaces;
    const scene::Scene* scene = nullptr;  // geometry-based techniques (shadow volumes, planar)
    float time = 0.0f;                    // scene time of the frame (object transforms)
    glm::ivec2 viewport{0};               // size of the frame being rendered
    std::uint32_t frameIndex = 0;  // seeds per-frame randomness (stochastic techniques)
    const scene::Camera* camera = nullptr;  // view-dependent techniques (cascades) fit to it
    float aspect = 1.0f;
    scene::Bounds sceneBounds;              // every object at this frame's time
    // Boxes around every surface a lookup may shade (a box per cluster of big meshes), at this
    // frame's time: cascades fit the texels they draw to them. Made when asked for, as
    // casterBounds: most techniques never do.
    std::function<std::vector<scene::Bounds>()> surfaceBounds;
};

// A texture worth showing in the debug overlay.
struct DebugView {
    std::string label;
    GLuint texture = 0;
    GLenum target = GL_TEXTURE_2D;
    bool depth = false;  // show as linearised grey
    int layer = 0;
};

// A world-space line segment for the debug overlay (cascade frusta, light boxes).
struct DebugLine {
    glm::vec3 a, b;
    glm::vec3 color;
};

class ShadowTechnique {
public:
    virtual ~ShadowTechnique() = default;
    virtual std::string name() const = 0;
    // GLSL file (relative to the source root) that defines shadowVisibility().
    virtual std::filesystem::path lookupShader() const = 0;
    // Fits view-dependent maps (cascades, warps) to this frame's camera. Called every frame before
    // the renderer chooses which casters the maps need, which asks shadowReachTexels and
    // shadowReachTexelsWithin: they answer for this frame's views from then on, not last frame's.
    // The frame's caster callbacks (drawCasters, casterBounds, casterTexels, casterBoxes,
    // casterDigest) are not set yet; drawSurfaces is.
    virtual void fitToView(const ShadowFrame& frame) { (void)frame; }
    // Re-renders every light's maps (called every frame, after fitToView).
    virtual void renderMaps(const ShadowFrame& frame) = 0;
    // Compile-time choices of the lookup (`NAME value` preprocessor defines), so that the
    // lighting program holds only the chosen filter's code: llvmpipe runs every branch of a
    // uniform-selected filter for every pixel, masked (measured for CSSM: 52 ms of a 90 ms
    // opaque pass). The renderer rebuilds the program when they change.
    virtual std::vector<std::string> lookupDefines() const { return {}; }
    // How far from a receiver's own texel, in texels of its light's map (LightSpace::texelScale),
    // a translucent caster's layer can change the lookup's answer: the farthest it reads what
    // translucent casters wrote (tint maps, coloured layers), or less where its answer is exactly
    // white unless a layer lies nearer (CSSM's box filters with coverage); normal offset not
    // counted; negative where that is not bounded by the light's map (maps of their
    // own, cascades or warps, whose texels may be coarser) or where the lookup reads no tint
    // (`none`): every receiver then gets the one whole program. The renderer shades receivers no
    // translucent caster's shadow reaches with a program that reads none (render/TintReach.h).
    // Default: the bilinear tint at the receiver (tintAt in shadow_filtering.glsl).
    virtual float tintReachTexels() const { return 2.0f; }
    // How far from a receiver's own texel, in texels of its light's map, any caster, opaque or
    // translucent, can make the lookup's answer other than exactly 1 (lit); normal offset not
    // counted. The renderer shades the screen rectangles of opaque receivers that no other caster's
    // shadow volume reaches with a build that leaves the light's lookup out (UNSHADOWED_LIGHTS:
    // Renderer's shadow reach): there the map holds the receiver itself, flat, or what lies behind
    // it. Negative (the default) where that is not bounded by the light's map, or where the
    // answer may be below 1 with no caster near (moment maps' light bleeding and variance floor).
    virtual float shadowReachTexels() const { return -1.0f; }
    // shadowReachTexels for light `light`'s lookups at receivers inside `region` (a world box):
    // less where the maps read there are finer than the coarsest the frame has (cascades near the
    // camera, warped texels near the warp's near plane, other lights' plain maps). The renderer
    // pads each footprint first by shadowReachTexels, then by this over that footprint's box: a
    // receiver point within either pad of the caster lies in the box (Renderer::addShadowReach).
    // Never above shadowReachTexels; the default is it.
    virtual float shadowReachTexelsWithin(int light, const scene::Bounds& region) const {
        (void)light;
        (void)region;
        return shadowReachTexels();
    }
    // A digest of what shadowReachTexelsWithin answers by besides shadowReachTexels (the views
    // fitToView fitted): equal digests, equal answers for every region. 0 (the default): nothing else.
    virtual std::uint64_t reachViewsDigest() const { return 0; }
    // How much deeper than its receiver's biased depth (window depth of the light's map) the
    // lookup may compare with an opaque caster's depths: 0 where every compare takes the
    // receiver's own depth, the receiver-plane taps' clamp where they extrapolate it (0.01,
    // tapReceiverDepth). An opaque caster lying wholly behind the receiver, by more than that,
    // cannot shadow it (render/TintReach.h, opaqueShadowFootprint). Negative (the default): not
    // bounded, every caster's shadow volume counts on both sides of it.
    virtual float shadowReachDepth() const { return -1.0f; }
    // How far from a receiver's own texel, in texels of its light's map, a lookup that filters
    // depths before it compares (moment maps: their blur, the mip levels they read, the bilinear
    // fetch) reads the map, averaging the receiver's own depth with its occluders': a flat caster
    // (a ground) stays in the map within that reach of every caster that shadows it and every
    // receiver it shadows, and is left out beyond, where the lookup would mix its depth with
    // nothing but the far plane's (Renderer::flatCasterNeeds). Negative (the default): the lookup
    // compares depths one by one (shadowReachTexels' rule), or its reach is not bounded.
    virtual float filterReachTexels() const { return -1.0f; }
    // Whether the lookup has a cheaper build for receivers behind every translucent layer around
    // them (RECEIVER_BEHIND_LAYERS), giving the same pixels there: CSSM's tint product without its
    // fallback loop. The renderer draws with it where render/TintReach.h shows every caster whose
    // shadow may reach a receiver lies in front of it (tintFootprintNotBehind).
    virtual bool behindLayersBuild() const { return false; }
    // Whether the lookup's translucent build has cheaper variants for receivers whose own layers
    // are known (flat or convex: Draw::ownLayersKnown) where every other translucent layer lies on
    // one side of them: behind (RECEIVER_UNTINTED with MATERIAL_TRANSLUCENT: only their own layers
    // in front, read from no map) or in front (RECEIVER_BEHIND_LAYERS with MATERIAL_TRANSLUCENT:
    // the tint with their own layers divided out), without what sorts out layers on both sides.
    // The renderer draws with them where render/TintReach.h shows that side for every other caster
    // (tintFootprintNotInFront, tintFootprintNotBehind). A lookup that reads the plain tint maps
    // through plainMapTint (shadow_filtering.glsl) has them: every technique but CSSM without its
    // tint map. Until stop 62 only hard and the view-dependent ones said so, and the PCF family, PCSS,
    // distance, the moment maps, shadow volumes and planar shadows gave a pane's far side, seen
    // through its near side, the tint of every layer at its texels, those behind it too
    // (`compare --behind-glass`: 16.6 % wrong on scenes/glass.json, now 0.28 %).
    virtual bool ownLayersBuild() const { return true; }
    // Binds textures and sets uniforms the lookup needs on the lighting program.
    virtual void bindLookup(const gl::Program& lighting) const = 0;
    virtual std::size_t memoryBytes() const = 0;
    virtual std::vector<DebugView> debugViews() const { return {}; }
    virtual std::vector<DebugLine> debugLines() const { return {}; }

    // The technique's typed knobs, each with the default a fresh technique had.
    std::vector<Parameter> parameters();
    // Remembers the current values as the defaults (the registry calls it on creation).
    void captureDefaults();

protected:
    virtual std::vector<Parameter> declareParameters() { return {}; }

private:
    std::vector<std::pair<std::string, std::string>> defaults_;
};

struct TechniqueInfo {
    std::string name;
    std::string description;
    std::function<std::unique_ptr<ShadowTechnique>()> create;
};

const std::vector<TechniqueInfo>& techniqueRegistry();
// Throws std::invalid_argument listing the known names when `name` is unknown.
std::unique_ptr<ShadowTechnique> createTechnique(const std::string& name);
std::string knownTechniqueNames();
// Registry lookup only: needs no GL context.
bool isKnownTechnique(const std::string& name);

}  // namespace penumbra::shadows
