#pragma once
// Minimal logging with "{}" placeholders (g++ 12 ships no std::format). Warnings are also kept
// in memory so tests can assert that a fallback (checker texture, ...) was announced.
#include <functional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::log {

// Driver: a message from the GL driver (KHR_debug), printed like a warning but not recorded
// with the project's own warnings.
enum class Level { Info, Warn, Error, Driver };

void write(Level level, const std::string& message);
// Warnings recorded since the last call (and clears them).
std::vector<std::string> takeWarnings();
void setQuiet(bool quiet);  // suppress Info lines on stderr

namespace detail {
inline void format(std::ostringstream& out, std::string_view fmt) { out << fmt; }
template <class T, class... Rest>
void format(std::ostringstream& out, std::string_view fmt, const T& value, const Rest&... rest) {
    const auto pos = fmt.find("{}");
    if (pos == std::string_view::npos) {
        out << fmt;
        return;
    }
    out << fmt.substr(0, pos) << value;
    format(out, fmt.substr(pos + 2), rest...);
}
}  // namespace detail

template <class... Args>
std::string format(std::string_view fmt, const Args&... args) {
    std::ostringstream out;
    detail::format(out, fmt, args...);
    return out.str();
}

template <class... Args>
void info(std::string_view fmt, const Args&... args) { write(Level::Info, format(fmt, args...)); }
template <class... Args>
void warn(std::string_view fmt, const Args&... args) { write(Level::Warn, format(fmt, args...)); }
template <class... Args>
void error(std::string_view fmt, const Args&... args) { write(Level::Error, format(fmt, args...)); }

}  // namespace penumbra::log
