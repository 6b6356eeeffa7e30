#include "gl/Program.h"

#include "util/DataPaths.h"

#include <algorithm>
#include <fstream>
#include <glm/gtc/type_ptr.hpp>
#include <regex>
#include <sstream>

namespace penumbra::gl {

namespace fs = std::filesystem;

fs::path shaderRoot() { return paths::dataRoot(); }

static std::string readFile(const fs::path& p, const fs::path& includer, int includerLine) {
    std::ifstream in(p, std::ios::binary);
    if (!in) {
        std::string where = includer.empty() ? "" : includer.string() + ":" + std::to_string(includerLine) + ": ";
        throw ShaderError(where + "cannot open shader file '" + p.string() + "'");
    }
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

ShaderSource ShaderSource::load(const fs::path& file, const ProgramDesc& desc) {
    ShaderSource src;
    const fs::path path = file.is_absolute() ? file : shaderRoot() / file;
    src.append(path, desc, 0, {}, 0);
    return src;
}

void ShaderSource::append(const fs::path& file, const ProgramDesc& desc, int depth,
                          const fs::path& includer, int includerLine) {
    if (depth > 16) throw ShaderError(includer.string() + ":" + std::to_string(includerLine) +
                                      ": #include nested too deeply (cycle?)");
    const fs::path canonical = fs::weakly_canonical(file);
    if (std::find(included_.begin(), included_.end(), canonical) != included_.end()) return;
    included_.push_back(canonical);
    const std::string content = readFile(file, includer, includerLine);
    const int fileIndex = static_cast<int>(files_.size());
    files_.push_back(file);

    static const std::regex includeRe(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
    std::istringstream lines(content);
    std::string line;
    int lineNo = 0;
    bool versionSeen = depth > 0;
    if (depth > 0) text_ += "#line 1 " + std::to_string(fileIndex) + "\n";
    while (std::getline(lines, line)) {
        ++lineNo;
        std::smatch m;
        if (std::regex_match(line, m, includeRe)) {
            const std::string name = m[1];
            fs::path target;
            if (auto it = desc.includeOverrides.find(name); it != desc.includeOverrides.end())
                target = it->second.is_absolute() ? it->second : shaderRoot() / it->second;
            else if (fs::exists(file.parent_path() / name))
                target = file.parent_path() / name;
            else
                target = shaderRoot() / name;
            append(target, desc, depth + 1, file, lineNo);
            text_ += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(fileIndex) + "\n";
            continue;
        }
        text_ += line + "\n";
        if (!versionSeen && line.rfind("#version", 0) == 0) {
            versionSeen = true;
            for (const auto& d : desc.defines) text_ += "#define " + d + "\n";
            text_ += "#line " + std::to_string(lineNo + 1) + " " + std::to_string(fileIndex) + "\n";
        }
    }
}

std::string ShaderSource::translateLog(const std::string& log) const {
    static const std::regex mesa(R"(^(\d+):(\d+)\((\d+)\):\s*(.*)$)");
    static const std::regex nvidia(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
    std::istringstream in(log);
    std::string line, out;
    while (std::getline(in, line)) {
        std::smatch m;
        auto name = [&](const std::string& idx) {
            const std::size_t i = std::stoul(idx);
            return i < files_.size() ? files_[i].string() : "<source " + idx + ">";
        };
        if (std::regex_match(line, m, mesa))
            out += name(m[1]) + ":" + m[2].str() + ":" + m[3].str() + ": " + m[4].str() + "\n";
        else if (std::regex_match(line, m, nvidia))
            out += name(m[1]) + ":" + m[2].str() + ": " + m[3].str() + "\n";
        else if (!line.empty())
            out += line + "\n";
    }
    return out;
}

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

void Program::set(const char* n, int v) const { glProgramUniform1i(id(), location(n), v); }
void Program::set(const char* n, float v) const { glProgramUniform1f(id(), location(n), v); }
void Program::set(const char* n, const glm::vec2& v) const { glProgramUniform2fv(id(), location(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::ivec2& v) const { glProgramUniform2iv(id(), location(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::vec3& v) const { glProgramUniform3fv(id(), location(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::vec4& v) const { glProgramUniform4fv(id(), location(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::mat4& v) const {
    glProgramUniformMatrix4fv(id(), location(n), 1, GL_FALSE, glm::value_ptr(v));
}

}  // namespace penumbra::gl
