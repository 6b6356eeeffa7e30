#pragma once
// Scene description files (JSON, documented in docs/scene-format.md) and bare model files.
#include "scene/Scene.h"

#include <filesystem>
#include <string>

namespace penumbra::scene::io {

// A `.json` path is read as a scene file; anything else is imported as a model and wrapped
// with a ground plane, a sun, ambient light and a camera that frames it.
// Throws InputError naming file (and line where known) and what is wrong.
Scene loadScene(const std::filesystem::path& path);
Scene parseSceneJson(const std::string& text, const std::filesystem::path& file);
Scene wrapModel(const std::filesystem::path& modelFile);
// The built-in default scene: default.json in paths::sceneDir() (installed, or the source tree).
std::filesystem::path defaultScenePath();

}  // namespace penumbra::scene::io
