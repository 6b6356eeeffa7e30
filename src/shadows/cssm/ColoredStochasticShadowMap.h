#pragma once
#include "gl/Framebuffer.h"
#include "gl/Sampler.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"
#include "shadows/common/MapRegion.h"
#include "shadows/common/PoissonDisk.h"
#include "shadows/cssm/CssmFilter.h"

#include <glm/glm.hpp>

#include <optional>

namespace penumbra::shadows {

// Colored Stochastic Shadow Maps (McGuire & Enderton 2011; Mátl 2013 ch. 4-5). Per light: the
// opaque casters' depth map, and a colour map into which translucent casters write their depth
// per channel with probability ρ_λ = (1 - t_λ) α under MIN blending. Layers multiply naturally:
// light passes a texel only if no layer stopped it, so two green panes give t², which the
// thesis (sorting whole objects) could not.
//   cssm2: one ξ per fragment shared by the channels, RGBA16F (the thesis's RGB16F + alpha).
//   cssm1: an independent ξ per channel, RGBA32F ("one depth map per wavelength"; the thesis's
//          one pass per channel, drawn here as one pass with a ξ stream per channel).
// The defaults go past the thesis (each step selectable, the thesis's method being
// separate_opaque=false xi=white filter=cross13 coverage=false):
//   - separate_opaque: opaque occlusion is a hard test on the depth map; the colour map holds
//     translucent layers only (no blurred opaque edges, no lit-wall line artefact);
//   - xi=stratified: every threshold stratum once per 8 x 8 texel tile (caster.frag);
//   - filter=box64 with coverage: the receiver's own texels place the coloured edge (as sharp
//     as the plain map's), the tile counts of tiles.frag, blended between the 2 x 2 nearest
//     tiles, give the transmittance, exact to 1/64 inside a layer. The counts live in the
//     colour map's own mip level log2(side), so the lookup reads tiles and (where the tiles
//     cannot decide) texels in one loop with one fetch.
class ColoredStochasticShadowMap final : public ShadowTechnique {
public:
    enum class Variant { PerChannel = 1, Rgb = 2 };
    explicit ColoredStochasticShadowMap(Variant variant);

    std::string name() const override { return variant_ == Variant::Rgb ? "cssm2" : "cssm1"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/cssm/lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override;
    std::vector<std::string> lookupDefines() const override;
    float tintReachTexels() const override;
    // With the opaque casters in a map of their own, its hard compare and the coloured term, exactly
    // 1 beyond the tint's reach; without, the colour map holds them too.
    float shadowReachTexels() const override { return tintReachTexels() < 0.0f ? -1.0f : std::max(2.0f, tintReachTexels()); }
    // The separate opaque map's compare takes the receiver's own depth at its texel (compareAt).
    float shadowReachDepth() const override { return tintReachTexels() < 0.0f ? -1.0f : 0.0f; }
    bool behindLayersBuild() const override { return tintBehindAll(); }  // (tiles need the separate opaque map)
    bool ownLayersBuild() const override { return tintBehindAll(); }
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override;
    std::vector<DebugView> debugViews() const override;

protected:
    std::vector<Parameter> declareParameters() override;

private:
    struct LightMap {
        int resolution = 0;
        bool cube = false;
        GLenum format = 0;
        gl::Texture colour;
        std::vector<gl::Texture> depthFaces;    // 2D views of the depth map's faces (copy input)
        std::vector<gl::Framebuffer> targets;   // colour face + the depth map face (depth test)
        // Per face: the texels (x0, y0, x1, y1) that may hold something other than white, so that
        // the next frame clears only those (a 2048² RGBA32F clear is 64 MiB of writes).
        std::vector<TexelRect> dirty;
        // Per face: the digest of what the colour map and its tiles hold (0: nothing kept), so
        // that a face whose translucent casters, opaque depth under them and ξ are as in the last
        // frame is not redrawn (DepthAndTintMaps::LightMaps::translucentKeys).
        std::vector<std::uint64_t> holds;
        // With coverage: tiles.frag's statistics, one texel per side x side tile, in the colour
        // map's mip level log2(side) (0: no tiles).
        int tileSide = 0;
        std::vector<gl::Texture> colourFaces;      // 2D views of the colour map's level 0 faces (tiles input)
        std::vector<gl::Framebuffer> tileTargets;          // per face: its level log2(side)
        std::vector<gl::Framebuffer> nearestLayerTargets;  // per face: its level log2(side) - 1 (nearest_layer.frag)
    };
    void ensure(std::size_t light, const DepthAndTintMaps::LightMaps& depth);
    bool usesTiles() const;  // the lookup reads per-tile statistics (box filter, coverage, separate opaque)
    bool tintBehindAll() const { return usesTiles() && tintBehindAll_; }  // the lookup reads the tint maps
    int tileSide() const;
    float tapRadiusTexels() const;  // the Poisson and random filters' radius
    // Face `face` of light `light`'s colour map (and its tiles), over depth_'s opaque depth as it is now.
    void renderColour(const ShadowFrame& frame, std::size_t light, std::size_t face);
    void renderTiles(LightMap& m, std::size_t face, const TexelRect& rect, bool whole);
    void buildCasters();
    // What face `face` of light `light`'s colour map is drawn from this frame (0: not keepable).
    std::uint64_t colourKey(std::size_t light, std::size_t face) const;

    Variant variant_;
    int filter_ = gpu::kCssmBox64, generator_ = gpu::kRandomPcg, xi_ = gpu::kXiStratified;
    float radiusTexels_ = 0.0f;
    bool fp16_, separateOpaque_ = true, coverage_ = true, decideByNearestLayer_ = true, tintBehindAll_ = true;
    PoissonDisk poisson_;
    // With tint maps where tintBehindAll() (renderMaps), whose alpha tells the lookup whether an
    // opaque receiver is behind every layer around it (lookup.glsl, colouredByTint).
    DepthAndTintMaps depth_{/*withTint=*/false, DepthAndTintMaps::TintAlpha::FarthestLayer};
    std::vector<LightMap> maps_;
    gl::Program copy_, tiles_, nearestLayer_;
    std::optional<CasterProgramPair> casters_;  // buildCasters
    int castersXi_ = -1;  // the ξ kind casters_ was built with (-1: not built)
    gl::Sampler depthSampler_{GL_NEAREST, GL_NEAREST};  // depth as values, not comparisons
    gl::VertexArray fullscreenVao_;
};

}  // namespace penumbra::shadows
