// Shadow volumes and planar shadows, the geometry: adjacency and closedness of the built-in
// shapes, Blinn's flattening matrix, and the choice of the receiver plane.
#include "scene/Shapes.h"
#include "scene/io/SceneFile.h"
#include "shadows/planar/PlanarFit.h"
#include "shadows/volumes/Adjacency.h"
#include "shadows/volumes/NearClipVolume.h"
#include "shadows/volumes/VolumeExtent.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

#include <gtest/gtest.h>

namespace penumbra::shadows {
namespace {

TEST(Adjacency, BoxAndSphereAreClosedAPlaneHasFourBorderEdges) {
    const AdjacencyMesh box = buildAdjacency(scene::shapes::box(glm::vec3(1.0f)));
    EXPECT_TRUE(box.closed());
    EXPECT_EQ(box.positions.size(), 8u) << "the box's 24 vertices (split normals) weld to 8 corners";
    EXPECT_EQ(box.indices.size(), 12u * 6u);
    const AdjacencyMesh sphere = buildAdjacency(scene::shapes::sphere(0.5f));
    EXPECT_TRUE(sphere.closed()) << sphere.edges.boundary << " border, " << sphere.edges.nonManifold << " non-manifold edges";
    const AdjacencyMesh plane = buildAdjacency(scene::shapes::plane(2.0f, 2.0f));
    EXPECT_EQ(plane.edges.boundary, 4u);
    EXPECT_FALSE(plane.closed());
}

// The volumes pair triangles over the weld by which the renderer judges a part closed
// (Mesh::weldedPositionIds), so the two agree: judged alone (as the volumes judge a translucent
// part, buildAdjacency's `alone`), a part the renderer draws as a solid is closed for them too.
// Until stop 67 the volumes welded on a grid of a millionth of the mesh: it merged distinct
// vertices of the park's trash can (part 2 of its OBJ), leaving 31 edges shared by three triangles
// in a part the renderer culls as a solid. (Drawn opaque, the trash can's parts are paired
// together and its other parts are open, so it casts from both sides either way.)
TEST(Adjacency, APartTheRendererFindsClosedIsClosedForTheVolumes) {
    const scene::Scene park = scene::io::loadScene(PENUMBRA_SCENE_DIR "/park.json");
    int checked = 0, trashCanClosed = 0;
    for (const scene::Mesh& mesh : park.meshes) {
        const std::vector<bool> closed = mesh.closedParts();
        const AdjacencyMesh adjacency = buildAdjacency(mesh, std::vector<bool>(mesh.parts.size(), true));
        for (std::size_t p = 0; p < mesh.parts.size(); ++p) {
            if (!closed[p]) continue;
            ++checked;
            const EdgeCounts& edges = adjacency.parts[p];
            EXPECT_TRUE(edges.closed()) << mesh.name << " part " << p << ": " << edges.boundary << " border, " << edges.nonManifold
                                        << " non-manifold, " << edges.misoriented << " misoriented edges";
            trashCanClosed += mesh.name.find("trashcan") != std::string::npos;
        }
    }
    EXPECT_GE(checked, 3);
    EXPECT_GE(trashCanClosed, 1) << "the trash can's closed part";
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

// Every neighbour relation goes both ways: if triangle t's edge (a, b) has n as its neighbour's
// corner, the triangle (a, b, n) has t's opposite corner on that edge. The geometry shader's
// invocations for t and for it then agree whether the edge is a silhouette. Returns the number
// of edges with a partner.
std::size_t expectSymmetricPairs(const AdjacencyMesh& m) {
    auto own = [&](std::size_t t, int e) { return m.indices[t + static_cast<std::size_t>(e + 4) % 6]; };
    std::size_t paired = 0;
    for (std::size_t t = 0; t < m.indices.size(); t += 6)
        for (int e = 0; e < 6; e += 2) {
            const std::uint32_t a = m.indices[t + static_cast<std::size_t>(e)], b = m.indices[t + static_cast<std::size_t>(e + 2) % 6];
            const std::uint32_t n = m.indices[t + static_cast<std::size_t>(e) + 1];
            if (n == own(t, e)) continue;  // no partner: a border, the odd one of a fan
            ++paired;
            int partners = 0;
            for (std::size_t u = 0; u < m.indices.size(); u += 6)
                for (int f = 0; f < 6 && u != t; f += 2) {
                    const std::uint32_t c = m.indices[u + static_cast<std::size_t>(f)], d = m.indices[u + static_cast<std::size_t>(f + 2) % 6];
                    const bool sameEdge = (c == a && d == b) || (c == b && d == a);
                    if (sameEdge && own(u, f) == n && m.indices[u + static_cast<std::size_t>(f) + 1] == own(t, e)) ++partners;
                }
            // Exactly one, or two where copies of the pair (same corners) mirror each other too.
            EXPECT_GE(partners, 1) << "triangle " << t / 6 << " edge " << e / 2;
            EXPECT_LE(partners, 2) << "triangle " << t / 6 << " edge " << e / 2;
        }
    return paired;
}

TEST(Adjacency, TrianglesArePairedOnEachEdgeWhicheverWayTheyRunIt) {
    scene::Mesh box = scene::shapes::box(glm::vec3(1.0f));
    std::swap(box.indices[1], box.indices[2]);  // the first triangle wound against its neighbours
    const AdjacencyMesh misWound = buildAdjacency(box);
    EXPECT_EQ(misWound.edges.misoriented, 3u);
    EXPECT_EQ(misWound.edges.boundary, 0u);
    EXPECT_FALSE(misWound.closed()) << "it needs both sides";
    EXPECT_EQ(expectSymmetricPairs(misWound), 36u) << "every edge of the 12 triangles still has its partner";

    // Four triangles on the edge (0, 1), as two double-sided quads crossing there: two pairs.
    scene::Mesh fan;
    for (const glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0.5f, 1, 0), glm::vec3(0.5f, -1, 0),
                              glm::vec3(0.5f, 0, 1), glm::vec3(0.5f, 0, -1)})
        fan.vertices.push_back({.position = p});
    fan.indices = {0, 1, 2, 0, 1, 3, 1, 0, 4, 1, 0, 5};
    fan.parts.push_back({.firstIndex = 0, .indexCount = 12});
    const AdjacencyMesh four = buildAdjacency(fan);
    EXPECT_EQ(four.edges.nonManifold, 1u);
    EXPECT_EQ(four.edges.boundary, 8u);
    EXPECT_EQ(expectSymmetricPairs(four), 4u) << "the shared edge's four triangles, in two pairs";

    // A quad made two-sided by copying each triangle reversed right after it (the street's trash
    // can): a triangle is paired with its neighbour across the diagonal, never with its own copy,
    // whose volume's side there never cancels.
    scene::Mesh twoSided = scene::shapes::plane(2.0f, 2.0f);
    ASSERT_EQ(twoSided.indices.size(), 6u);
    const std::vector<std::uint32_t> one = twoSided.indices;
    twoSided.indices = {one[0], one[1], one[2], one[0], one[2], one[1], one[3], one[4], one[5], one[3], one[5], one[4]};
    twoSided.parts[0].indexCount = 12;
    const AdjacencyMesh copies = buildAdjacency(twoSided);
    EXPECT_EQ(expectSymmetricPairs(copies), 4u) << "the diagonal's four triangles, each with one across it";
    EXPECT_EQ(copies.edges.boundary, 8u) << "each outer edge: a triangle and its copy, unpaired";
    EXPECT_EQ(copies.edges.misoriented, 0u);
}

TEST(Adjacency, PartsThatMayBeLeftOutArePairedAlone) {
    // A box whose top and bottom are a second part (another material).
    scene::Mesh box = scene::shapes::box(glm::vec3(1.0f));
    ASSERT_EQ(box.parts.size(), 1u);
    box.parts = {{.firstIndex = 0, .indexCount = 18}, {.firstIndex = 18, .indexCount = 18}};
    // Both drawn together: still one closed surface, one-sided volumes for both parts.
    const AdjacencyMesh together = buildAdjacency(box);
    ASSERT_EQ(together.parts.size(), 2u);
    EXPECT_TRUE(together.parts[0].closed() && together.parts[1].closed());
    EXPECT_EQ(expectSymmetricPairs(together), 36u);
    // The second part may be left out (glass): no triangle of either leans on the other.
    const AdjacencyMesh split = buildAdjacency(box, {false, true});
    EXPECT_FALSE(split.parts[0].closed());
    EXPECT_FALSE(split.parts[1].closed());
    EXPECT_EQ(split.parts[0].boundary, 8u) << "three faces in a row: 10 edges, 2 shared inside the part";
    EXPECT_EQ(split.parts[1].boundary, 8u);
    EXPECT_EQ(split.edges.boundary, 16u);
    EXPECT_EQ(expectSymmetricPairs(split), 36u - 16u);
}

scene::Bounds boxAround(const glm::vec3& centre, float half) {
    scene::Bounds b;
    b.add(centre - glm::vec3(half));
    b.add(centre + glm::vec3(half));
    return b;
}

// The camera at the origin looks down -z with its near plane at 0.1: only casters between that
// plane's small rectangle and the light can put the camera in their shadow volume.
TEST(NearClipVolume, HoldsOnlyWhatLiesBetweenTheNearPlaneAndTheLight) {
    const glm::mat4 inverseViewProj = glm::inverse(glm::perspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 100.0f) *
                                                   glm::lookAt(glm::vec3(0.0f), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0)));
    scene::Light sun;
    sun.direction = glm::normalize(glm::vec3(0.0f, -1.0f, 0.2f));  // from above, a little from behind the camera
    const NearClipVolume underSun(inverseViewProj, sun);
    EXPECT_TRUE(underSun.mayHold(boxAround({0, 5, -1.1f}, 0.5f))) << "a roof straight towards the sun";
    EXPECT_FALSE(underSun.mayHold(boxAround({4, 5, -1}, 0.5f))) << "a roof off to the side";
    EXPECT_FALSE(underSun.mayHold(boxAround({0, -3, -1}, 0.5f))) << "below the camera, away from the sun";
    EXPECT_FALSE(underSun.mayHold(boxAround({0, 0, -20}, 1.0f))) << "ahead in the view, not towards the sun";
    EXPECT_FALSE(underSun.mayHold(scene::Bounds{}));

    scene::Light lamp;
    lamp.type = scene::Light::Type::Point;
    lamp.position = {0, 10, 0};
    const NearClipVolume underLamp(inverseViewProj, lamp);
    EXPECT_TRUE(underLamp.mayHold(boxAround({0, 5, -0.05f}, 0.3f)));
    EXPECT_FALSE(underLamp.mayHold(boxAround({1, 15, 0}, 0.3f))) << "beyond the lamp its volume points away from the camera";
    // Conservative: a box that straddles every bounding plane counts as held, even beyond the lamp.
    EXPECT_TRUE(underLamp.mayHold(boxAround({0, 15, 0}, 0.3f)));

    // The light in the near plane's own plane: the sweep is flat, so everything takes z-fail.
    scene::Light edgeOn;
    edgeOn.direction = {1, 0, 0};
    EXPECT_TRUE(NearClipVolume(inverseViewProj, edgeOn).mayHold(boxAround({0, 0, -50}, 0.1f)));
}

// A sun's volume may end on a plane per caster: past every point of the scene's box that a ray
// from the caster reaches, and for a low sun over a long street far short of the street's end.
TEST(VolumeExtent, ASunsVolumeEndsPastEveryReceiverItsCasterShadows) {
    scene::Bounds street;
    street.add({-10, 0, -100});
    street.add({10, 12, 100});
    for (const glm::vec3& direction : {glm::vec3(0.3f, -0.35f, -1.0f), glm::vec3(-0.2f, -1.0f, 0.1f), glm::vec3(0.05f, -0.04f, 1.0f)}) {
        scene::Light sun;
        sun.direction = glm::normalize(direction);
        const VolumeExtent extent(sun, street, false);
        const glm::vec3 d = glm::vec3(extent.light());
        const glm::vec4 wholeStreet = extent.farPlane(street);
        for (const scene::Bounds& caster : {boxAround({0, 4, 0}, 1.0f), boxAround({-8, 10, 90}, 2.0f), boxAround({9, 1, -99}, 1.0f), street}) {
            const glm::vec4 plane = extent.farPlane(caster);
            const glm::vec3 n(plane);
            ASSERT_GT(glm::dot(n, d), 0.0f) << "every ray from the caster meets the plane";
            EXPECT_LE(extent.longestRay(plane, caster), extent.longestRay(wholeStreet, caster));
            // Points of the caster's box, followed along the light while they stay in the street's box.
            for (int i = 0; i <= 4; ++i)
                for (int j = 0; j <= 4; ++j)
                    for (int k = 0; k <= 4; ++k) {
                        const glm::vec3 p = caster.min + caster.extent() * glm::vec3(i, j, k) / 4.0f;
                        float t = 1e30f;
                        for (int a = 0; a < 3; ++a)
                            if (d[a] != 0.0f) t = std::min(t, ((d[a] > 0 ? street.max[a] : street.min[a]) - p[a]) / d[a]);
                        EXPECT_LT(glm::dot(n, p), plane.w) << "the caster lies short of its plane";
                        EXPECT_LT(glm::dot(n, p + t * d), plane.w) << "a receiver past the plane would be left out of the shadow";
                    }
        }
    }
    // Under a low sun along the street a post's volume ends just under the ground past its shadow
    // (16 m from the top of a 5 m post), not across the light past the street's far corner.
    scene::Light low;
    low.direction = glm::normalize(glm::vec3(0.3f, -0.35f, -1.0f));
    const VolumeExtent extent(low, street, false);
    const scene::Bounds post = boxAround({0, 4, 0}, 1.0f);
    float farCorner = -1e30f;
    for (const glm::vec3& c : street.corners()) farCorner = std::max(farCorner, glm::dot(glm::vec3(extent.light()), c));
    EXPECT_LT(extent.longestRay(extent.farPlane(post), post), 25.0f);
    EXPECT_GT(extent.longestRay(glm::vec4(glm::vec3(extent.light()), farCorner), post), 80.0f);
}

// A point light's volume may end on a face of the scene's box that every ray from its caster
// leaves through: the ground under a street lamp. Casters on every side of the light get none.
TEST(VolumeExtent, APointLightsVolumeEndsOnAFaceItsCastersRaysAllLeaveThrough) {
    scene::Bounds street;
    street.add({-10, 0, -100});
    street.add({10, 12, 100});
    scene::Light lamp;
    lamp.type = scene::Light::Type::Point;
    lamp.position = {2, 6, 5};
    const VolumeExtent extent(lamp, street, false);
    for (const scene::Bounds& caster : {boxAround({0, 2, 3}, 1.0f), boxAround({6, 5, 5}, 0.5f), boxAround({2, 9, 40}, 2.0f)}) {
        const glm::vec4 plane = extent.farPlane(caster);
        const glm::vec3 n(plane);
        ASSERT_NE(n, glm::vec3(0.0f)) << "the caster lies to one side of the lamp on some axis";
        EXPECT_LT(extent.longestRay(plane, caster), extent.extrusion()) << "sooner than the fixed push";
        for (int i = 0; i <= 4; ++i)
            for (int j = 0; j <= 4; ++j)
                for (int k = 0; k <= 4; ++k) {
                    const glm::vec3 p = caster.min + caster.extent() * glm::vec3(i, j, k) / 4.0f;
                    const glm::vec3 d = p - lamp.position;
                    ASSERT_GT(glm::dot(n, d), 0.0f) << "every ray crosses the plane outwards";
                    float t = 1e30f;  // where the ray from the lamp through p leaves the street's box
                    for (int a = 0; a < 3; ++a)
                        if (d[a] != 0.0f) t = std::min(t, ((d[a] > 0 ? street.max[a] : street.min[a]) - lamp.position[a]) / d[a]);
                    EXPECT_LT(glm::dot(n, p), plane.w) << "the caster lies short of its plane";
                    EXPECT_LT(glm::dot(n, lamp.position + t * d), plane.w) << "a receiver past the plane would be left out";
                }
    }
    const scene::Bounds under = boxAround({0, 2, 3}, 1.0f);
    EXPECT_EQ(extent.farPlane(under), glm::vec4(0, -1, 0, extent.farPlane(under).w)) << "the ground's plane, just under it";
    EXPECT_EQ(extent.farPlane(boxAround(lamp.position, 1.0f)), glm::vec4(0.0f)) << "around the lamp: the fixed push";
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
