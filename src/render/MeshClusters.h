#pragma once
// Large mesh parts cut into spatially compact clusters, so that a shadow pass can skip the parts
// of a big caster that lie outside a cascade, a LiSPSM layer or a cube face (issue 15: "split big
// meshes into clusters so culling can bite"). Object culling alone drew all 871k triangles of the
// dragon into every cascade.
//
// The part's triangles are reordered by median splits of their centroids (only in the GPU's index
// buffer: the scene keeps its own order) into runs of at most kClusterTriangles, each with its
// bounding box. A run outside a pass's clip volume produces no fragment there, so skipping it
// leaves the map bit for bit as drawing it would. Within a run the triangles are then ordered for
// the post-transform vertex cache (meshoptimizer): the splits leave them shuffled, and llvmpipe
// shades a vertex again each time it has left its cache (measured on the dragon: hard's shadow
// pass a third less, the shadowless opaque pass a fifth; docs/measurements.md).
#include "scene/Mesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace penumbra::render {

struct MeshCluster {
    std::uint32_t firstIndex = 0;  // into the reordered index buffer
    std::uint32_t indexCount = 0;
    scene::Bounds bounds;          // mesh space
};

// Parts with fewer triangles stay whole: culling the object already covers them, and a draw per
// cluster would cost more than it saves.
inline constexpr std::uint32_t kClusteredPartTriangles = 32768;
inline constexpr std::uint32_t kClusterTriangles = 4096;

struct ClusteredIndices {
    std::vector<std::uint32_t> indices;             // the mesh's indices, large parts reordered
    std::vector<std::vector<MeshCluster>> clusters;  // per part; empty for parts left whole
};

ClusteredIndices clusterMesh(const scene::Mesh& mesh);

// True when the box, taken through `clipFromBox`, lies wholly outside one plane of the clip volume.
bool outsideClipVolume(const scene::Bounds& box, const glm::mat4& clipFromBox);
// True when the box lies wholly on the outer side (dot(plane, P) < 0) of one of `planes`, in the
// box's own space (a world plane p is transpose(model) p in a mesh's).
bool outsideAnyPlane(const scene::Bounds& box, std::span<const glm::vec4> planes);

// Whether the near plane of a pass drawn through `viewProj` (world to clip) may cut `bounds`:
// some corner lies in front of it (z + w >= 0 in clip space) and some behind it or behind the eye.
bool nearPlaneMayCut(const glm::mat4& viewProj, const scene::Bounds& bounds);

// The index ranges of the clusters inside the clip volume and on the inner side of every plane of
// `meshPlanes` (mesh space), neighbours merged into one range.
struct IndexRange {
    std::uint32_t firstIndex;
    std::uint32_t indexCount;
};
std::vector<IndexRange> visibleRanges(const std::vector<MeshCluster>& clusters, const glm::mat4& clipFromMesh,
                                      std::span<const glm::vec4> meshPlanes = {});

}  // namespace penumbra::render
