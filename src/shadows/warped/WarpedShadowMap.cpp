#include "shadows/warped/WarpedShadowMap.h"

#include "gl/Debug.h"
#include "gpu/ShaderContract.h"
#include "shadows/LightSpace.h"
#include "util/Digest.h"

#include <algorithm>
#include <cmath>

namespace penumbra::shadows {

namespace {
constexpr float kReachMargin = 1.5f;
}  // namespace

WarpedShadowMap::WarpedShadowMap(std::string name, Warp warp, int cols, int rows)
    : name_(std::move(name)), warp_(warp), cols_(cols), rows_(rows) {}

std::vector<Parameter> WarpedShadowMap::declareParameters() {
    std::vector<Parameter> p = {Parameter::integer("cols", cols_, 1, 4, "screen tiles across, each with its own warped map (Plachý 2012 §3.5)"),
                                Parameter::integer("rows", rows_, 1, 4, "screen tiles down")};
    if (warp_ == Warp::Lispsm) {
        p.push_back(Parameter::real("n_scale", nScale_, 0.05f, 20.0f, "factor on Wimmer's optimal n"));
        p.push_back(Parameter::real("min_sin_gamma", minSinGamma_, 0.0f, 1.0f,
                                    "below this sine of the view-light angle: uniform (orthographic) map"));
        p.push_back(Parameter::flag("near_from_camera", nearFromCamera_, "z_n from the camera's near plane (as Wimmer's code), else the body's nearest point"));
    } else {
        p.push_back(Parameter::real("min_near", psmMinNear_, 0.001f, 1.0f, "virtual camera's near plane at least this share of far"));
    }
    p.push_back(Parameter::flag("debug_tint", debugTint_, "tint each tile"));
    p.push_back(Parameter::flag("freeze", freeze_, "stop refitting, to fly away and look"));
    return p;
}

void WarpedShadowMap::fitToView(const ShadowFrame& frame) {
    light_ = frame.camera ? frame.slots->sun : -1;
    reachTexels_ = -1.0f;
    if (light_ < 0) return;
    const glm::ivec2 grid = requestedGrid();
    if (!freeze_ || grid != grid_ || static_cast<int>(views_.size()) != grid.x * grid.y)
        fitViews(frame, (*frame.lights)[static_cast<std::size_t>(light_)], grid);
}

void WarpedShadowMap::renderMaps(const ShadowFrame& frame) {
    // Other lights, and every light's coloured tint; the sun's depth lives in the layered map.
    const scene::Light* sunLight = maps_.renderAllButTheSun(frame);
    if (!sunLight || light_ < 0) return;
    const scene::Light& sun = *sunLight;
    const int res = (*frame.lightSpaces)[static_cast<std::size_t>(light_)].resolution;
    resolution_ = res;
    gl::DebugGroup group(name_.c_str());
    std::vector<glm::mat4> viewProj;
    std::vector<glm::vec4> planes;
    for (const auto& v : views_) {
        viewProj.push_back(v.viewProj);
        planes.push_back(v.clipPlane);
    }
    warped_.render(frame, sun, res, viewProj, planes);
}

// Each tile's view fitted to this frame's camera, or last frame's held while it still serves
// (ShadowFrame::holdSunBox; followWarpedView). The first frame, and any after a change of the
// light, the resolution, the grid or a parameter, gets the tight fit, as a single frame does.
void WarpedShadowMap::fitViews(const ShadowFrame& frame, const scene::Light& sun, glm::ivec2 grid) {
    const scene::Camera& cam = *frame.camera;
    const LightSpace& plain = (*frame.lightSpaces)[static_cast<std::size_t>(light_)];
    // Tiles reach only as far as the scene does: a 1 km far plane must not thin the warp.
    const float far = std::min(cam.far, glm::length(cam.position - frame.sceneBounds.center()) +
                                            0.5f * glm::length(frame.sceneBounds.extent()));
    const float reach = std::max(far, cam.near * 2.0f);
    WarpScene where(frame.sceneBounds);
    if (frame.scene)
        for (const auto& obj : frame.scene->objects)
            where.objects.push_back(frame.scene->meshes[static_cast<std::size_t>(obj.mesh)].bounds.transformed(obj.transformAt(frame.time)));
    const std::uint64_t fitKey = util::Digest()
                                     .add(sun.direction, plain.resolution, grid, nScale_, minSinGamma_, nearFromCamera_, psmMinNear_)
                                     .value();
    const bool hold = frame.holdSunBox && fitKey == fitKey_ && static_cast<int>(views_.size()) == grid.x * grid.y;
    // A still camera over still objects refits to the views it has: they are kept (the 98k grid's
    // 100 objects, 2,420 corners in the camera's body, cost psm's fit 1.07 ms of CPU a frame).
    // With `hold`, last frame's views are an input too; they came from these same inputs.
    util::Digest inputs;
    inputs.add(fitKey, hold, cam.position, cam.target, cam.up, cam.fovDeg, cam.near, cam.far, frame.aspect, frame.sceneBounds,
               plain.viewProj[0], plain.shadowMatrix, plain.texelScale, sun.shadow.normalOffset);
    for (const scene::Bounds& box : where.objects) inputs.add(box);
    if (inputs.value() == fitInputs_ && static_cast<int>(views_.size()) == grid.x * grid.y) {
        reachTexels_ = fittedReach_;
        return;
    }
    fitInputs_ = inputs.value();
    fitKey_ = fitKey;
    grid_ = grid;
    float coarsest = plain.texelScale;  // of the maps on the bodies their pixels lie in
    const AcrossLight across(sun.direction);
    reachView_.reset();
    std::vector<WarpedView> views;
    for (int r = 0; r < grid.y; ++r)
        for (int c = 0; c < grid.x; ++c) {
            const glm::mat4 tile = tileProjection(cam, frame.aspect, grid.x, grid.y, c, r, reach) * cam.view();
            WarpBody body;
            WarpedView v;
            if (makeWarpBody(sun, tile, where, body))
                v = warp_ == Warp::Lispsm ? fitLispsm(sun, cam, body, {nScale_, minSinGamma_, nearFromCamera_})
                                          : fitPsm(sun, cam, body, psmMinNear_);
            if (!v.valid) {  // the tile sees nothing of the scene: the plain fit keeps lookups defined
                v.viewProj = plain.viewProj[0];
                v.shadowMatrix = plain.shadowMatrix;
                views.push_back(v);
                continue;
            }
            if (hold) v = followWarpedView(v, &views_[views.size()], body, sun.direction);
            // Over the body's corners; a margin for texels that grow faster than linearly between
            // them (PSM's double projection).
            const WarpedTexelGauge texel(v.shadowMatrix, across, plain.resolution);
            for (const glm::vec3& p : body.visible) coarsest = std::max(coarsest, kReachMargin * texel.at(p));
            if (grid == glm::ivec2(1))
                reachView_ = ReachView{Frustum(tile), texel, frame.sceneBounds, warpBodyMargin(frame.sceneBounds)};
            views.push_back(v);
        }
    views_ = std::move(views);
    plainTexel_ = plain.texelScale;
    normalOffset_ = sun.shadow.normalOffset;
    reachTexels_ = reachInPlainTexels(coarsest, plainTexel_, normalOffset_);
    fittedReach_ = reachTexels_;
    cameraViewProj_ = cam.projection(frame.aspect) * cam.view();
}

// Pixels lie in the camera's body: of `region`, only its part inside the view (and the scene's
// box) is read. Over that part's corners, as fitViews over the body's, with the same margin, where
// each lies in front of the warp; else the coarsest of the frame.
float WarpedShadowMap::shadowReachTexelsWithin(int light, const scene::Bounds& region) const {
    if (reachTexels_ < 0.0f) return reachTexels_;
    if (light != light_) return kPlainCompareReachTexels;  // other lights: hard's lookup
    if (!reachView_ || region.empty() || views_.size() != 1) return reachTexels_;
    // A flat region (a floor's footprint) has a box of zero thickness: the body's margin (warpBodyMargin).
    scene::Bounds grown = region;
    grown.min = glm::max(grown.min - reachView_->margin, reachView_->scene.min);
    grown.max = glm::min(grown.max + reachView_->margin, reachView_->scene.max);
    if (glm::any(glm::greaterThan(grown.min, grown.max))) return 2.0f;  // outside the scene: no receiver there
    const WarpedView& view = views_.front();
    float coarsest = plainTexel_;
    for (const glm::vec3& p : frustumInsideBox(reachView_->frustum, grown)) {
        if (!((view.shadowMatrix * glm::vec4(p, 1.0f)).w > 0.0f)) return reachTexels_;
        coarsest = std::max(coarsest, kReachMargin * reachView_->texel.at(p));
    }
    return std::min(reachInPlainTexels(coarsest, plainTexel_, normalOffset_), reachTexels_);
}

std::uint64_t WarpedShadowMap::reachViewsDigest() const {
    util::Digest digest;
    digest.add(light_, plainTexel_, normalOffset_, views_.size(), reachView_.has_value());
    for (const WarpedView& v : views_) digest.add(v.shadowMatrix);
    if (reachView_) digest.add(reachView_->frustum.planes, reachView_->scene, reachView_->margin);
    return digest.value();
}

glm::ivec2 WarpedShadowMap::requestedGrid() const { return {std::clamp(cols_, 1, 4), std::clamp(rows_, 1, 4)}; }

std::vector<std::string> WarpedShadowMap::lookupDefines() const {
    const glm::ivec2 grid = requestedGrid();
    return {"WARPED_TILES " + std::to_string(grid.x * grid.y)};
}

void WarpedShadowMap::bindLookup(const gl::Program& lighting) const {
    maps_.bind();
    lighting.set("uWarpedLight", warped_.empty() ? -1 : light_);
    if (light_ < 0 || warped_.empty()) return;
    warped_.bind(gpu::kUnitLayered);
    std::vector<glm::mat4> matrices;
    for (const auto& v : views_) matrices.push_back(v.shadowMatrix);
    glProgramUniformMatrix4fv(lighting.id(), lighting.location("uWarpedMatrix[0]"), static_cast<GLsizei>(matrices.size()),
                              GL_FALSE, &matrices[0][0][0]);
    lighting.set("uWarpedGrid", grid_);
    lighting.set("uWarpedCameraViewProj", cameraViewProj_);
    lighting.set("uWarpedResolution", static_cast<float>(resolution_));
    lighting.set("uWarpedDebug", debugTint_ ? 1 : 0);
}

std::vector<DebugView> WarpedShadowMap::debugViews() const {
    auto views = maps_.debugViews();
    if (!warped_.empty()) views.insert(views.begin(), warped_.debugView(name_ + " tile 0"));
    return views;
}

}  // namespace penumbra::shadows
