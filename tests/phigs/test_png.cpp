// PNG files: what writePng stores reads back as the same pixels, for opaque pictures (stored as
// RGB) and translucent ones (RGBA), of any size and content; bad input is a clear error.
#include "phigs/image/Image.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include <sys/stat.h>  // mkfifo

namespace test_png {

using namespace phigs;

namespace {

std::filesystem::path scratch(const char* name) {
    const auto dir = std::filesystem::temp_directory_path() / "phigs_test_png";
    std::filesystem::create_directories(dir);
    return dir / name;
}

/// Flat areas, gradients and noise, the kinds of rows a picture has.
Image randomImage(std::mt19937& random, bool opaque) {
    const auto w = std::uniform_int_distribution<std::uint32_t>(1, 300)(random);
    const auto h = std::uniform_int_distribution<std::uint32_t>(1, 200)(random);
    Image image(w, h);
    std::uniform_int_distribution<int> byte(0, 255), kind(0, 2);
    for (std::uint32_t y = 0; y < h; ++y) {
        const int rowKind = kind(random);
        for (std::uint32_t x = 0; x < w; ++x) {
            std::uint8_t* p = &image.rgba[(std::size_t{y} * w + x) * 4];
            for (int c = 0; c < 3; ++c)
                p[c] = std::uint8_t(rowKind == 0 ? 40 * c : rowKind == 1 ? (x + c * y) & 255 : byte(random));
            p[3] = opaque ? 255 : std::uint8_t(byte(random));
        }
    }
    return image;
}

}  // namespace

TEST_CASE("png: written pictures read back pixel for pixel", "[png]") {
    std::mt19937 random(7);
    const auto file = scratch("round_trip.png");
    for (int i = 0; i < 24; ++i) {
        const bool opaque = i % 3 != 0;
        const Image image = randomImage(random, opaque);
        CAPTURE(i, image.width, image.height, opaque);
        writePng(image, file);
        const Image back = readPng(file);
        REQUIRE(back.width == image.width);
        REQUIRE(back.height == image.height);
        CHECK(back.rgba == image.rgba);
        CHECK_FALSE(std::filesystem::exists(file.string() + ".partial"));
    }
    std::filesystem::remove(file);
}

TEST_CASE("png: bad input and unwritable places are errors naming the file", "[png]") {
    Image wrong(4, 4);
    wrong.rgba.resize(10);
    CHECK_THROWS_WITH(writePng(wrong, scratch("wrong.png")), Catch::Contains("wrong.png"));
    CHECK_THROWS_WITH(writePng(Image(0, 0), scratch("empty.png")), Catch::Contains("empty"));
    CHECK_THROWS_WITH(writePng(Image(2, 2), scratch("no_such_dir") / "x.png"), Catch::Contains("x.png"));
    // A link is written through (it stays a link), a FIFO is refused rather than replaced.
    const auto target = scratch("link_target.png"), link = scratch("link.png"), fifo = scratch("fifo.png");
    std::filesystem::remove(target), std::filesystem::remove(link), std::filesystem::remove(fifo);
    std::filesystem::create_symlink(target.filename(), link);
    writePng(Image(3, 2), link);
    CHECK(std::filesystem::is_symlink(link));
    CHECK(readPng(target).width == 3);
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    CHECK_THROWS_WITH(writePng(Image(2, 2), fifo), Catch::Contains("fifo.png: is not a regular file"));
    CHECK(std::filesystem::is_fifo(fifo));
}

}  // namespace test_png
