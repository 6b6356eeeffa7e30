#include "FuzzFiles.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <unistd.h>

namespace penumbra::fuzz {

namespace fs = std::filesystem;

std::vector<NamedPart> splitParts(const std::uint8_t* data, std::size_t size, const std::string& mainName) {
    const std::string_view all(reinterpret_cast<const char*>(data), size);
    std::vector<NamedPart> parts;
    std::size_t start = 0;
    std::string name = mainName;
    while (true) {
        const std::size_t marker = all.find(kSeparator, start);
        parts.push_back({name, std::string(all.substr(start, marker == std::string_view::npos ? all.npos : marker - start))});
        if (marker == std::string_view::npos || parts.size() == 8) break;
        const std::size_t nameStart = marker + kSeparator.size();
        const std::size_t nameEnd = all.find('\n', nameStart);
        std::string next(all.substr(nameStart, nameEnd == std::string_view::npos ? all.npos : nameEnd - nameStart));
        for (char& c : next)
            if (c == '/' || c == '\\' || c == '\0') c = '_';
        if (next.empty() || next == "." || next == ".." || next.size() > 64) next = "part" + std::to_string(parts.size());
        name = next;
        if (nameEnd == std::string_view::npos) { parts.push_back({name, ""}); break; }
        start = nameEnd + 1;
    }
    return parts;
}

// This process's scratch folder, created on first use and removed when the process exits. The
// exit handler is registered once the path exists, so it runs before the path is destroyed
// (registered inside the initialiser, it ran after: valgrind saw remove_all read freed memory).
static const fs::path& scratchFolder() {
    static const fs::path folder = [] {
        const char* tmp = std::getenv("TMPDIR");
        fs::path f = fs::path(tmp && *tmp ? tmp : "/tmp") / ("penumbra-fuzz-" + std::to_string(::getpid()));
        fs::create_directories(f);
        return f;
    }();
    static const bool removedAtExit = std::atexit([] {
        std::error_code ec;
        fs::remove_all(folder, ec);
    }) == 0;
    (void)removedAtExit;
    return folder;
}

fs::path freshScratchFolder() {
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(scratchFolder(), ec)) fs::remove_all(entry.path(), ec);
    return scratchFolder();
}

fs::path writeParts(const std::vector<NamedPart>& parts) {
    const fs::path folder = freshScratchFolder();
    for (const auto& part : parts) {
        std::ofstream out(folder / part.name, std::ios::binary);
        out.write(part.bytes.data(), static_cast<std::streamsize>(part.bytes.size()));
    }
    return folder / parts.front().name;
}

void unexpectedException(const char* target, const std::exception& e) {
    std::fprintf(stderr, "%s: a loader let an unexpected exception escape: %s\n", target, e.what());
    std::abort();
}

}  // namespace penumbra::fuzz
