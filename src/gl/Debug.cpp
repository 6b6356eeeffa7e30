#include "gl/Debug.h"

#include "util/Log.h"

#include <atomic>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <utility>

namespace penumbra::gl {

static std::atomic<int> g_errors{0}, g_warnings{0};
static bool g_enabled = false;
static DebugMessageHook g_hook = nullptr;
static DebugGroupHook g_groupHook = nullptr;

// A driver repeats a message every frame while its cause lasts (30,046 times in one 10 s bench run
// on an H200): each distinct message is logged this many times, then only counted, so that the log
// stays readable and printing it does not slow the frames being timed.
static constexpr int kLoggedRepeats = 3;

static void logFirstTimes(const std::string& text) {
    static std::mutex mutex;
    static std::map<std::string, int> seen;
    const std::lock_guard<std::mutex> lock(mutex);
    const int n = ++seen[text];
    if (n <= kLoggedRepeats) log::write(log::Level::Driver, text);
    if (n == kLoggedRepeats) log::write(log::Level::Driver, "(the message above repeats; further repeats are counted, not logged)");
}

static void GLAPIENTRY onMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei,
                                 const GLchar* message, const void*) {
    if (type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP || type == GL_DEBUG_TYPE_MARKER) return;
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    // Compile and link errors reach the caller as ShaderError, with file:line; not counted here.
    if (source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
    if (type == GL_DEBUG_TYPE_ERROR) {
        ++g_errors;
        logFirstTimes(log::format("error: {}", message));
        if (g_hook) g_hook(message);
        return;
    }
    if (type == GL_DEBUG_TYPE_PERFORMANCE || severity == GL_DEBUG_SEVERITY_LOW) return;
    ++g_warnings;
    logFirstTimes(message);
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
DebugMessageHook setDebugMessageHook(DebugMessageHook hook) { return std::exchange(g_hook, hook); }
void resetDebugErrorCount() { g_errors = 0; }

void checkError(const char* where) {
    const GLenum e = glGetError();
    if (e != GL_NO_ERROR) {
        ++g_errors;
        throw std::runtime_error(std::string(where) + ": GL error 0x" + std::to_string(e));
    }
}

DebugGroupHook setDebugGroupHook(DebugGroupHook hook) { return std::exchange(g_groupHook, hook); }

DebugGroup::DebugGroup(const char* name) {
    if (g_groupHook) g_groupHook(name);
    if (g_enabled) glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, name);
}
DebugGroup::~DebugGroup() {
    if (g_enabled) glPopDebugGroup();
    if (g_groupHook) g_groupHook(nullptr);
}

}  // namespace penumbra::gl
