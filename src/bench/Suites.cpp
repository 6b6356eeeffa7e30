#include "bench/Suites.h"

#include "scene/Shapes.h"
#include "shadows/ShadowTechnique.h"
#include "util/DataPaths.h"
#include "util/OutputFiles.h"

#include <cmath>
#include <fstream>
#include <glm/gtc/constants.hpp>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace penumbra::bench {

namespace fs = std::filesystem;

namespace {

// A torus around +Y: `major` radius to the tube's centre, `minor` tube radius. The seams' second
// copies (i = around, j = tube: other texture coordinates) take the angle of the first (% around,
// % tube) so their positions are equal to the bit: sin(2π) in floats is 1.7e-7, which left the
// seams open to Mesh::closedParts (welded by exact position) and the tori drawn with both faces
// (stop 63: the 98k grid shaded 1.97 million fragments a frame instead of 1.51).
scene::Mesh torus(float major, float minor, int around, int tube) {
    scene::Mesh m;
    for (int i = 0; i <= around; ++i)
        for (int j = 0; j <= tube; ++j) {
            const float u = glm::two_pi<float>() * static_cast<float>(i % around) / static_cast<float>(around);
            const float v = glm::two_pi<float>() * static_cast<float>(j % tube) / static_cast<float>(tube);
            const glm::vec3 centre(major * std::cos(u), 0.0f, major * std::sin(u));
            const glm::vec3 normal(std::cos(v) * std::cos(u), std::sin(v), std::cos(v) * std::sin(u));
            m.vertices.push_back({centre + minor * normal, normal, {static_cast<float>(i) / around, static_cast<float>(j) / tube}});
        }
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < tube; ++j) {
            const auto at = [&](int a, int b) { return static_cast<std::uint32_t>(a * (tube + 1) + b); };
            m.indices.insert(m.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
        }
    m.parts.push_back({0, static_cast<std::uint32_t>(m.indices.size()), 0});
    m.computeBounds();
    return m;
}

void writeObj(std::ostream& out, const scene::Mesh& mesh, const glm::vec3& offset, std::size_t& vertexBase) {
    for (const auto& v : mesh.vertices) out << "v " << v.position.x + offset.x << ' ' << v.position.y + offset.y << ' ' << v.position.z + offset.z << '\n';
    for (const auto& v : mesh.vertices) out << "vn " << v.normal.x << ' ' << v.normal.y << ' ' << v.normal.z << '\n';
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        out << 'f';
        for (int k = 0; k < 3; ++k) {
            const std::size_t n = vertexBase + mesh.indices[i + static_cast<std::size_t>(k)] + 1;
            out << ' ' << n << "//" << n;
        }
        out << '\n';
    }
    vertexBase += mesh.vertices.size();
}

void writeObjFile(const fs::path& file, const scene::Mesh& mesh) {
    std::ofstream out(file);
    std::size_t base = 0;
    writeObj(out, mesh, glm::vec3(0.0f), base);
    if (!out) throw std::runtime_error(file.string() + ": cannot write");
}

fs::path defaultScene() { return paths::sceneDir() / "default.json"; }

// The ~1M-triangle scene: the fetched Stanford dragon when scripts/fetch-assets.sh has run,
// else a generated grid of the same order.
fs::path millionScene(const fs::path& sceneDir) {
    const fs::path dragon = paths::dataRoot() / "bench/dragon.json";
    const fs::path model = paths::dataRoot() / "bench/assets/dragon_vrip.ply";
    if (fs::exists(dragon) && fs::exists(model)) return dragon;
    return writeGridScene(sceneDir, "grid_975k", 975000, false);
}

BenchCase make(const std::string& suite, const fs::path& scene, const std::string& technique, int res,
               shadows::ParameterValues params = {}, std::string label = "") {
    return {suite, scene, technique, res, std::move(params), std::move(label)};
}

}  // namespace

fs::path writeGridScene(const fs::path& dir, const std::string& name, std::size_t triangles, bool colouredGlass) {
    util::createOutputDirectory(dir);
    const fs::path json = dir / (name + ".json");
    if (fs::exists(json)) return json;
    // 50 spheres of n slices x n/2 stacks (about n^2 triangles) and 50 tori of 2v x v (4v^2).
    const double perShape = std::max(80.0, static_cast<double>(triangles) / 100.0);
    const int slices = std::max(8, static_cast<int>(std::lround(std::sqrt(perShape))));
    const int tube = std::max(4, static_cast<int>(std::lround(std::sqrt(perShape / 4.0))));
    const scene::Mesh sphere = scene::shapes::sphere(0.7f, slices, slices / 2);
    const scene::Mesh ring = torus(0.6f, 0.22f, 2 * tube, tube);
    writeObjFile(dir / (name + "_sphere.obj"), sphere);
    writeObjFile(dir / (name + "_torus.obj"), ring);

    const glm::vec3 glass[4] = {{0.9f, 0.15f, 0.1f}, {0.1f, 0.85f, 0.15f}, {0.15f, 0.3f, 0.95f}, {0.95f, 0.7f, 0.1f}};
    nlohmann::json objects = nlohmann::json::array();
    // No highlight on the opaque shapes: bench/peers/osgshadow draws the same triangles with an
    // osg::Material whose specular is black (its default), and the frames compare like for like.
    const nlohmann::json noSpecular = {0, 0, 0};
    objects.push_back({{"name", "ground"}, {"shape", "plane"}, {"size", {40, 40}},
                       {"material", {{"diffuse", {0.6, 0.6, 0.58}}, {"specular", noSpecular}}}});
    std::ofstream whole(dir / (name + ".obj"));
    whole << "# " << name << ": the same triangles as " << name << ".json in one file\n";
    std::size_t base = 0;
    writeObj(whole, scene::shapes::plane(40.0f, 40.0f), glm::vec3(0.0f), base);
    for (int i = 0; i < 10; ++i)
        for (int k = 0; k < 10; ++k) {
            const int index = i * 10 + k;
            const bool isSphere = (i + k) % 2 == 0;
            const glm::vec3 at(-13.5f + 3.0f * static_cast<float>(i), isSphere ? 1.6f : 1.2f, -13.5f + 3.0f * static_cast<float>(k));
            nlohmann::json o = {{"name", (isSphere ? "sphere_" : "torus_") + std::to_string(index)},
                                {"model", name + (isSphere ? "_sphere.obj" : "_torus.obj")},
                                {"position", {at.x, at.y, at.z}}};
            if (colouredGlass && (index / 2) % 2 == 1) {
                const glm::vec3& t = glass[(index / 4) % 4];
                o["material"] = {{"diffuse", {t.x, t.y, t.z}}, {"alpha", 0.6}, {"transmission", {t.x, t.y, t.z}}};
            } else {
                o["material"] = {{"diffuse", {0.8, 0.78, 0.75}}, {"specular", noSpecular}};
            }
            objects.push_back(o);
            writeObj(whole, isSphere ? sphere : ring, at, base);
        }
    if (!whole) throw std::runtime_error((dir / (name + ".obj")).string() + ": cannot write");
    const std::size_t total = 2 + 50 * (sphere.triangleCount() + ring.triangleCount());
    const nlohmann::json scene = {
        {"name", name},
        {"description", "generated by penumbra bench: ground and a 10x10 grid of floating spheres and tori, " + std::to_string(total) +
                            " triangles" + (colouredGlass ? ", every other pair coloured glass" : "")},
        {"camera", {{"position", {0, 16, 30}}, {"target", {0, 0, 0}}, {"fov_deg", 45}, {"near", 0.5}, {"far", 120}}},
        {"ambient", {0.08, 0.08, 0.09}},
        {"background", {0.45, 0.6, 0.8}},
        {"lights", {{{"type", "directional"}, {"name", "sun"}, {"direction", {-0.4, -1.0, -0.3}}, {"intensity", 1.0},
                     {"shadow", {{"resolution", 2048}}}}}},
        {"objects", objects},
    };
    util::writeJson(json, scene);
    return json;
}

std::vector<std::string> suiteNames() { return {"cssm-table", "osg-tables", "all-techniques", "floor", "triangle-scaling"}; }

std::string suiteList() {
    std::string list;
    for (const auto& s : suiteNames()) list += (list.empty() ? "" : ", ") + s;
    return list;
}

std::vector<BenchCase> suiteCases(const std::string& suite, const fs::path& sceneDir) {
    std::vector<BenchCase> cases;
    if (suite == "cssm-table") {
        // Mátl 2013 Table 6.1: scenes of about 12k, 37k and 786k triangles.
        const std::pair<const char*, std::size_t> scenes[] = {{"glass_12k", 12000}, {"glass_37k", 37000}, {"glass_786k", 786000}};
        for (const auto& [name, triangles] : scenes) {
            const fs::path scene = writeGridScene(sceneDir, name, triangles, true);
            for (int res : {2048, 4096, 8192})
                for (const char* technique : {"hard", "cssm2"}) cases.push_back(make(suite, scene, technique, res));
        }
    } else if (suite == "osg-tables") {
        // Plachý 2012 Tables 4.1-4.8 on the 98k-triangle grid the OpenSceneGraph peer also draws.
        const fs::path scene = writeGridScene(sceneDir, "grid_98k", 98000, false);
        cases.push_back(make(suite, scene, "none", 0, {}, "no shadows"));
        for (int res : {256, 512, 1024, 2048, 4096}) cases.push_back(make(suite, scene, "hard", res, {}, "SM " + std::to_string(res)));
        cases.push_back(make(suite, scene, "pcf-poisson16", 1024, {}, "PCF soft (poisson16) 1024"));
        cases.push_back(make(suite, scene, "cascaded", 1024, {}, "PSSM / cascaded 1024"));
        cases.push_back(make(suite, scene, "lispsm", 1024, {}, "LiSPSM 1024"));
        // Table 4.4 / 4.8: the screen in 1x1, 2x2 and 3x3 tiles, each with its own LiSPSM.
        for (int res : {256, 512, 1024, 2048})
            for (int tiles : {1, 2, 3})
                cases.push_back(make(suite, scene, "lispsm-tiled", res, {{"cols", std::to_string(tiles)}, {"rows", std::to_string(tiles)}},
                                     "LiSPSM " + std::to_string(tiles) + "x" + std::to_string(tiles) + " " + std::to_string(res)));
    } else if (suite == "all-techniques") {
        for (const fs::path& scene : {defaultScene(), millionScene(sceneDir)})
            for (const auto& t : shadows::techniqueRegistry()) cases.push_back(make(suite, scene, t.name, 0));
    } else if (suite == "floor") {
        for (const char* technique : kFloors) cases.push_back(make(suite, defaultScene(), technique, 2048));
        for (const char* technique : {"none", "hard"}) cases.push_back(make(suite, defaultScene(), technique, 2048));
        // The floor redraws its map every frame; hard keeps what still casters drew unless told.
        BenchCase redrawn = make(suite, defaultScene(), "hard", 2048, {}, "hard 2048, maps redrawn");
        redrawn.redrawShadowMaps = true;
        cases.push_back(std::move(redrawn));
    } else if (suite == "triangle-scaling") {
        // The same grid from 10k to 1M triangles, every map redrawn every frame (the grid stands
        // still, so kept maps would cost nothing): the bench fits shadow pass against triangles.
        for (const std::size_t triangles : {10000u, 30000u, 100000u, 300000u, 1000000u}) {
            const fs::path scene = writeGridScene(sceneDir, "grid_" + std::to_string(triangles / 1000) + "k", triangles, false);
            for (const char* technique : {"hard", "cascaded", "lispsm", "vsm"}) {
                BenchCase c = make(suite, scene, technique, 0);
                c.redrawShadowMaps = true;
                cases.push_back(std::move(c));
            }
        }
    } else {
        throw std::invalid_argument("unknown suite '" + suite + "'; suites: " + suiteList());
    }
    return cases;
}

}  // namespace penumbra::bench
