// Mesh::partIsClosed: whether a part bounds a solid, which tells translucent receivers that light
// entering it leaves it through one more face of the same material (tintThroughOwnLayers).
#include "bench/Suites.h"
#include "scene/Mesh.h"
#include "scene/Shapes.h"
#include "scene/io/SceneFile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <unistd.h>

namespace penumbra::scene {
namespace {

TEST(MeshClosed, BoxesAndSpheresBoundSolidsAndAPlaneDoesNot) {
    // The box repeats each corner on three faces, the sphere its seam and poles (with degenerate
    // triangles there): welding by position must see through both.
    EXPECT_TRUE(shapes::box({1.0f, 2.0f, 0.04f}).partIsClosed(0));
    EXPECT_TRUE(shapes::sphere(0.45f).partIsClosed(0));
    EXPECT_FALSE(shapes::plane(2.0f, 2.0f).partIsClosed(0));
    EXPECT_FALSE(shapes::box({1.0f, 1.0f, 1.0f}).partIsClosed(1)) << "no such part";
}

// The bench's generated grid (its OBJ files read back as any model is): every sphere and torus
// bounds a solid, so the renderer and the floor cull their back faces. The torus's seams were off
// by sin(2π) in floats (1.7e-7) until stop 63: open, drawn with both faces, 31 % more fragments.
TEST(MeshClosed, TheBenchGridsSpheresAndToriBoundSolids) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("penumbra_grid_" + std::to_string(::getpid()));
    const Scene scene = io::loadScene(bench::writeGridScene(dir, "grid", 20000, false));
    int solids = 0;
    for (const Object& o : scene.objects) {
        const bool shape = o.name.rfind("sphere_", 0) == 0 || o.name.rfind("torus_", 0) == 0;
        if (!shape) continue;
        EXPECT_TRUE(scene.meshes[static_cast<std::size_t>(o.mesh)].partIsClosed(0)) << o.name;
        ++solids;
    }
    EXPECT_EQ(solids, 100);
    std::filesystem::remove_all(dir);
}

TEST(MeshClosed, AHoleOrAnInwardWindingIsNotASolid) {
    Mesh holed = shapes::box({1.0f, 1.0f, 1.0f});
    holed.indices.resize(holed.indices.size() - 3);  // one triangle of the last face gone
    holed.parts[0].indexCount -= 3;
    EXPECT_FALSE(holed.partIsClosed(0));

    Mesh inward = shapes::sphere(1.0f, 16, 8);
    for (std::size_t t = 0; t + 2 < inward.indices.size(); t += 3) std::swap(inward.indices[t + 1], inward.indices[t + 2]);
    EXPECT_FALSE(inward.partIsClosed(0)) << "wound clockwise seen from outside: negative volume";

    Mesh flipped = shapes::box({1.0f, 1.0f, 1.0f});
    std::swap(flipped.indices[1], flipped.indices[2]);  // one triangle against its neighbours
    EXPECT_FALSE(flipped.partIsClosed(0));
}

TEST(MeshClosed, EachPartIsJudgedByItsOwnTriangles) {
    // Two boxes in one mesh, the second a part of its own: each part closed; one part holding
    // half of each box is not.
    Mesh a = shapes::box({1.0f, 1.0f, 1.0f}), b = shapes::box({0.5f, 0.5f, 0.5f});
    const auto offset = static_cast<std::uint32_t>(a.vertices.size()), firstB = static_cast<std::uint32_t>(a.indices.size());
    for (Vertex v : b.vertices) {
        v.position += glm::vec3(3.0f, 0.0f, 0.0f);
        a.vertices.push_back(v);
    }
    for (std::uint32_t i : b.indices) a.indices.push_back(i + offset);
    a.parts = {MeshPart{0, firstB, 0}, MeshPart{firstB, static_cast<std::uint32_t>(b.indices.size()), 0}};
    EXPECT_TRUE(a.partIsClosed(0));
    EXPECT_TRUE(a.partIsClosed(1));
    a.parts = {MeshPart{firstB / 2, firstB, 0}};
    EXPECT_FALSE(a.partIsClosed(0));
}

// Mesh::partIsConvex and partIsFlat: which parts a ray crosses at most twice, so that a
// translucent receiver's own layers are the ones its lookup divides out (Draw::ownLayersKnown).
TEST(MeshConvex, BoxesAndSpheresAreConvexAPlaneIsFlat) {
    EXPECT_TRUE(shapes::box({1.0f, 2.0f, 0.04f}).partIsConvex(0));
    EXPECT_TRUE(shapes::sphere(0.45f).partIsConvex(0)) << "its poles' degenerate triangles have no plane";
    EXPECT_TRUE(shapes::plane(2.0f, 2.0f).partIsFlat(0));
    EXPECT_TRUE(shapes::plane(2.0f, 2.0f).partIsConvex(0)) << "every vertex on its one plane";
    EXPECT_FALSE(shapes::box({1.0f, 1.0f, 1.0f}).partIsFlat(0));
    EXPECT_FALSE(shapes::sphere(1.0f).partIsFlat(0));
    EXPECT_FALSE(shapes::sphere(1.0f, 48, 24).partIsConvex(0, 100)) << "over the triangle limit: not checked";
    EXPECT_FALSE(shapes::box({1.0f, 1.0f, 1.0f}).partIsConvex(1)) << "no such part";
}

// Mesh::partHasFaceNormals: flat shading, which a convex solid needs to shadow none of its own lit
// points (Draw::selfShadowFree): a smooth normal can light a facet turned from the light.
TEST(MeshFaceNormals, ABoxAndAPlaneAreShadedFlatASphereIsNot) {
    EXPECT_TRUE(shapes::box({1.0f, 2.0f, 0.5f}).partHasFaceNormals(0));
    EXPECT_TRUE(shapes::plane(2.0f, 2.0f).partHasFaceNormals(0));
    EXPECT_FALSE(shapes::sphere(1.0f, 16, 8).partHasFaceNormals(0));
    Mesh tilted = shapes::box({1.0f, 1.0f, 1.0f});
    tilted.vertices[0].normal = glm::normalize(tilted.vertices[0].normal + glm::vec3(0.0f, 1e-3f, 1e-3f));
    EXPECT_FALSE(tilted.partHasFaceNormals(0)) << "one vertex normal a thousandth off its face's";
    EXPECT_FALSE(shapes::box({1.0f, 1.0f, 1.0f}).partHasFaceNormals(1)) << "no such part";
}

TEST(MeshConvex, TwoBoxesInOnePartOrAnInwardWindingAreNot) {
    // Two boxes side by side in one part: a ray along x crosses four faces.
    Mesh a = shapes::box({1.0f, 1.0f, 1.0f}), b = shapes::box({1.0f, 1.0f, 1.0f});
    const auto offset = static_cast<std::uint32_t>(a.vertices.size());
    for (Vertex v : b.vertices) {
        v.position += glm::vec3(3.0f, 0.0f, 0.0f);
        a.vertices.push_back(v);
    }
    for (std::uint32_t i : b.indices) a.indices.push_back(i + offset);
    a.parts = {MeshPart{0, static_cast<std::uint32_t>(a.indices.size()), 0}};
    EXPECT_FALSE(a.partIsConvex(0));
    EXPECT_FALSE(a.partIsFlat(0));

    Mesh inward = shapes::sphere(1.0f, 16, 8);
    for (std::size_t t = 0; t + 2 < inward.indices.size(); t += 3) std::swap(inward.indices[t + 1], inward.indices[t + 2]);
    EXPECT_FALSE(inward.partIsConvex(0)) << "wound inwards: every vertex in front of the faces";

    Mesh dented = shapes::sphere(1.0f, 16, 8);
    dented.vertices[dented.vertices.size() / 2].position *= 0.8f;  // one vertex pushed in
    EXPECT_FALSE(dented.partIsConvex(0));
}

}  // namespace
}  // namespace penumbra::scene
