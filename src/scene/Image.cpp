#include "scene/Image.h"

#include "util/Log.h"

#include <stb_image.h>

#include <filesystem>
#include <limits>

namespace penumbra::scene {

bool Image::hasTranslucentAlpha() const {
    for (std::size_t i = 3; i < rgba.size(); i += 4)
        if (rgba[i] < 255) return true;
    return false;
}

Image checkerImage(int size, int squares) {
    Image img;
    img.source = "<checker>";
    img.width = img.height = size;
    img.fallback = true;
    img.rgba.resize(static_cast<std::size_t>(size) * size * 4);
    const int cell = std::max(1, size / squares);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const bool on = ((x / cell) + (y / cell)) % 2 == 0;
            std::uint8_t* p = &img.rgba[(static_cast<std::size_t>(y) * size + x) * 4];
            p[0] = on ? 255 : 20;
            p[1] = on ? 0 : 20;
            p[2] = on ? 255 : 20;
            p[3] = 255;
        }
    return img;
}

static Image fromStb(stbi_uc* pixels, int w, int h, const std::string& label) {
    Image img;
    img.source = label;
    img.width = w;
    img.height = h;
    img.rgba.assign(pixels, pixels + static_cast<std::size_t>(w) * h * 4);
    stbi_image_free(pixels);
    return img;
}

// The largest picture decoded: 8192 x 8192 RGBA is 256 MiB. Larger ones (a 16k x 16k photo is
// 1 GiB decoded) become the checker with a warning giving the size, instead of exhausting memory.
constexpr long long kMaxImagePixels = 8192LL * 8192LL;

static std::string tooLarge(int w, int h) {
    if (w <= 0 || h <= 0) return {};
    if (static_cast<long long>(w) * h <= kMaxImagePixels && w <= 16384 && h <= 16384) return {};
    return "it is " + std::to_string(w) + "x" + std::to_string(h) +
           "; pictures are limited to 8192x8192 pixels (16384 on a side)";
}

static Image missing(const std::filesystem::path& file) {
    Image checker = checkerImage();
    checker.source = file.string() + " (missing: checker)";
    return checker;
}

Image loadImageOrChecker(const std::filesystem::path& file, const std::string& referencedFrom) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) {
        log::warn("{}: texture '{}' {}; using a checker", referencedFrom, file.string(),
                  std::filesystem::exists(file, ec) ? "is not a regular file" : "does not exist");
        return missing(file);
    }
    int w = 0, h = 0, n = 0;
    if (stbi_info(file.string().c_str(), &w, &h, &n)) {
        if (const std::string why = tooLarge(w, h); !why.empty()) {
            log::warn("{}: texture '{}' is too large ({}); using a checker", referencedFrom, file.string(), why);
            return missing(file);
        }
    }
    stbi_uc* pixels = stbi_load(file.string().c_str(), &w, &h, &n, 4);
    if (!pixels) {
        log::warn("{}: texture '{}' cannot be read ({}); using a checker", referencedFrom, file.string(),
                  stbi_failure_reason() ? stbi_failure_reason() : "unknown reason");
        return missing(file);
    }
    return fromStb(pixels, w, h, file.string());
}

Image imageFromMemory(const std::uint8_t* data, std::size_t bytes, const std::string& label) {
    int w = 0, h = 0, n = 0;
    if (bytes > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
        log::warn("embedded texture '{}' is over 2 GiB; using a checker", label);
        return checkerImage();
    }
    const int size = static_cast<int>(bytes);
    if (stbi_info_from_memory(data, size, &w, &h, &n)) {
        if (const std::string why = tooLarge(w, h); !why.empty()) {
            log::warn("embedded texture '{}' is too large ({}); using a checker", label, why);
            return checkerImage();
        }
    }
    stbi_uc* pixels = stbi_load_from_memory(data, size, &w, &h, &n, 4);
    if (!pixels) {
        log::warn("embedded texture '{}' cannot be decoded; using a checker", label);
        return checkerImage();
    }
    return fromStb(pixels, w, h, label);
}

}  // namespace penumbra::scene
