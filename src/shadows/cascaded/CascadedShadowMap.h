#pragma once
#include "shadows/ShadowTechnique.h"
#include "shadows/cascaded/CascadeFit.h"
#include "shadows/cascaded/DepthBounds.h"
#include "shadows/common/DepthAndTintMaps.h"
#include "shadows/common/LayeredDepthMap.h"

namespace penumbra::shadows {

// Cascaded shadow maps for the first shadowed directional light: 1-8 splits placed by λ, all
// rendered into the layers of one depth array, stabilised against shimmer, blended across
// borders, tinted per cascade on request, freezable to inspect from elsewhere. Other lights and
// the coloured tint use the shared per-light maps.
class CascadedShadowMap final : public ShadowTechnique {
public:
    std::string name() const override { return "cascaded"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/cascaded/lookup.glsl"; }
    // The splits and each cascade's box fitted to the camera (or held), and the reach over them.
    void fitToView(const ShadowFrame& frame) override;
    void renderMaps(const ShadowFrame& frame) override;
    // The coloured tint is the plain tint maps' (plainMapTint in shadow_filtering.glsl), read at the
    // receiver's texel as hard's: the default tint reach, and the default own-layers builds
    // (ShadowTechnique::ownLayersBuild) for glass receivers with every other layer on one side.
    // One texel compared at the receiver's own depth, in the coarsest cascade's texels
    // (reachInPlainTexels, set by renderMaps). Other lights' hard lookups reach less.
    float shadowReachTexels() const override { return reachTexels_; }
    // Over the cascades that pixels in `region` read (its view depths, blend bands included);
    // other lights' hard lookups: 2, as hard's.
    float shadowReachTexelsWithin(int light, const scene::Bounds& region) const override;
    std::uint64_t reachViewsDigest() const override;
    float shadowReachDepth() const override { return reachTexels_ < 0.0f ? -1.0f : 0.0f; }
    // CASCADE_SELECT: how a pixel picks its cascade, compiled in (llvmpipe would otherwise test
    // the other way too, a matrix product per cascade tried).
    std::vector<std::string> lookupDefines() const override { return {"CASCADE_SELECT " + std::to_string(select_)}; }
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override { return maps_.memoryBytes() + cascades_.memoryBytes(); }
    std::vector<DebugView> debugViews() const override;
    std::vector<DebugLine> debugLines() const override;
    const std::vector<Cascade>& cascades() const { return fitted_; }
    // Per cascade (fit_receivers; none given: whole layers): the texels a lookup can read, and the
    // column along the light over them (columnPlanes).
    struct Reads {
        std::vector<TexelRect> texels;
        std::vector<std::vector<glm::vec4>> columns;
    };
    Reads readTexels(const ShadowFrame& frame, const scene::Light& sun, int resolution) const;

protected:
    std::vector<Parameter> declareParameters() override;

private:
    int count_ = 4, select_ = 0;  // select: 0 by depth, 1 by projection (the lookup's CASCADE_SELECT)
    float lambda_ = 0.75f, blend_ = 0.1f, maxDistance_ = 0;
    bool stabilize_ = true, debugTint_ = false, freeze_ = false, sdsm_ = false, drawFrusta_ = true, fitReceivers_ = true;
    int light_ = -1, fittedResolution_ = 0;
    float reachTexels_ = -1.0f;  // shadowReachTexels: negative until the cascades are fitted
    float plainTexel_ = 0.0f, normalOffset_ = 0.0f;  // the sun's plain map's, for reachInPlainTexels
    glm::mat4 cameraView_{1.0f};
    std::vector<float> splits_;
    std::vector<Cascade> fitted_;
    std::vector<std::array<glm::vec3, 8>> slices_;  // camera frustum slice of each cascade, for the debug lines
    std::vector<glm::mat4> readSlices_;  // per cascade: the camera slice whose pixels read it, blend band included
    DepthBounds depthBounds_;
    LayeredDepthMap cascades_;
    DepthAndTintMaps maps_;
};

}  // namespace penumbra::shadows
