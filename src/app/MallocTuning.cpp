#include "app/MallocTuning.h"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <limits>
#include <malloc.h>

namespace penumbra::app {

void addMallocOption(CLI::App& command, bool& tuned) {
    command
        .add_option_function<std::string>(
            "--malloc", [&tuned](const std::string& m) { tuned = m == "tuned"; },
            "tuned (default: keep llvmpipe's memory mapped, see PLATFORM.md) | default (glibc as configured)")
        ->check(CLI::IsMember({"tuned", "default"}));
}

nlohmann::json configureMalloc(bool tuned) {
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    nlohmann::json m = {{"mode", tuned ? "tuned" : "default"},
                        {"GLIBC_TUNABLES", tunables ? nlohmann::json(tunables) : nlohmann::json(nullptr)}};
    if (!tuned) return m;
    constexpr int kMmapThreshold = 32 * 1024 * 1024;  // blocks below it come from the heap, kept
    constexpr int kTopPad = 256 * 1024 * 1024;        // the heap grows in steps this large
    mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
    mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());  // never trimmed on free
    mallopt(M_TOP_PAD, kTopPad);
    m["mallopt"] = {{"M_MMAP_THRESHOLD", kMmapThreshold}, {"M_TRIM_THRESHOLD", std::numeric_limits<int>::max()},
                    {"M_TOP_PAD", kTopPad}};
    return m;
}

}  // namespace penumbra::app
