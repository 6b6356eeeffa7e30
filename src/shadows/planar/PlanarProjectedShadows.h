#pragma once
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"
#include "shadows/common/ScreenShadowMask.h"
#include "shadows/planar/PlanarFit.h"

namespace penumbra::shadows {

// Planar projected shadows (Blinn 1988) onto one receiver plane (the largest flat object, or the
// one chosen by index): casters flattened by PlanarFit's matrix darken the receiver in each
// light's screen mask. The stencil marks the receiver's pixels (so nothing spills off it) and
// counts each pixel once (so overlapping casters do not darken twice). Both tricks, and the
// clipping of casters that are not between the plane and the light, can be switched off to show
// the failure modes of Plachý 2012 §2.3. Nothing but the receiver is shadowed.
class PlanarProjectedShadows final : public ShadowTechnique {
public:
    PlanarProjectedShadows();
    std::string name() const override { return "planar"; }
    std::filesystem::path lookupShader() const override { return "src/shadows/common/glsl/screen_mask_lookup.glsl"; }
    void renderMaps(const ShadowFrame& frame) override;
    void bindLookup(const gl::Program& lighting) const override;
    std::size_t memoryBytes() const override { return maps_.memoryBytes() + mask_.memoryBytes(); }
    std::vector<DebugView> debugViews() const override { return mask_.debugViews(); }
    const std::optional<ReceiverPlane>& receiver() const { return receiver_; }

protected:
    std::vector<Parameter> declareParameters() override;

private:
    void flattenCasters(const ShadowFrame& frame, int light);
    int receiverObject_ = -1;
    bool clipToReceiver_ = true, stencilOnce_ = true, naive_ = false;
    float opacity_ = 1;
    std::optional<ReceiverPlane> receiver_;
    gl::Program flattened_;
    ScreenShadowMask mask_;
    DepthAndTintMaps maps_;
};

}  // namespace penumbra::shadows
