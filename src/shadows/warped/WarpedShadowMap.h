#pragma once
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"
#include "shadows/common/LayeredDepthMap.h"
#include "shadows/warped/WarpFit.h"

namespace penumbra::shadows {

// View-dependent shadow maps for the first shadowed directional light: LiSPSM or PSM
// (WarpFit.h), over the whole view or per tile of a cols x rows grid over the screen, each tile's
// sub-frustum with its own warped map (Plachý 2012 §3.5, its -cw/-ch), each tile a layer of one
// LayeredDepthMap. Other lights, and every light's coloured tint, use the shared per-light maps.
class WarpedShadowMap final : public ShadowTechnique {
public:
    enum class Warp { Lispsm, Psm };
    WarpedShadowMap(std::string name, Warp warp, int cols, int rows);
    std::string name() const override { return name_; }
    std::filesystem::path lookupShader() const override { return "src/shadows/warped/lookup.glsl"; }
    // The views (one per tile) fitted to the camera, or held (fitViews), and the reach over them.
    void fitToView(const ShadowFrame& frame) override;
    void renderMaps(const ShadowFrame& frame) override;
    // The coloured tint is the plain tint maps' (plainMapTint in shadow_filtering.glsl), read at the
    // receiver's texel as hard's: the default tint reach, and the default own-layers builds
    // (ShadowTechnique::ownLayersBuild) for glass receivers with every other layer on one side.
    // One texel compared at the receiver's own depth, in the coarsest texel of the warped maps on
    // the camera's body (reachInPlainTexels, set by fitViews; none while frozen).
    float shadowReachTexels() const override { return reachTexels_; }
    // A single map's (no tiles): over `region`'s part of the camera's body, as shadowReachTexels
    // over the whole body; other lights' hard lookups: 2, as hard's.
    float shadowReachTexelsWithin(int light, const scene::Bounds& region) const override;
    std::uint64_t reachViewsDigest() const override;
    float shadowReachDepth() const override { return reachTexels_ < 0.0f ? -1.0f : 0.0f; }
    // WARPED_TILES: the tile count this frame's maps will have (renderMaps fits the grid the
    // parameters ask for, frozen or not), so a single map compiles without the per-pixel tile
    // search and its dynamically indexed matrix.
    std::vector<std::string> lookupDefines() const override;
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override { return maps_.memoryBytes() + warped_.memoryBytes(); }
    std::vector<DebugView> debugViews() const override;
    const std::vector<WarpedView>& views() const { return views_; }

protected:
    std::vector<Parameter> declareParameters() override;

private:
    glm::ivec2 requestedGrid() const;
    void fitViews(const ShadowFrame& frame, const scene::Light& sun, glm::ivec2 grid);

    std::string name_;
    Warp warp_;
    int cols_, rows_;
    float nScale_ = 1.0f, minSinGamma_ = 0.05f, psmMinNear_ = 0.02f;
    bool debugTint_ = false, freeze_ = false, nearFromCamera_ = true;
    int light_ = -1, resolution_ = 0;
    glm::ivec2 grid_{1, 1};
    glm::mat4 cameraViewProj_{1.0f};
    std::vector<WarpedView> views_;  // this frame's, one per tile (last frame's while fitViews runs)
    std::uint64_t fitKey_ = 0;       // what views_ were fitted under: light, resolution, grid, parameters
    // Everything fitViews reads (fitKey_, the camera, the objects' boxes, whether the views are held):
    // the same again refits to the same views, which are kept.
    std::uint64_t fitInputs_ = 0;
    float reachTexels_ = -1.0f;      // shadowReachTexels
    float fittedReach_ = -1.0f;      // reachTexels_ as fitViews left it
    // shadowReachTexelsWithin's: the single view's frustum (none with tiles), its map's texel
    // sizes, the scene's box and the body's margin (warpBodyMargin).
    struct ReachView {
        Frustum frustum;
        WarpedTexelGauge texel;
        scene::Bounds scene;
        glm::vec3 margin;
    };
    std::optional<ReachView> reachView_;
    float plainTexel_ = 0.0f, normalOffset_ = 0.0f;
    LayeredDepthMap warped_;
    DepthAndTintMaps maps_;
};

}  // namespace penumbra::shadows
