#include "render/RegionView.h"

#include <stdexcept>

namespace penumbra::render {

RenderOptions regionOptions(const RenderOptions& base, const scene::Region& region) {
    RenderOptions o = base;
    if (!region.technique.empty()) o.technique = region.technique;
    if (region.shadowResolution > 0) o.shadowResolution = region.shadowResolution;
    o.parameters.assign(region.parameters.begin(), region.parameters.end());
    o.strictParameters = true;  // a misspelt parameter in a scene file is an error, not a no-op
    return o;
}

RegionView::RegionView(scene::Scene& scene, const RenderOptions& base) {
    const std::size_t objects = scene.objects.size();
    std::vector<bool> unassigned(objects);
    for (std::size_t i = 0; i < objects; ++i) unassigned[i] = scene.objects[i].region < 0;
    base_ = std::make_unique<Renderer>(scene, base);
    base_->setReceivers(unassigned, false);
    for (std::size_t r = 0; r < scene.regions.size(); ++r) {
        const scene::Region& region = scene.regions[r];
        std::vector<bool> own(objects);
        for (std::size_t i = 0; i < objects; ++i) own[i] = scene.objects[i].region == static_cast<int>(r);
        try {
            regions_.push_back(std::make_unique<Renderer>(scene, regionOptions(base, region)));
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(scene.source.string() + ": regions[" + std::to_string(r) + "] '" + region.name +
                                        "': " + e.what());
        }
        regions_.back()->setReceivers(std::move(own), true);
    }
}

void RegionView::render(float time, const scene::Camera& camera, int width, int height, GLuint target) {
    base_->render(time, camera, width, height, target);
    for (auto& region : regions_) region->render(time, camera, width, height, target);
}

static void add(PassTimes& sum, const PassTimes& t) {
    sum.shadowMs += t.shadowMs;
    sum.opaqueMs += t.opaqueMs;
    sum.translucentMs += t.translucentMs;
    sum.postMs += t.postMs;
}

PassTimes RegionView::waitForTimes() {
    PassTimes sum = base_->waitForTimes();
    for (auto& region : regions_) add(sum, region->waitForTimes());
    return sum;
}

PassTimes RegionView::lastTimes() const {
    PassTimes sum = base_->lastTimes();
    for (const auto& region : regions_) add(sum, region->lastTimes());
    return sum;
}

std::size_t RegionView::shadowMemoryBytes() const {
    std::size_t bytes = base_->shadowMemoryBytes();
    for (const auto& region : regions_) bytes += region->shadowMemoryBytes();
    return bytes;
}

}  // namespace penumbra::render
