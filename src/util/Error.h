#pragma once
// Bad input from a user's file: what() reads "file:line: what is wrong" (line when known).
#include <filesystem>
#include <stdexcept>
#include <string>

namespace penumbra {

struct InputError : std::runtime_error {
    InputError(const std::filesystem::path& file, int line, const std::string& what)
        : std::runtime_error(file.string() + (line > 0 ? ":" + std::to_string(line) : "") + ": " + what) {}
    InputError(const std::filesystem::path& file, const std::string& what) : InputError(file, 0, what) {}
};

}  // namespace penumbra
