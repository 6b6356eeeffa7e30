#pragma once
// A shared-map technique whose lookup runs a kernel of taps (PCF, PCSS): it also keeps
// DepthTileBounds of the maps, from which the lookup (common/glsl/depth_tiles.glsl) skips the taps
// wherever they all give one answer. The parameter `skip_agreeing_taps` turns that off (the
// pictures are the same either way; the tests compare them).
#include "shadows/common/DepthTileBounds.h"
#include "shadows/common/SharedMapTechnique.h"

namespace penumbra::shadows {

class KernelTechnique : public SharedMapTechnique {
public:
    void renderMaps(const ShadowFrame& frame) override {
        maps_.render(frame);
        if (skipAgreeing_) tileBounds_.update(maps_, tileReachTexels(), boundsEveryFrame_);
        else tileBounds_.forget();  // stale from here on: remade whole when turned on again
    }
    std::size_t memoryBytes() const override { return maps_.memoryBytes() + tileBounds_.memoryBytes(); }
    std::vector<DebugView> debugViews() const override {
        std::vector<DebugView> views = maps_.debugViews(), bounds = tileBounds_.debugViews(maps_.slots());
        views.insert(views.end(), bounds.begin(), bounds.end());
        return views;
    }

protected:
    // The farthest, along x or y, that the lookup asks tapsAgree() to bound (texels; < 0: no bound
    // known, every level of the tile bounds is made).
    virtual float tileReachTexels() const = 0;
    // `what`: which taps the lookup skips where the bounds show their answer.
    std::vector<Parameter> skipAgreeingParameters(const std::string& what) {
        return {Parameter::flag("skip_agreeing_taps", skipAgreeing_, what + " (same pixels)"),
                Parameter::flag("tile_bounds_every_frame", boundsEveryFrame_,
                                "make the depth tile bounds also for maps drawn whole every frame (on llvmpipe "
                                "they cost more than the taps they save there; on a GPU, measure)")};
    }
    void bindTileBounds(const gl::Program& lighting) const {
        tileBounds_.bind();
        lighting.set("uSkipAgreeing", skipAgreeing_ ? 1 : 0);
    }

private:
    DepthTileBounds tileBounds_;
    bool skipAgreeing_ = true;
    bool boundsEveryFrame_ = false;  // DepthTileBounds::update's `everyFrame`
};

}  // namespace penumbra::shadows
