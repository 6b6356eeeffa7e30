#pragma once
// One shadow technique = data (its maps) + passes (renderMaps) + a GLSL lookup that the
// lighting shader includes as "shadow_lookup.glsl", defining
//     vec3 shadowVisibility(int light, vec3 worldPos, vec3 worldNormal, float NdotL);
// (rgb: coloured visibility, 1 = fully lit). Adding a technique = a folder here + one line in
// Registry.cpp.
#include "gl/Program.h"
#include "scene/Camera.h"
#include "scene/Scene.h"
#include "shadows/LightSpace.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace penumbra::shadows {

// Which casters a pass wants. Opaque casters block; translucent ones (coverage < 1 or
// transmission > 0) tint (SPEC §4).
enum class Casters { Opaque, Translucent };

// What the renderer gives a technique for one frame.
struct ShadowFrame {
    const std::vector<scene::Light>* lights = nullptr;
    const std::vector<LightSpace>* lightSpaces = nullptr;  // one per light
    // Draws the chosen casters with `program` bound (uModel and material uniforms are set,
    // the diffuse texture is on unit 0); the caller sets the light's matrices.
    std::function<void(const gl::Program& program, Casters casters)> drawCasters;
    // Draws the visible opaque surfaces (every one, or only object `onlyObject` when >= 0) with
    // `program` bound: depth pre-passes and receiver masks of screen-space techniques.
    std::function<void(const gl::Program& program, int onlyObject)> drawSurfaces;
    const scene::Scene* scene = nullptr;  // geometry-based techniques (shadow volumes, planar)
    float time = 0.0f;                    // scene time of the frame (object transforms)
    glm::ivec2 viewport{0};               // size of the frame being rendered
    std::uint32_t frameIndex = 0;  // seeds per-frame randomness (stochastic techniques)
    const scene::Camera* camera = nullptr;  // view-dependent techniques (cascades) fit to it
    float aspect = 1.0f;
    scene::Bounds sceneBounds;              // every object at this frame's time
};

// A texture worth showing in the debug overlay.
struct DebugView {
    std::string label;
    GLuint texture = 0;
    GLenum target = GL_TEXTURE_2D;
    bool depth = false;  // show as linearised grey
    int layer = 0;
};

// A world-space line segment for the debug overlay (cascade frusta, light boxes).
struct DebugLine {
    glm::vec3 a, b;
    glm::vec3 color;
};

// A live, typed knob (UI slider, CLI --param name=value).
struct Parameter {
    std::string name;
    float* value;
    float min, max;
};

class ShadowTechnique {
public:
    virtual ~ShadowTechnique() = default;
    virtual std::string name() const = 0;
    // GLSL file (relative to the source root) that defines shadowVisibility().
    virtual std::filesystem::path lookupShader() const = 0;
    // Re-renders every light's maps (called every frame).
    virtual void renderMaps(const ShadowFrame& frame) = 0;
    // Binds textures and sets uniforms the lookup needs on the lighting program.
    virtual void bindLookup(const gl::Program& lighting) const = 0;
    virtual std::size_t memoryBytes() const = 0;
    virtual std::vector<DebugView> debugViews() const { return {}; }
    virtual std::vector<DebugLine> debugLines() const { return {}; }
    virtual std::vector<Parameter> parameters() { return {}; }
};

// Sets the named parameters the technique has; returns the names it does not have.
std::vector<std::string> applyParameters(ShadowTechnique& technique, const std::vector<std::pair<std::string, float>>& values);
// Parses "name=value"; throws std::invalid_argument on bad text.
std::pair<std::string, float> parseParameter(const std::string& text);

struct TechniqueInfo {
    std::string name;
    std::string description;
    std::function<std::unique_ptr<ShadowTechnique>()> create;
};

const std::vector<TechniqueInfo>& techniqueRegistry();
// Throws std::invalid_argument listing the known names when `name` is unknown.
std::unique_ptr<ShadowTechnique> createTechnique(const std::string& name);
std::string knownTechniqueNames();
// Registry lookup only: needs no GL context.
bool isKnownTechnique(const std::string& name);

}  // namespace penumbra::shadows
