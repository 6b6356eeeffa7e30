#pragma once
// A technique that renders nothing of its own: it reads the shared per-light depth + tint maps
// (DepthAndTintMaps) through its lookup, so only its lookup and parameters differ (hard, PCF,
// PCSS, distance-softened).
#include "shadows/ShadowTechnique.h"
#include "shadows/common/DepthAndTintMaps.h"

namespace penumbra::shadows {

class SharedMapTechnique : public ShadowTechnique {
public:
    void renderMaps(const ShadowFrame& frame) override { maps_.render(frame); }
    std::size_t memoryBytes() const override { return maps_.memoryBytes(); }
    std::vector<DebugView> debugViews() const override { return maps_.debugViews(); }

protected:
    DepthAndTintMaps maps_;
};

}  // namespace penumbra::shadows
