#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace phigs {

/// An 8-bit RGBA raster, rows top to bottom, as read back from a workstation or a PNG file.
struct Image {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> rgba;  ///< width * height * 4 bytes

    Image() = default;
    Image(std::uint32_t w, std::uint32_t h) : width(w), height(h), rgba(std::size_t{w} * h * 4, 0) {}

    std::uint8_t* pixel(std::uint32_t x, std::uint32_t y) { return &rgba[(std::size_t{y} * width + x) * 4]; }
    const std::uint8_t* pixel(std::uint32_t x, std::uint32_t y) const {
        return &rgba[(std::size_t{y} * width + x) * 4];
    }
};

/// Writes an image as a PNG (libpng, fast compression; RGB when every pixel is opaque, else
/// RGBA: readPng gives the same pixels back); the file appears whole or not at all (written to a
/// temporary name and renamed). Throws std::runtime_error naming the file on failure.
void writePng(const Image& image, const std::filesystem::path& path);

/// Reads any 8-bit PNG into RGBA. Throws std::runtime_error naming the file and the reason.
Image readPng(const std::filesystem::path& path);

}  // namespace phigs
