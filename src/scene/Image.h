#pragma once
// Decoded 8-bit RGBA images (stb_image). A texture that cannot be read becomes a magenta
// checker and a warning, so the problem is visible on screen and in the log.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::scene {

struct Image {
    std::string source;  // file the pixels came from ("<checker>" for the fallback)
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // row 0 = top of the picture
    bool srgb = true;                // colour data (decoded to linear on the GPU)
    bool fallback = false;
    bool hasTranslucentAlpha() const;
};

Image loadImageOrChecker(const std::filesystem::path& file, const std::string& referencedFrom);
Image checkerImage(int size = 64, int squares = 8);
Image imageFromMemory(const std::uint8_t* data, std::size_t bytes, const std::string& label);

}  // namespace penumbra::scene
