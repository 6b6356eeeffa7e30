#pragma once
#include "gl/Buffer.h"
#include "gl/VertexArray.h"
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"
#include "shadows/common/ScreenShadowMask.h"
#include "shadows/volumes/Adjacency.h"

namespace penumbra::shadows {

// Stencil shadow volumes (Crow 1977; z-fail after Carmack / Everitt & Kilgard 2002): silhouette
// edges found from triangle adjacency in a geometry shader and extruded to infinity, counted
// per pixel in the stencil buffer, z-pass or z-fail with capped volumes. Exact (per pixel, any
// light type) for closed meshes; open meshes are warned about, and their volumes closed along
// the border, which is right for the side facing the light. Translucent casters tint through
// the shared per-light maps and alpha-tested holes are not seen (the volume is the geometry).
class ShadowVolumes final : public ShadowTechnique {
public:
    ShadowVolumes();
    std::string name() const override { return "shadow-volumes"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/common/screen_mask_lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override;
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override;
    std::vector<DebugView> debugViews() const override { return mask_.debugViews(); }
    std::vector<Parameter> parameters() override { return {{"zfail", &zFail_, 0, 1}, {"infinite", &infinite_, 0, 1}}; }

private:
    struct GpuAdjacency {
        gl::Buffer positions, indices;
        gl::VertexArray vao;
        bool closed = true;
    };
    void upload(const ShadowFrame& frame);
    void drawVolumes(const ShadowFrame& frame, const scene::Light& light);
    float zFail_ = 1, infinite_ = 0;
    const scene::Scene* uploaded_ = nullptr;
    std::vector<GpuAdjacency> meshes_;
    gl::Program volumes_;
    ScreenShadowMask mask_;
    DepthAndTintMaps maps_;
};

}  // namespace penumbra::shadows
