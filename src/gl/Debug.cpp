#include "gl/Debug.h"

#include "util/Log.h"

#include <atomic>
#include <stdexcept>

namespace penumbra::gl {

static std::atomic<int> g_errors{0}, g_warnings{0};
static bool g_enabled = false;
static void (*g_hook)(const char*) = nullptr;

static void GLAPIENTRY onMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei,
                                 const GLchar* message, const void*) {
    if (type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP || type == GL_DEBUG_TYPE_MARKER) return;
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    // Compile and link errors reach the caller as ShaderError, with file:line; not counted here.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    if (type == GL_DEBUG_TYPE_ERROR) {
        ++g_errors;
        log::write(log::Level::Driver, log::format("error: {}", message));
        if (g_hook) g_hook(message);
        return;
    }
    if (type == GL_DEBUG_TYPE_PERFORMANCE || severity == GL_DEBUG_SEVERITY_LOW) return;
    ++g_warnings;
    log::write(log::Level::Driver, message);
    if (g_hook) g_hook(message);
}

void enableDebugOutput() {
    if (!epoxy_has_gl_extension("GL_KHR_debug") && epoxy_gl_version() < 43) return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onMessage, nullptr);
    g_enabled = true;
}

int debugErrorCount() { return g_errors.load(); }
int debugWarningCount() { return g_warnings.load(); }
void setDebugMessageHook(void (*hook)(const char*)) { g_hook = hook; }
void resetDebugErrorCount() { g_errors = 0; }

void checkError(const char* where) {
    const GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        ++g_errors;
        throw std::runtime_error(std::string(where) + ": GL error 0x" + std::to_string(e));
    }
}

DebugGroup::DebugGroup(const char* name) {
    if (g_enabled) glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name);
}
DebugGroup::~DebugGroup() {
    if (g_enabled) glPopDebugGroup();
}

}  // namespace penumbra::gl
