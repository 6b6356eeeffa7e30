#pragma once
// Where penumbra's data (shaders, the GLSL of each technique, scenes) lives:
//   1. $PENUMBRA_SHADER_DIR / $PENUMBRA_SCENE_DIR when set;
//   2. an installed copy beside the executable: <prefix>/bin/penumbra -> <prefix>/share/penumbra;
//   3. the source tree the build came from (development).
#include <filesystem>

namespace penumbra::paths {

// The root that shader paths ("shaders/passes/...", "src/shadows/...") are relative to.
std::filesystem::path dataRoot();
// The folder of the built-in scenes (default.json).
std::filesystem::path sceneDir();

}  // namespace penumbra::paths
