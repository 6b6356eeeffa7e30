#pragma once
// What a loaded scene promises the renderer, checked the same way by the fuzz targets and by the
// bad-input corpus test: every index in range, every number finite, every picture whole.
#include "scene/Scene.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace penumbra::fuzz {

inline bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// "" when `s` is drawable, else what is wrong with it.
inline std::string whyNotDrawable(const scene::Scene& s) {
    if (s.objects.empty()) return "no objects";
    if (s.lights.size() > static_cast<std::size_t>(scene::kLightLimit)) return "more lights than the renderer holds";
    if (!finite(s.camera.position) || !finite(s.camera.target) || !std::isfinite(s.camera.far)) return "camera not finite";
    for (const auto& l : s.lights)
        if (!finite(l.position) || !finite(l.direction) || !std::isfinite(l.intensity)) return "light '" + l.name + "' not finite";
    for (const auto& o : s.objects) {
        if (o.mesh < 0 || o.mesh >= static_cast<int>(s.meshes.size())) return "object '" + o.name + "' has no mesh";
        if (!finite(o.position) || !finite(o.scale)) return "object '" + o.name + "' not finite";
    }
    for (const auto& m : s.meshes) {
        for (std::uint32_t i : m.indices)
            if (i >= m.vertices.size()) return "mesh '" + m.name + "': index past its vertices";
        for (const auto& v : m.vertices)
            if (!finite(v.position) || !finite(v.normal)) return "mesh '" + m.name + "': vertex not finite";
        for (const auto& p : m.parts)
            if (p.material < 0 || p.material >= static_cast<int>(s.materials.size()) ||
                std::size_t(p.firstIndex) + p.indexCount > m.indices.size())
                return "mesh '" + m.name + "': part out of range";
    }
    for (const auto& mat : s.materials) {
        if (!(mat.alpha >= 0 && mat.alpha <= 1)) return "material '" + mat.name + "': alpha outside 0..1";
        if (mat.diffuseTexture >= static_cast<int>(s.images.size())) return "material '" + mat.name + "': no such texture";
    }
    for (const auto& img : s.images)
        if (img.width <= 0 || img.height <= 0 || img.rgba.size() != static_cast<std::size_t>(img.width) * img.height * 4)
            return "image '" + img.source + "' is not whole";
    return {};
}

// For the fuzz targets: a scene the loader accepted but the renderer could not draw is a bug.
inline void requireDrawable(const char* target, const scene::Scene& s) {
    if (const std::string why = whyNotDrawable(s); !why.empty()) {
        std::fprintf(stderr, "%s: the loader accepted a scene the renderer cannot draw: %s\n", target, why.c_str());
        std::abort();
    }
}

}  // namespace penumbra::fuzz
