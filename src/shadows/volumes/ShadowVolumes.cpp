#include "shadows/volumes/ShadowVolumes.h"

#include "gl/Debug.h"
#include "gl/PassState.h"
#include "shadows/volumes/NearClipVolume.h"
#include "util/Log.h"

#include <cstdint>
#include <map>
#include <utility>

namespace penumbra::shadows {

ShadowVolumes::ShadowVolumes() {
    volumes_ = gl::Program::build({.vertex = "src/shadows/volumes/volume.vert",
                                   .fragment = "src/shadows/volumes/volume.frag",
                                   .geometry = "src/shadows/volumes/volume.geom"});
    kept_ = gl::Program::build({.vertex = "src/shadows/volumes/volume_kept.vert", .fragment = "src/shadows/volumes/volume.frag"});
}

std::size_t ShadowVolumes::memoryBytes() const {
    std::size_t bytes = maps_.memoryBytes() + mask_.memoryBytes() + cache_.memoryBytes();
    for (const auto& m : meshes_) bytes += m.positions.size() + m.indices.size();
    return bytes;
}

namespace {

// Not a fault: such meshes shadow right, at up to twice the volume fill of a closed one.
void logBothSided(const std::map<std::string, int>& open, std::size_t meshCount) {
    if (open.empty()) return;
    std::string list;
    std::size_t meshes = 0;
    for (const auto& [mesh, count] : open) {
        meshes += static_cast<std::size_t>(count);
        list += (list.empty() ? "" : "; ") + mesh + (count > 1 ? log::format(" x{}", count) : std::string());
    }
    log::info("shadow volumes: {} of {} meshes are open, non-manifold or not consistently wound, and cast from both sides of "
              "every triangle: {}", meshes, meshCount, list);
}

}  // namespace

// Adjacency for every mesh, once per scene; the meshes that need both sides are listed.
void ShadowVolumes::upload(const ShadowFrame& frame) {
    if (uploaded_ == frame.scene) return;
    uploaded_ = frame.scene;
    meshes_.clear();
    cache_.reset(0, 0);
    std::map<std::string, int> open;  // "name (its edges)" of the meshes that cast from both sides -> how many
    const scene::Scene& scene = *frame.scene;
    // Per mesh, the parts some object leaves out of its volumes (glass): paired on their own.
    std::vector<std::vector<bool>> alone(scene.meshes.size());
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) alone[m].assign(scene.meshes[m].parts.size(), false);
    for (const auto& obj : scene.objects) {
        const auto m = static_cast<std::size_t>(obj.mesh);
        for (std::size_t p = 0; obj.castsShadow && p < alone[m].size(); ++p)
            if (scene.material(obj, scene.meshes[m].parts[p]).translucent()) alone[m][p] = true;
    }
    for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const scene::Mesh& mesh = scene.meshes[m];
        const AdjacencyMesh adj = buildAdjacency(mesh, alone[m]);
        GpuAdjacency g{gl::Buffer(std::span<const glm::vec3>(adj.positions)), gl::Buffer(std::span<const std::uint32_t>(adj.indices)),
                       gl::VertexArray(), {}};
        for (const EdgeCounts& part : adj.parts) g.partClosed.push_back(part.closed());
        glVertexArrayVertexBuffer(g.vao.id(), 0, g.positions.id(), 0, sizeof(glm::vec3));
        glVertexArrayElementBuffer(g.vao.id(), g.indices.id());
        g.vao.attribute(0, 0, 3, 0);
        meshes_.push_back(std::move(g));
        const EdgeCounts& edges = adj.edges;
        if (edges.closed()) continue;
        ++open[log::format("{} ({} border, {} shared by more than two, {} wound against their neighbour)",
                           mesh.name.empty() ? std::string("unnamed mesh") : mesh.name, edges.boundary, edges.nonManifold, edges.misoriented)];
    }
    logBothSided(open, scene.meshes.size());
}

VolumeExtent ShadowVolumes::setLight(const ShadowFrame& frame, const scene::Light& light) {
    const VolumeExtent extent(light, frame.sceneBounds, infinite_);
    volumes_.set("uLight", extent.light());
    volumes_.set("uViewProj", mask_.viewProj());
    volumes_.set("uExtrusion", extent.extrusion());
    return extent;
}

// The casting objects with their transforms, split by how their volumes are counted for `light`.
std::array<std::vector<ShadowVolumes::Caster>, 2> ShadowVolumes::castersByCounting(const ShadowFrame& frame, const scene::Light& light,
                                                                                    const VolumeExtent& extent) const {
    const NearClipVolume nearClip(glm::inverse(mask_.viewProj()), light);
    std::array<std::vector<Caster>, 2> out;  // [0]: z-fail, [1]: z-pass
    for (const auto& obj : frame.scene->objects) {
        if (!obj.castsShadow) continue;
        const glm::mat4 model = obj.transformAt(frame.time);
        const scene::Mesh& mesh = frame.scene->meshes[static_cast<std::size_t>(obj.mesh)];
        const scene::Bounds box = mesh.bounds.transformed(model);
        const bool zFail = counting_ == kAuto ? nearClip.mayHold(box) : counting_ == kZFail;
        out[zFail ? 0 : 1].push_back({&obj, model, extent.farPlane(box)});
    }
    return out;
}

// One caster's volume through the geometry shader (uEmit set by the caller).
void ShadowVolumes::drawVolume(const scene::Scene& scene, const Caster& caster) const {
    volumes_.set("uModel", caster.model);
    volumes_.set("uFarPlane", caster.farPlane);
    const scene::Mesh& mesh = scene.meshes[static_cast<std::size_t>(caster.object->mesh)];
    const GpuAdjacency& adjacency = meshes_[static_cast<std::size_t>(caster.object->mesh)];
    adjacency.vao.bind();
    for (std::size_t p = 0; p < mesh.parts.size(); ++p) {
        const scene::MeshPart& part = mesh.parts[p];
        if (scene.material(*caster.object, part).translucent()) continue;  // tints through the shared maps instead
        volumes_.set("uBothSides", adjacency.partClosed[p] ? 0 : 1);
        glDrawElements(GL_TRIANGLES_ADJACENCY, static_cast<GLsizei>(part.indexCount * 2), GL_UNSIGNED_INT,
                       reinterpret_cast<const void*>(static_cast<std::uintptr_t>(part.firstIndex) * 2 * sizeof(std::uint32_t)));
    }
}

// The casters' volumes under light `light`, sides and (z-fail) caps. A caster that held still
// since the last frame, under a light that did too, draws what VolumeCache captured of it; the
// others go through the geometry shader.
void ShadowVolumes::drawVolumes(const ShadowFrame& frame, std::size_t light, const VolumeExtent& extent,
                                const std::vector<Caster>& casters, bool zFail) {
    constexpr int kSides = 1, kCaps = 2;  // volume.geom's uEmit bits
    const scene::Scene& scene = *frame.scene;
    std::vector<const VolumeCache::Capture*> kept;
    volumes_.use();
    for (const Caster& caster : casters) {
        const auto object = static_cast<std::size_t>(caster.object - scene.objects.data());
        const VolumeCache::Key key{caster.model, extent.light(), caster.farPlane, extent.extrusion()};
        VolumeCache::Entry* still = frame.reuseStillCasters ? cache_.still(light, object, key) : nullptr;
        if (!still) {
            volumes_.set("uEmit", zFail ? kSides | kCaps : kSides);
            drawVolume(scene, caster);
            continue;
        }
        for (const auto& [capture, emit] : {std::pair{&still->sides, kSides}, std::pair{&still->caps, kCaps}}) {
            if (emit == kCaps && !zFail) continue;
            if (capture->vertices < 0) {
                volumes_.set("uEmit", emit);
                const std::size_t triangles = scene.meshes[static_cast<std::size_t>(caster.object->mesh)].triangleCount();
                cache_.capture(*capture, triangles * (emit == kSides ? 6 : 2), [&] { drawVolume(scene, caster); });
            }
            kept.push_back(capture);
        }
    }
    if (kept.empty()) return;
    kept_.use();
    kept_.set("uViewProj", mask_.viewProj());
    for (const VolumeCache::Capture* capture : kept) VolumeCache::draw(*capture);
}

namespace {

// Count volume faces per pixel: z-fail counts those behind the visible surface (back +1, front
// -1), right even where the near plane cuts a volume; z-pass those in front of it (front +1,
// back -1), which breaks there. The two sums add up in one stencil: each caster's volume
// counts 1 inside itself either way. Non-zero: in shadow. Depth clamp: the dark cap and the
// sides reach past the far plane.
gl::PassState countingState(bool zFail) {
    gl::PassState counting = gl::PassState::depthOnly();
    counting.depthWrite = false;
    counting.colorWrite = glm::bvec4(false);
    counting.depthClamp = true;
    counting.stencilTest = true;
    const gl::StencilFace up = zFail ? gl::StencilFace{.depthFail = GL_INCR_WRAP} : gl::StencilFace{.depthPass = GL_INCR_WRAP};
    const gl::StencilFace down = zFail ? gl::StencilFace{.depthFail = GL_DECR_WRAP} : gl::StencilFace{.depthPass = GL_DECR_WRAP};
    counting.stencilBack = zFail ? up : down;
    counting.stencilFront = zFail ? down : up;
    return counting;
}

}  // namespace

void ShadowVolumes::renderMaps(const ShadowFrame& frame) {
    maps_.render(frame);  // coloured tint, and the fallback for glass the pre-pass does not see
    if (!frame.scene || !frame.camera || frame.viewport.x <= 0) return;
    upload(frame);
    cache_.fit(frame.lights->size(), frame.scene->objects.size());
    gl::DebugGroup group("shadow volumes");
    mask_.begin(frame);
    const auto& lights = *frame.lights;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        mask_.beginLight(static_cast<int>(i));
        if (!lights[i].shadow.enabled) continue;
        const VolumeExtent extent = setLight(frame, lights[i]);
        const auto casters = castersByCounting(frame, lights[i], extent);
        for (const bool zFail : {true, false}) {
            const std::vector<Caster>& counted = casters[zFail ? 0 : 1];
            if (counted.empty()) continue;
            const gl::ScopedPassState state(countingState(zFail));
            drawVolumes(frame, i, extent, counted, zFail);
        }
        mask_.shadowWhereStencilNonZero();
    }
    cache_.releaseScratch();
}

void ShadowVolumes::bindLookup(const gl::Program& lighting) const {
    maps_.bind();
    mask_.bind(lighting);
}

}  // namespace penumbra::shadows
