#include "scene/Image.h"

#include "util/Log.h"

#include <stb_image.h>

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

Image loadImageOrChecker(const std::filesystem::path& file, const std::string& referencedFrom) {
    int w = 0, h = 0, n = 0;
    stbi_uc* pixels = stbi_load(file.string().c_str(), &w, &h, &n, 4);
    if (!pixels) {
        log::warn("{}: texture '{}' cannot be read ({}); using a checker", referencedFrom, file.string(),
                  stbi_failure_reason() ? stbi_failure_reason() : "unknown reason");
        Image checker = checkerImage();
        checker.source = file.string() + " (missing: checker)";
        return checker;
    }
    return fromStb(pixels, w, h, file.string());
}

Image imageFromMemory(const std::uint8_t* data, std::size_t bytes, const std::string& label) {
    int w = 0, h = 0, n = 0;
    stbi_uc* pixels = stbi_load_from_memory(data, static_cast<int>(bytes), &w, &h, &n, 4);
    if (!pixels) {
        log::warn("embedded texture '{}' cannot be decoded; using a checker", label);
        return checkerImage();
    }
    return fromStb(pixels, w, h, label);
}

}  // namespace penumbra::scene
