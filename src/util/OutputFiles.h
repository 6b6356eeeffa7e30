#pragma once
// What the program writes for a person: PNG images and JSON documents. Each throws
// std::runtime_error naming the file when it cannot be written.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace penumbra::util {

// RGBA8 pixels, top row first.
void writePng(const std::filesystem::path& file, int width, int height, const std::vector<std::uint8_t>& rgba);
// The same PNG in memory (for pages that embed their images).
std::vector<std::uint8_t> encodePng(int width, int height, const std::vector<std::uint8_t>& rgba);
// RFC 4648 base64 of `bytes` (data: URLs).
std::string base64(const std::vector<std::uint8_t>& bytes);
// Writes `text` to `file`, throwing naming it on failure.
void writeText(const std::filesystem::path& file, const std::string& text);
void writeJson(const std::filesystem::path& file, const nlohmann::json& document);
// Creates `dir` (and its parents); throws naming it when that fails.
void createOutputDirectory(const std::filesystem::path& dir);

}  // namespace penumbra::util
