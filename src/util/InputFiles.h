#pragma once
// Small helpers for reading users' files.
#include <filesystem>
#include <string>

namespace penumbra::util {

// The whole file as bytes (empty if it cannot be read).
std::string readBytes(const std::filesystem::path& file);

// The extension in lower case, with its dot (".glb"), so that MODEL.GLB is a GLB too.
std::string lowerExtension(const std::filesystem::path& file);

}  // namespace penumbra::util
