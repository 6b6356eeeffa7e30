#pragma once
// Helpers shared by the fuzz targets. Every loader of penumbra reads files by path (a scene names
// its models and textures relative to itself), so a fuzz input is written into a scratch folder
// of this process and loaded from there, exactly as a user's file would be.
//
// One input may hold several files: it is cut at lines reading `@@file NAME` (kSeparator),
// the part before the first marker being the main file. The seed corpora are built the same way
// by make_seeds.py, so an OBJ arrives with its MTL and a GLSL file with what it includes.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace penumbra::fuzz {

inline constexpr std::string_view kSeparator = "\n@@file ";

struct NamedPart {
    std::string name;   // file name inside the scratch folder (sanitised: no '/', no "..")
    std::string bytes;
};

// Splits `data` into the main file (named mainName) and any `@@file NAME` parts after it.
std::vector<NamedPart> splitParts(const std::uint8_t* data, std::size_t size, const std::string& mainName);

// This process's scratch folder, emptied before every input (created on first use under $TMPDIR).
std::filesystem::path freshScratchFolder();

// Writes the parts into the scratch folder; returns the path of the first (main) one.
std::filesystem::path writeParts(const std::vector<NamedPart>& parts);

// Anything but penumbra::InputError / ShaderError escaping a loader is a bug the fuzzer reports:
// loaders promise a clear message or a visible fallback, never another exception.
[[noreturn]] void unexpectedException(const char* target, const std::exception& e);

}  // namespace penumbra::fuzz
