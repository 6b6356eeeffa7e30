#include "render/MeshClusters.h"

#include <algorithm>
#include <array>
#include <meshoptimizer.h>
#include <numeric>

namespace penumbra::render {

namespace {

struct Centroid {
    glm::vec3 at;
    std::uint32_t triangle;
};

// Splits [first, last) at the median along the longest axis of its centroids' box until each
// run holds at most kClusterTriangles (a kd-tree's leaves, as BVH builders cut meshes): runs come
// out between half that and that, and compact, which a plain cut of a Morton-sorted list is not
// (a run that crosses an octant's border spans the mesh).
void splitAtMedians(std::vector<Centroid>::iterator first, std::vector<Centroid>::iterator last,
                    std::vector<std::pair<std::uint32_t, std::uint32_t>>& runs, std::uint32_t offset) {
    const auto count = static_cast<std::uint32_t>(last - first);
    if (count <= kClusterTriangles) {
        runs.push_back({offset, count});
        return;
    }
    scene::Bounds box;
    for (auto c = first; c != last; ++c) box.add(c->at);
    const glm::vec3 e = box.extent();
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const auto middle = first + count / 2;
    // Ties broken by triangle number: the same clusters on every run.
    std::nth_element(first, middle, last, [axis](const Centroid& a, const Centroid& b) {
        return a.at[axis] < b.at[axis] || (a.at[axis] == b.at[axis] && a.triangle < b.triangle);
    });
    splitAtMedians(first, middle, runs, offset);
    splitAtMedians(middle, last, runs, offset + count / 2);
}

// Reorders the triangles of `count` indices for the post-transform vertex cache (meshoptimizer's
// meshopt_optimizeVertexCache, after Forsyth 2006), over the vertices they use alone so that the
// cost follows the run, not the mesh.
void orderForVertexReuse(std::uint32_t* indices, std::size_t count) {
    std::vector<std::uint32_t> used(indices, indices + count);
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    std::vector<std::uint32_t> local(count), ordered(count);
    for (std::size_t i = 0; i < count; ++i)
        local[i] = static_cast<std::uint32_t>(std::lower_bound(used.begin(), used.end(), indices[i]) - used.begin());
    meshopt_optimizeVertexCache(ordered.data(), local.data(), count, used.size());
    for (std::size_t i = 0; i < count; ++i) indices[i] = used[ordered[i]];
}

std::vector<MeshCluster> clusterPart(const scene::Mesh& mesh, const scene::MeshPart& part, std::vector<std::uint32_t>& indices) {
    const std::uint32_t triangles = part.indexCount / 3;
    const auto corner = [&](std::uint32_t t, int k) {
        return mesh.vertices[mesh.indices[part.firstIndex + 3 * t + static_cast<std::uint32_t>(k)]].position;
    };
    std::vector<Centroid> order(triangles);
    for (std::uint32_t t = 0; t < triangles; ++t) order[t] = {(corner(t, 0) + corner(t, 1) + corner(t, 2)) / 3.0f, t};
    std::vector<std::pair<std::uint32_t, std::uint32_t>> runs;  // (first triangle, count) in `order`
    splitAtMedians(order.begin(), order.end(), runs, 0);

    std::vector<MeshCluster> clusters;
    for (const auto& [start, count] : runs) {
        MeshCluster c{part.firstIndex + 3 * start, 3 * count, {}};
        for (std::uint32_t i = start; i < start + count; ++i)
            for (int k = 0; k < 3; ++k) {
                indices[part.firstIndex + 3 * i + static_cast<std::uint32_t>(k)] =
                    mesh.indices[part.firstIndex + 3 * order[i].triangle + static_cast<std::uint32_t>(k)];
                c.bounds.add(corner(order[i].triangle, k));
            }
        orderForVertexReuse(indices.data() + c.firstIndex, c.indexCount);
        clusters.push_back(c);
    }
    return clusters;
}

std::array<glm::vec4, 8> clipCorners(const scene::Bounds& box, const glm::mat4& clipFromBox) {
    std::array<glm::vec4, 8> corners{};
    for (int i = 0; i < 8; ++i) corners[static_cast<std::size_t>(i)] = clipFromBox * glm::vec4(box.corner(i), 1.0f);
    return corners;
}

}  // namespace

ClusteredIndices clusterMesh(const scene::Mesh& mesh) {
    ClusteredIndices out{mesh.indices, {}};
    for (const scene::MeshPart& part : mesh.parts)
        out.clusters.push_back(part.indexCount / 3 >= kClusteredPartTriangles ? clusterPart(mesh, part, out.indices)
                                                                             : std::vector<MeshCluster>{});
    return out;
}

bool outsideClipVolume(const scene::Bounds& box, const glm::mat4& clipFromBox) {
    if (box.empty()) return true;
    const std::array<glm::vec4, 8> corners = clipCorners(box, clipFromBox);
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-1.0f, 1.0f}) {
            bool allOutside = true;
            for (const glm::vec4& c : corners) allOutside = allOutside && side * c[axis] > c.w;
            if (allOutside) return true;
        }
    return false;
}

bool nearPlaneMayCut(const glm::mat4& viewProj, const scene::Bounds& bounds) {
    bool front = false, behind = false;
    for (const glm::vec4& clip : clipCorners(bounds, viewProj)) (clip.z + clip.w >= 0.0f ? front : behind) = true;
    return front && behind;
}

bool outsideAnyPlane(const scene::Bounds& box, std::span<const glm::vec4> planes) {
    return std::any_of(planes.begin(), planes.end(), [&](const glm::vec4& p) {
        const glm::vec3 farthest = glm::mix(box.min, box.max, glm::step(glm::vec3(0.0f), glm::vec3(p)));  // its corner farthest inside
        return glm::dot(glm::vec3(p), farthest) + p.w < 0.0f;
    });
}

std::vector<IndexRange> visibleRanges(const std::vector<MeshCluster>& clusters, const glm::mat4& clipFromMesh,
                                      std::span<const glm::vec4> meshPlanes) {
    std::vector<IndexRange> ranges;
    for (const MeshCluster& c : clusters) {
        if (outsideClipVolume(c.bounds, clipFromMesh) || outsideAnyPlane(c.bounds, meshPlanes)) continue;
        if (!ranges.empty() && ranges.back().firstIndex + ranges.back().indexCount == c.firstIndex)
            ranges.back().indexCount += c.indexCount;
        else
            ranges.push_back({c.firstIndex, c.indexCount});
    }
    return ranges;
}

}  // namespace penumbra::render
