#pragma once
// Live shader editing in the window: notices when a shader file under the data root (shaders/,
// the GLSL of src/ and the headers GLSL includes) is saved.
#include <chrono>
#include <filesystem>
#include <map>

namespace penumbra::app {

class ShaderWatcher {
public:
    explicit ShaderWatcher(std::filesystem::path root);
    // True once after any watched file changed, appeared or vanished; looks at the disk at most
    // twice a second.
    bool changed();

private:
    using Times = std::map<std::filesystem::path, std::filesystem::file_time_type>;
    Times scan() const;
    std::filesystem::path root_;
    Times times_;
    std::chrono::steady_clock::time_point nextLook_;
};

}  // namespace penumbra::app
