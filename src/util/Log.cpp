#include "util/Log.h"

#include <iostream>
#include <mutex>
#include <utility>

namespace penumbra::log {

static std::mutex g_mutex;
static std::vector<std::string> g_warnings;
static bool g_quiet = false;

void write(Level level, const std::string& message) {
    std::lock_guard lock(g_mutex);
    switch (level) {
        case Level::Info:
            if (!g_quiet) std::cerr << "penumbra: " << message << "\n";
            break;
        case Level::Warn:
            g_warnings.push_back(message);
            std::cerr << "penumbra: warning: " << message << "\n";
            break;
        case Level::Error:
            std::cerr << "penumbra: error: " << message << "\n";
            break;
        case Level::Driver:
            std::cerr << "penumbra: warning: GL: " << message << "\n";
            break;
    }
}

std::vector<std::string> takeWarnings() {
    std::lock_guard lock(g_mutex);
    return std::exchange(g_warnings, {});
}

void setQuiet(bool quiet) { g_quiet = quiet; }

}  // namespace penumbra::log
