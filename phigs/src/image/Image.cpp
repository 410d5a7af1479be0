#include "phigs/image/Image.h"

#include "phigs/core/FileTarget.h"

#include <png.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace phigs {

namespace {

bool opaque(const Image& image) {
    for (std::size_t i = 3; i < image.rgba.size(); i += 4)
        if (image.rgba[i] != 255) return false;
    return true;
}

// libpng reports errors by longjmp: this function holds no C++ object that needs unwinding, and
// returns libpng's message (empty on success).
std::string encodePng(const Image& image, bool rgb, FILE* file) {
    static thread_local char message[256];
    message[0] = 0;
    png_structp png = png_create_write_struct(
        PNG_LIBPNG_VER_STRING, nullptr,
        [](png_structp p, png_const_charp text) {
            std::snprintf(message, sizeof message, "%s", text);
            png_longjmp(p, 1);
        },
        nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return "out of memory";
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return message[0] ? message : "libpng failed";
    }
    png_init_io(png, file);
    // Measured on the demo's pictures (large flat areas, 1024 x 768): zlib level 1 without row
    // filters encodes about 4x faster than libpng's defaults for files about a third larger.
    png_set_compression_level(png, 1);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(png, info, image.width, image.height, 8, rgb ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGBA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    if (rgb) png_set_filler(png, 0, PNG_FILLER_AFTER);  // drop the (all opaque) alpha bytes
    for (std::uint32_t y = 0; y < image.height; ++y)
        png_write_row(png, &image.rgba[std::size_t{y} * image.width * 4]);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return {};
}

}  // namespace

void writePng(const Image& image, const std::filesystem::path& path) {
    if (image.rgba.size() != std::size_t{image.width} * image.height * 4)
        throw std::runtime_error("writePng " + path.string() + ": pixel buffer does not match " +
                                 std::to_string(image.width) + "x" + std::to_string(image.height));
    if (image.width == 0 || image.height == 0)
        throw std::runtime_error("writePng " + path.string() + ": the image is empty");
    // Written beside the file it replaces, a link's target for a link.
    const std::filesystem::path target = replacedFile(path);
    if (const std::string why = notReplaceable(target); !why.empty())
        throw std::runtime_error("writePng " + path.string() + ": " + why);
    std::filesystem::path temp = target;
    temp += ".partial";
    FILE* file = std::fopen(temp.c_str(), "wb");
    if (!file) throw std::runtime_error("writePng " + path.string() + ": cannot open " + temp.string());
    // An opaque picture (every one a workstation draws) is stored as RGB: the same pixels, read
    // back with alpha 255.
    std::string reason = encodePng(image, opaque(image), file);
    if (std::fclose(file) != 0 && reason.empty()) reason = "writing failed";
    if (!reason.empty()) {
        std::filesystem::remove(temp);
        throw std::runtime_error("writePng " + path.string() + ": " + reason);
    }
    std::error_code ec;
    std::filesystem::rename(temp, target, ec);
    if (ec) {
        std::filesystem::remove(temp);
        throw std::runtime_error("writePng " + path.string() + ": " + ec.message());
    }
}

Image readPng(const std::filesystem::path& path) {
    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, path.c_str()))
        throw std::runtime_error("readPng " + path.string() + ": " + png.message);
    png.format = PNG_FORMAT_RGBA;
    Image image(png.width, png.height);
    if (!png_image_finish_read(&png, nullptr, image.rgba.data(), 0, nullptr)) {
        const std::string reason = png.message;
        png_image_free(&png);
        throw std::runtime_error("readPng " + path.string() + ": " + reason);
    }
    return image;
}

}  // namespace phigs
