#pragma once
// KHR_debug hookup: driver messages go to the log; errors are counted so tests can assert
// that a frame was clean.
#include <epoxy/gl.h>
#include <string>

namespace penumbra::gl {

void enableDebugOutput();
int debugErrorCount();
void resetDebugErrorCount();
// Driver messages of medium or high severity that are not errors (undefined behaviour,
// deprecated or non-portable use, ...); performance hints are not counted.
int debugWarningCount();
// Called for each counted error or warning (tests turn them into failures); returns the hook it
// replaces. The log shows each distinct message its first few times only; the hook sees them all.
using DebugMessageHook = void (*)(const char* message);
DebugMessageHook setDebugMessageHook(DebugMessageHook hook);
// Checks glGetError and throws std::runtime_error naming `where` if one is pending.
void checkError(const char* where);

// Called as each DebugGroup opens (with its name) and closes (with nullptr); returns the hook it
// replaces. render::SubPassClock times the groups through it.
using DebugGroupHook = void (*)(const char* openedName);
DebugGroupHook setDebugGroupHook(DebugGroupHook hook);

// RAII debug group: shows up in apitrace/RenderDoc captures and debug logs.
class DebugGroup {
public:
    explicit DebugGroup(const char* name);
    ~DebugGroup();
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

}  // namespace penumbra::gl
