#include "shadows/pcss/PercentageCloserSoftShadows.h"

#include "shadows/pcf/PercentageCloserFilter.h"

#include <algorithm>
#include <cmath>

namespace penumbra::shadows {

PercentageCloserSoftShadows::PercentageCloserSoftShadows() : poisson_(poissonDisk(32)) {}

std::vector<Parameter> PercentageCloserSoftShadows::parameters() {
    return {{"blocker_samples", &blockerSamples_, 4, 32},
            {"filter_taps", &filterTaps_, 4, 32},
            {"light_size", &lightSize_, 0.0f, 5.0f},
            {"sun_angle_deg", &sunAngle_, 0.0f, 20.0f},
            {"max_radius_texels", &maxRadius_, 1.0f, 128.0f}};
}

void PercentageCloserSoftShadows::bindLookup(const gl::Program& lighting) const {
    maps_.bind(/*rawDepth=*/true);
    lighting.set("uBlockerSamples", std::clamp(static_cast<int>(std::lround(blockerSamples_)), 1, 32));
    lighting.set("uFilterTaps", std::clamp(static_cast<int>(std::lround(filterTaps_)), 1, 32));
    lighting.set("uLightSizeDefault", lightSize_);
    lighting.set("uSunAngleDefault", sunAngle_);
    lighting.set("uMaxRadiusTexels", maxRadius_);
    glProgramUniform2fv(lighting.id(), lighting.location("uPoisson[0]"), static_cast<GLsizei>(poisson_.size()), &poisson_[0].x);
}

std::vector<Parameter> DistanceSoftenedShadows::parameters() {
    return {{"near_distance", &nearDistance_, 0.0f, 10.0f},
            {"far_distance", &farDistance_, 0.0f, 50.0f},
            {"spacing_texels", &spacing_, 0.5f, 8.0f}};
}

void DistanceSoftenedShadows::bindLookup(const gl::Program& lighting) const {
    maps_.bind(/*rawDepth=*/true);
    lighting.set("uNearDistance", nearDistance_);
    lighting.set("uFarDistance", std::max(farDistance_, nearDistance_));
    lighting.set("uSpacingTexels", spacing_);
}

}  // namespace penumbra::shadows
