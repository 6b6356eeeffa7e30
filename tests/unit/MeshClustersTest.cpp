// MeshClusters: a big part's triangles are reordered into spatially compact clusters, each in an
// order that reuses transformed vertices; culling them against a clip volume must keep every
// triangle that reaches the volume.
#include "render/MeshClusters.h"
#include "scene/Shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <glm/gtc/matrix_transform.hpp>
#include <meshoptimizer.h>

namespace penumbra::render {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

std::vector<Triangle> triangles(const std::vector<std::uint32_t>& indices, std::uint32_t first, std::uint32_t count) {
    std::vector<Triangle> out;
    for (std::uint32_t i = first; i < first + count; i += 3) out.push_back({indices[i], indices[i + 1], indices[i + 2]});
    return out;
}

scene::Mesh bigSphere() {
    scene::Mesh m = scene::shapes::sphere(1.0f, 256, 128);
    EXPECT_GE(m.triangleCount(), kClusteredPartTriangles);
    return m;
}

TEST(MeshClusters, ABigPartKeepsItsTrianglesInClustersThatBoundThem) {
    const scene::Mesh mesh = bigSphere();
    const ClusteredIndices c = clusterMesh(mesh);
    ASSERT_EQ(c.clusters.size(), 1u);
    const std::vector<MeshCluster>& clusters = c.clusters[0];
    EXPECT_GE(clusters.size(), (mesh.triangleCount() + kClusterTriangles - 1) / kClusterTriangles);
    EXPECT_LE(clusters.size(), 2 * mesh.triangleCount() / kClusterTriangles);
    // The same triangles, corners in the same winding, in another order.
    auto before = triangles(mesh.indices, 0, static_cast<std::uint32_t>(mesh.indices.size()));
    auto after = triangles(c.indices, 0, static_cast<std::uint32_t>(c.indices.size()));
    std::sort(before.begin(), before.end());
    std::sort(after.begin(), after.end());
    EXPECT_EQ(before, after);
    // Clusters follow each other and bound their triangles; they are compact: on a unit sphere a
    // cluster of 4096 of 65k triangles spans far less than the sphere.
    std::uint32_t next = 0;
    for (const MeshCluster& cl : clusters) {
        EXPECT_EQ(cl.firstIndex, next);
        next += cl.indexCount;
        for (const Triangle& t : triangles(c.indices, cl.firstIndex, cl.indexCount))
            for (std::uint32_t v : t) {
                const glm::vec3 p = mesh.vertices[v].position;
                EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, cl.bounds.min)) && glm::all(glm::lessThanEqual(p, cl.bounds.max)));
            }
        EXPECT_LT(glm::length(cl.bounds.extent()), 1.8f) << "cluster at " << cl.firstIndex << " is not compact";
    }
    EXPECT_EQ(next, mesh.indices.size());
}

// Each cluster's triangles come in an order that reuses transformed vertices: the median splits
// leave them shuffled along one axis, and llvmpipe (like a GPU) shades a vertex again whenever
// it has left its small cache. Cache misses per triangle through a 16-entry FIFO
// (meshopt_analyzeVertexCache; about 0.5 for a long regular grid, 3 for no reuse): measured,
// at most 0.68 per cluster of this sphere, 1.45 in the median splits' order and 1.00 in the
// sphere's own row order.
TEST(MeshClusters, EachClusterReusesItsTransformedVertices) {
    const scene::Mesh mesh = bigSphere();
    const ClusteredIndices c = clusterMesh(mesh);
    for (const MeshCluster& cl : c.clusters[0]) {
        const meshopt_VertexCacheStatistics s =
            meshopt_analyzeVertexCache(c.indices.data() + cl.firstIndex, cl.indexCount, mesh.vertices.size(), 16, 0, 0);
        EXPECT_LT(s.acmr, 0.75f) << "cluster at " << cl.firstIndex;
    }
}

TEST(MeshClusters, SmallPartsStayWholeAndInOrder) {
    const scene::Mesh mesh = scene::shapes::sphere(1.0f, 48, 24);
    const ClusteredIndices c = clusterMesh(mesh);
    EXPECT_EQ(c.indices, mesh.indices);
    ASSERT_EQ(c.clusters.size(), 1u);
    EXPECT_TRUE(c.clusters[0].empty());
}

// Every triangle with a corner inside the clip volume lies in a kept range; the ranges are merged
// and leave out clusters wholly outside.
TEST(MeshClusters, CullingKeepsEveryTriangleThatReachesTheVolume) {
    const scene::Mesh mesh = bigSphere();
    const ClusteredIndices c = clusterMesh(mesh);
    // A narrow orthographic box looking down -z at the sphere's +x side.
    const glm::mat4 clip = glm::ortho(0.4f, 1.2f, -0.3f, 0.3f, -5.0f, 5.0f);
    const std::vector<IndexRange> ranges = visibleRanges(c.clusters[0], clip);
    ASSERT_FALSE(ranges.empty());
    std::vector<bool> kept(c.indices.size() / 3, false);
    std::uint32_t keptTriangles = 0;
    for (std::size_t i = 0; i < ranges.size(); ++i) {
        if (i > 0) {
            EXPECT_GT(ranges[i].firstIndex, ranges[i - 1].firstIndex + ranges[i - 1].indexCount) << "neighbours not merged";
        }
        for (std::uint32_t t = ranges[i].firstIndex / 3; t < (ranges[i].firstIndex + ranges[i].indexCount) / 3; ++t) kept[t] = true;
        keptTriangles += ranges[i].indexCount / 3;
    }
    EXPECT_LT(keptTriangles, mesh.triangleCount() / 2) << "the box sees a small part of the sphere";
    int reaching = 0;
    for (std::size_t t = 0; t < kept.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const glm::vec4 p = clip * glm::vec4(mesh.vertices[c.indices[3 * t + static_cast<std::size_t>(k)]].position, 1.0f);
            if (glm::all(glm::lessThanEqual(glm::abs(glm::vec3(p)), glm::vec3(p.w)))) {
                ++reaching;
                EXPECT_TRUE(kept[t]) << "triangle " << t << " reaches the volume but was culled";
            }
        }
    EXPECT_GT(reaching, 0);
}

// Planes cut clusters too (a cascade's column along the light): every triangle with a corner on
// the inner side of both planes lies in a kept range, and the clusters wholly beyond one are out.
TEST(MeshClusters, CullingByPlanesKeepsEveryTriangleOnTheirInnerSide) {
    const scene::Mesh mesh = bigSphere();
    const ClusteredIndices c = clusterMesh(mesh);
    const glm::mat4 everything = glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, -5.0f, 5.0f);
    // A slab 0.4 wide, tilted: 0.3 <= (x + y) / sqrt(2) <= 0.7.
    const float r = 1.0f / std::sqrt(2.0f);
    const std::vector<glm::vec4> planes{{r, r, 0.0f, -0.3f}, {-r, -r, 0.0f, 0.7f}};
    const std::vector<IndexRange> ranges = visibleRanges(c.clusters[0], everything, planes);
    std::vector<bool> kept(c.indices.size() / 3, false);
    std::uint32_t keptTriangles = 0;
    for (const IndexRange& range : ranges) {
        for (std::uint32_t t = range.firstIndex / 3; t < (range.firstIndex + range.indexCount) / 3; ++t) kept[t] = true;
        keptTriangles += range.indexCount / 3;
    }
    EXPECT_LT(keptTriangles, mesh.triangleCount() * 3 / 4) << "clusters beyond the slab left out";
    int reaching = 0;
    for (std::size_t t = 0; t < kept.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 p = mesh.vertices[c.indices[3 * t + static_cast<std::size_t>(k)]].position;
            if (std::all_of(planes.begin(), planes.end(), [&](const glm::vec4& q) { return glm::dot(glm::vec3(q), p) + q.w >= 0.0f; })) {
                ++reaching;
                EXPECT_TRUE(kept[t]) << "triangle " << t << " reaches the slab but was culled";
            }
        }
    EXPECT_GT(reaching, 0);
    EXPECT_EQ(visibleRanges(c.clusters[0], everything).size(), 1u) << "without planes: every cluster, one range";
}

TEST(MeshClusters, ABoxWhollyOutsideOnePlaneIsOutside) {
    const glm::mat4 clip = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, -1.0f, 1.0f);
    scene::Bounds inside, straddling, beside;
    inside.add(glm::vec3(-0.5f));
    inside.add(glm::vec3(0.5f));
    straddling.add(glm::vec3(0.5f, 0.0f, 0.0f));
    straddling.add(glm::vec3(3.0f, 0.2f, 0.2f));
    beside.add(glm::vec3(1.5f, 0.0f, 0.0f));
    beside.add(glm::vec3(3.0f, 0.2f, 0.2f));
    EXPECT_FALSE(outsideClipVolume(inside, clip));
    EXPECT_FALSE(outsideClipVolume(straddling, clip));
    EXPECT_TRUE(outsideClipVolume(beside, clip));
    EXPECT_TRUE(outsideClipVolume(scene::Bounds{}, clip)) << "an empty box";
}

}  // namespace
}  // namespace penumbra::render
