#pragma once
// What the front-ends write for a person: PNG images and JSON documents. Each throws
// std::runtime_error naming the file when it cannot be written.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

namespace penumbra::app {

// RGBA8 pixels, top row first.
void writePng(const std::filesystem::path& file, int width, int height, const std::vector<std::uint8_t>& rgba);
void writeJson(const std::filesystem::path& file, const nlohmann::json& document);
// Creates `dir` (and its parents); throws naming it when that fails.
void createOutputDirectory(const std::filesystem::path& dir);

}  // namespace penumbra::app
