#pragma once
// Per-light storage most shadow-map techniques share: an opaque-caster depth map (2D or cube)
// and a transmittance ("tint") map of translucent casters in front of it (the per-light colour
// buffer of Nápravník 2020). Which light has maps, and on which units, is the frame's
// ShadowSlots. Reallocated when a light's resolution changes.
//
// Redrawn only where something changed (ShadowFrame::reuseStillCasters, on by default): a face
// whose light, map and still casters (ShadowFrame::casterDigest) are as in the last frame keeps
// its depth when no animated caster reaches it; when one does, the still casters' depth comes
// from a copy kept in `still` and only the animated ones are drawn over it. The tint is kept
// while the still translucent and opaque casters are, and redrawn only where animated casters
// were last frame or are now: translucent ones, and opaque ones over the translucent casters'
// texels (`translucentKeys`, `translucentRedo`, which techniques with maps of their own over the
// same depth, CSSM's, use too). Opaque ones only where a translucent caster may lie in front of
// them: where every one that shares their texels lies behind them, the tint is drawn over the
// still casters' depth and the animated ones after it (NearestLayer maps, kept or redrawn alike;
// see translucentBehindMoving in the .cpp). Moments redo only the animated casters' texels (`stillKeys`,
// `movingTexels`). Measured on llvmpipe, default scene (one animated sphere) and glass scene (a
// flying glass ball): see the README's "Shadow maps of still casters".
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Sampler.h"
#include "gl/Texture.h"
#include "shadows/ShadowTechnique.h"
#include "shadows/common/MapRegion.h"

#include <functional>
#include <vector>

namespace penumbra::shadows {

class DepthAndTintMaps {
public:
    struct LightMaps {
        int resolution = 0;
        bool cube = false;
        gl::Texture depth;  // DEPTH_COMPONENT32F, hardware compare enabled
        gl::Texture tint;   // RGBA16F: rgb transmittance, a as TintAlpha says
        // Per face (6 for cubes): depth only for the opaque pass (llvmpipe then never touches
        // the colour tiles), depth + colour for the translucent pass.
        std::vector<gl::Framebuffer> depthFaces, tintFaces;
        // Per face: the texels that may hold something other than white (where translucent
        // casters were last drawn), so that the next frame clears only those, and a face with no
        // translucent caster in view, already white, has neither a clear nor a pass.
        std::vector<TexelRect> tintDirty;
        // Per face, digests of what a map holds (0: unknown or something that moves): `depth`
        // drawn from still casters only, `still` (allocated in scenes that animate anything).
        std::vector<std::uint64_t> depthHolds, stillHolds;
        // Per face, this frame's digest of what a pass of translucent casters depth-tested against
        // this map draws outside `translucentRedo`: the still translucent casters, the still opaque
        // depth and the light (0: unknown). A map drawn from that pass (the tint, CSSM's colour
        // map) that was drawn with the same key last frame needs drawing again only in
        // `translucentRedo`: the texels where animated casters, translucent or opaque over the
        // translucent ones, were last frame or are now. With another key, everything is redone.
        std::vector<std::uint64_t> translucentKeys;
        std::vector<TexelRect> translucentRedo;
        std::vector<TexelRect> translucentMoving;  // this frame's part of translucentRedo, for the next
        // Per face, this frame: the digest of the still opaque casters (0: maps are not kept) and
        // the texels the animated ones can cover, so that passes over the depth (moments) redo
        // only what changed.
        std::vector<std::uint64_t> stillKeys;
        std::vector<TexelRect> movingTexels;
        gl::Texture still;  // the still casters' depth, copied into `depth` before the animated ones are drawn
        // Per face, after a frame that drew animated casters over a copy of `still`: the digest of
        // that copy (0: none) and the texels they were drawn in. Outside those `depth` equals
        // `still`, so the next such frame copies back only them and this frame's (a whole 2048^2
        // face cost llvmpipe about 4 ms a frame).
        std::vector<std::uint64_t> depthOverStill;
        std::vector<TexelRect> depthMovedIn;
        std::vector<gl::Framebuffer> stillFaces;
        // The drawn alpha (RG32F: 1 - the farthest layer's depth per texel, 1 - the farthest
        // entry's, transmit.frag), which the tint pass writes as its second target (tintFaces'
        // attachment 1; a cube map's faces through drawnFaceViews): translucent receivers read it
        // (bind(), at ShadowSlots::drawnUnit) to divide their own layers out of the tint. Made with
        // the map under FarthestLayer (CSSM); under NearestLayer in scenes with translucent casters
        // (ShadowFrame::translucentCasters; without, the plain techniques' maps go without its 8
        // bytes per texel).
        gl::Texture drawn;
        std::vector<gl::Texture> drawnFaceViews;
    };

    // What the alpha of a tint texel holds.
    enum class TintAlpha {
        // 1 - the nearest translucent layer's window depth (0: no layer): a receiver beyond it is
        // tinted (the hard lookups' tintBehind). Stored as 1 - depth because half floats are
        // finest near 0 and a perspective light's depths crowd towards 1: stored as the depth,
        // rounding by up to 2^-12 outgrew the receiver's bias, and translucent receivers under a
        // spot or projector tinted themselves (compare --translucent-receivers, default scene's
        // projector: 12.6 % of pixels wrong).
        NearestLayer,
        // 1 - the farthest translucent layer's window depth (1: no layer), MIN-blended by the tint
        // pass itself. A gather of the alpha under a receiver's bilinear fetch gives the 2 x 2
        // texels that fetch blends, so their least tells whether the receiver lies behind every
        // layer of them: least > 1 - its depth (CSSM's opaque receivers, colouredByTint, which then
        // need no per-texel test). Sampled bilinearly: rgb blends the 2 x 2 products, white where
        // no layer is. (Until stop 52 a pass of its own wrote each texel's least over its 3 x 3
        // neighbours into the alpha, so that the bilinear fetch's alpha bounded the 2 x 2 by
        // itself: 0.5 ms of the glass scene's shadow pass whenever its ball moved, against a gather
        // in the lookup that costs nothing measurable.)
        FarthestLayer,
    };

    // Passes that draw translucent casters over a light's opaque depth, tested and not written (the
    // tint here, CSSM's colour map), push each fragment's tested depth back by this (factor, units)
    // offset (glsl/over_opaque.glsl): the light's polygon offset, which the opaque casters were
    // drawn with, and a few units more. A translucent face lying on an opaque surface (a glass
    // block's bottom on the floor) then fails the test and tints nothing there, as an opaque
    // surface does not shadow itself, and as the ray-traced reference, whose shadow rays start past
    // the receiver, sees it. The depth they store stays the fragment's own.
    static glm::vec2 translucentTestOffset(const scene::Light& light);

    // `withTint` false: opaque depth only (techniques that handle translucency themselves).
    explicit DepthAndTintMaps(bool withTint = true, TintAlpha tintAlpha = TintAlpha::NearestLayer);
    // Turns the tint maps on or off; the maps are made again on the next render.
    void setWithTint(bool withTint);
    bool withTint() const { return withTint_; }
    // `elsewhere` (a light index, -1: none, kEveryLight: all): a light whose opaque depth the
    // technique keeps in a map of its own (cascades, warped maps, moments). Its plain depth map is
    // drawn only when translucent casters need it as the depth test of the tint pass, and then
    // only under them (culled and scissored to their texels); otherwise the light costs no pass
    // here (measured on the 975k-triangle grid: 965k triangles per frame saved).
    // `translucentPass` (may be empty): the technique's own pass of translucent casters tested
    // against this depth (CSSM's colour map), called per light and face right after the tint's.
    // The depth it tests against then holds the animated opaque casters only where a translucent
    // caster may lie in front of them (translucentBehindMoving in the .cpp; translucentRedo counts
    // their texels only then); without it, only the plain tint (NearestLayer) is drawn that way.
    using TranslucentPass = std::function<void(std::size_t light, std::size_t face)>;
    static constexpr int kEveryLight = -2;
    void render(const ShadowFrame& frame, int elsewhere = -1, const TranslucentPass& translucentPass = {});
    // For techniques that keep the sun's depth in a layered map of their own (cascades, warped
    // maps), which needs a camera to fit: render(frame, sun) while a camera looks, else every map
    // here. Returns the sun to draw that map for, or nullptr (no sun or no camera this frame).
    const scene::Light* renderAllButTheSun(const ShadowFrame& frame);
    // Binds each light's maps to the units of its slot (gpu/ShaderContract.h); with `rawDepth`
    // the depth map is also bound, without comparison, to the raw units.
    void bind(bool rawDepth = false) const;
    std::size_t memoryBytes() const;
    std::vector<DebugView> debugViews() const;
    void setFiltering(GLenum filter);  // GL_NEAREST (hard) or GL_LINEAR (hardware 2x2 PCF)

    // The slots of the last rendered frame (lights without maps have slot -1).
    const ShadowSlots& slots() const { return slots_; }
    const LightMaps& maps(std::size_t light) const { return maps_[light]; }
    const DepthCasterProgram& depthProgram() const { return depthProgram_; }  // opaque casters -> depth

private:
    void ensure(std::size_t light, int resolution, bool cube);
    void ensureStill(LightMaps& maps);
    bool ensureDrawn(LightMaps& maps);  // allocates LightMaps::drawn, cleared to "no layer"; true if it did
    // Where a face's opaque depth is needed: the clip space casters are culled against (the
    // light's, or that cropped to `texels`) and, when `cropped`, the texels drawn and cleared.
    struct OpaqueRegion {
        glm::mat4 cull;
        TexelRect texels;
        bool cropped;
    };
    // Makes face `face` of light `light`'s depth map hold this frame's opaque casters in `region`,
    // drawing as little as the digests allow; `stillKey` is their digest (0: do not reuse).
    // `movingLater`: the animated ones are left for drawMovingOver, so that the tint pass between
    // the two is tested against the still casters' depth alone.
    void renderOpaque(const ShadowFrame& frame, LightMaps& maps, std::size_t face, int light, const OpaqueRegion& region,
                      std::uint64_t stillKey, bool moving, bool movingLater);
    // Draws the animated opaque casters over face `face`'s depth, inside their texels
    // (maps.movingTexels) or the cropped region.
    void drawMovingOver(const ShadowFrame& frame, LightMaps& maps, std::size_t face, int light, const OpaqueRegion& region);
    // Sets face `face`'s translucentKeys and translucentRedo for this frame's `key` and the
    // texels `changed` by animated casters; true when the maps drawn last frame are kept (the
    // same key), so that only translucentRedo is drawn again.
    bool keepTranslucent(LightMaps& maps, std::size_t face, std::uint64_t key, const TexelRect& changed);
    // Clears the tint in `redraw` and draws the `translucent` casters (none: nullptr) there again.
    void redrawTint(const ShadowFrame& frame, LightMaps& maps, std::size_t face, const CasterSelection* translucent,
                    const TexelRect& redraw, const scene::Light& light);
    GLenum tintFilter() const { return tintAlpha_ == TintAlpha::FarthestLayer ? GL_LINEAR : filter_; }
    std::vector<LightMaps> maps_;
    ShadowSlots slots_;
    DepthCasterProgram depthProgram_;
    TintCasterProgram tintProgram_;
    gl::Sampler rawSampler_{GL_NEAREST, GL_NEAREST};  // reads depth maps without comparison
    GLenum filter_ = GL_NEAREST;
    bool withTint_ = true;
    TintAlpha tintAlpha_;
    int depthElsewhere_ = -1;  // of the last render
    bool depthElsewhere(int light) const { return depthElsewhere_ == kEveryLight || light == depthElsewhere_; }
};

}  // namespace penumbra::shadows
