// Scene files: every documented key is read into the scene; bad input names file and line.
#include "scene/io/SceneFile.h"
#include "util/Error.h"
#include "util/Log.h"

#include <gtest/gtest.h>

namespace penumbra::scene::io {
namespace {

namespace fs = std::filesystem;
const fs::path kData = PENUMBRA_TEST_DATA;

Scene parse(const std::string& json) { return parseSceneJson(json, kData / "inline.json"); }

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "<no error>";
}

TEST(SceneFile, ReadsEveryDocumentedKey) {
    const Scene s = parse(R"({
      "name": "all keys", "description": "every key of the format",
      "camera": { "position": [1, 2, 3], "target": [0, 1, 0], "up": [0, 0, 1], "fov_deg": 70, "near": 0.2,
                  "far": 80, "controller": "orbit" },
      "ambient": [0.1, 0.2, 0.3], "background": [0.4, 0.5, 0.6], "fog": { "start": 10, "end": 70 },
      "technique": "none",
      "lights": [
        { "type": "directional", "name": "sun", "direction": [0, -2, 0], "color": [1, 0.5, 0.25], "intensity": 2,
          "shadow": { "resolution": 1024, "bias": 0.5, "slope_bias": 2, "normal_offset": 1.5,
                      "polygon_offset": [1, 4], "enabled": true } },
        { "type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0], "angle_deg": 30, "near": 0.5, "range": 40 },
        { "type": "point", "position": [1, 1, 1], "size": 0.3, "shadow": { "enabled": false } },
        { "type": "projector", "position": [0, 2, 5], "direction": [0, 0, -1], "image": "textures_missing.png" }
      ],
      "objects": [
        { "shape": "plane", "size": [8, 6] },
        { "shape": "box", "size": [1, 2, 3], "position": [1, 1, 0], "rotation_deg": [0, 45, 0], "scale": 2,
          "cast_shadows": false },
        { "name": "ball", "shape": "sphere", "radius": 0.7, "scale": [1, 2, 1],
          "material": { "name": "glass", "diffuse": [0.1, 0.9, 0.1], "specular": [1, 1, 1], "shininess": 90,
                        "alpha": 0.5, "transmission": [0.1, 0.9, 0.1], "alpha_cutoff": 0.2, "double_sided": true },
          "animation": { "position": [[0, 0, 0, 0], [1, 1, 0, 0]], "rotation_deg": [[0, 0, 0, 0], [2, 0, 90, 0]] } },
        { "model": "materials.obj", "animation": [[0, 0, 0, 0], [2, 0, 1, 0], [4, 0, 0, 0]] }
      ] })");
    log::takeWarnings();
    EXPECT_EQ(s.camera.position, glm::vec3(1, 2, 3));
    EXPECT_EQ(s.camera.up, glm::vec3(0, 0, 1));
    EXPECT_FLOAT_EQ(s.camera.fovDeg, 70);
    EXPECT_FLOAT_EQ(s.camera.near, 0.2f);
    EXPECT_FLOAT_EQ(s.camera.far, 80);
    EXPECT_EQ(s.camera.controller, Camera::Controller::Orbit);
    EXPECT_EQ(s.ambient, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(s.background, glm::vec3(0.4f, 0.5f, 0.6f));
    EXPECT_TRUE(s.fog.enabled);
    EXPECT_FLOAT_EQ(s.fog.start, 10);
    EXPECT_FLOAT_EQ(s.fog.end, 70);
    EXPECT_EQ(s.technique, "none");

    ASSERT_EQ(s.lights.size(), 4u);
    const Light& sun = s.lights[0];
    EXPECT_EQ(sun.type, Light::Type::Directional);
    EXPECT_EQ(sun.name, "sun");
    EXPECT_EQ(sun.direction, glm::vec3(0, -1, 0)) << "direction is normalised";
    EXPECT_EQ(sun.radiance(), glm::vec3(2, 1, 0.5f));
    EXPECT_EQ(sun.shadow.resolution, 1024);
    EXPECT_FLOAT_EQ(sun.shadow.bias, 0.5f);
    EXPECT_FLOAT_EQ(sun.shadow.slopeBias, 2);
    EXPECT_FLOAT_EQ(sun.shadow.normalOffset, 1.5f);
    EXPECT_EQ(sun.shadow.polygonOffset, glm::vec2(1, 4));
    EXPECT_EQ(s.lights[1].type, Light::Type::Spot);
    EXPECT_FLOAT_EQ(s.lights[1].angleDeg, 30);
    EXPECT_FLOAT_EQ(s.lights[1].near, 0.5f);
    EXPECT_FLOAT_EQ(s.lights[1].range, 40);
    EXPECT_EQ(s.lights[2].type, Light::Type::Point);
    EXPECT_FLOAT_EQ(s.lights[2].size, 0.3f);
    EXPECT_FALSE(s.lights[2].shadow.enabled);
    EXPECT_EQ(s.lights[3].type, Light::Type::Projector);
    ASSERT_GE(s.lights[3].image, 0);
    EXPECT_TRUE(s.images[static_cast<std::size_t>(s.lights[3].image)].fallback) << "missing picture -> checker";

    ASSERT_EQ(s.objects.size(), 4u);
    EXPECT_EQ(s.meshes[0].bounds.extent(), glm::vec3(8, 0, 6));
    EXPECT_EQ(s.meshes[1].bounds.extent(), glm::vec3(1, 2, 3));
    EXPECT_EQ(s.objects[1].scale, glm::vec3(2));
    EXPECT_EQ(s.objects[1].rotationDeg, glm::vec3(0, 45, 0));
    EXPECT_FALSE(s.objects[1].castsShadow);
    EXPECT_NEAR(s.meshes[2].bounds.extent().x, 1.4f, 1e-4f);
    const Object& ball = s.objects[2];
    EXPECT_EQ(ball.name, "ball");
    ASSERT_GE(ball.materialOverride, 0);
    const Material& glass = s.materials[static_cast<std::size_t>(ball.materialOverride)];
    EXPECT_EQ(glass.transmission, glm::vec3(0.1f, 0.9f, 0.1f));
    EXPECT_FLOAT_EQ(glass.alpha, 0.5f);
    EXPECT_FLOAT_EQ(glass.shininess, 90);
    EXPECT_FLOAT_EQ(glass.alphaCutoff, 0.2f);
    EXPECT_TRUE(glass.doubleSided);
    EXPECT_TRUE(glass.translucent());
    EXPECT_NEAR(glm::vec3(ball.transformAt(0.5f)[3]).x, 0.5f, 1e-5f) << "animated position";
    EXPECT_NEAR(glm::vec3(s.objects[3].transformAt(2.0f)[3]).y, 1.0f, 1e-5f) << "array form of keyframes";
    EXPECT_NEAR(glm::vec3(s.objects[3].transformAt(6.0f)[3]).y, 1.0f, 1e-5f) << "animation loops";
}

TEST(SceneFile, MalformedJsonNamesFileAndLine) {
    const std::string e = errorOf([] { loadScene(kData / "malformed.json"); });
    EXPECT_NE(e.find("malformed.json:4"), std::string::npos) << e;
    EXPECT_NE(e.find("invalid JSON"), std::string::npos) << e;
}

TEST(SceneFile, UnknownKeyNamesLineAndSuggests) {
    const std::string e = errorOf([] { loadScene(kData / "unknown_key.json"); });
    EXPECT_NE(e.find("unknown_key.json:4"), std::string::npos) << e;
    EXPECT_NE(e.find("unknown key 'materail'"), std::string::npos) << e;
    EXPECT_NE(e.find("did you mean 'material'"), std::string::npos) << e;
}

TEST(SceneFile, UnknownLightTypeListsTheKnownOnes) {
    const std::string e = errorOf([] { loadScene(kData / "unknown_light.json"); });
    EXPECT_NE(e.find("unknown_light.json:2"), std::string::npos) << e;
    EXPECT_NE(e.find("'laser'"), std::string::npos) << e;
    EXPECT_NE(e.find("directional, spot, point, projector"), std::string::npos) << e;
}

TEST(SceneFile, BadValuesAreRejected) {
    EXPECT_NE(errorOf([] { parse(R"({ "objects": [ { "shape": "box", "size": [1, 2] } ] })"); }).find("3 numbers"),
              std::string::npos);
    EXPECT_NE(errorOf([] { parse(R"({ "objects": [ { "shape": "cone" } ] })"); }).find("unknown shape 'cone'"),
              std::string::npos);
    EXPECT_NE(errorOf([] { parse(R"({ "objects": [] })"); }).find("non-empty 'objects'"), std::string::npos);
    EXPECT_NE(errorOf([] { parse(R"({ "camera": { "near": 5, "far": 1 }, "objects": [ { "shape": "box" } ] })"); })
                  .find("'far' must be greater"),
              std::string::npos);
    EXPECT_NE(errorOf([] {
                  parse(R"({ "objects": [ { "shape": "box", "material": { "alpha": 1.5 } } ] })");
              }).find("'alpha' (coverage) must be within 0..1"),
              std::string::npos);
    EXPECT_NE(errorOf([] {
                  parse(R"({ "objects": [ { "shape": "box", "animation": [[1, 0, 0, 0], [0, 1, 1, 1]] } ] })");
              }).find("increase"),
              std::string::npos);
    EXPECT_NE(errorOf([] { parse(R"({ "lights": [ { "type": "spot" } ], "objects": [ { "shape": "box" } ] })"); })
                  .find("needs a 'position'"),
              std::string::npos);
}

TEST(SceneFile, CameraPathMovesEyeAndTarget) {
    const Scene s = parse(R"({ "camera": { "position": [0, 2, 5], "target": [0, 0, 0] },
        "camera_path": { "position": [[0, 0, 2, 5], [1, 5, 2, 0], [2, 0, 2, 5]] },
        "objects": [ { "shape": "box" } ] })");
    EXPECT_EQ(s.cameraAt(0.0f).position, glm::vec3(0, 2, 5));
    EXPECT_NEAR(s.cameraAt(1.0f).position.x, 5.0f, 1e-5f);  // passes through every key
    EXPECT_EQ(s.cameraAt(1.0f).target, glm::vec3(0.0f));     // no target keys: the camera's own
    EXPECT_EQ(s.cameraAt(2.0f).position, s.cameraAt(0.0f).position);  // loops
    const Scene still = parse(R"({ "objects": [ { "shape": "box" } ] })");
    EXPECT_EQ(still.cameraAt(3.0f).position, still.camera.position);
    EXPECT_NE(errorOf([] { parse(R"({ "camera_path": {}, "objects": [ { "shape": "box" } ] })"); })
                  .find("needs 'position' or 'target'"),
              std::string::npos);
    EXPECT_NE(errorOf([] { parse(R"({ "camera_path": { "target": [[0, 1, 2]] }, "objects": [ { "shape": "box" } ] })"); })
                  .find("[t, x, y, z]"),
              std::string::npos);
    EXPECT_NE(errorOf([] { parse(R"({ "camera_path": { "positon": [] }, "objects": [ { "shape": "box" } ] })"); })
                  .find("did you mean 'position'"),
              std::string::npos);
}

// A model placed many times (street.json: six models, seven times each) is imported once: its
// objects share one mesh and its materials, each with its own transform. "./" names the same file.
TEST(SceneFile, AModelNamedTwiceIsImportedOnce) {
    const Scene s = parse(R"({ "lights": [ { "type": "directional", "direction": [0, -1, 0] } ],
      "objects": [ { "model": "materials.obj" }, { "model": "./materials.obj", "position": [3, 0, 0], "material": { "diffuse": [1, 0, 0] } },
                   { "shape": "box" } ] })");
    ASSERT_EQ(s.objects.size(), 3u);
    EXPECT_EQ(s.objects[0].mesh, s.objects[1].mesh);
    EXPECT_EQ(s.meshes.size(), 2u) << "the model once, the box";
    EXPECT_NE(s.objects[0].transformAt(0.0f), s.objects[1].transformAt(0.0f));
    EXPECT_LT(s.objects[0].materialOverride, 0) << "the first keeps the model's materials";
    EXPECT_GE(s.objects[1].materialOverride, 0) << "the second overrides them, for itself only";
}

TEST(SceneFile, MissingModelNamesTheModelFile) {
    const std::string e = errorOf([] { loadScene(kData / "missing_model.json"); });
    EXPECT_NE(e.find("no/such/model.obj"), std::string::npos) << e;
    EXPECT_NE(e.find("not found"), std::string::npos) << e;
}

TEST(SceneFile, MissingTextureFallsBackToCheckerWithWarning) {
    log::takeWarnings();
    const Scene s = loadScene(kData / "missing_texture.json");
    const auto warnings = log::takeWarnings();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("no_such_texture.png"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("checker"), std::string::npos) << warnings[0];
    const Material& m = s.materials[static_cast<std::size_t>(s.objects[0].materialOverride)];
    ASSERT_GE(m.diffuseTexture, 0);
    const Image& img = s.images[static_cast<std::size_t>(m.diffuseTexture)];
    EXPECT_TRUE(img.fallback);
    EXPECT_EQ(img.rgba[0], 255);  // magenta square first
    EXPECT_EQ(img.rgba[1], 0);
    EXPECT_EQ(img.rgba[2], 255);
}

TEST(SceneFile, MissingSceneFileSaysSo) {
    const std::string e = errorOf([] { loadScene(kData / "nope.json"); });
    EXPECT_NE(e.find("nope.json: file not found"), std::string::npos) << e;
}

TEST(SceneFile, DefaultSceneLoadsWithItsMission) {
    const Scene s = loadScene(defaultScenePath());
    EXPECT_GE(s.lights.size(), 2u);
    bool glass = false, moving = false, projector = false;
    for (const auto& o : s.objects) {
        moving |= !o.animation.empty();
        for (const auto& p : s.meshes[static_cast<std::size_t>(o.mesh)].parts)
            glass |= glm::any(glm::greaterThan(s.material(o, p).transmission, glm::vec3(0)));
    }
    for (const auto& l : s.lights) projector |= l.type == Light::Type::Projector;
    EXPECT_TRUE(glass && moving && projector);
}

}  // namespace
}  // namespace penumbra::scene::io
