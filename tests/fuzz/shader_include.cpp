// Fuzz target: the GLSL `#include` resolver and the driver-log translation (gl/ShaderSource).
// The input is main.glsl plus the files it may include as `@@file` parts; the resolver must
// assemble them or throw ShaderError naming file:line (missing file, cycle, nesting too deep).
#include "FuzzFiles.h"

#include "gl/ShaderSource.h"

#include <string>

using namespace penumbra;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto parts = fuzz::splitParts(data, size, "main.glsl");
    const auto file = fuzz::writeParts(parts);
    gl::ProgramDesc desc;
    desc.defines = {"PENUMBRA_FUZZ 1"};
    desc.includeOverrides["slot.glsl"] = file.parent_path() / (parts.size() > 1 ? parts[1].name : "missing.glsl");
    try {
        const gl::ShaderSource src = gl::ShaderSource::load(file, desc);
        // A driver log in either vendor's format, with the input's own text as messages.
        const std::string log = "0:1(2): error: x\n" + std::to_string(size) + "(3) : error y\n" + parts.front().bytes;
        (void)src.translateLog(log);
    } catch (const gl::ShaderError&) {
    } catch (const std::exception& e) {
        fuzz::unexpectedException("shader_include", e);
    }
    return 0;
}
