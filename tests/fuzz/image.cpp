// Fuzz target: texture and projector-image loading (PNG, JPG and whatever stb_image reads), from
// a file as scenes and OBJ materials name them, and from memory as GLB embeds them. A picture
// that cannot be used must come back as the checker fallback, never as garbage or a crash.
#include "FuzzFiles.h"

#include "scene/Image.h"

#include <cstdlib>

using namespace penumbra;

static void check(const scene::Image& img) {
    if (img.width <= 0 || img.height <= 0 || img.rgba.size() != std::size_t(img.width) * img.height * 4) std::abort();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    check(scene::imageFromMemory(data, size, "fuzz input"));
    const auto file = fuzz::writeParts(fuzz::splitParts(data, size, "texture.png"));
    check(scene::loadImageOrChecker(file, "fuzz"));
    return 0;
}
