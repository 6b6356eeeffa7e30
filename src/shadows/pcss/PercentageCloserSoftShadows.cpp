#include "shadows/pcss/PercentageCloserSoftShadows.h"

#include "util/Digest.h"
#include "util/PerspectiveDepth.h"

#include <algorithm>
#include <cmath>

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

void PercentageCloserSoftShadows::fitToView(const ShadowFrame& frame) {
    lightReach_.clear();
    if (!frame.lights || !frame.lightSpaces) return;
    for (std::size_t i = 0; i < frame.lights->size() && i < frame.lightSpaces->size(); ++i) {
        const scene::Light& light = (*frame.lights)[i];
        const LightSpace& space = (*frame.lightSpaces)[i];
        LightReach r;
        r.bounded = space.faceCount == 1 && space.texelScale > 0.0f && space.far > space.near;
        r.perspective = space.perspective;
        r.shadowMatrix = space.shadowMatrix;
        r.near = space.near;
        r.far = space.far;
        r.texelScale = space.texelScale;
        r.normalOffset = std::max(light.shadow.normalOffset, 0.0f);
        const bool sun = light.type == scene::Light::Type::Directional;
        r.size = light.size > 0.0f ? light.size : (sun ? sunAngle_ : lightSize_);  // lookup.glsl's lightSize
        lightReach_.push_back(r);
    }
}

// The filter's radius is half the penumbra that the blockers' mean depth b makes at the receiver's
// depth r; the search's is narrower (b a quarter of the way from r to the near plane n, or n under a
// spot; lookup.glsl). Every blocker lies at or behind n. A sun's penumbra, (r - b) 2 tan(angle / 2)
// over the texel's size, is widest with b = n; a spot's, size (r - b) / (b r) over the texel scale,
// too. r is at most the region's deepest corner's depth, a normal offset further.
float PercentageCloserSoftShadows::shadowReachTexelsWithin(int light, const scene::Bounds& region) const {
    const float whole = shadowReachTexels();
    if (light < 0 || static_cast<std::size_t>(light) >= lightReach_.size() || region.empty()) return whole;
    const LightReach& l = lightReach_[static_cast<std::size_t>(light)];
    if (!l.bounded) return whole;
    float deepest = l.near;  // view depth along the light's axis
    for (int i = 0; i < 8; ++i) {
        const glm::vec4 s = l.shadowMatrix * glm::vec4(region.corner(i), 1.0f);
        if (!l.perspective) {
            deepest = std::max(deepest, l.near + s.z * (l.far - l.near));
            continue;
        }
        if (!(s.w > 0.0f)) return whole;  // behind the light: its depth bounds nothing
        deepest = std::max(deepest, util::perspectiveViewDepth(l.near, l.far, std::min(s.z / s.w, 1.0f)));
    }
    float penumbra = 0.0f;
    if (!l.perspective) {
        deepest += l.normalOffset * l.texelScale;
        penumbra = (deepest - l.near) * 2.0f * std::tan(glm::radians(l.size) * 0.5f) / l.texelScale;
    } else {
        deepest *= 1.0f + l.normalOffset * l.texelScale;
        penumbra = l.size * (deepest - l.near) / (l.near * l.texelScale * deepest);
    }
    // Whole texels, so that the renderer's memo of footprints keeps its keys while a sun's box moves a little.
    const float radius = std::clamp(std::ceil(0.5f * penumbra), 1.0f, maxRadius_);
    return std::min(radiusReachTexels(radius), whole);
}

std::uint64_t PercentageCloserSoftShadows::reachViewsDigest() const {
    util::Digest digest;
    digest.add(maxRadius_, lightReach_.size());
    for (const LightReach& l : lightReach_)
        digest.add(l.bounded, l.perspective, l.shadowMatrix, l.near, l.far, l.texelScale, l.normalOffset, l.size);
    return digest.value();
}

}  // namespace penumbra::shadows
