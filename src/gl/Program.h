#pragma once
#include "gl/Object.h"
#include "gl/ShaderSource.h"

#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace penumbra::gl {

class Program {
public:
    Program() = default;
    static Program build(const ProgramDesc& desc);
    // Programs this process has linked so far (every build, failed ones too). A frame that links
    // one pays for the compile, which on llvmpipe runs to hundreds of milliseconds with a cold
    // shader cache: the bench repeats a measurement that did (bench/Bench.cpp).
    static std::uint64_t linkedSoFar();

    GLuint id() const { return object_.id(); }
    void use() const { glUseProgram(id()); }
    GLint location(const char* name) const;

    void set(const char* name, int v) const;
    void set(const char* name, float v) const;
    void set(const char* name, const glm::vec2& v) const;
    void set(const char* name, const glm::ivec2& v) const;
    void set(const char* name, const glm::vec3& v) const;
    void set(const char* name, const glm::vec4& v) const;
    void set(const char* name, const glm::ivec4& v) const;
    void set(const char* name, const glm::mat4& v) const;

private:
    Object<detail::deleteProgram> object_;
    mutable std::map<std::string, GLint, std::less<>> locations_;
};

}  // namespace penumbra::gl
