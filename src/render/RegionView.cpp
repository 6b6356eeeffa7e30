#include "render/RegionView.h"

#include <stdexcept>

namespace penumbra::render {

RenderOptions regionOptions(const RenderOptions& base, const scene::Region& region) {
    RenderOptions o = base;
    if (!region.technique.empty()) o.technique = region.technique;
    if (region.shadowResolution > 0) o.shadowResolution = region.shadowResolution;
    o.parameters.assign(region.parameters.begin(), region.parameters.end());
    o.strictParameters = true;  // a misspelt parameter in a scene file is an error, not a no-op
    o.floatTarget = true;  // it keeps the pixels it owns only (setReceivers): the resolve's discard; its programs built for that at once
    return o;
}

bool drawsByRegion(const RenderOptions& options, const scene::Scene& scene) {
    if (options.requireRegions && scene.regions.empty())
        throw std::invalid_argument(scene.source.string() +
                                    ": -sh 6 (a combination of techniques, one per region) needs a scene with 'regions', "
                                    "such as the street (-sc 3)");
    return !scene.regions.empty() && options.technique.empty();
}

RegionView::RegionView(scene::Scene& scene, const RenderOptions& base) {
    // The objects of region `r` (-1: of none), as Renderer::setReceivers takes them.
    const auto objectsOf = [&scene](int r) {
        std::vector<bool> own(scene.objects.size());
        for (std::size_t i = 0; i < own.size(); ++i) own[i] = scene.objects[i].region == r;
        return own;
    };
    base_ = std::make_unique<Renderer>(scene, base);
    base_->setReceivers(objectsOf(-1), false);
    for (std::size_t r = 0; r < scene.regions.size(); ++r) {
        const scene::Region& region = scene.regions[r];
        try {
            regions_.push_back(std::make_unique<Renderer>(scene, regionOptions(base, region)));
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument(scene.source.string() + ": regions[" + std::to_string(r) + "] '" + region.name +
                                        "': " + e.what());
        }
        regions_.back()->setReceivers(objectsOf(static_cast<int>(r)), true);
    }
}

void RegionView::render(float time, const scene::Camera& camera, int width, int height, GLuint target) {
    base_->render(time, camera, width, height, target);
    for (auto& region : regions_) region->render(time, camera, width, height, target);
}

PassTimes RegionView::waitForTimes() {
    PassTimes sum = base_->waitForTimes();
    for (auto& region : regions_) sum += region->waitForTimes();
    return sum;
}

PassTimes RegionView::lastTimes() const {
    PassTimes sum = base_->lastTimes();
    for (const auto& region : regions_) sum += region->lastTimes();
    return sum;
}

std::size_t RegionView::shadowMemoryBytes() const {
    std::size_t bytes = base_->shadowMemoryBytes();
    for (const auto& region : regions_) bytes += region->shadowMemoryBytes();
    return bytes;
}

}  // namespace penumbra::render
