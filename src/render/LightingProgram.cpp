#include "render/LightingProgram.h"

namespace penumbra::render {

std::vector<std::string> lightLayoutDefines(const gpu::LightBlock& block, int sunLight, bool translucentCasters) {
    std::string types, shadowSlots, projectorSlots;
    for (int i = 0; i < gpu::kMaxLights; ++i) {
        const gpu::LightData& l = block.lights[i];
        const bool used = i < block.count.x;
        const char* comma = i ? ", " : "";
        types += comma + std::to_string(used ? static_cast<int>(l.colorType.w) : -1);
        shadowSlots += comma + std::to_string(used ? static_cast<int>(l.cone.w) : -1);
        projectorSlots += comma + std::to_string(used ? static_cast<int>(l.cone.z) : -1);
    }
    std::string eachLight;
    for (int i = 0; i < block.count.x; ++i) eachLight += " SHADE_LIGHT(" + std::to_string(i) + ")";
    return {"SCENE_LIGHT_COUNT " + std::to_string(block.count.x), "SHADE_EACH_LIGHT" + eachLight, "SCENE_LIGHT_TYPES " + types,
            "SCENE_SHADOW_SLOTS " + shadowSlots, "SCENE_PROJECTOR_SLOTS " + projectorSlots,
            "SCENE_SUN_LIGHT " + std::to_string(sunLight), std::string("SCENE_TRANSLUCENT_CASTERS ") + (translucentCasters ? "1" : "0")};
}

gl::Program buildLightingProgram(const std::filesystem::path& lookup, const std::vector<std::string>& defines) {
    return gl::Program::build({.vertex = "shaders/passes/lighting.vert",
                               .fragment = "shaders/passes/lighting.frag",
                               .defines = defines,
                               .includeOverrides = {{"shadow_lookup.glsl", lookup}}});
}

LightingPrograms::LightingPrograms(std::filesystem::path lookup, std::vector<std::string> defines, bool anyTexturedMaterial)
    : lookup_(std::move(lookup)), defines_(std::move(defines)) {
    scene::Material first;
    if (anyTexturedMaterial) first.diffuseTexture = 0;
    of(first);
}

const gl::Program& LightingPrograms::of(const scene::Material& material, bool translucent, TintLookup tint, unsigned unlit,
                                        unsigned unshadowed) {
    const bool untextured = material.diffuseTexture < 0, alphaTested = material.alphaCutoff > 0.0f;
    const bool noSpecular = material.specular == glm::vec3(0.0f);
    const unsigned key = (untextured ? 1u : 0u) + (translucent ? 2u : 0u) + (alphaTested ? 4u : 0u) + (noSpecular ? 8u : 0u) +
                         16u * static_cast<unsigned>(tint) + 48u * unlit;
    gl::Program& build = builds_[key + (std::uint64_t{unshadowed} << 32)];
    if (!build.id()) {
        std::vector<std::string> defines = defines_;
        if (untextured) defines.emplace_back("MATERIAL_UNTEXTURED 1");
        if (translucent) defines.emplace_back("MATERIAL_TRANSLUCENT 1");
        if (!alphaTested) defines.emplace_back("MATERIAL_NO_ALPHA_TEST 1");
        if (noSpecular) defines.emplace_back("MATERIAL_NO_SPECULAR 1");
        if (tint == TintLookup::Untinted) defines.emplace_back("RECEIVER_UNTINTED 1");
        if (tint == TintLookup::BehindLayers) defines.emplace_back("RECEIVER_BEHIND_LAYERS 1");
        if (unlit != 0) defines.emplace_back("SKIPPED_LIGHTS " + std::to_string(unlit) + "u");
        if (unshadowed != 0) defines.emplace_back("UNSHADOWED_LIGHTS " + std::to_string(unshadowed) + "u");
        build = buildLightingProgram(lookup_, defines);
    }
    return build;
}

}  // namespace penumbra::render
