// PATTERN interiors and PHIGS PLUS transparency in the vector hardcopy: the PDF and SVG files
// tile a fill area with the pattern's cells where the placement puts them, and a transparent
// surface blends over what lies behind it.
#include "VectorRaster.h"
#include "phigs/hardcopy/VectorWorkstation.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <random>

namespace test_vector_patterns {

using namespace phigs;
using namespace phigs::hardcopy;

namespace {

constexpr std::uint32_t kPixels = 200;

std::filesystem::path outputDir() {
    const auto dir = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "hardcopy";
    std::filesystem::create_directories(dir);
    return dir;
}

std::string contents(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

PageSetup squarePage() {
    PageSetup page;
    page.paper = {double(kPixels), double(kPixels)};
    page.nominalPixel = 1.0;
    return page;
}

DrawList scene() {
    DrawList list;
    list.views.push_back(DrawView{});
    list.background = {0.1f, 0.1f, 0.1f};
    return list;
}

DrawItem square(double x0, double y0, double x1, double y1, double z, const InteriorStyleSet& interior) {
    DrawFillArea f;
    f.contours = {{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}};
    f.interior = interior;
    DrawItem item;
    item.primitive = std::move(f);
    return item;
}

const glm::vec3 kPalette[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}};

/// The page files of `list` as rasters, PDF then SVG, after checking each holds a pattern.
std::vector<Image> drawnFiles(const DrawList& list, const std::string& name, bool patterned) {
    std::vector<Image> out;
    for (VectorFormat format : {VectorFormat::Pdf, VectorFormat::Svg}) {
        const bool pdf = format == VectorFormat::Pdf;
        const auto file = outputDir() / (name + (pdf ? ".pdf" : ".svg"));
        {
            VectorWorkstation ws(file, format, squarePage());
            ws.update(list);
        }
        if (patterned && !pdf) CHECK(contents(file).find("<pattern") != std::string::npos);
        if (patterned && pdf) CHECK(contents(file).find("/PatternType 1") != std::string::npos);
        out.push_back(pdf ? vector_test::rasterisePdf(file, kPixels, kPixels)
                          : vector_test::rasteriseSvg(file, kPixels, kPixels));
    }
    return out;
}

bool near(const std::uint8_t* p, glm::vec3 rgb, int tolerance) {
    for (int k = 0; k < 3; ++k)
        if (std::abs(int(p[k]) - int(std::lround(rgb[k] * 255.0f))) > tolerance) return false;
    return true;
}

}  // namespace

TEST_CASE("vector hardcopy: PDF and SVG tile PATTERN fill areas and meshes with the placement's cells",
          "[hardcopy][pattern]") {
    std::mt19937 random(23);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 4; ++trial) {
        INFO("trial " << trial);
        DrawList list = scene();
        DrawPattern pattern;
        pattern.columns = std::uniform_int_distribution<int>(1, 4)(random);
        pattern.rows = std::uniform_int_distribution<int>(1, 4)(random);
        pattern.colours.clear();
        for (int k = 0; k < pattern.columns * pattern.rows; ++k)
            pattern.colours.push_back(kPalette[std::uniform_int_distribution<int>(0, 6)(random)]);
        list.patterns[2] = pattern;
        InteriorStyleSet interior;
        interior.style = InteriorStyle::Pattern;
        interior.styleIndex = 2;
        PatternPlacement& p = interior.pattern;
        p.referencePoint = {unit(random), unit(random), 0.0};
        const double a = 6.283185307 * unit(random), skew = 1.5708 + 0.6 * (unit(random) - 0.5);
        p.vectorX = glm::dvec3(std::cos(a), std::sin(a), 0.0) * (0.5 + unit(random));
        p.vectorY = glm::dvec3(std::cos(a + skew), std::sin(a + skew), 0.0);
        const double cell = (16.0 + 14.0 * unit(random)) / kPixels;
        p.size = {cell * pattern.columns, cell * pattern.rows};
        if (trial % 2 == 0) {
            list.items.push_back(square(0.1, 0.1, 0.9, 0.9, 0.5, interior));
        } else {
            // A mesh: each triangle is a facet of its own, its pattern fitted to it.
            auto mesh = std::make_shared<MeshData>();
            mesh->positions = {{0.1, 0.1, 0.5}, {0.9, 0.1, 0.5}, {0.9, 0.9, 0.5}, {0.1, 0.9, 0.5}};
            mesh->triangles = {0, 1, 2, 0, 2, 3};
            DrawMesh m;
            m.mesh = mesh;
            m.interior = interior;
            DrawItem item;
            item.primitive = std::move(m);
            list.items.push_back(std::move(item));
        }
        const std::vector<Image> rasters = drawnFiles(list, "pattern" + std::to_string(trial), true);
        // The cell of a page pixel, solved in the box edges (the plane is the box's own).
        const glm::dvec2 ea = glm::dvec2(glm::normalize(p.vectorX)) * p.size.x;
        const glm::dvec2 eb = glm::dvec2(glm::normalize(p.vectorY)) * p.size.y;
        const double det = ea.x * eb.y - ea.y * eb.x;
        int sampled = 0, mismatched = 0;
        for (int k = 0; k < 300; ++k) {
            const std::uint32_t px = std::uint32_t(unit(random) * kPixels);
            const std::uint32_t py = std::uint32_t(unit(random) * kPixels);
            const glm::dvec2 x((px + 0.5) / kPixels, 1.0 - (py + 0.5) / kPixels);
            if (x.x < 0.12 || x.x > 0.88 || x.y < 0.12 || x.y > 0.88) continue;
            const glm::dvec2 d = x - glm::dvec2(p.referencePoint);
            const double s = (d.x * eb.y - d.y * eb.x) / det * pattern.columns;
            const double t = (ea.x * d.y - ea.y * d.x) / det * pattern.rows;
            auto inside = [](double v) { return v - std::floor(v) > 0.2 && v - std::floor(v) < 0.8; };
            if (!inside(s) || !inside(t)) continue;
            auto wrap = [](double v, int n) { return ((int(std::floor(v)) % n) + n) % n; };
            const glm::vec3 expected =
                pattern
                    .colours[std::size_t(wrap(t, pattern.rows) * pattern.columns + wrap(s, pattern.columns))];
            ++sampled;
            for (const Image& image : rasters)
                if (!near(image.pixel(px, py), expected, 12)) ++mismatched;
        }
        CHECK(sampled > 30);
        CHECK(mismatched == 0);
    }
}

TEST_CASE("vector hardcopy: large pattern cells stay sharp to their edges in PDF and SVG",
          "[hardcopy][pattern]") {
    // Viewers smooth an SVG image however it is filtered: a cell of a few image pixels blown up
    // to 60-90 page pixels blurred into its neighbours over several pixels of its edge.
    std::mt19937 random(707);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 3; ++trial) {
        DrawList list = scene();
        DrawPattern pattern;
        pattern.columns = pattern.rows = 2;
        pattern.colours = {kPalette[0], kPalette[1], kPalette[2], kPalette[3]};
        list.patterns[2] = pattern;
        InteriorStyleSet interior;
        interior.style = InteriorStyle::Pattern;
        interior.styleIndex = 2;
        PatternPlacement& p = interior.pattern;
        p.referencePoint = {0.1, 0.1, 0.0};
        p.vectorX = {1, 0, 0};
        p.vectorY = {0, 1, 0};
        const double cell = (60.0 + 30.0 * unit(random)) / kPixels;
        p.size = {2 * cell, 2 * cell};
        list.items.push_back(square(0.1, 0.1, 0.9, 0.9, 0.5, interior));
        const std::vector<Image> rasters = drawnFiles(list, "pattern_large" + std::to_string(trial), true);
        INFO("trial " << trial << ", cell " << cell * kPixels << " pixels");
        for (std::size_t f = 0; f < rasters.size(); ++f) {
            int sampled = 0, mismatched = 0;
            for (std::uint32_t py = 0; py < kPixels; ++py)
                for (std::uint32_t px = 0; px < kPixels; ++px) {
                    const glm::dvec2 x((px + 0.5) / kPixels, 1.0 - (py + 0.5) / kPixels);
                    if (x.x < 0.11 || x.x > 0.89 || x.y < 0.11 || x.y > 0.89) continue;
                    const double s = (x.x - 0.1) / cell, t = (x.y - 0.1) / cell;
                    // A pixel and a half from a cell's edge at most: the rasteriser's own antialiasing.
                    const double margin = 1.5 / (cell * kPixels);
                    auto inside = [&](double v) {
                        return v - std::floor(v) > margin && v - std::floor(v) < 1.0 - margin;
                    };
                    if (!inside(s) || !inside(t)) continue;
                    const glm::vec3 expected =
                        pattern.colours[std::size_t((int(std::floor(t)) % 2) * 2 + int(std::floor(s)) % 2)];
                    ++sampled;
                    mismatched += !near(rasters[f].pixel(px, py), expected, 8);
                }
            INFO((f == 0 ? "PDF" : "SVG") << ": " << mismatched << " of " << sampled << " pixels blurred");
            CHECK(sampled > 20000);
            CHECK(mismatched == 0);
        }
    }
}

TEST_CASE("vector hardcopy: a transparent surface blends over the opaque one behind it",
          "[hardcopy][transparency]") {
    DrawList list = scene();
    list.hiddenSurfaceRemoval = true;
    InteriorStyleSet red, blue;
    red.style = blue.style = InteriorStyle::Solid;
    red.colour = {1, 0, 0};
    blue.colour = {0, 0, 1};
    std::mt19937 random(5);
    const float transparency = std::uniform_real_distribution<float>(0.2f, 0.8f)(random);
    blue.properties.transparency = transparency;
    // Traversal order: the see-through blue (front) first, then the opaque red behind it.
    list.items.push_back(square(0.1, 0.2, 0.9, 0.8, 0.8, blue));
    list.items.push_back(square(0.1, 0.2, 0.5, 0.8, 0.3, red));
    const float opacity = 1.0f - transparency;
    for (const Image& image : drawnFiles(list, "transparency", false)) {
        // Blue over red, and blue over the background: c = opacity * blue + (1 - opacity) * behind.
        CHECK(near(image.pixel(60, 100), glm::vec3(1.0f - opacity, 0.0f, opacity), 6));
        CHECK(near(image.pixel(140, 100),
                   glm::vec3(0.1f * (1 - opacity), 0.1f * (1 - opacity), opacity + 0.1f * (1 - opacity)), 6));
        CHECK(near(image.pixel(100, 10), glm::vec3(0.1f), 4));
    }
}

}  // namespace test_vector_patterns
