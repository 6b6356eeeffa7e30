#pragma once
// Seed 002's combined technique (its section 3.2 and Fig. 3.2, the street scene): regions of one
// scene shaded at once with different techniques and map resolutions, so a person walking from
// one to the next sees the differences without restarting. Generalised: a scene file lists
// `regions` (technique, shadow_resolution, parameters) and an object names its `region`.
//
// One renderer per region, plus the base renderer for the objects of no region and the
// background. Each keeps its own shadow maps (every caster casts into every region's maps) and
// shades only its own objects' surfaces; the others it draws into depth alone. The base writes
// the whole frame first; each region then writes the pixels whose nearest opaque surface is one
// of its objects (Renderer::setReceivers). A pixel is therefore exactly what its owner's
// technique renders for the whole scene alone.
#include "render/Renderer.h"

#include <memory>
#include <vector>

namespace penumbra::render {

class RegionView {
public:
    // `base`: the options of the objects of no region (its technique "" = the scene's). Regions
    // take the rest of `base` and replace the technique, resolution and parameters they name.
    // Throws std::invalid_argument naming the scene file and region when a region's technique or
    // parameter is unknown.
    RegionView(scene::Scene& scene, const RenderOptions& base);

    void render(float time, const scene::Camera& camera, int width, int height, GLuint targetFramebuffer);
    Renderer& base() { return *base_; }
    std::size_t regionCount() const { return regions_.size(); }
    Renderer& region(std::size_t i) { return *regions_[i]; }
    // The last frame's GPU times of all renderers together (waits for them).
    PassTimes waitForTimes();
    // The newest finished frame's times of all renderers together, without waiting (the panel).
    PassTimes lastTimes() const;
    std::size_t shadowMemoryBytes() const;

private:
    std::unique_ptr<Renderer> base_;
    std::vector<std::unique_ptr<Renderer>> regions_;
};

// Whether a frame of `scene` with `options` is drawn by regions: the scene has them and no
// technique is forced on the whole scene (--technique). Throws std::invalid_argument naming the
// scene when `options.requireRegions` and it has none.
bool drawsByRegion(const RenderOptions& options, const scene::Scene& scene);

// The options region `region` of `scene` is drawn with: `base` with the region's technique,
// resolution and parameters.
RenderOptions regionOptions(const RenderOptions& base, const scene::Region& region);

}  // namespace penumbra::render
