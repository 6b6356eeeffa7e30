#pragma once
#include "gl/Object.h"

#include <filesystem>
#include <glm/glm.hpp>
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

class Program {
public:
    Program() = default;
    static Program build(const ProgramDesc& desc);

    GLuint id() const { return object_.id(); }
    void use() const { glUseProgram(id()); }
    GLint location(const char* name) const;

    void set(const char* name, int v) const;
    void set(const char* name, float v) const;
    void set(const char* name, const glm::vec2& v) const;
    void set(const char* name, const glm::ivec2& v) const;
    void set(const char* name, const glm::vec3& v) const;
    void set(const char* name, const glm::vec4& v) const;
    void set(const char* name, const glm::mat4& v) const;

private:
    Object<detail::deleteProgram> object_;
    mutable std::map<std::string, GLint, std::less<>> locations_;
};

std::filesystem::path shaderRoot();

}  // namespace penumbra::gl
