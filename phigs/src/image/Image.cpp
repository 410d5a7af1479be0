#include "phigs/image/Image.h"

#include <png.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace phigs {

void writePng(const Image& image, const std::filesystem::path& path) {
    if (image.rgba.size() != std::size_t{image.width} * image.height * 4)
        throw std::runtime_error("writePng " + path.string() + ": pixel buffer does not match " +
                                 std::to_string(image.width) + "x" + std::to_string(image.height));
    png_image png;
    std::memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    png.width = image.width;
    png.height = image.height;
    png.format = PNG_FORMAT_RGBA;
    std::filesystem::path temp = path;
    temp += ".partial";
    if (!png_image_write_to_file(&png, temp.c_str(), 0, image.rgba.data(), 0, nullptr)) {
        const std::string reason = png.message;
        std::filesystem::remove(temp);
        throw std::runtime_error("writePng " + path.string() + ": " + reason);
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
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
