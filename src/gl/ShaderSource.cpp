#include "gl/ShaderSource.h"

#include "util/DataPaths.h"

#include <algorithm>
#include <fstream>
#include <optional>
#include <string_view>
#include <sstream>

namespace penumbra::gl {

namespace fs = std::filesystem;

fs::path shaderRoot() { return paths::dataRoot(); }

static std::string where(const fs::path& includer, int includerLine) {
    return includer.empty() ? "" : includer.string() + ":" + std::to_string(includerLine) + ": ";
}

// Shader files are small text files: anything else (a folder, a device such as /dev/zero, a
// file over 4 MiB) is refused before reading, so a bad #include cannot hang or exhaust memory.
static std::string readFile(const fs::path& p, const fs::path& includer, int includerLine) {
    constexpr std::uintmax_t kMaxShaderBytes = 4u << 20;
    std::error_code ec;
    if (!fs::is_regular_file(p, ec))
        throw ShaderError(where(includer, includerLine) + "cannot open shader file '" + p.string() + "'" +
                          (fs::exists(p, ec) ? " (not a regular file)" : ""));
    if (fs::file_size(p, ec) > kMaxShaderBytes)
        throw ShaderError(where(includer, includerLine) + "shader file '" + p.string() + "' is over 4 MiB");
    std::ifstream in(p, std::ios::binary);
    if (!in) throw ShaderError(where(includer, includerLine) + "cannot open shader file '" + p.string() + "'");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// `#include "name"` with optional blanks around '#' and the keyword: returns name, or nothing.
// Hand-parsed: std::regex recurses per character and overflows the stack on long lines.
static std::optional<std::string> includedName(std::string_view line) {
    auto skipBlanks = [&] { while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1); };
    skipBlanks();
    if (line.empty() || line.front() != '#') return std::nullopt;
    line.remove_prefix(1);
    skipBlanks();
    if (line.substr(0, 7) != "include") return std::nullopt;
    line.remove_prefix(7);
    if (line.empty() || (line.front() != ' ' && line.front() != '\t')) return std::nullopt;
    skipBlanks();
    if (line.empty() || line.front() != '"') return std::nullopt;
    const std::size_t close = line.find('"', 1);
    if (close == std::string_view::npos || close == 1) return std::nullopt;
    std::string_view rest = line.substr(close + 1);
    while (!rest.empty() && (rest.back() == ' ' || rest.back() == '\t' || rest.back() == '\r')) rest.remove_suffix(1);
    if (!rest.empty()) return std::nullopt;
    return std::string(line.substr(1, close - 1));
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
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(file, ec);
    if (ec) throw ShaderError(where(includer, includerLine) + "cannot open shader file '" + file.string() + "': " + ec.message());
    if (std::find(included_.begin(), included_.end(), canonical) != included_.end()) return;
    included_.push_back(canonical);
    const std::string content = readFile(file, includer, includerLine);
    const int fileIndex = static_cast<int>(files_.size());
    files_.push_back(file);

    std::istringstream lines(content);
    std::string line;
    int lineNo = 0;
    bool versionSeen = depth > 0;
    if (depth > 0) text_ += "#line 1 " + std::to_string(fileIndex) + "\n";
    while (std::getline(lines, line)) {
        ++lineNo;
        if (const auto included = includedName(line)) {
            const std::string& name = *included;
            fs::path target;
            if (auto it = desc.includeOverrides.find(name); it != desc.includeOverrides.end())
                target = it->second.is_absolute() ? it->second : shaderRoot() / it->second;
            else if (fs::exists(file.parent_path() / name, ec))
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

// Leading decimal digits of `s` (consumed), or nothing.
static std::optional<std::string_view> digits(std::string_view& s) {
    std::size_t n = 0;
    while (n < s.size() && s[n] >= '0' && s[n] <= '9') ++n;
    if (n == 0) return std::nullopt;
    const std::string_view d = s.substr(0, n);
    s.remove_prefix(n);
    return d;
}

static bool consume(std::string_view& s, char c) {
    if (s.empty() || s.front() != c) return false;
    s.remove_prefix(1);
    return true;
}

static std::string_view trimLeft(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    return s;
}

std::string ShaderSource::translateLog(const std::string& log) const {
    auto name = [&](std::string_view index) {
        // A source number past our files (or too long to be one) is printed as it came.
        if (index.size() < 6) {
            const std::size_t i = std::stoul(std::string(index));
            if (i < files_.size()) return files_[i].string();
        }
        return "<source " + std::string(index) + ">";
    };
    std::istringstream in(log);
    std::string line, out;
    while (std::getline(in, line)) {
        std::string_view s = line;
        const auto file = digits(s);
        std::string_view rest = s;
        if (file && consume(rest, ':')) {  // Mesa: "0:12(5): error ..."
            const auto lineNo = digits(rest);
            if (lineNo && consume(rest, '(')) {
                if (auto c = digits(rest); c && consume(rest, ')') && consume(rest, ':')) {
                    out += name(*file) + ":" + std::string(*lineNo) + ":" + std::string(*c) + ": " +
                           std::string(trimLeft(rest)) + "\n";
                    continue;
                }
            }
        }
        rest = s;
        if (file && consume(rest, '(')) {  // NVIDIA: "0(12) : error ..."
            if (auto lineNo = digits(rest); lineNo && consume(rest, ')')) {
                rest = trimLeft(rest);
                if (consume(rest, ':')) {
                    out += name(*file) + ":" + std::string(*lineNo) + ": " + std::string(trimLeft(rest)) + "\n";
                    continue;
                }
            }
        }
        if (!line.empty()) out += line + "\n";
    }
    return out;
}

}  // namespace penumbra::gl
