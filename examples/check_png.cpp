// The examples' tests: check_png FILE R G B MIN [--quadrants] [--shades N] counts the pixels
// within 60 of the colour (R, G, B) (0-255 each) and fails unless there are at least MIN of
// them (in each quadrant of the picture with --quadrants), and at least N distinct colours
// among them with --shades (a shaded surface, not a flat one). Not an example itself.
#include "phigs/image/Image.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <set>
#include <string>

int main(int argc, char** argv) {
    if (argc < 6) {
        std::fprintf(stderr, "usage: check_png FILE R G B MIN [--quadrants] [--shades N]\n");
        return 2;
    }
    const int rgb[3] = {std::atoi(argv[2]), std::atoi(argv[3]), std::atoi(argv[4])};
    const long minimum = std::atol(argv[5]);
    bool quadrants = false;
    std::size_t shades = 0;
    for (int i = 6; i < argc; ++i) {
        const std::string option = argv[i];
        if (option == "--quadrants")
            quadrants = true;
        else if (option == "--shades" && i + 1 < argc)
            shades = std::strtoul(argv[++i], nullptr, 10);
        else {
            std::fprintf(stderr, "check_png: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    try {
        const phigs::Image image = phigs::readPng(argv[1]);
        long counts[4] = {0, 0, 0, 0};
        std::set<int> colours;
        for (std::uint32_t y = 0; y < image.height; ++y)
            for (std::uint32_t x = 0; x < image.width; ++x) {
                const std::uint8_t* p = image.pixel(x, y);
                if (std::abs(p[0] - rgb[0]) > 60 || std::abs(p[1] - rgb[1]) > 60 ||
                    std::abs(p[2] - rgb[2]) > 60)
                    continue;
                ++counts[(x >= image.width / 2 ? 1 : 0) + (y >= image.height / 2 ? 2 : 0)];
                colours.insert(p[0] << 16 | p[1] << 8 | p[2]);
            }
        const long total = counts[0] + counts[1] + counts[2] + counts[3];
        std::printf("%s: %ld pixels near (%d, %d, %d) (quadrants %ld %ld %ld %ld), %zu shades\n", argv[1],
                    total, rgb[0], rgb[1], rgb[2], counts[0], counts[1], counts[2], counts[3],
                    colours.size());
        bool ok = total >= minimum && colours.size() >= shades;
        if (quadrants)
            for (long count : counts) ok = ok && count >= minimum;
        return ok ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "check_png: %s\n", e.what());
        return 1;
    }
}
