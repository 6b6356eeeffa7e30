#include "app/OutputFiles.h"

#include <fstream>
#include <stb_image_write.h>
#include <stdexcept>

namespace penumbra::app {

void writePng(const std::filesystem::path& file, int width, int height, const std::vector<std::uint8_t>& rgba) {
    if (!stbi_write_png(file.string().c_str(), width, height, 4, rgba.data(), width * 4))
        throw std::runtime_error(file.string() + ": cannot write PNG");
}

void writeJson(const std::filesystem::path& file, const nlohmann::json& document) {
    std::ofstream out(file);
    out << document.dump(2) << "\n";
    if (!out) throw std::runtime_error(file.string() + ": cannot write");
}

void createOutputDirectory(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw std::runtime_error(dir.string() + ": cannot create output directory: " + ec.message());
}

}  // namespace penumbra::app
