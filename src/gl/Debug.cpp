#include "gl/Debug.h"

#include "util/Log.h"

#include <atomic>
#include <stdexcept>

namespace penumbra::gl {

static std::atomic<int> g_errors{0};
static bool g_enabled = false;

static void GLAPIENTRY onMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei,
                                 const GLchar* message, const void*) {
    if (type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP) return;
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    if (type == GL_DEBUG_TYPE_ERROR) {
        ++g_errors;
        log::warn("GL error: {}", message);
    } else if (type != GL_DEBUG_TYPE_PERFORMANCE && type != GL_DEBUG_TYPE_OTHER) {
        log::warn("GL: {}", message);
    }
}

void enableDebugOutput() {
    if (!epoxy_has_gl_extension("GL_KHR_debug") && epoxy_gl_version() < 43) return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onMessage, nullptr);
    g_enabled = true;
}

int debugErrorCount() { return g_errors.load(); }
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
