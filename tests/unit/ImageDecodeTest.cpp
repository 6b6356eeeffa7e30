// Which decoder a picture reaches (scene/Image.cpp). stb_image's JPEG decoder must never run:
// Debian 12's aborts on corrupt streams (CVE-2022-29977) and reads out of bounds on others, so
// every input stb would take for a JPEG goes to libjpeg, whose errors say "corrupt JPEG".
#include "scene/Image.h"
#include "util/Log.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace penumbra::test {
namespace {

std::vector<std::uint8_t> readBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// stb's JPEG test skips any 0xFF fill bytes before the start-of-image marker: this input, found by
// the image fuzzer, starts FF FF FF D8. It reached stb's decoder (which read out of bounds under
// ASan, "unknown marker" otherwise); libjpeg refuses it and the checker stands in.
TEST(ImageDecode, AJpegWithFillBytesBeforeItsStartGoesToLibjpeg) {
    const auto bytes = readBytes(std::filesystem::path(PENUMBRA_TEST_DATA) / "../fuzz/regressions/image/jpeg-after-fill-bytes.jpg");
    ASSERT_GT(bytes.size(), 4u);
    ASSERT_EQ(bytes[1], 0xFF);  // fill bytes before SOI
    log::takeWarnings();
    const scene::Image image = scene::imageFromMemory(bytes.data(), bytes.size(), "fill bytes");
    const auto warnings = log::takeWarnings();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("corrupt JPEG"), std::string::npos) << warnings[0];
    const scene::Image checker = scene::checkerImage();
    EXPECT_EQ(image.width, checker.width);
    EXPECT_EQ(image.rgba, checker.rgba);
}

}  // namespace
}  // namespace penumbra::test
