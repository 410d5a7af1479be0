#pragma once

// Shared by the vector hardcopy tests: PDF and SVG files rasterised by the Debian tools
// (pdftoppm of poppler-utils, rsvg-convert of librsvg2-bin), the drawn-pixel overlap of two
// pictures, and what pdfimages and pdfinfo say about a PDF.

#include "phigs/image/Image.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#ifndef PHIGS_PDFTOPPM
#define PHIGS_PDFTOPPM "pdftoppm"
#endif
#ifndef PHIGS_PDFIMAGES
#define PHIGS_PDFIMAGES "pdfimages"
#endif
#ifndef PHIGS_RSVG_CONVERT
#define PHIGS_RSVG_CONVERT "rsvg-convert"
#endif

namespace vector_test {

inline std::string quoted(const std::filesystem::path& p) {
    std::string out = "'";
    for (char c : p.string()) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

/// The standard output of a command; throws when it fails.
/// A command line from its parts, appended in place (GCC 12 warns falsely, -Warray-bounds, on
/// chains of string temporaries).
inline std::string commandLine(std::initializer_list<std::string_view> parts) {
    std::string line;
    for (std::string_view part : parts) line += part;
    return line;
}

inline std::string output(const std::string& command) {
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((command + " 2>&1").c_str(), "r"), pclose);
    if (!pipe) throw std::runtime_error("cannot run " + command);
    std::string text;
    std::array<char, 4096> buffer{};
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe.get()))
        text.append(buffer.data(), n);
    const int status = pclose(pipe.release());
    if (status != 0) throw std::runtime_error(command + " failed: " + text);
    return text;
}

/// Page `page` of a PDF as width x height pixels (anti-aliased, as a viewer shows it).
inline phigs::Image rasterisePdf(const std::filesystem::path& pdf, std::uint32_t width, std::uint32_t height,
                                 int page = 1) {
    const std::filesystem::path prefix = pdf.string() + ".raster" + std::to_string(page);
    output(commandLine({PHIGS_PDFTOPPM, " -png -singlefile -f ", std::to_string(page), " -l ",
                        std::to_string(page), " -scale-to-x ", std::to_string(width), " -scale-to-y ",
                        std::to_string(height), " ", quoted(pdf), " ", quoted(prefix)}));
    return phigs::readPng(prefix.string() + ".png");
}

/// An SVG file as width x height pixels.
inline phigs::Image rasteriseSvg(const std::filesystem::path& svg, std::uint32_t width,
                                 std::uint32_t height) {
    const std::filesystem::path png = svg.string() + ".raster.png";
    output(commandLine({PHIGS_RSVG_CONVERT, " -w ", std::to_string(width), " -h ", std::to_string(height),
                        " -o ", quoted(png), " ", quoted(svg)}));
    return phigs::readPng(png);
}

/// The raster images a PDF holds, as `pdfimages -list` counts them (its two header lines aside).
inline int pdfImageCount(const std::filesystem::path& pdf) {
    std::istringstream lines(output(commandLine({PHIGS_PDFIMAGES, " -list ", quoted(pdf)})));
    int count = 0;
    for (std::string line; std::getline(lines, line);) count += !line.empty();
    return std::max(0, count - 2);
}

/// What pdfinfo (poppler-utils, beside pdfimages) says after `key:`, trimmed.
inline std::string pdfInfo(const std::filesystem::path& pdf, const std::string& key) {
    std::filesystem::path pdfinfo = std::filesystem::path(PHIGS_PDFIMAGES).parent_path() / "pdfinfo";
    if (pdfinfo.parent_path().empty()) pdfinfo = "pdfinfo";
    std::istringstream lines(output(quoted(pdfinfo) + " " + quoted(pdf)));
    for (std::string line; std::getline(lines, line);)
        if (line.rfind(key + ":", 0) == 0) {
            const auto start = line.find_first_not_of(' ', key.size() + 1);
            return start == std::string::npos ? "" : line.substr(start);
        }
    return "";
}

/// Whether a pixel differs from the background by more than `threshold` in some channel.
inline bool drawn(const phigs::Image& image, std::uint32_t x, std::uint32_t y, glm::vec3 background,
                  int threshold) {
    const std::uint8_t* p = image.pixel(x, y);
    for (int c = 0; c < 3; ++c)
        if (std::abs(int(p[c]) - int(std::lround(background[c] * 255.0f))) > threshold) return true;
    return false;
}

/// How far two pictures of one scene agree: the share of each one's drawn pixels that have a
/// drawn pixel of the other within `tolerance` pixels (Chebyshev distance).
struct Overlap {
    std::size_t drawnA = 0, drawnB = 0;
    double aInB = 0.0, bInA = 0.0;
    double worst() const { return std::min(aInB, bInA); }
};

inline double coveredShare(const phigs::Image& a, const phigs::Image& b, glm::vec3 background, int threshold,
                           int tolerance, std::size_t& count) {
    std::size_t covered = 0;
    count = 0;
    for (std::uint32_t y = 0; y < a.height; ++y)
        for (std::uint32_t x = 0; x < a.width; ++x) {
            if (!drawn(a, x, y, background, threshold)) continue;
            ++count;
            bool found = false;
            for (int dy = -tolerance; dy <= tolerance && !found; ++dy)
                for (int dx = -tolerance; dx <= tolerance && !found; ++dx) {
                    const long u = long(x) + dx, v = long(y) + dy;
                    found = u >= 0 && v >= 0 && u < long(b.width) && v < long(b.height) &&
                            drawn(b, std::uint32_t(u), std::uint32_t(v), background, threshold);
                }
            covered += found;
        }
    return count ? double(covered) / double(count) : 1.0;
}

inline Overlap drawnOverlap(const phigs::Image& a, const phigs::Image& b, glm::vec3 background,
                            int threshold = 40, int tolerance = 1) {
    if (a.width != b.width || a.height != b.height) throw std::invalid_argument("drawnOverlap: sizes differ");
    Overlap o;
    o.aInB = coveredShare(a, b, background, threshold, tolerance, o.drawnA);
    o.bInA = coveredShare(b, a, background, threshold, tolerance, o.drawnB);
    return o;
}

}  // namespace vector_test
