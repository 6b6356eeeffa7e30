#include "app/ShaderWatcher.h"

#include <system_error>

namespace penumbra::app {

namespace fs = std::filesystem;

ShaderWatcher::ShaderWatcher(fs::path root) : root_(std::move(root)), times_(scan()) {}

ShaderWatcher::Times ShaderWatcher::scan() const {
    Times times;
    for (const char* folder : {"shaders", "src"}) {
        std::error_code ec;
        for (fs::recursive_directory_iterator it(root_ / folder, ec), end; !ec && it != end; it.increment(ec)) {
            const std::string ext = it->path().extension().string();
            if (ext != ".glsl" && ext != ".frag" && ext != ".vert" && ext != ".geom" && ext != ".h") continue;
            std::error_code timeError;
            const auto time = fs::last_write_time(it->path(), timeError);
            if (!timeError) times[it->path()] = time;
        }
    }
    return times;
}

bool ShaderWatcher::changed() {
    const auto now = std::chrono::steady_clock::now();
    if (now < nextLook_) return false;
    nextLook_ = now + std::chrono::milliseconds(500);
    Times current = scan();
    if (current == times_) return false;
    times_ = std::move(current);
    return true;
}

}  // namespace penumbra::app
