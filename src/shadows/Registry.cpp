#include "shadows/ShadowTechnique.h"
#include "shadows/hard/HardShadowMap.h"
#include "shadows/none/NoShadows.h"

#include <stdexcept>

namespace penumbra::shadows {

const std::vector<TechniqueInfo>& techniqueRegistry() {
    static const std::vector<TechniqueInfo> registry = {
        {"hard", "shadow map (Williams 1978), hardware depth compare, coloured tint from translucent casters",
         [] { return std::make_unique<HardShadowMap>(); }},
        {"none", "no shadows: every light reaches every surface", [] { return std::make_unique<NoShadows>(); }},
    };
    return registry;
}

std::string knownTechniqueNames() {
    std::string names;
    for (const auto& t : techniqueRegistry()) names += (names.empty() ? "" : ", ") + t.name;
    return names;
}

std::unique_ptr<ShadowTechnique> createTechnique(const std::string& name) {
    for (const auto& t : techniqueRegistry())
        if (t.name == name) return t.create();
    throw std::invalid_argument("unknown shadow technique '" + name + "'; known: " + knownTechniqueNames());
}

}  // namespace penumbra::shadows
