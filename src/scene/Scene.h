#pragma once
// A scene as data: meshes, materials, images, lights, camera, animated objects.
// It knows nothing about GL or shadows; the renderer and the reference consume it.
#include "scene/Animation.h"
#include "scene/Camera.h"
#include "scene/Image.h"
#include "scene/Light.h"
#include "scene/Material.h"
#include "scene/Mesh.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace penumbra::scene {

struct Object {
    std::string name;
    int mesh = 0;
    int materialOverride = -1;  // replaces every part's material when >= 0
    glm::vec3 position{0.0f};
    glm::vec3 rotationDeg{0.0f};  // applied Z, then Y, then X... see transformAt
    glm::vec3 scale{1.0f};
    Animation animation;
    bool castsShadow = true;
    bool visible = true;  // false: a shadow-only caster the camera does not see
    int region = -1;      // index into Scene::regions; -1: drawn with the scene's own technique

    glm::mat4 transformAt(float time) const;
};

// A flight through the scene for benchmarks and recordings: looping keyframes of the eye and of
// the point it looks at (either may be absent: the camera's own stays).
struct CameraPath {
    Track position;
    Track target;
    bool empty() const { return position.empty() && target.empty(); }
};

// Seed 002's combined technique (its section 3.2, Fig. 3.2): a part of the scene whose surfaces are
// shaded with a technique and map resolution of their own, beside the others in the same frame.
// The scene only names them; render/RegionView.h gives each region its renderer and maps.
struct Region {
    std::string name;
    std::string technique;     // a shadow technique's name, "" = the scene's
    int shadowResolution = 0;  // > 0: every light's map resolution for this region
    std::map<std::string, std::string> parameters;  // technique parameters as text, e.g. "radius_texels": "3"
};

struct Fog {
    bool enabled = false;
    float start = 0.0f, end = 0.0f;  // distance from the camera
};

struct Scene {
    std::filesystem::path source;  // file it came from (empty for code-built scenes)
    Camera camera;
    CameraPath cameraPath;
    glm::vec3 ambient{0.08f};
    glm::vec3 background{0.05f, 0.06f, 0.08f};
    Fog fog;
    std::string technique;  // preferred shadow technique, "" = the program's default
    std::vector<Light> lights;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Image> images;
    std::vector<Object> objects;
    std::vector<Region> regions;  // empty: one technique for the whole scene

    const Material& material(const Object& object, const MeshPart& part) const;
    Bounds boundsAt(float time) const;  // world bounds of every object at `time`
    std::size_t triangleCount() const;
    bool animated() const;
    // The camera at `time`: `camera` moved along `cameraPath` (unchanged without one).
    Camera cameraAt(float time) const;
};

}  // namespace penumbra::scene
