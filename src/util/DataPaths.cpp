#include "util/DataPaths.h"

#include <cstdlib>
#include <system_error>

namespace penumbra::paths {

namespace fs = std::filesystem;

// <prefix>/share/penumbra when this executable runs from <prefix>/bin and that folder holds the
// shaders; empty otherwise.
static fs::path installedRoot() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const fs::path root = exe.parent_path().parent_path() / "share" / "penumbra";
    return fs::exists(root / "shaders" / "passes" / "lighting.frag", ec) ? root : fs::path();
}

fs::path dataRoot() {
    if (const char* env = std::getenv("PENUMBRA_SHADER_DIR")) return env;
    static const fs::path installed = installedRoot();
    return installed.empty() ? fs::path(PENUMBRA_SHADER_DIR) : installed;
}

fs::path sceneDir() {
    if (const char* env = std::getenv("PENUMBRA_SCENE_DIR")) return env;
    static const fs::path installed = installedRoot();
    return installed.empty() ? fs::path(PENUMBRA_SCENE_DIR) : installed / "scenes";
}

}  // namespace penumbra::paths
