#include "shadows/pcss/PercentageCloserSoftShadows.h"

namespace penumbra::shadows {

std::vector<Parameter> PercentageCloserSoftShadows::declareParameters() {
    std::vector<Parameter> p{Parameter::integer("blocker_samples", blockerSamples_, 4, kMaxTaps, "taps of the blocker search"),
            Parameter::integer("filter_taps", filterTaps_, 4, kMaxTaps, "taps of the variable-width PCF"),
            Parameter::real("light_size", lightSize_, 0.0f, 5.0f, "world diameter of local lights without a scene `size`"),
            Parameter::real("sun_angle_deg", sunAngle_, 0.0f, 20.0f, "angular diameter of suns without a scene `size`"),
            Parameter::real("max_radius_texels", maxRadius_, 1.0f, 128.0f, "cap on search and filter radius (bounds the cost)")};
    for (Parameter& q : skipAgreeingParameters("skip search and filter where depth bounds of the receiver's tile show how they end"))
        p.push_back(std::move(q));
    return p;
}

void PercentageCloserSoftShadows::bindLookup(const gl::Program& lighting) const {
    maps_.bind(/*rawDepth=*/true);
    bindTileBounds(lighting);
    lighting.set("uBlockerSamples", blockerSamples_);
    lighting.set("uFilterTaps", filterTaps_);
    lighting.set("uLightSizeDefault", lightSize_);
    lighting.set("uSunAngleDefault", sunAngle_);
    lighting.set("uMaxRadiusTexels", maxRadius_);
}

}  // namespace penumbra::shadows
