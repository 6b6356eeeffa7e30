#include "scene/io/SceneFile.h"

#include "scene/Shapes.h"
#include "scene/io/ModelImporter.h"
#include "util/DataPaths.h"
#include "util/Error.h"
#include "util/InputFiles.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <glm/gtc/constants.hpp>
#include <set>
#include <sstream>

namespace penumbra::scene::io {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Reads one JSON scene document, remembering the file text so that messages can name the line
// of an offending key (nlohmann's DOM keeps no positions; the key's first occurrence is used).
class Reader {
public:
    Reader(const std::string& text, fs::path file) : text_(text), file_(std::move(file)) {}

    [[noreturn]] void fail(const std::string& path, const std::string& key, const std::string& what) const {
        int line = lineOf(key);
        if (line == 0) line = lineOf(lastKeyOf(path));  // "objects[1].animation" -> "animation"
        throw InputError(file_, line, (path.empty() ? "" : path + ": ") + what);
    }

    static std::string lastKeyOf(const std::string& path) {
        std::string last = path.substr(path.find_last_of('.') == std::string::npos ? 0 : path.find_last_of('.') + 1);
        return last.substr(0, last.find('['));
    }

    void allowKeys(const json& obj, const std::string& path, std::initializer_list<const char*> keys) const {
        if (!obj.is_object()) fail(path, "", "expected an object, got " + std::string(obj.type_name()));
        const std::set<std::string> allowed(keys.begin(), keys.end());
        for (const auto& [k, v] : obj.items()) {
            if (allowed.count(k)) continue;
            std::string msg = "unknown key '" + k + "'";
            if (auto guess = closest(k, allowed); !guess.empty()) msg += " (did you mean '" + guess + "'?)";
            std::string list;
            for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
            fail(path, k, msg + "; allowed: " + list);
        }
    }

    float number(const json& obj, const char* key, const std::string& path, float fallback) const {
        if (!obj.contains(key)) return fallback;
        const json& v = obj.at(key);
        if (!v.is_number()) fail(path, key, std::string("'") + key + "' must be a number, got " + v.type_name());
        return finiteFloat(v.get<double>(), key, path);
    }

    // JSON numbers beyond float range (1e39, -1e300) would become inf or NaN downstream.
    float finiteFloat(double d, const char* key, const std::string& path) const {
        if (!std::isfinite(d) || std::fabs(d) > 1e30) fail(path, key, std::string("'") + key + "' is not a finite number within +-1e30");
        return static_cast<float>(d);
    }

    // An array of exactly `count` numbers, each finite (as number()); else fails with `shape`.
    std::vector<float> numbers(const json& v, std::size_t count, const char* key, const std::string& path,
                               const std::string& shape) const {
        if (!v.is_array() || v.size() != count || !std::all_of(v.begin(), v.end(), [](const json& e) { return e.is_number(); }))
            fail(path, key, shape);
        std::vector<float> out;
        for (const json& e : v) out.push_back(finiteFloat(e.get<double>(), key, path));
        return out;
    }

    float positive(const json& obj, const char* key, const std::string& path, float fallback) const {
        const float v = number(obj, key, path, fallback);
        if (!(v > 0)) fail(path, key, std::string("'") + key + "' must be > 0");
        return v;
    }

    glm::vec3 vec3(const json& obj, const char* key, const std::string& path, glm::vec3 fallback) const {
        if (!obj.contains(key)) return fallback;
        return vec3Value(obj.at(key), key, path);
    }

    glm::vec3 vec3Value(const json& v, const char* key, const std::string& path) const {
        if (v.is_number()) return glm::vec3(finiteFloat(v.get<double>(), key, path));
        const std::vector<float> f = numbers(v, 3, key, path, std::string("'") + key + "' must be an array of 3 numbers");
        return {f[0], f[1], f[2]};
    }

    // A shadow-map resolution: a number within 16..16384 texels.
    int resolution(const json& obj, const char* key, const std::string& path, int fallback) const {
        const float v = number(obj, key, path, static_cast<float>(fallback));
        if (!(v >= 16 && v <= 16384)) fail(path, key, std::string("'") + key + "' must be within 16..16384");
        return static_cast<int>(v);
    }

    std::string string(const json& obj, const char* key, const std::string& path, const std::string& fallback) const {
        if (!obj.contains(key)) return fallback;
        if (!obj.at(key).is_string()) fail(path, key, std::string("'") + key + "' must be a string");
        return obj.at(key).get<std::string>();
    }

    template <class E>
    E choice(const json& obj, const char* key, const std::string& path, E fallback,
             std::initializer_list<std::pair<const char*, E>> options) const {
        if (!obj.contains(key)) return fallback;
        const std::string s = string(obj, key, path, "");
        std::string list;
        for (const auto& [name, value] : options) {
            if (s == name) return value;
            list += (list.empty() ? "" : ", ") + std::string(name);
        }
        fail(path, s, "'" + std::string(key) + "' is '" + s + "'; expected one of: " + list);
    }

    fs::path resolve(const std::string& rel) const { return file_.parent_path() / rel; }
    const fs::path& file() const { return file_; }

    int lineOf(const std::string& key) const {
        if (key.empty()) return 0;
        const std::size_t pos = text_.find("\"" + key + "\"");
        if (pos == std::string::npos) return 0;
        return 1 + static_cast<int>(std::count(text_.begin(), text_.begin() + static_cast<long>(pos), '\n'));
    }

private:
    static std::string closest(const std::string& k, const std::set<std::string>& allowed) {
        std::string best;
        std::size_t bestDist = 3;  // suggest only near misses
        for (const auto& a : allowed) {
            const std::size_t d = editDistance(k, a);
            if (d < bestDist) { bestDist = d; best = a; }
        }
        return best;
    }
    static std::size_t editDistance(const std::string& a, const std::string& b) {
        std::vector<std::size_t> row(b.size() + 1);
        for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
        for (std::size_t i = 1; i <= a.size(); ++i) {
            std::size_t prev = row[0];
            row[0] = i;
            for (std::size_t j = 1; j <= b.size(); ++j) {
                const std::size_t cur = row[j];
                row[j] = std::min({row[j] + 1, row[j - 1] + 1, prev + (a[i - 1] == b[j - 1] ? 0 : 1)});
                prev = cur;
            }
        }
        return row[b.size()];
    }

    const std::string& text_;
    fs::path file_;
};

void readCamera(const Reader& r, const json& j, Camera& cam) {
    const std::string p = "camera";
    r.allowKeys(j, p, {"position", "target", "up", "fov_deg", "near", "far", "controller"});
    cam.position = r.vec3(j, "position", p, cam.position);
    cam.target = r.vec3(j, "target", p, cam.target);
    cam.up = r.vec3(j, "up", p, cam.up);
    cam.fovDeg = r.positive(j, "fov_deg", p, cam.fovDeg);
    cam.near = r.positive(j, "near", p, cam.near);
    cam.far = r.positive(j, "far", p, cam.far);
    if (cam.far <= cam.near) r.fail(p, "far", "'far' must be greater than 'near'");
    if (cam.fovDeg >= 179.0f) r.fail(p, "fov_deg", "'fov_deg' must be below 179");
    if (glm::length(cam.position - cam.target) <= 0) r.fail(p, "target", "'target' equals 'position'");
    if (glm::length(glm::cross(glm::normalize(cam.target - cam.position), cam.up)) < 1e-6f)
        r.fail(p, "up", "'up' is zero or parallel to the view direction");
    cam.controller = r.choice(j, "controller", p, cam.controller,
                              {{"fly", Camera::Controller::Fly},
                               {"trackball", Camera::Controller::Trackball},
                               {"orbit", Camera::Controller::Orbit}});
}

ShadowSettings readShadow(const Reader& r, const json& j, const std::string& p) {
    r.allowKeys(j, p, {"enabled", "resolution", "bias", "slope_bias", "normal_offset", "polygon_offset"});
    ShadowSettings s;
    if (j.contains("enabled")) {
        if (!j["enabled"].is_boolean()) r.fail(p, "enabled", "'enabled' must be true or false");
        s.enabled = j["enabled"].get<bool>();
    }
    s.resolution = r.resolution(j, "resolution", p, s.resolution);
    s.bias = r.number(j, "bias", p, s.bias);
    s.slopeBias = r.number(j, "slope_bias", p, s.slopeBias);
    s.normalOffset = r.number(j, "normal_offset", p, s.normalOffset);
    if (j.contains("polygon_offset")) {
        const std::vector<float> f = r.numbers(j["polygon_offset"], 2, "polygon_offset", p, "'polygon_offset' must be [factor, units]");
        s.polygonOffset = {f[0], f[1]};
    }
    return s;
}

void readLight(const Reader& r, const json& j, const std::string& p, Scene& scene) {
    r.allowKeys(j, p, {"type", "name", "color", "intensity", "direction", "position", "angle_deg", "image", "shadow",
                       "size", "near", "range"});
    Light l;
    if (!j.contains("type")) r.fail(p, "", "a light needs a 'type'");
    l.type = r.choice(j, "type", p, l.type,
                      {{"directional", Light::Type::Directional}, {"spot", Light::Type::Spot},
                       {"point", Light::Type::Point}, {"projector", Light::Type::Projector}});
    l.name = r.string(j, "name", p, std::string(toString(l.type)) + " " + std::to_string(scene.lights.size()));
    l.color = r.vec3(j, "color", p, l.color);
    l.intensity = r.number(j, "intensity", p, l.intensity);
    l.position = r.vec3(j, "position", p, l.position);
    l.direction = r.vec3(j, "direction", p, l.direction);
    if (glm::length(l.direction) < 1e-6f) r.fail(p, "direction", "'direction' must not be zero");
    l.direction = glm::normalize(l.direction);
    l.angleDeg = r.positive(j, "angle_deg", p, l.angleDeg);
    if (l.angleDeg >= 170.0f) r.fail(p, "angle_deg", "'angle_deg' must be below 170");
    l.size = r.number(j, "size", p, l.size);
    if (l.size < 0) r.fail(p, "size", "'size' must be >= 0");
    l.near = r.positive(j, "near", p, l.near);
    l.range = r.positive(j, "range", p, l.range);
    if (l.range <= l.near) r.fail(p, "range", "'range' must be greater than 'near'");
    if (l.type == Light::Type::Directional && !j.contains("direction"))
        r.fail(p, "type", "a directional light needs a 'direction'");
    if ((l.type == Light::Type::Spot || l.type == Light::Type::Projector || l.type == Light::Type::Point) &&
        !j.contains("position"))
        r.fail(p, "type", std::string("a ") + toString(l.type) + " light needs a 'position'");
    if (l.type == Light::Type::Projector) {
        if (!j.contains("image")) r.fail(p, "type", "a projector needs an 'image'");
        scene.images.push_back(loadImageOrChecker(r.resolve(r.string(j, "image", p, "")), r.file().string()));
        l.image = static_cast<int>(scene.images.size()) - 1;
    }
    if (j.contains("shadow")) l.shadow = readShadow(r, j["shadow"], p + ".shadow");
    scene.lights.push_back(l);
}

int readMaterial(const Reader& r, const json& j, const std::string& p, Scene& scene) {
    r.allowKeys(j, p, {"name", "diffuse", "specular", "shininess", "texture", "alpha", "transmission", "alpha_cutoff",
                       "double_sided"});
    Material m;
    m.name = r.string(j, "name", p, p);
    m.diffuse = r.vec3(j, "diffuse", p, m.diffuse);
    m.specular = r.vec3(j, "specular", p, m.specular);
    m.shininess = r.positive(j, "shininess", p, m.shininess);
    m.alpha = r.number(j, "alpha", p, m.alpha);
    if (m.alpha < 0 || m.alpha > 1) r.fail(p, "alpha", "'alpha' (coverage) must be within 0..1");
    m.transmission = r.vec3(j, "transmission", p, m.transmission);
    if (glm::any(glm::lessThan(m.transmission, glm::vec3(0))) || glm::any(glm::greaterThan(m.transmission, glm::vec3(1))))
        r.fail(p, "transmission", "'transmission' must be within 0..1 per channel");
    m.alphaCutoff = r.number(j, "alpha_cutoff", p, m.alphaCutoff);
    if (m.alphaCutoff < 0) r.fail(p, "alpha_cutoff", "'alpha_cutoff' must be >= 0 (above 1 every texel is a hole)");
    if (j.contains("double_sided")) m.doubleSided = j["double_sided"].is_boolean() && j["double_sided"].get<bool>();
    if (j.contains("texture")) {
        scene.images.push_back(loadImageOrChecker(r.resolve(r.string(j, "texture", p, "")), r.file().string()));
        m.diffuseTexture = static_cast<int>(scene.images.size()) - 1;
    }
    scene.materials.push_back(m);
    return static_cast<int>(scene.materials.size()) - 1;
}

Track readTrack(const Reader& r, const json& keys, const std::string& p, const char* key) {
    if (!keys.is_array() || keys.empty()) r.fail(p, key, "keyframes must be a non-empty array of [t, x, y, z]");
    std::vector<Keyframe> out;
    for (const auto& k : keys) {
        const std::vector<float> f = r.numbers(k, 4, key, p, "each keyframe must be [t, x, y, z]");
        out.push_back({f[0], {f[1], f[2], f[3]}});
    }
    try {
        return Track(std::move(out));
    } catch (const std::invalid_argument& e) {
        r.fail(p, key, e.what());
    }
}

Animation readAnimation(const Reader& r, const json& j, const std::string& p) {
    Animation a;
    if (j.is_array()) {
        a.position = readTrack(r, j, p, "animation");
        return a;
    }
    r.allowKeys(j, p, {"position", "rotation_deg"});
    if (j.contains("position")) a.position = readTrack(r, j["position"], p + ".position", "position");
    if (j.contains("rotation_deg")) a.rotationDeg = readTrack(r, j["rotation_deg"], p + ".rotation_deg", "rotation_deg");
    return a;
}

// `models`: each model file imported so far -> its mesh. Objects that name the same file share
// one mesh (street.json places each of its six models seven times): one import, one upload.
void readObject(const Reader& r, const json& j, const std::string& p, Scene& scene, std::map<fs::path, int>& models) {
    r.allowKeys(j, p, {"name", "model", "shape", "size", "radius", "position", "rotation_deg", "scale", "material",
                       "animation", "cast_shadows", "visible", "region"});
    Object o;
    const bool hasModel = j.contains("model"), hasShape = j.contains("shape");
    if (hasModel == hasShape) r.fail(p, "", "an object needs exactly one of 'model' or 'shape'");
    if (hasModel) {
        try {
            const fs::path file = r.resolve(r.string(j, "model", p, "")).lexically_normal();
            const auto found = models.find(file);
            o.mesh = found != models.end() ? found->second : models[file] = importModel(file, scene);
        } catch (const InputError& e) {  // name the scene's line too: "scene.json:12: objects[3]: model.obj: ..."
            r.fail(p, "model", e.what());
        }
        o.name = r.string(j, "name", p, fs::path(r.string(j, "model", p, "")).stem().string());
    } else {
        const std::string shape = r.string(j, "shape", p, "");
        Mesh mesh;
        if (shape == "plane") {
            glm::vec2 size{10.0f};
            if (j.contains("size")) {
                const std::vector<float> f = r.numbers(j["size"], 2, "size", p, "a plane's 'size' is [x, z]");
                if (!(f[0] > 0 && f[1] > 0)) r.fail(p, "size", "a plane's 'size' must be > 0");
                size = {f[0], f[1]};
            }
            mesh = shapes::plane(size.x, size.y);
        } else if (shape == "box") {
            const glm::vec3 size = r.vec3(j, "size", p, glm::vec3(1.0f));
            if (!glm::all(glm::greaterThan(size, glm::vec3(0)))) r.fail(p, "size", "a box's 'size' must be > 0 on every axis");
            mesh = shapes::box(size);
        } else if (shape == "sphere") {
            mesh = shapes::sphere(r.positive(j, "radius", p, 0.5f));
        } else {
            r.fail(p, "shape", "unknown shape '" + shape + "'; expected one of: plane, box, sphere");
        }
        scene.materials.push_back(Material{});
        mesh.parts[0].material = static_cast<int>(scene.materials.size()) - 1;
        scene.meshes.push_back(std::move(mesh));
        o.mesh = static_cast<int>(scene.meshes.size()) - 1;
        o.name = r.string(j, "name", p, shape);
    }
    o.position = r.vec3(j, "position", p, o.position);
    o.rotationDeg = r.vec3(j, "rotation_deg", p, o.rotationDeg);
    o.scale = r.vec3(j, "scale", p, o.scale);
    if (glm::any(glm::lessThan(glm::abs(o.scale), glm::vec3(1e-6f))))
        r.fail(p, "scale", "'scale' must not be zero on any axis (the object would have no area and no normals)");
    if (j.contains("material")) o.materialOverride = readMaterial(r, j["material"], p + ".material", scene);
    if (j.contains("animation")) o.animation = readAnimation(r, j["animation"], p + ".animation");
    for (const auto& [key, flag] : {std::pair<const char*, bool*>{"cast_shadows", &o.castsShadow}, {"visible", &o.visible}}) {
        if (!j.contains(key)) continue;
        if (!j[key].is_boolean()) r.fail(p, key, std::string("'") + key + "' must be true or false");
        *flag = j[key].get<bool>();
    }
    if (j.contains("region")) {
        const std::string name = r.string(j, "region", p, "");
        const auto it = std::find_if(scene.regions.begin(), scene.regions.end(), [&](const Region& g) { return g.name == name; });
        if (it == scene.regions.end()) {
            std::string known;
            for (const Region& g : scene.regions) known += (known.empty() ? "'" : ", '") + g.name + "'";
            r.fail(p, "region", "unknown region '" + name + "'; the scene's 'regions' are: " + (known.empty() ? "none" : known));
        }
        o.region = static_cast<int>(it - scene.regions.begin());
    }
    scene.objects.push_back(std::move(o));
}

void readRegion(const Reader& r, const json& j, const std::string& p, Scene& scene) {
    r.allowKeys(j, p, {"name", "technique", "shadow_resolution", "parameters"});
    Region g;
    g.name = r.string(j, "name", p, "");
    if (g.name.empty()) r.fail(p, "name", "a region needs a non-empty 'name' (objects name it in their 'region')");
    for (const Region& other : scene.regions)
        if (other.name == g.name) r.fail(p, "name", "two regions are named '" + g.name + "'");
    g.technique = r.string(j, "technique", p, "");
    if (j.contains("shadow_resolution")) g.shadowResolution = r.resolution(j, "shadow_resolution", p, 0);
    if (j.contains("parameters")) {
        const json& params = j["parameters"];
        if (!params.is_object()) r.fail(p, "parameters", "'parameters' must be an object of name: value");
        for (const auto& [name, value] : params.items()) {
            if (value.is_string()) g.parameters[name] = value.get<std::string>();
            else if (value.is_number() || value.is_boolean()) g.parameters[name] = value.dump();
            else r.fail(p + ".parameters", name, "parameter '" + name + "' must be a number, true/false or a string");
        }
    }
    scene.regions.push_back(std::move(g));
}

// nlohmann reports a byte offset; turn it into line:column of the file.
std::string parseErrorLocation(const std::string& text, std::size_t byte, int& line) {
    byte = std::min(byte, text.size());
    line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(byte), '\n'));
    const std::size_t lineStart = text.rfind('\n', byte > 0 ? byte - 1 : 0);
    const std::size_t col = lineStart == std::string::npos ? byte : byte - lineStart - 1;
    return std::to_string(col);
}

}  // namespace

Scene parseSceneJson(const std::string& text, const fs::path& file) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::out_of_range& e) {  // a number too large for a double, e.g. 1e400
        throw InputError(file, "invalid JSON: " + std::string(e.what()));
    } catch (const json::parse_error& e) {
        int line = 0;
        const std::string col = parseErrorLocation(text, e.byte > 0 ? e.byte - 1 : 0, line);
        std::string what = e.what();
        if (auto pos = what.find("syntax error"); pos != std::string::npos) what = what.substr(pos);
        throw InputError(file, line, "column " + col + ": invalid JSON: " + what);
    }
    const Reader r(text, file);
    r.allowKeys(doc, "", {"name", "description", "camera", "camera_path", "ambient", "background", "fog", "lights",
                          "objects", "technique", "regions"});
    Scene scene;
    scene.source = file;
    if (doc.contains("camera")) readCamera(r, doc["camera"], scene.camera);
    if (doc.contains("camera_path")) {
        const json& path = doc["camera_path"];
        r.allowKeys(path, "camera_path", {"position", "target"});
        if (!path.contains("position") && !path.contains("target"))
            r.fail("", "camera_path", "'camera_path' needs 'position' or 'target' keyframes");
        if (path.contains("position")) scene.cameraPath.position = readTrack(r, path["position"], "camera_path", "position");
        if (path.contains("target")) scene.cameraPath.target = readTrack(r, path["target"], "camera_path", "target");
    }
    scene.ambient = r.vec3(doc, "ambient", "", scene.ambient);
    scene.background = r.vec3(doc, "background", "", scene.background);
    scene.technique = r.string(doc, "technique", "", "");
    if (doc.contains("fog")) {
        r.allowKeys(doc["fog"], "fog", {"start", "end"});
        scene.fog.enabled = true;
        scene.fog.start = r.number(doc["fog"], "start", "fog", scene.camera.far * 0.7f);
        scene.fog.end = r.number(doc["fog"], "end", "fog", scene.camera.far);
        if (scene.fog.end <= scene.fog.start) r.fail("fog", "end", "'end' must be greater than 'start'");
    }
    if (doc.contains("lights")) {
        if (!doc["lights"].is_array()) r.fail("", "lights", "'lights' must be an array");
        if (doc["lights"].size() > static_cast<std::size_t>(kLightLimit))
            r.fail("", "lights", std::to_string(doc["lights"].size()) + " lights; penumbra draws at most " +
                                     std::to_string(kLightLimit));
        for (std::size_t i = 0; i < doc["lights"].size(); ++i)
            readLight(r, doc["lights"][i], "lights[" + std::to_string(i) + "]", scene);
    }
    if (doc.contains("regions")) {  // before the objects, which name them
        if (!doc["regions"].is_array()) r.fail("", "regions", "'regions' must be an array");
        for (std::size_t i = 0; i < doc["regions"].size(); ++i)
            readRegion(r, doc["regions"][i], "regions[" + std::to_string(i) + "]", scene);
    }
    if (!doc.contains("objects") || !doc["objects"].is_array() || doc["objects"].empty())
        r.fail("", "objects", "a scene needs a non-empty 'objects' array");
    std::map<fs::path, int> models;
    for (std::size_t i = 0; i < doc["objects"].size(); ++i)
        readObject(r, doc["objects"][i], "objects[" + std::to_string(i) + "]", scene, models);
    return scene;
}

Scene wrapModel(const fs::path& modelFile) {
    Scene scene;
    scene.source = modelFile;
    Object model;
    model.mesh = importModel(modelFile, scene);
    model.name = modelFile.stem().string();
    scene.objects.push_back(model);

    const Bounds b = scene.meshes[0].bounds;
    const glm::vec3 c = b.center();
    const float radius = std::max(glm::length(b.extent()) * 0.5f, 1e-3f);
    // Ground just under the model, large enough to catch its shadow.
    Mesh ground = shapes::plane(radius * 8.0f, radius * 8.0f);
    scene.materials.push_back(Material{.name = "ground", .diffuse = glm::vec3(0.7f)});
    ground.parts[0].material = static_cast<int>(scene.materials.size()) - 1;
    scene.meshes.push_back(std::move(ground));
    Object groundObject;
    groundObject.name = "ground";
    groundObject.mesh = 1;
    groundObject.position = {c.x, b.min.y - radius * 0.002f, c.z};
    scene.objects.push_back(groundObject);

    Light sun;
    sun.name = "sun";
    sun.direction = glm::normalize(glm::vec3(-0.4f, -1.0f, -0.3f));
    sun.intensity = 1.0f;
    scene.lights.push_back(sun);
    scene.ambient = glm::vec3(0.15f);

    // Frame the bounding sphere: distance so that it fills ~80% of the vertical field of view,
    // looking slightly down from above the ground.
    Camera& cam = scene.camera;
    const float distance = radius / std::sin(glm::radians(cam.fovDeg) * 0.4f);
    cam.target = c;
    cam.position = c + glm::normalize(glm::vec3(0.6f, 0.45f, 1.0f)) * distance;
    cam.position.y = std::max(cam.position.y, b.min.y + radius * 0.2f);
    cam.near = distance * 0.01f;
    cam.far = distance * 20.0f;
    return scene;
}

Scene loadScene(const fs::path& path) {
    if (!fs::exists(path)) throw InputError(path, "file not found");
    if (util::lowerExtension(path) != ".json") return wrapModel(path);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, "cannot open scene file");
    std::stringstream ss;
    ss << in.rdbuf();
    return parseSceneJson(ss.str(), path);
}

fs::path defaultScenePath() { return paths::sceneDir() / "default.json"; }

}  // namespace penumbra::scene::io
