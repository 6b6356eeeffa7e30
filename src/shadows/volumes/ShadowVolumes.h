#pragma once
#include "gl/Buffer.h"
#include "gl/VertexArray.h"
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"
#include "shadows/common/ScreenShadowMask.h"
#include "shadows/volumes/Adjacency.h"
#include "shadows/volumes/VolumeCache.h"
#include "shadows/volumes/VolumeExtent.h"

#include <array>
#include <vector>

namespace penumbra::shadows {

// Stencil shadow volumes (Crow 1977; z-fail after Carmack / Everitt & Kilgard 2002): silhouette
// edges found from triangle adjacency in a geometry shader and extruded away from the light,
// counted per pixel in the stencil buffer: z-fail with capped volumes for casters whose volume
// the near plane may cut (NearClipVolume), z-pass for the rest. Exact per pixel, any light type.
// Open, non-manifold or inconsistently wound parts cast from both sides of every triangle, as
// the reference sees them, at up to twice the fill. Each caster's volume ends on a plane just
// past what it can shadow (VolumeExtent); still casters under still lights keep their
// volumes across frames (VolumeCache), and only the counting follows the camera. Translucent
// casters tint through the shared per-light maps and alpha-tested holes are not seen (the volume
// is the geometry).
class ShadowVolumes final : public ShadowTechnique {
public:
    ShadowVolumes();
    std::string name() const override { return "shadow-volumes"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/common/glsl/screen_mask_lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override;
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override;
    std::vector<DebugView> debugViews() const override { return mask_.debugViews(); }

protected:
    std::vector<Parameter> declareParameters() override {
        return {Parameter::choice("counting", counting_, {"auto", "zfail", "zpass"},
                                  "auto: z-pass for casters whose volume cannot reach the near plane, z-fail with caps (Carmack's "
                                  "reverse) for the rest (Everitt & Kilgard 2002); zfail or zpass: one for every caster"),
                Parameter::flag("infinite", infinite_, "extrude to infinity (w = 0) instead of just past the scene")};
    }

private:
    struct GpuAdjacency {
        gl::Buffer positions, indices;
        gl::VertexArray vao;
        std::vector<bool> partClosed;  // per mesh part: closed parts cast from the side facing the light only
    };
    void upload(const ShadowFrame& frame);
    enum Counting { kAuto, kZFail, kZPass };  // the labels' order in declareParameters
    struct Caster {
        const scene::Object* object;
        glm::mat4 model;
        glm::vec4 farPlane;  // the plane its volume ends on (VolumeExtent::farPlane; n = 0: the fixed push)
    };
    VolumeExtent setLight(const ShadowFrame& frame, const scene::Light& light);
    std::array<std::vector<Caster>, 2> castersByCounting(const ShadowFrame& frame, const scene::Light& light, const VolumeExtent& extent) const;
    void drawVolume(const scene::Scene& scene, const Caster& caster) const;
    void drawVolumes(const ShadowFrame& frame, std::size_t light, const VolumeExtent& extent, const std::vector<Caster>& casters, bool zFail);
    int counting_ = kAuto;
    bool infinite_ = false;
    const scene::Scene* uploaded_ = nullptr;
    std::vector<GpuAdjacency> meshes_;
    gl::Program volumes_;
    gl::Program kept_;  // draws VolumeCache's captures
    VolumeCache cache_;
    ScreenShadowMask mask_;
    DepthAndTintMaps maps_;
};

}  // namespace penumbra::shadows
