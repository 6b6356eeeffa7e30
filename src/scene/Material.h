#pragma once
#include <glm/glm.hpp>

#include <string>

namespace penumbra::scene {

// Surface description shared by shading and (later) coloured shadows. The coverage/transmission
// pair follows McGuire & Enderton 2011: a photon hitting the surface is intercepted
// with probability `alpha`; an intercepted photon passes through with probability
// `transmission` per channel. The fraction stopped is rho = (1 - t) * alpha.
struct Material {
    std::string name = "default";
    glm::vec3 diffuse{0.8f};
    glm::vec3 specular{0.04f};
    float shininess = 32.0f;
    int diffuseTexture = -1;       // index into Scene::images; its alpha multiplies `alpha`
    float alpha = 1.0f;            // coverage
    glm::vec3 transmission{0.0f};  // t_rgb
    float alphaCutoff = 0.0f;      // > 0: alpha-test (glTF MASK); fragments below it vanish
    bool doubleSided = false;

    glm::vec3 stopped() const { return (glm::vec3(1.0f) - transmission) * alpha; }
    // Anything that lets light through needs blending for the camera and colour for shadows.
    bool translucent() const { return alpha < 1.0f || glm::any(glm::greaterThan(transmission, glm::vec3(0.0f))); }
};

}  // namespace penumbra::scene
