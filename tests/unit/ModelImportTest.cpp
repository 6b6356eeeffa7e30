// Model files map onto the material model: OBJ/MTL Kd, map_Kd, d/Tr (coverage) and Tf
// (transmission); glTF base colour, alpha modes, transmission and volume attenuation.
#include "scene/io/ModelImporter.h"
#include "scene/io/SceneFile.h"
#include "util/Error.h"
#include "util/Log.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace penumbra::scene::io {
namespace {

const std::filesystem::path kData = PENUMBRA_TEST_DATA;

const Material& byName(const Scene& s, const std::string& name) {
    for (const auto& m : s.materials)
        if (m.name == name) return m;
    throw std::runtime_error("no material " + name);
}

TEST(ModelImport, ObjMtlCoverageAndTransmission) {
    log::takeWarnings();
    Scene s;
    const int mesh = importModel(kData / "materials.obj", s);
    EXPECT_EQ(s.meshes[static_cast<std::size_t>(mesh)].triangleCount(), 5u);

    const Material& glass = byName(s, "green_glass");
    EXPECT_FLOAT_EQ(glass.alpha, 1.0f);
    EXPECT_EQ(glass.transmission, glm::vec3(0.1f, 0.9f, 0.1f));
    EXPECT_EQ(glass.diffuse, glm::vec3(0.1f, 0.9f, 0.1f));

    const Material& nylon = byName(s, "nylon");
    EXPECT_FLOAT_EQ(nylon.alpha, 0.25f);
    EXPECT_EQ(nylon.transmission, glm::vec3(0.5f));
    EXPECT_NEAR(nylon.stopped().g, 0.125f, 1e-6f);

    const Material& wall = byName(s, "wall");
    EXPECT_EQ(wall.transmission, glm::vec3(0.0f)) << "Tf on a non-refracting illum model carries no transmission";
    EXPECT_FLOAT_EQ(wall.alpha, 1.0f);
    EXPECT_FALSE(wall.translucent());
    ASSERT_GE(wall.diffuseTexture, 0);
    EXPECT_TRUE(s.images[static_cast<std::size_t>(wall.diffuseTexture)].fallback);
    const auto warnings = log::takeWarnings();
    ASSERT_FALSE(warnings.empty());
    EXPECT_NE(warnings[0].find("does_not_exist.png"), std::string::npos);

    EXPECT_NEAR(byName(s, "tr_only").alpha, 0.25f, 1e-6f) << "Tr is 1 - d";
}

// Two-vertex faces ("f 1 2", as Sweet Home 3D's park-light.obj has) are lines, dropped; the
// triangle and the quad around them load (Assimp's own validation used to reject the file).
TEST(ModelImport, ObjTwoVertexFacesAreDroppedNotFatal) {
    Scene s;
    const int mesh = importModel(kData / "two_vertex_faces.obj", s);
    EXPECT_EQ(s.meshes[static_cast<std::size_t>(mesh)].triangleCount(), 3u) << "1 triangle + a quad as 2";
}

TEST(ModelImport, GltfAlphaModesTransmissionAndVolume) {
    Scene s;
    importModel(kData / "materials.gltf", s);
    const Material& glass = byName(s, "green glass");
    EXPECT_NEAR(glass.transmission.r, 0.1f, 1e-6f);
    EXPECT_NEAR(glass.transmission.g, 0.9f, 1e-6f);
    EXPECT_FLOAT_EQ(glass.alpha, 1.0f);
    const Material& blend = byName(s, "blend");
    EXPECT_FLOAT_EQ(blend.alpha, 0.4f);
    EXPECT_NEAR(blend.diffuse.r, 0.8f, 1e-6f);
    const Material& mask = byName(s, "mask");
    EXPECT_FLOAT_EQ(mask.alphaCutoff, 0.3f);
    EXPECT_FLOAT_EQ(mask.alpha, 1.0f);
    EXPECT_EQ(s.meshes[0].triangleCount(), 6u);
    EXPECT_NEAR(s.meshes[0].bounds.max.x, 4.5f, 1e-5f) << "node transforms are baked in";
}

TEST(ModelImport, MalformedFilesNameTheFile) {
    for (const char* name : {"broken.obj", "broken.gltf"}) {
        Scene s;
        try {
            importModel(kData / name, s);
            ADD_FAILURE() << name << " was accepted";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    }
}

// A regression input of tests/fuzz (a main file, then `@@file NAME` parts) written out as files;
// returns the main file's path.
std::filesystem::path writeFuzzInput(const std::filesystem::path& input, const std::string& mainName) {
    std::ifstream in(input, std::ios::binary);
    const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / ("penumbra_probe_" + mainName);
    std::filesystem::create_directories(folder);
    const std::string separator = "\n@@file ";
    std::size_t end = all.find(separator);
    std::ofstream(folder / mainName, std::ios::binary) << all.substr(0, end);
    while (end != std::string::npos) {
        const std::size_t nameEnd = all.find('\n', end + separator.size());
        const std::string name = all.substr(end + separator.size(), nameEnd - end - separator.size());
        const std::size_t next = all.find(separator, nameEnd);
        std::ofstream(folder / name, std::ios::binary) << all.substr(nameEnd + 1, next == std::string::npos ? next : next - nameEnd - 1);
        end = next;
    }
    return folder / mainName;
}

std::string importError(const std::filesystem::path& file) {
    Scene s;
    try {
        importModel(file, s);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// Assimp runs first in a helper process that reads file after file: one that crashed or was
// stopped on a file is replaced, so the next file reads normally and the same bad file is named
// the same way again.
TEST(ModelImport, TheImporterHelperSurvivesCrashesAndHangs) {
    const std::filesystem::path fuzz = std::filesystem::path(PENUMBRA_SOURCE_DIR) / "tests/fuzz/regressions";
    const std::filesystem::path crashing = writeFuzzInput(fuzz / "model_obj/crash-assimp-segv-1", "crash.obj");
    // Found by the model_ply fuzz target: an `element` line without a name, which Assimp 5.2 reads
    // forever. importModel's PLY check now refuses it first (FormatChecks), so the helper is
    // asked directly here.
    const std::filesystem::path hanging = kData / "assimp-loops-forever.ply";
    auto probeError = [](const std::filesystem::path& file) -> std::string {
        try {
            probeWithAssimp(file);
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    };
    for (int round = 0; round < 2; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        const std::string crashed = importError(crashing);
        EXPECT_NE(crashed.find("crashed on this file (signal 11)"), std::string::npos) << crashed;
        EXPECT_NE(crashed.find("crash.obj"), std::string::npos) << crashed;
        EXPECT_EQ(importError(kData / "materials.obj"), "") << "a good file after a crash";
        EXPECT_EQ(importError(kData / "materials.obj"), "") << "and again, from the same helper";
        setModelImportTimeout(1);
        const std::string hung = probeError(hanging);
        setModelImportTimeout(120);
        EXPECT_NE(hung.find("did not finish within 1 s"), std::string::npos) << hung;
        EXPECT_EQ(importError(kData / "materials.obj"), "") << "a good file after a hang";
    }
}

// Files that break their format's rules are refused by FormatChecks before Assimp sees them,
// naming the rule (and the line, for text): Assimp 5.2 loops forever on some such PLY headers
// and allocates whatever a glTF buffer or accessor declares. Well-formed files still load.
TEST(ModelImport, FormatChecksNameTheBrokenRuleBeforeAssimpReadsIt) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "penumbra_format_checks";
    std::filesystem::create_directories(dir);
    auto write = [&](const std::string& name, const std::string& bytes) {
        std::ofstream(dir / name, std::ios::binary) << bytes;
        return dir / name;
    };
    auto le32 = [](std::uint32_t v) { return std::string{char(v), char(v >> 8), char(v >> 16), char(v >> 24)}; };
    // A GLB from its parts: header (magic, version, length) and a JSON chunk, then `tail`.
    auto glb = [&](std::uint32_t version, std::uint32_t jsonType, const std::string& json, const std::string& tail, int extraLength) {
        std::string padded = json;
        while (padded.size() % 4) padded += ' ';
        const std::string body = le32(static_cast<std::uint32_t>(padded.size())) + le32(jsonType) + padded + tail;
        return "glTF" + le32(version) + le32(static_cast<std::uint32_t>(12 + body.size() + extraLength)) + body;
    };
    const std::string plyHead = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
    const std::string binaryHead =
        "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nelement face 1\nproperty list int int vertex_indices\nend_header\n";
    const std::string triangle = R"("asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
                                 R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}])";
    const std::string view = R"("bufferViews":[{"buffer":0,"byteLength":36}])";
    const std::string accessor = R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}])";
    const std::string data36 = R"("buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}])";
    struct Case {
        std::filesystem::path file;
        std::string expected;  // a part of the message: "name:line: what"
    };
    const std::vector<Case> cases = {
        {write("nameless.ply", "ply\nformat ascii 1.0\nelement \nproperty float x\nend_header\n"), "nameless.ply:3: an element line must read"},
        {write("format.ply", "ply\nformat binary_lit2tle_endian 1.0\nend_header\n"), "format.ply:2: unknown PLY format"},
        {write("version.ply", "ply\nformat ascii 2.0\nend_header\n"), "version.ply:2: the format line must read"},
        {write("orphan.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n"), "orphan.ply:3: 'property' before any 'element'"},
        {write("garbage.ply", "ply\nformat ascii 1.0\nelemeblue\nend_header\n"), "garbage.ply:3: unknown PLY header line 'elemeblue'"},
        {write("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty flsat y\nend_header\n0\n"), "type.ply:4: unknown property type 'flsat'"},
        {write("empty-element.ply", "ply\nformat ascii 1.0\nelement vertex 1\nelement face 0\nproperty uchar n\nend_header\n0\n"),
         "empty-element.ply:3: element 'vertex' has no properties"},
        {write("noheaderend.ply", plyHead), "truncated PLY: the header has no 'end_header' line"},
        {write("short.ply", plyHead + "end_header\n0 0 0\n1 0 0\n"), "short.ply:9: truncated ASCII PLY: the header announces 3 'vertex' elements; the file ends after 2"},
        {write("extra.ply", plyHead + "end_header\n0 0 0\n1 0 0 7\n0 1 0\n"), "extra.ply:9: element 'vertex' has more values than its properties take"},
        {write("word.ply", plyHead + "end_header\n0 0 0\n1 zero 0\n0 1 0\n"), "word.ply:9: element 'vertex': 'zero' is not a finite number"},
        {write("nan.ply", plyHead + "end_header\n0 0 0\n1 nan 0\n0 1 0\n"), "nan.ply:9: element 'vertex': 'nan' is not a finite number"},
        {write("list.ply", binaryHead + le32(3) + le32(0) + le32(1)), "truncated binary PLY: the header announces 1 'face' elements"},
        {write("negative.ply", binaryHead + le32(0xffffffffu)), "has a list of negative length"},
        {write("notply.ply", "solid cube\n"), "notply.ply:1: not a PLY file"},
        // Found by tests/fuzz: Assimp writes past its vertex array when "vertex" comes twice.
        {write("twice.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float z\nelement vertex 1\nproperty float z\nend_header\n0\n0\n"),
         "twice.ply:5: element 'vertex' is declared twice (first on line 3)"},
        {write("vt.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\v\n0\n"),
         "vt.ply:5: control character 0x0B in the PLY header (only spaces and tabs separate words)"},
        {write("eof.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 3\nend_header"),
         "eof.ply:4: truncated PLY: 'end_header' must end with a line break"},
        {write("xx.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float x\nend_header\n0 0\n"),
         "xx.ply:5: property 'x' of element 'vertex' is declared twice"},
        {write("huge.gltf", "{" + triangle + "," + accessor + "," + view + R"(,"buffers":[{"byteLength":1000000000,"uri":"data:application/octet-stream;base64,AAAA"}]})"),
         "huge.gltf: buffers[0] declares 1000000000 bytes; its data holds 3"},
        {write("count.gltf", "{" + triangle + R"(,"accessors":[{"bufferView":0,"componentType":5126,"count":4000000,"type":"VEC3"}],)" + view + "," + data36 + "}"),
         "count.gltf: accessors[0]: 4000000 elements of 12 bytes do not fit bufferView 0 (36 bytes)"},
        {write("view.gltf", "{" + triangle + "," + accessor + R"(,"bufferViews":[{"buffer":0,"byteOffset":30,"byteLength":36}],)" + data36 + "}"),
         "view.gltf: bufferViews[0] reaches byte 66 of buffer 0, which has 36"},
        {write("missing.gltf", "{" + triangle + "," + accessor + "," + view + R"(,"buffers":[{"byteLength":36,"uri":"nowhere.bin"}]})"),
         "missing.gltf: buffers[0].uri names 'nowhere.bin', which cannot be read"},
        {write("syntax.gltf", "{\n  \"asset\": {\"version\": \"2.0\"},\n  \"meshes\": [,]\n}\n"), "syntax.gltf:3: glTF is not valid JSON"},
        {write("long.glb", glb(2, 0x4E4F534Au, "{" + triangle + "}", "", 100)), "long.glb: truncated GLB: the header announces"},
        {write("v1.glb", glb(1, 0x4E4F534Au, "{" + triangle + "}", "", 0)), "v1.glb: GLB version 1; only version 2 is read"},
        {write("chunk.glb", glb(2, 0x004E4942u, "{" + triangle + "}", "", 0)), "chunk.glb: the GLB's first chunk must be JSON"},
        {write("nobin.glb", glb(2, 0x4E4F534Au, "{" + triangle + "," + accessor + "," + view + R"(,"buffers":[{"byteLength":36}]})", "", 0)),
         "nobin.glb: buffers[0] has no uri and no GLB BIN chunk holds it"},
        {write("notglb.glb", "{}"), "notglb.glb: not a GLB file"},
    };
    for (const Case& c : cases) {
        const std::string error = importError(c.file);
        EXPECT_NE(error.find(c.expected), std::string::npos) << c.file.filename() << ": " << error;
    }
    // Well-formed files pass the checks and load: a glTF with its data in a data: URI, the same
    // as a GLB with a BIN chunk, both PLY encodings, and the suite's glTF.
    const std::string bin(std::string("\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0\0\0\0\0\0\0\0\0\0\0\x80\x3f\0\0\0\0", 36));
    const std::string fixture = std::string(PENUMBRA_SOURCE_DIR) + "/tests/fuzz/seeds/";
    for (const std::filesystem::path& good :
         {write("good.gltf", "{" + triangle + "," + accessor + "," + view + "," + data36 + "}"),
          write("good.glb", glb(2, 0x4E4F534Au, "{" + triangle + "," + accessor + "," + view + R"(,"buffers":[{"byteLength":36}]})",
                                le32(36) + le32(0x004E4942u) + bin, 0)),
          write("good.ply", plyHead + "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
          std::filesystem::path(fixture + "model_ply/binary.ply"), std::filesystem::path(fixture + "model_ply/ascii.ply"),
          std::filesystem::path(fixture + "model_glb/materials.glb"), kData / "materials.gltf"})
        EXPECT_EQ(importError(good), "") << good;
}

// Values outside what the equations mean are clamped, and the warning names each kind once (a
// colour out of range in three channels is one "diffuse colour", not three).
TEST(ModelImport, OutOfRangeMaterialValuesAreClampedAndNamedOnce) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "penumbra_wild_material";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "wild.obj") << "mtllib wild.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl w\nf 1 2 3\n";
    std::ofstream(folder / "wild.mtl") << "newmtl w\nKd nan 2000 -1\nd 7\nTf 3 -1 0.5\nillum 4\n";
    log::takeWarnings();
    Scene s;
    importModel(folder / "wild.obj", s);
    const Material& w = byName(s, "w");
    EXPECT_EQ(w.diffuse, glm::vec3(0.8f, 1000.0f, 0.0f));
    EXPECT_FLOAT_EQ(w.alpha, 1.0f);
    EXPECT_EQ(w.transmission, glm::vec3(1.0f, 0.0f, 0.5f));
    std::string warning;
    for (const std::string& line : log::takeWarnings())
        if (line.find("out of range") != std::string::npos) warning = line;
    EXPECT_NE(warning.find("material 'w': opacity, transmission, diffuse colour out of range, clamped"),
              std::string::npos)
        << warning;
}

TEST(ModelImport, BareModelGetsGroundSunAndFraming) {
    const Scene s = loadScene(kData / "materials.obj");
    ASSERT_EQ(s.objects.size(), 2u);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, Light::Type::Directional);
    EXPECT_GT(s.ambient.r, 0.0f);
    const Bounds model = s.meshes[0].bounds;
    const Bounds ground = s.meshes[1].bounds.transformed(s.objects[1].transformAt(0));
    EXPECT_LE(ground.max.y, model.min.y) << "ground sits under the model";
    EXPECT_GT(ground.extent().x, model.extent().x * 4);
    // The camera looks at the model's centre from outside it, above the ground.
    EXPECT_LT(glm::length(s.camera.target - model.center()), 1e-5f);
    EXPECT_GT(glm::length(s.camera.position - model.center()), glm::length(model.extent()));
    EXPECT_GT(s.camera.position.y, ground.max.y);
}

}  // namespace
}  // namespace penumbra::scene::io
