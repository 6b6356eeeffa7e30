// Shadow volumes and planar shadows, the geometry: adjacency and closedness of the built-in
// shapes, Blinn's flattening matrix, and the choice of the receiver plane.
#include "scene/Shapes.h"
#include "shadows/planar/PlanarFit.h"
#include "shadows/volumes/Adjacency.h"

#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

TEST(Adjacency, BoxAndSphereAreClosedAPlaneHasFourBorderEdges) {
    const AdjacencyMesh box = buildAdjacency(scene::shapes::box(glm::vec3(1.0f)));
    EXPECT_TRUE(box.closed());
    EXPECT_EQ(box.positions.size(), 8u) << "the box's 24 vertices (split normals) weld to 8 corners";
    EXPECT_EQ(box.indices.size(), 12u * 6u);
    const AdjacencyMesh sphere = buildAdjacency(scene::shapes::sphere(0.5f));
    EXPECT_TRUE(sphere.closed()) << sphere.boundaryEdges << " border, " << sphere.nonManifoldEdges << " non-manifold edges";
    const AdjacencyMesh plane = buildAdjacency(scene::shapes::plane(2.0f, 2.0f));
    EXPECT_EQ(plane.boundaryEdges, 4u);
    EXPECT_FALSE(plane.closed());
}

TEST(Adjacency, NeighboursShareTheEdgeTheOtherWay) {
    const AdjacencyMesh box = buildAdjacency(scene::shapes::box(glm::vec3(1.0f)));
    for (std::size_t t = 0; t < box.indices.size(); t += 6)
        for (int e = 0; e < 6; e += 2) {
            const std::uint32_t a = box.indices[t + e], b = box.indices[t + (e + 2) % 6], n = box.indices[t + e + 1];
            // Find the neighbour triangle (a, n, b) wound b -> a somewhere in the list.
            bool found = false;
            for (std::size_t u = 0; u < box.indices.size() && !found; u += 6)
                for (int k = 0; k < 6; k += 2)
                    if (box.indices[u + k] == b && box.indices[u + (k + 2) % 6] == a && box.indices[u + (k + 4) % 6] == n) found = true;
            EXPECT_TRUE(found) << "triangle " << t / 6 << " edge " << e / 2;
        }
}

TEST(PlanarShadow, FlattensOntoThePlaneAlongTheLight) {
    const glm::vec4 ground(0.0f, 1.0f, 0.0f, 0.0f);
    const glm::vec3 x(1.0f, 2.0f, 0.5f);
    // Point light at (0, 4, 0): the shadow of x lies where the ray from the light through x meets y = 0.
    const glm::vec4 s = planarShadowMatrix(ground, glm::vec4(0.0f, 4.0f, 0.0f, 1.0f)) * glm::vec4(x, 1.0f);
    const glm::vec3 p = glm::vec3(s) / s.w;
    EXPECT_NEAR(p.y, 0.0f, 1e-5f);
    EXPECT_NEAR(p.x, 2.0f, 1e-5f);  // scale 4 / (4 - 2) = 2
    EXPECT_NEAR(p.z, 1.0f, 1e-5f);
    // Sun from direction (1, 1, 0): x slides 2 along -x.
    const glm::vec4 d = planarShadowMatrix(ground, glm::vec4(glm::normalize(glm::vec3(1, 1, 0)), 0.0f)) * glm::vec4(x, 1.0f);
    EXPECT_NEAR(d.x / d.w, -1.0f, 1e-5f);
    EXPECT_NEAR(d.y / d.w, 0.0f, 1e-5f);
    // A caster above the light lands behind the light's projection: w < 0, what the clipper drops.
    const glm::vec4 above = planarShadowMatrix(ground, glm::vec4(0.0f, 4.0f, 0.0f, 1.0f)) * glm::vec4(1.0f, 6.0f, 0.0f, 1.0f);
    EXPECT_LT(above.w, 0.0f);
}

}  // namespace
}  // namespace penumbra::shadows
