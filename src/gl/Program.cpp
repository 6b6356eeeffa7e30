#include "gl/Program.h"

#include <glm/gtc/type_ptr.hpp>

namespace penumbra::gl {

namespace fs = std::filesystem;

static std::uint64_t linked = 0;  // GL is driven from one thread: no atomic needed

std::uint64_t Program::linkedSoFar() { return linked; }

static GLuint compileStage(GLenum stage, const fs::path& file, const ProgramDesc& desc) {
    const ShaderSource src = ShaderSource::load(file, desc);
    const GLuint shader = glCreateShader(stage);
    const char* text = src.text().c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
        std::string log(static_cast<std::size_t>(len > 0 ? len : 1), '\0');
        glGetShaderInfoLog(shader, len, nullptr, log.data());
        glDeleteShader(shader);
        throw ShaderError("shader compile failed:\n" + src.translateLog(log.c_str()));
    }
    return shader;
}

Program Program::build(const ProgramDesc& desc) {
    std::vector<Object<detail::deleteShader>> stages;
    auto add = [&](GLenum stage, const fs::path& p) {
        if (!p.empty()) stages.emplace_back(compileStage(stage, p, desc));
    };
    add(GL_VERTEX_SHADER, desc.vertex);
    add(GL_GEOMETRY_SHADER, desc.geometry);
    add(GL_FRAGMENT_SHADER, desc.fragment);
    add(GL_COMPUTE_SHADER, desc.compute);

    Program program;
    program.object_ = Object<detail::deleteProgram>(glCreateProgram());
    for (const auto& s : stages) glAttachShader(program.id(), s.id());
    glLinkProgram(program.id());
    ++linked;
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &len);
        std::string log(static_cast<std::size_t>(len > 0 ? len : 1), '\0');
        glGetProgramInfoLog(program.id(), len, nullptr, log.data());
        throw ShaderError("program link failed (" + desc.vertex.string() + ", " +
                          desc.fragment.string() + desc.compute.string() + "):\n" + log.c_str());
    }
    for (const auto& s : stages) glDetachShader(program.id(), s.id());
    return program;
}

GLint Program::location(const char* name) const {
    if (auto it = locations_.find(name); it != locations_.end()) return it->second;
    const GLint loc = glGetUniformLocation(id(), name);
    locations_.emplace(name, loc);
    return loc;
}

// A name the program does not use (location -1) is a no-op in GL: not called at all. Materials set
// the same uniforms on every program that draws them, depth-only ones included (half the uniform
// calls of a default-scene frame were such).
void Program::set(const char* n, int v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform1i(id(), at, v);
}
void Program::set(const char* n, float v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform1f(id(), at, v);
}
void Program::set(const char* n, const glm::vec2& v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform2fv(id(), at, 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::ivec2& v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform2iv(id(), at, 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec3& v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform3fv(id(), at, 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::vec4& v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform4fv(id(), at, 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::ivec4& v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniform4iv(id(), at, 1, glm::value_ptr(v));
}
void Program::set(const char* n, const glm::mat4& v) const {
    if (const GLint at = location(n); at >= 0) glProgramUniformMatrix4fv(id(), at, 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace penumbra::gl
