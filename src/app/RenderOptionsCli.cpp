#include "app/RenderOptionsCli.h"

#include "shadows/ShadowTechnique.h"

#include <cstdio>
#include <map>

namespace penumbra::app {

using render::TransparencyMode;

std::string checkTechniqueName(const std::string& name) {
    return shadows::isKnownTechnique(name) ? std::string() : "unknown shadow technique '" + name + "'; known: " + shadows::knownTechniqueNames();
}

void addRenderOptions(CLI::App& command, render::RenderOptions& options, RenderCli which) {
    if (which.technique)
        command.add_option("--technique", options.technique, "shadow technique (see `penumbra techniques`)")->check(checkTechniqueName);
    if (which.shadowResolution)
        command.add_option("--shadow-res", options.shadowResolution, "shadow-map resolution for every light")
            ->check(CLI::Range(16, 16384));
    command.add_option("--anisotropy", options.anisotropy, "anisotropic filtering of textures and projector pictures, 1-16 (default 1: trilinear)")
        ->check(CLI::Range(1, 16));
    command.add_flag_callback(
        "--redraw-shadow-maps", [&options] { options.reuseStillCasters = false; },
        "redraw every shadow map every frame (default: keep what still casters drew while they and the light stay put)");
    command.add_flag_callback(
        "--refit-sun-box", [&options] { options.holdSunBox = false; },
        "fit each directional light's box to the view every frame (default: keep it while it holds the view and move "
        "it with room to spare, so that a moving camera has the sun's map drawn whole every few frames, not every frame)");
    command.add_flag_callback(
        "--whole-casters", [&options] { options.clusterCasters = false; },
        "draw big meshes whole into every shadow map they reach (default: cull their clusters per cascade, layer and cube face)");
    command.add_flag_callback(
        "--both-faces", [&options] { options.cullSolidBackFaces = false; },
        "draw both faces of closed opaque parts in the camera's opaque passes and the depth maps (default: cull back "
        "faces; the same pixels and maps but for a few silhouette texels, less raster work)");
    command.add_flag_callback(
        "--tint-everywhere", [&options] { options.tintOnlyWhereReached = false; },
        "shade every receiver with the whole coloured-shadow lookup (default: where no translucent caster's "
        "shadow can reach, a program that reads no tint, the same pixels; on glass with every other layer on one side, "
        "its own layers in front taken from its faces, not from the map: the two differ at rims, and on "
        "scenes/glass.json by up to 16/255 over the thin green box, whose own layers the whole lookup reads from the map)");
    command.add_flag_callback(
        "--light-everywhere", [&options] { options.lightOnlyWhereReached = false; },
        "shade every light on every pixel (default: where a projector or spot light's frustum cannot reach, a program "
        "that leaves that light out; the same pixels)");
    command.add_flag_callback(
        "--shadow-everywhere", [&options] { options.shadowOnlyWhereCast = false; },
        "look every light's shadow up on every pixel (default: where no other caster's shadow can fall on an opaque "
        "receiver, a program that leaves that lookup out, with the techniques that bound their lookup's reach: hard, "
        "pcf-*, pcss, distance, cssm1, cssm2, cascaded, lispsm, psm; the same pixels)");
    command.add_flag_callback(
        "--every-caster", [&options] { options.onlyCastersThatShadow = false; },
        "draw every caster whole into every light's maps (default: with the techniques that bound their lookup's reach, "
        "leave out the flat opaque ones, a ground, whose shadow can fall on no other surface, and draw a ground carrying "
        "a few still casters only around them, under suns, spots and projectors; with vsm, esm, evsm2 and evsm4 a ground "
        "only around the shadows on it and what it shadows, moving casters too, blurred and mip-mapped only there; the "
        "same pixels)");
    options.floatTarget = false;  // the front-ends' default: straight into 8-bit sRGB where the frame allows
    command.add_flag("--float-target", options.floatTarget,
                     "shade into a 32-bit float target and resolve it (fog, sRGB) in a pass of its own (default: straight "
                     "into 8-bit sRGB, fog in the lighting shader; the same picture to within rounding, ~15 ms less per "
                     "frame on llvmpipe at 1280x720)");
    command.add_flag("--depth-prepass", options.depthPrepass,
                     "draw the opaque surfaces' depth first, then shade each visible pixel once (same pixels; pays with "
                     "overdraw and dear shading, e.g. on a GPU)");
    command.add_option_function<std::vector<std::string>>(
        "--param",
        [&options](const std::vector<std::string>& texts) {
            for (const auto& text : texts) {
                try {
                    options.parameters.push_back(shadows::parseParameter(text));
                } catch (const std::invalid_argument& e) {
                    throw CLI::ValidationError("--param", e.what());
                }
            }
        },
        "technique parameter name=value (repeatable; `penumbra techniques --verbose` lists them)");
    if (which.overlay) command.add_flag("--overlay", options.debugOverlay, "draw the light-space debug maps over the frame");
    if (!which.transparency) return;
    std::map<std::string, TransparencyMode> modes;
    for (auto m : {TransparencyMode::SortedObjects, TransparencyMode::SortedTriangles, TransparencyMode::DepthPeeling,
                   TransparencyMode::DualDepthPeeling, TransparencyMode::WeightedBlended, TransparencyMode::Stochastic})
        modes[render::toString(m)] = m;
    command.add_option("--transparency", options.transparency, "camera transparency: sorted-objects | sorted-triangles | depth-peeling | dual-depth-peeling | weighted | stochastic")
        ->transform(CLI::CheckedTransformer(modes));
    command.add_option("--peel-layers", options.peelLayers, "layers kept by (dual) depth peeling (default 4)")->check(CLI::Range(1, 32));
}

render::RenderOptions splitSideOptions(const render::RenderOptions& left, const std::string& spec) {
    render::RenderOptions right = left;
    right.technique = spec.substr(0, spec.find(':'));
    if (!shadows::isKnownTechnique(right.technique))
        throw std::invalid_argument("--split: unknown shadow technique '" + right.technique + "'; known: " + shadows::knownTechniqueNames());
    try {
        right.parameters = shadows::splitTechniqueParameters(spec, ',').second;
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("--split: ") + e.what());
    }
    return right;
}

void addSceneAndSize(CLI::App& command, std::filesystem::path& scene, int& width, int& height, const char* defaultSize) {
    command.add_option("scene", scene, "scene file (.json) or model file; default: the built-in scene");
    addSize(command, width, height, defaultSize);
}

void addSize(CLI::App& command, int& width, int& height, const char* defaultSize) {
    command.add_option_function<std::string>(
        "--size",
        [&width, &height](const std::string& text) {
            int w = 0, h = 0;
            char tail = 0;
            if (std::sscanf(text.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w <= 0 || h <= 0 || w > 16384 || h > 16384)
                throw CLI::ValidationError("--size", "expected WxH within 1x1..16384x16384, e.g. 1280x720, got '" + text + "'");
            width = w;
            height = h;
        },
        std::string("image size WxH (default ") + defaultSize + ")");
}

void addEglPlatform(CLI::App& command, std::string& platform) {
    command.add_option("--egl-platform", platform, "auto | surfaceless | device | device:N (the Nth EGL device)")
        ->check(CLI::Validator(
            [](const std::string& s) -> std::string {
                if (s == "auto" || s == "surfaceless" || s == "device") return {};
                if (s.rfind("device:", 0) == 0 && s.size() > 7 && s.size() < 12 &&
                    s.find_first_not_of("0123456789", 7) == std::string::npos)
                    return {};
                return "expected auto, surfaceless, device or device:N, got '" + s + "'";
            },
            "PLATFORM"));
}

}  // namespace penumbra::app
