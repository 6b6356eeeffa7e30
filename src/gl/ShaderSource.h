#pragma once
// GLSL source assembled from files, before any GL call: `#include` resolution, defines and the
// #line bookkeeping that maps driver messages back to file:line. No GL here, so the resolver can
// be fuzzed and tested without a context (tests/fuzz).
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace penumbra::gl {

// A shader failed to load, preprocess, compile or link. what() names file:line.
struct ShaderError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct ProgramDesc {
    std::filesystem::path vertex, fragment, geometry, compute;  // empty = stage absent
    std::vector<std::string> defines;                           // "NAME" or "NAME VALUE"
    // `#include "name"` resolves here first: lets a caller choose which file fills a slot
    // (a shadow technique's lookup, for example).
    std::map<std::string, std::filesystem::path> includeOverrides;
};

// GLSL source assembled from files: `#include "file"` is resolved relative to the including
// file, then to the shader root; every file gets a `#line` directive with its own source
// number so driver messages can be mapped back to file:line.
class ShaderSource {
public:
    static ShaderSource load(const std::filesystem::path& file, const ProgramDesc& desc);
    const std::string& text() const { return text_; }
    // Rewrites "0:12(5): error ..." (Mesa) or "0(12) : error ..." (NVIDIA) into "file:12: ...".
    std::string translateLog(const std::string& log) const;

private:
    void append(const std::filesystem::path& file, const ProgramDesc& desc, int depth,
                const std::filesystem::path& includer, int includerLine);
    std::string text_;
    std::vector<std::filesystem::path> files_;
    std::vector<std::filesystem::path> included_;  // each file is included once (like #pragma once)
};

std::filesystem::path shaderRoot();

}  // namespace penumbra::gl
