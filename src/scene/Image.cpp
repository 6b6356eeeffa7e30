#include "scene/Image.h"

#include "util/Log.h"

#include <stb_image.h>

#include <csetjmp>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <vector>

#include <jpeglib.h>

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

// JPEG goes through libjpeg-turbo rather than stb_image: Debian 12's stb_image (git 2022-09-08)
// aborts the whole process on some corrupt JPEG streams (an assertion in stbi__jpeg_huff_decode,
// CVE-2022-29977, nothings/stb#1289), which penumbra's image fuzzer hit within 40,000 inputs
// (tests/fuzz/regressions/image/). libjpeg-turbo reports a corrupt stream as an error.
struct JpegDecode {
    jpeg_decompress_struct info{};
    jpeg_error_mgr errors{};
    std::jmp_buf failed{};
    char message[JMSG_LENGTH_MAX] = {};
    std::uint8_t* pixels = nullptr;  // malloc'd RGBA rows; the caller frees it
    int width = 0, height = 0;
};

// Whatever stb_image would take for a JPEG goes to libjpeg instead, so that stb's JPEG decoder
// never runs. stb's test is its marker reader: 0xFF, any number of 0xFF fill bytes, then SOI
// (0xD8). An input with fill bytes before SOI (found by the image fuzzer) reached stb's decoder,
// which read far out of bounds; libjpeg refuses it ("Not a JPEG file").
static bool isJpeg(const std::uint8_t* data, std::size_t bytes) {
    if (bytes < 2 || data[0] != 0xFF) return false;
    std::size_t i = 1;
    while (i < bytes && data[i] == 0xFF) ++i;
    return i < bytes && data[i] == 0xD8;
}

// libjpeg reports errors by calling error_exit, which must not return: it jumps back to
// decodeJpeg's setjmp. Only C state lives between the two, so no destructor is skipped.
static bool decodeJpeg(JpegDecode& job, const std::uint8_t* data, std::size_t bytes) {
    job.info.err = jpeg_std_error(&job.errors);
    job.errors.error_exit = [](j_common_ptr info) {
        auto* self = reinterpret_cast<JpegDecode*>(reinterpret_cast<char*>(info->err) - offsetof(JpegDecode, errors));
        (*info->err->format_message)(info, self->message);
        std::longjmp(self->failed, 1);
    };
    job.errors.output_message = [](j_common_ptr) {};  // recoverable corruption: decoded as far as it goes
    if (setjmp(job.failed)) {
        jpeg_destroy_decompress(&job.info);
        return false;
    }
    jpeg_create_decompress(&job.info);
    jpeg_mem_src(&job.info, data, static_cast<unsigned long>(bytes));
    jpeg_read_header(&job.info, TRUE);
    job.width = static_cast<int>(job.info.image_width);
    job.height = static_cast<int>(job.info.image_height);
    if (!tooLarge(job.width, job.height).empty()) {
        jpeg_destroy_decompress(&job.info);
        return false;  // the caller names the size
    }
    job.info.out_color_space = JCS_EXT_RGBA;
    jpeg_start_decompress(&job.info);
    const std::size_t row = static_cast<std::size_t>(job.info.output_width) * 4;
    job.pixels = static_cast<std::uint8_t*>(std::malloc(row * job.info.output_height));
    if (!job.pixels) {
        std::snprintf(job.message, sizeof job.message, "out of memory for %dx%d pixels", job.width, job.height);
        jpeg_destroy_decompress(&job.info);
        return false;
    }
    while (job.info.output_scanline < job.info.output_height) {
        JSAMPROW line = job.pixels + row * job.info.output_scanline;
        jpeg_read_scanlines(&job.info, &line, 1);
    }
    jpeg_finish_decompress(&job.info);
    jpeg_destroy_decompress(&job.info);
    return true;
}

// A picture in memory as RGBA8, or why not: too large (the checker says its size), or corrupt.
struct Decoded {
    bool ok = false;
    Image image;                       // when ok
    std::string tooLarge, unreadable;  // else why: the size, or what is wrong with the data
};
static Decoded decode(const std::uint8_t* data, std::size_t bytes, const std::string& label) {
    Decoded d;
    if (bytes > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
        d.tooLarge = "it is over 2 GiB";
        return d;
    }
    if (isJpeg(data, bytes)) {
        JpegDecode job;
        const bool ok = decodeJpeg(job, data, bytes);
        if (ok) {
            d.ok = true;
            d.image.source = label;
            d.image.width = job.width;
            d.image.height = job.height;
            d.image.rgba.assign(job.pixels, job.pixels + static_cast<std::size_t>(job.width) * job.height * 4);
        } else if (d.tooLarge = tooLarge(job.width, job.height); d.tooLarge.empty()) {
            d.unreadable = std::string("corrupt JPEG: ") + (job.message[0] ? job.message : "unknown error");
        }
        std::free(job.pixels);
        return d;
    }
    const int size = static_cast<int>(bytes);
    int w = 0, h = 0, n = 0;
    if (stbi_info_from_memory(data, size, &w, &h, &n) && !(d.tooLarge = tooLarge(w, h)).empty()) return d;
    stbi_uc* pixels = stbi_load_from_memory(data, size, &w, &h, &n, 4);
    if (!pixels) {
        // stb may fail without a reason (seen with a fuzzed PNG): never an empty message.
        const char* reason = stbi_failure_reason();
        d.unreadable = reason && *reason ? reason : "unknown reason";
        return d;
    }
    if (w <= 0 || h <= 0) {  // stb "decodes" a BMP of height 0 (found by the image fuzzer)
        stbi_image_free(pixels);
        d.unreadable = "it has no pixels (" + std::to_string(w) + "x" + std::to_string(h) + ")";
        return d;
    }
    d.ok = true;
    d.image = fromStb(pixels, w, h, label);
    return d;
}

Image loadImageOrChecker(const std::filesystem::path& file, const std::string& referencedFrom) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) {
        log::warn("{}: texture '{}' {}; using a checker", referencedFrom, file.string(),
                  std::filesystem::exists(file, ec) ? "is not a regular file" : "does not exist");
        return missing(file);
    }
    std::ifstream in(file, std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) {
        log::warn("{}: texture '{}' cannot be read; using a checker", referencedFrom, file.string());
        return missing(file);
    }
    Decoded d = decode(bytes.data(), bytes.size(), file.string());
    if (d.ok) return std::move(d.image);
    if (!d.tooLarge.empty()) {
        log::warn("{}: texture '{}' is too large ({}); using a checker", referencedFrom, file.string(), d.tooLarge);
        return missing(file);
    }
    log::warn("{}: texture '{}' cannot be read ({}); using a checker", referencedFrom, file.string(), d.unreadable);
    return missing(file);
}

Image imageFromMemory(const std::uint8_t* data, std::size_t bytes, const std::string& label) {
    Decoded d = decode(data, bytes, label);
    if (d.ok) return std::move(d.image);
    if (!d.tooLarge.empty()) {
        log::warn("embedded texture '{}' is too large ({}); using a checker", label, d.tooLarge);
        return checkerImage();
    }
    log::warn("embedded texture '{}' cannot be decoded ({}); using a checker", label, d.unreadable);
    return checkerImage();
}

}  // namespace penumbra::scene
