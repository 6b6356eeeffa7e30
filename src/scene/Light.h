#pragma once
#include <glm/glm.hpp>

#include <string>

namespace penumbra::scene {

// How a light's shadow map is made and read. Units: `bias` in light-space depth units
// (world units for directional lights, normalised distance for point lights), `slopeBias`
// multiplies tan(angle between N and L) on top of it, `normalOffset` moves the lookup point
// along the surface normal by that many shadow-map texels, `polygonOffset` is glPolygonOffset
// (factor, units) applied while rendering the map.
struct ShadowSettings {
    bool enabled = true;
    int resolution = 2048;
    float bias = 0.2f;
    float slopeBias = 0.5f;
    float normalOffset = 1.0f;
    glm::vec2 polygonOffset{1.5f, 2.0f};
};

// The renderer's light block holds this many lights (gpu::kMaxLights, checked where the block is
// filled); scene files with more are refused rather than drawn with some lights missing.
inline constexpr int kLightLimit = 8;

struct Light {
    enum class Type { Directional, Spot, Point, Projector };
    Type type = Type::Directional;
    std::string name;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    glm::vec3 position{0.0f, 10.0f, 0.0f};
    glm::vec3 direction{0.0f, -1.0f, 0.0f};  // the way light travels (unit length)
    float angleDeg = 45.0f;                  // spot/projector full cone angle
    float near = 0.05f;                      // spot/point/projector shadow near plane
    float range = 100.0f;                    // spot/point/projector shadow far plane
    float size = 0.0f;                       // area-light size (world units) for soft techniques
    int image = -1;                          // projector picture (index into Scene::images)
    ShadowSettings shadow;

    glm::vec3 radiance() const { return color * intensity; }
};

const char* toString(Light::Type type);

}  // namespace penumbra::scene
