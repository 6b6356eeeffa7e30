#include "shadows/distance/DistanceSoftenedShadows.h"

#include <algorithm>

namespace penumbra::shadows {

std::vector<Parameter> DistanceSoftenedShadows::declareParameters() {
    return {Parameter::real("near_distance", nearDistance_, 0.0f, 10.0f, "world caster-receiver distance below which the sharp kernel"),
            Parameter::real("far_distance", farDistance_, 0.0f, 50.0f, "world distance above which the widest kernel"),
            Parameter::real("spacing_texels", spacing_, 0.5f, 8.0f, "distance between the 3x3 taps")};
}

void DistanceSoftenedShadows::bindLookup(const gl::Program& lighting) const {
    maps_.bind(/*rawDepth=*/true);
    lighting.set("uNearDistance", nearDistance_);
    lighting.set("uFarDistance", std::max(farDistance_, nearDistance_));
    lighting.set("uSpacingTexels", spacing_);
}

}  // namespace penumbra::shadows
