#include "shadows/cascaded/CascadedShadowMap.h"

#include "gl/Debug.h"
#include "gpu/ShaderContract.h"
#include "shadows/LightSpace.h"
#include "util/Digest.h"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <cmath>
#include <limits>

namespace penumbra::shadows {

namespace {

// SDSM's bounds rounded outward onto a geometric grid of 5 % steps. Bounds taken as they come
// move every frame the camera moves, and with them every split: each cascade's box is fitted
// again, its map redrawn and its shadow edges swim. On the grid the splits hold while the visible
// range stays within its steps, the boxes hold (stabilised) and the maps are kept, for at most 5 %
// more depth range than the tight bounds.
constexpr float kSdsmStep = 1.05f;
float sdsmStepDown(float d) { return std::pow(kSdsmStep, std::floor(std::log(d) / std::log(kSdsmStep))); }
float sdsmStepUp(float d) { return std::pow(kSdsmStep, std::ceil(std::log(d) / std::log(kSdsmStep))); }

}  // namespace

std::vector<Parameter> CascadedShadowMap::declareParameters() {
    return {Parameter::integer("cascades", count_, 1, 8, "number of splits m"),
            Parameter::real("lambda", lambda_, 0, 1, "split scheme: C_i = λ C_log + (1 - λ) C_uni (Zhang et al. 2006)"),
            Parameter::flag("stabilize", stabilize_, "bounding-sphere fit and texel snapping against shimmer"),
            Parameter::real("blend", blend_, 0, 0.5f, "share of each cascade blended into the next"),
            Parameter::choice("select", select_, {"depth", "projection"}, "cascade chosen by view depth or by the first box holding the point"),
            Parameter::flag("debug_tint", debugTint_, "tint each cascade"),
            Parameter::flag("freeze", freeze_, "stop refitting, to fly away and look at the cascades"),
            Parameter::real("max_distance", maxDistance_, 0, 100000, "> 0: split no further than this (world units)"),
            Parameter::flag("sdsm", sdsm_, "split only the visible depth range, from a camera pre-pass (Lauritzen et al. 2011), rounded out to 5 % steps so that the splits hold"),
            Parameter::flag("draw_frusta", drawFrusta_, "draw each cascade's camera slice and light box with the overlay"),
            Parameter::flag("fit_receivers", fitReceivers_,
                            "draw each cascade only where its camera slice meets the scene (casters culled, texels scissored)")};
}

void CascadedShadowMap::fitToView(const ShadowFrame& frame) {
    light_ = frame.camera ? frame.slots->sun : -1;
    reachTexels_ = -1.0f;
    if (light_ < 0) return;
    const scene::Light& sun = (*frame.lights)[static_cast<std::size_t>(light_)];
    const int count = std::clamp(count_, 1, 8);
    const int res = (*frame.lightSpaces)[static_cast<std::size_t>(light_)].resolution;
    const scene::Camera& cam = *frame.camera;
    // Boxes held while they hold their slices (fitCascade's `previous`).
    const bool holdBoxes = frame.holdSunBox && stabilize_ && !freeze_;
    if (!freeze_ || static_cast<int>(fitted_.size()) != count || fittedResolution_ != res) {
        const std::vector<Cascade> last = holdBoxes && fittedResolution_ == res ? fitted_ : std::vector<Cascade>{};
        fittedResolution_ = res;
        float near = cam.near, far = maxDistance_ > 0.0f ? std::min(maxDistance_, cam.far) : cam.far;
        if (sdsm_ && frame.drawSurfaces)
            if (const auto bounds = depthBounds_.measure(frame)) {  // SDSM: split only what is visible
                near = std::max(near, sdsmStepDown(bounds->first * 0.99f));
                far = std::max(std::min(far, sdsmStepUp(bounds->second * 1.01f)), near * 1.01f);
            }
        splits_ = cascadeSplits(near, far, count, lambda_);
        fitted_.clear();
        slices_.clear();
        readSlices_.clear();
        for (int c = 0; c < count; ++c) {
            const auto i = static_cast<std::size_t>(c);
            const float a = splits_[i], b = splits_[i + 1];
            const auto slice = [&](float n, float f) { return glm::perspective(glm::radians(cam.fovDeg), frame.aspect, n, f) * cam.view(); };
            fitted_.push_back(fitCascade(sun, cam, frame.aspect, a, b, frame.sceneBounds, res, stabilize_,
                                         i < last.size() ? &last[i] : nullptr));
            slices_.push_back(frustumCorners(slice(a, b)));
            // The lookup blends cascade c - 1 into c over the last `blend` of slice c - 1.
            readSlices_.push_back(slice(c > 0 ? a - blend_ * (a - splits_[i - 1]) : a, b));
        }
        cameraView_ = cam.view();
    }
    plainTexel_ = (*frame.lightSpaces)[static_cast<std::size_t>(light_)].texelScale;
    normalOffset_ = sun.shadow.normalOffset;
    float coarsest = plainTexel_;
    for (const Cascade& c : fitted_) coarsest = std::max(coarsest, c.texelWorld);
    reachTexels_ = reachInPlainTexels(coarsest, plainTexel_, normalOffset_);
}

void CascadedShadowMap::renderMaps(const ShadowFrame& frame) {
    // Other lights, and every light's coloured tint; the sun's depth lives in the layered map.
    const scene::Light* sunLight = maps_.renderAllButTheSun(frame);
    if (!sunLight || light_ < 0) return;
    const scene::Light& sun = *sunLight;
    const int res = (*frame.lightSpaces)[static_cast<std::size_t>(light_)].resolution;
    const bool holdBoxes = frame.holdSunBox && stabilize_ && !freeze_;
    gl::DebugGroup group("cascades");
    std::vector<glm::mat4> viewProj;
    for (const auto& c : fitted_) viewProj.push_back(c.viewProj);
    // Held boxes leave the slice room to move by kBoxSlack / 2 of the box each way: the layers are
    // drawn with as much room around their reads.
    const Reads reads = readTexels(frame, sun, res);
    cascades_.render(frame, sun, res, viewProj, {}, reads.texels, holdBoxes ? static_cast<int>(static_cast<float>(res) * kBoxSlack * 0.5f) : 0,
                     reads.columns);
}

// The lookup (lookup.glsl) reads cascade c at view depths from the start of cascade c - 1's
// blend band (the first: from the camera) to split c + 1; a box's view depths lie between its
// corners'. By projection (select=projection) any cascade whose box holds a point may be first:
// the coarsest of all.
float CascadedShadowMap::shadowReachTexelsWithin(int light, const scene::Bounds& region) const {
    if (reachTexels_ < 0.0f) return reachTexels_;
    if (light != light_) return kPlainCompareReachTexels;  // other lights: hard's lookup
    if (select_ != 0 || region.empty() || splits_.size() != fitted_.size() + 1) return reachTexels_;
    float nearest = std::numeric_limits<float>::max(), farthest = std::numeric_limits<float>::lowest();
    for (int k = 0; k < 8; ++k) {
        const float depth = -(cameraView_ * glm::vec4(region.corner(k), 1.0f)).z;
        nearest = std::min(nearest, depth);
        farthest = std::max(farthest, depth);
    }
    float coarsest = plainTexel_;
    for (std::size_t c = 0; c < fitted_.size(); ++c) {
        const bool first = c == 0, last = c + 1 == fitted_.size();
        const float from = first ? std::numeric_limits<float>::lowest() : splits_[c] - blend_ * (splits_[c] - splits_[c - 1]);
        const float to = last ? std::numeric_limits<float>::max() : splits_[c + 1];
        if (farthest >= from && nearest <= to) coarsest = std::max(coarsest, fitted_[c].texelWorld);
    }
    return std::min(reachInPlainTexels(coarsest, plainTexel_, normalOffset_), reachTexels_);
}

std::uint64_t CascadedShadowMap::reachViewsDigest() const {
    util::Digest digest;
    digest.add(light_, select_, blend_, plainTexel_, normalOffset_, cameraView_);
    for (float split : splits_) digest.add(split);
    for (const Cascade& c : fitted_) digest.add(c.texelWorld);
    return digest.value();
}

// A cascade is read only by pixels of its camera slice (select=depth), and pixels are surfaces of
// the scene: where the slice meets the boxes around them (ShadowFrame::surfaceBounds, a box per
// cluster of big meshes), projected into the cascade, lies every texel a lookup reads, widened by
// the normal offset and the comparison's texel: their rectangle scissors the pass, their hull's
// column culls its casters. The far cascades of a small scene meet nothing and cost no pass.
CascadedShadowMap::Reads CascadedShadowMap::readTexels(const ShadowFrame& frame, const scene::Light& sun, int res) const {
    Reads reads;
    if (!fitReceivers_ || select_ != 0 || readSlices_.size() != fitted_.size() || !frame.surfaceBounds) return reads;
    const std::vector<scene::Bounds> surfaces = frame.surfaceBounds();
    const int margin = 2 + static_cast<int>(std::ceil(std::abs(sun.shadow.normalOffset)));
    for (std::size_t c = 0; c < fitted_.size(); ++c) {
        const Frustum slice(readSlices_[c]);
        std::vector<glm::vec3> points;
        for (const scene::Bounds& surface : surfaces) {
            const std::vector<glm::vec3> inside = frustumInsideBox(slice, surface);
            points.insert(points.end(), inside.begin(), inside.end());
        }
        reads.texels.push_back(grown(texelRect(points, fitted_[c].viewProj, res), glm::ivec2(margin), res));
        reads.columns.push_back(columnPlanes(points, fitted_[c].viewProj, res, static_cast<float>(margin)));
    }
    return reads;
}

void CascadedShadowMap::bindLookup(const gl::Program& lighting) const {
    maps_.bind();
    lighting.set("uCascadeLight", cascades_.empty() ? -1 : light_);
    if (light_ < 0 || cascades_.empty()) return;
    cascades_.bind(gpu::kUnitLayered);
    const int count = static_cast<int>(fitted_.size());
    lighting.set("uCascadeCount", count);
    glProgramUniform1fv(lighting.id(), lighting.location("uCascadeSplits[0]"), count + 1, splits_.data());
    std::vector<glm::mat4> matrices;
    std::vector<glm::vec3> texels;
    for (const auto& c : fitted_) {
        matrices.push_back(c.shadowMatrix);
        texels.push_back({c.texelWorld, c.depthFar - c.depthNear, 0.0f});
    }
    glProgramUniformMatrix4fv(lighting.id(), lighting.location("uCascadeMatrix[0]"), count, GL_FALSE, &matrices[0][0][0]);
    glProgramUniform3fv(lighting.id(), lighting.location("uCascadeTexel[0]"), count, &texels[0].x);
    lighting.set("uCascadeCameraView", cameraView_);
    lighting.set("uCascadeBlend", blend_);
    lighting.set("uCascadeDebug", debugTint_ ? 1 : 0);
}

std::vector<DebugView> CascadedShadowMap::debugViews() const {
    auto views = maps_.debugViews();
    if (!cascades_.empty()) views.insert(views.begin(), cascades_.debugView("cascade 0"));
    return views;
}

static void appendBox(std::vector<DebugLine>& lines, const std::array<glm::vec3, 8>& c, const glm::vec3& color) {
    for (int i = 0; i < 8; ++i)
        for (int bit = 1; bit < 8; bit <<= 1)
            if (!(i & bit)) lines.push_back({c[static_cast<std::size_t>(i)], c[static_cast<std::size_t>(i | bit)], color});
}

// Each cascade's slice of the camera frustum and its light-space box, in the cascade's tint:
// freeze the cascades and fly away to see how they cover the view.
std::vector<DebugLine> CascadedShadowMap::debugLines() const {
    std::vector<DebugLine> lines;
    if (!drawFrusta_) return lines;
    static const glm::vec3 kTints[4] = {{1.0f, 0.3f, 0.3f}, {0.3f, 1.0f, 0.3f}, {0.3f, 0.3f, 1.0f}, {1.0f, 1.0f, 0.3f}};
    for (std::size_t c = 0; c < fitted_.size() && c < slices_.size(); ++c) {
        appendBox(lines, slices_[c], kTints[c % 4]);
        appendBox(lines, frustumCorners(fitted_[c].viewProj), kTints[c % 4] * 0.5f);
    }
    return lines;
}

}  // namespace penumbra::shadows
