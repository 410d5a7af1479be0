// The vector hardcopy workstations as files: formats, vectors only (no raster image), page size
// and orientation, one page per update or a document, whole files, errors that name the file.
#include "VectorRaster.h"
#include "phigs/hardcopy/VectorWorkstation.h"
#include "phigs/ws/WorkstationType.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>

#include <sys/stat.h>  // mkfifo

namespace test_vector_files {

using namespace phigs;
using namespace phigs::hardcopy;

namespace {

std::filesystem::path outputDir() {
    const auto dir = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "hardcopy";
    std::filesystem::create_directories(dir);
    return dir;
}

std::string contents(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// One view, world = NPC, over a dark background, the primitives drawn in order.
DrawList sceneOf(std::initializer_list<DrawPrimitive> primitives) {
    DrawList list;
    list.views.push_back(DrawView{});
    list.background = {0.1f, 0.1f, 0.1f};
    for (const DrawPrimitive& p : primitives) {
        DrawItem item;
        item.primitive = p;
        list.items.push_back(std::move(item));
    }
    return list;
}

/// A line, a marker, a filled square and a word over a dark background, world = NPC.
DrawList sampleScene(glm::vec3 squareColour = {0, 0.8f, 1}) {
    DrawFillArea square;
    square.contours = {{{0.1, 0.1, 0.5}, {0.5, 0.1, 0.5}, {0.5, 0.5, 0.5}, {0.1, 0.5, 0.5}}};
    square.interior.edit().style = InteriorStyle::Solid;
    square.interior.edit().colour = squareColour;
    DrawPolyline line;
    line.points = {{0.1, 0.8, 0.5}, {0.9, 0.9, 0.5}};
    line.style.edit().colour = {1, 1, 0};
    line.style.edit().type = LineType::Dashed;
    DrawPolymarker marker;
    marker.points = {{0.75, 0.3, 0.5}};
    marker.style.edit().type = MarkerType::Circle;
    marker.style.edit().scale = 3;
    DrawText text;
    text.text = "PHIGS";
    text.position = {0.55, 0.6, 0.5};
    text.style.edit().height = 0.08;
    return sceneOf({DrawPrimitive(square), DrawPrimitive(line), DrawPrimitive(marker), DrawPrimitive(text)});
}

PageSetup squarePage(double size) {
    PageSetup page;
    page.paper = {size, size};
    page.nominalPixel = 1.0;
    return page;
}

}  // namespace

TEST_CASE("vector hardcopy: PDF, SVG and EPS files hold vector paths and no raster image", "[hardcopy]") {
    const auto dir = outputDir();
    const DrawList list = sampleScene();
    for (VectorFormat format : {VectorFormat::Pdf, VectorFormat::Svg, VectorFormat::Eps}) {
        const auto file = dir / (std::string("sample.") + (format == VectorFormat::Pdf   ? "pdf"
                                                           : format == VectorFormat::Svg ? "svg"
                                                                                         : "eps"));
        {
            VectorWorkstation ws(file, format, squarePage(200));
            ws.update(list);
            CHECK(ws.pages() == 1);
            CHECK(ws.lastOperations() > 0);
            CHECK(ws.lastPicture().ops.empty());  // given back once cairo recorded them
        }
        REQUIRE(std::filesystem::exists(file));
        CHECK_FALSE(std::filesystem::exists(file.string() + ".tmp"));
        const std::string text = contents(file);
        INFO(file.string() << ": " << text.size() << " bytes");
        if (format == VectorFormat::Pdf) {
            CHECK(text.rfind("%PDF-", 0) == 0);
            CHECK(vector_test::pdfImageCount(file) == 0);
        } else if (format == VectorFormat::Svg) {
            CHECK(text.find("<svg") != std::string::npos);
            CHECK(text.find("<image") == std::string::npos);
        } else {
            CHECK(text.rfind("%!PS-Adobe-3.0 EPSF-3.0", 0) == 0);
            CHECK(text.find("%%BoundingBox: 0 0 200 200") != std::string::npos);
            CHECK(text.find("/ImageType") == std::string::npos);
        }
    }
    // The PDF and the SVG show the same picture: the square's colour inside it, background outside.
    const Image pdf = vector_test::rasterisePdf(dir / "sample.pdf", 200, 200);
    const Image svg = vector_test::rasteriseSvg(dir / "sample.svg", 200, 200);
    for (const Image* image : {&pdf, &svg}) {
        const std::uint8_t* inside = image->pixel(60, 140);
        CHECK(int(inside[0]) < 10);
        CHECK(std::abs(int(inside[1]) - 204) < 6);
        CHECK(int(inside[2]) > 248);
        const std::uint8_t* outside = image->pixel(150, 190);
        CHECK(std::abs(int(outside[0]) - 26) < 4);
    }
    const vector_test::Overlap same = vector_test::drawnOverlap(pdf, svg, list.background);
    CHECK(same.worst() > 0.97);
}

TEST_CASE("vector hardcopy: page size and orientation, the picture centred in the margins", "[hardcopy]") {
    const auto dir = outputDir();
    PageSetup page;
    page.paper = PageSetup::kA4;
    page.orientation = PageOrientation::Landscape;
    {
        VectorWorkstation ws(dir / "a4_landscape.pdf", VectorFormat::Pdf, page);
        ws.update(sampleScene());
    }
    CHECK(vector_test::pdfInfo(dir / "a4_landscape.pdf", "Page size").rfind("841.89 x 595.276 pts", 0) == 0);
    page.orientation = PageOrientation::Portrait;
    page.paper = PageSetup::kLetter;
    page.margin = 36;
    VectorWorkstation ws(dir / "letter_portrait.pdf", VectorFormat::Pdf, page);
    ws.update(sampleScene());
    ws.close();
    CHECK(vector_test::pdfInfo(dir / "letter_portrait.pdf", "Page size").rfind("612 x 792 pts", 0) == 0);
    // The unit display square fills the width less the margins, centred vertically.
    const PageRect& r = ws.lastPicture().backgroundRect;
    CHECK(r.min.x == Approx(36));
    CHECK(r.max.x == Approx(612 - 36));
    CHECK(r.min.y == Approx((792 - 540) / 2.0));
}

TEST_CASE("vector hardcopy: a document takes one page per update, replace keeps the last", "[hardcopy]") {
    const auto dir = outputDir();
    const glm::vec3 colours[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    std::filesystem::remove(dir / "pages.pdf");
    {
        VectorWorkstation document(dir / "pages.pdf", VectorFormat::Pdf, squarePage(100), {},
                                   PageMode::Document);
        for (const glm::vec3& c : colours) document.update(sampleScene(c));
        CHECK(document.pages() == 3);
        // Complete only once closed.
        CHECK_FALSE(std::filesystem::exists(dir / "pages.pdf"));
    }
    CHECK(vector_test::pdfInfo(dir / "pages.pdf", "Pages") == "3");
    for (int page = 1; page <= 3; ++page) {
        const Image image = vector_test::rasterisePdf(dir / "pages.pdf", 100, 100, page);
        const std::uint8_t* p = image.pixel(30, 70);
        CHECK(int(p[page - 1]) > 240);
    }
    {
        VectorWorkstation replace(dir / "replaced.pdf", VectorFormat::Pdf, squarePage(100));
        for (const glm::vec3& c : colours) replace.update(sampleScene(c));
    }
    CHECK(vector_test::pdfInfo(dir / "replaced.pdf", "Pages") == "1");
    CHECK(int(vector_test::rasterisePdf(dir / "replaced.pdf", 100, 100).pixel(30, 70)[2]) > 240);
    CHECK_THROWS_AS(VectorWorkstation(dir / "pages.svg", VectorFormat::Svg, {}, {}, PageMode::Document),
                    std::invalid_argument);
}

TEST_CASE("vector hardcopy: formats by name and type, errors name the file", "[hardcopy]") {
    CHECK(vectorFormatForFile("a/b/Picture.PDF") == VectorFormat::Pdf);
    CHECK(vectorFormatForFile("x.svg") == VectorFormat::Svg);
    CHECK(vectorFormatForFile("x.eps") == VectorFormat::Eps);
    CHECK_THROWS_WITH(vectorFormatForFile("x.png"), Catch::Contains("x.png"));
    CHECK(vectorFormatOf(WorkstationType::PdfFile) == VectorFormat::Pdf);
    CHECK(vectorFormatOf(WorkstationType::SvgFile) == VectorFormat::Svg);
    CHECK(vectorFormatOf(WorkstationType::EpsFile) == VectorFormat::Eps);
    CHECK_FALSE(vectorFormatOf(WorkstationType::Hardcopy));
    for (VectorFormat f : {VectorFormat::Pdf, VectorFormat::Svg, VectorFormat::Eps})
        CHECK(vectorFormatOf(workstationTypeOf(f)) == f);
    const WorkstationDescription pdf = describeWorkstationType(WorkstationType::PdfFile);
    CHECK(pdf.name == "PDF hardcopy");
    CHECK(pdf.category == WorkstationCategory::Output);
    CHECK(pdf.displaySize.x == Approx(841.8898));
    CHECK(describeWorkstationType(WorkstationType::EpsFile).name == "EPS hardcopy");

    const auto dir = outputDir();
    std::ofstream(dir / "not_a_directory") << "x";
    VectorWorkstation bad(dir / "not_a_directory" / "picture.pdf", VectorFormat::Pdf);
    CHECK_THROWS_WITH(bad.update(sampleScene()), Catch::Contains("not_a_directory"));
    VectorWorkstation closed(dir / "closed.svg", VectorFormat::Svg);
    closed.close();
    CHECK_THROWS_AS(closed.update(sampleScene()), std::logic_error);
}

TEST_CASE("vector hardcopy: a link is written through, a FIFO or directory refused", "[hardcopy]") {
    // The file is written beside its target and renamed over it: over a link that would replace
    // the link, over a device or FIFO swap it for a regular file.
    const auto dir = outputDir() / "targets";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "real");
    std::ofstream(dir / "real" / "old.pdf") << "old";
    std::filesystem::create_symlink("real/old.pdf", dir / "link.pdf");
    std::filesystem::create_symlink("real/new.svg", dir / "dangling.svg");
    for (const char* name : {"link.pdf", "dangling.svg"}) {
        VectorWorkstation ws(dir / name, vectorFormatForFile(name));
        ws.update(sampleScene());
        ws.close();
        INFO(name);
        CHECK(std::filesystem::is_symlink(dir / name));
    }
    CHECK(std::filesystem::file_size(dir / "real" / "old.pdf") > 100);
    CHECK(std::filesystem::file_size(dir / "real" / "new.svg") > 100);
    REQUIRE(::mkfifo((dir / "fifo.eps").c_str(), 0600) == 0);
    std::filesystem::create_directories(dir / "folder.pdf");
    for (const char* name : {"fifo.eps", "folder.pdf"}) {
        VectorWorkstation ws(dir / name, vectorFormatForFile(name));
        CHECK_THROWS_WITH(ws.update(sampleScene()),
                          Catch::Contains(name) && (Catch::Contains("is not a regular file") ||
                                                    Catch::Contains("is a directory")));
    }
    CHECK(std::filesystem::is_fifo(dir / "fifo.eps"));
    CHECK(std::filesystem::is_directory(dir / "folder.pdf"));
}

TEST_CASE("vector hardcopy: hatched holes stay empty in PDF and SVG, whichever way they wind", "[hardcopy]") {
    // Random fill area sets: a star-shaped outline and a diamond hole wound either way, hatch
    // styles 1-6. Even-odd leaves the hole empty; SVG readers took the hatch's clip path by the
    // non-zero rule (cairo writes the rule elsewhere), and hatched a hole wound like its outline.
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto dir = outputDir();
    for (int trial = 0; trial < 8; ++trial) {
        DrawFillArea set;
        std::vector<glm::dvec3> outline, hole;
        const int points = 5 + trial % 4;
        for (int k = 0; k < 2 * points; ++k) {
            const double a = 6.283185307179586 * k / (2 * points), r = k % 2 ? 0.3 + 0.05 * unit(rng) : 0.45;
            outline.push_back({0.5 + r * std::cos(a), 0.5 + r * std::sin(a), 0.5});
        }
        const double h = 0.15 + 0.05 * unit(rng);
        hole = {{0.5, 0.5 - h, 0.5}, {0.5 + h, 0.5, 0.5}, {0.5, 0.5 + h, 0.5}, {0.5 - h, 0.5, 0.5}};
        if (trial % 2) std::reverse(hole.begin(), hole.end());
        set.contours = {outline, hole};
        set.interior.edit().style = InteriorStyle::Hatch;
        set.interior.edit().styleIndex = 1 + trial % 6;
        set.interior.edit().colour = {1, 1, 1};
        const DrawList list = sceneOf({DrawPrimitive(set)});
        for (const VectorFormat format : {VectorFormat::Pdf, VectorFormat::Svg}) {
            const auto file = dir / ("hatched_hole." + std::string(vectorFormatName(format)));
            VectorWorkstation ws(file, format, squarePage(200));
            ws.update(list);
            ws.close();
            const Image picture = format == VectorFormat::Pdf ? vector_test::rasterisePdf(file, 200, 200)
                                                              : vector_test::rasteriseSvg(file, 200, 200);
            int inHole = 0, inRing = 0;
            for (std::uint32_t y = 0; y < 200; ++y)
                for (std::uint32_t x = 0; x < 200; ++x) {
                    // Page y is down; the scene is symmetric about y = 0.5, so the same test.
                    const double px = (x + 0.5) / 200.0 - 0.5, py = (y + 0.5) / 200.0 - 0.5;
                    const bool drawn = vector_test::drawn(picture, x, y, list.background, 40);
                    if (std::abs(px) + std::abs(py) < h - 0.02) inHole += drawn;
                    if (std::hypot(px, py) < 0.28 && std::abs(px) + std::abs(py) > h + 0.02) inRing += drawn;
                }
            INFO("trial " << trial << " " << vectorFormatName(format));
            CHECK(inHole == 0);
            CHECK(inRing > 100);
        }
    }
}

TEST_CASE("vector hardcopy: a transparent hatch blends as the raster's does", "[hardcopy]") {
    DrawFillArea square;
    square.contours = {{{0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}, {0.8, 0.8, 0.5}, {0.2, 0.8, 0.5}}};
    square.interior.edit().style = InteriorStyle::Hatch;
    square.interior.edit().styleIndex = 1;
    square.interior.edit().colour = {1, 1, 1};
    square.interior.edit().properties.transparency = 0.7f;
    const DrawList list = sceneOf({DrawPrimitive(square)});
    const auto file = outputDir() / "transparent_hatch.pdf";
    VectorWorkstation ws(file, VectorFormat::Pdf, squarePage(200));
    ws.update(list);
    ws.close();
    const Image picture = vector_test::rasterisePdf(file, 200, 200);
    int brightest = 0;
    for (std::uint32_t y = 0; y < 200; ++y)
        for (std::uint32_t x = 0; x < 200; ++x) brightest = std::max<int>(brightest, picture.pixel(x, y)[0]);
    // 0.3 of white over 0.7 of the background's 0.1: 94 of 255 (it was 255, opaque).
    CHECK(std::abs(brightest - 94) <= 6);
}

TEST_CASE("vector hardcopy: sizes no file can hold: no hang, no NaN in the file, a named error",
          "[hardcopy][errors]") {
    const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
    const auto dir = outputDir();
    // Markers of an infinite scale (a circle hung cairo cutting an endless arc), lines of an
    // infinite or NaN width, and a dashed line whose length along itself overflows.
    DrawList list;
    list.views.push_back(DrawView{});
    for (const MarkerType type :
         {MarkerType::Dot, MarkerType::Plus, MarkerType::Asterisk, MarkerType::Circle, MarkerType::Cross}) {
        for (const double scale : {inf, nan, 1e300, -2.0}) {
            DrawPolymarker marker;
            marker.points = {{0.5, 0.5, 0.5}};
            marker.style.edit().type = type;
            marker.style.edit().scale = float(scale);
            DrawItem item;
            item.primitive = DrawPrimitive(marker);
            list.items.push_back(std::move(item));
        }
    }
    for (const double width : {inf, nan}) {
        DrawPolyline line;
        line.points = {{0.1, 0.2, 0.5}, {0.9, 0.2, 0.5}};
        line.style.edit().type = LineType::Dashed;
        line.style.edit().width = float(width);
        DrawItem item;
        item.primitive = DrawPrimitive(line);
        list.items.push_back(std::move(item));
    }
    DrawPolyline far;
    far.points = {{-1e300, 0.5, 0.5}, {1e300, 0.5, 0.5}};
    far.style.edit().type = LineType::Dashed;
    DrawItem farItem;
    farItem.primitive = DrawPrimitive(far);
    list.items.push_back(std::move(farItem));
    for (const VectorFormat format : {VectorFormat::Pdf, VectorFormat::Svg, VectorFormat::Eps}) {
        const auto file = dir / ("unbounded." + std::string(vectorFormatName(format)));
        VectorWorkstation ws(file, format, squarePage(200));
        ws.update(list);
        ws.close();
        if (format == VectorFormat::Svg) {
            const std::string text = contents(file);
            CHECK(text.find("nan") == std::string::npos);
            CHECK(text.find("inf") == std::string::npos);
            vector_test::rasteriseSvg(file, 100, 100);  // it opens
        }
    }
    // Paper no format can hold is refused by name before a file is made.
    for (const glm::dvec2 paper :
         {glm::dvec2(0, 0), glm::dvec2(nan, 100), glm::dvec2(-100, 100), glm::dvec2(inf, 1)}) {
        PageSetup page;
        page.paper = paper;
        const auto file = dir / "no_paper.svg";
        std::filesystem::remove(file);
        VectorWorkstation ws(file, VectorFormat::Svg, page);
        REQUIRE_THROWS_WITH(ws.update(sampleScene()), Catch::Contains("paper"));
        CHECK_FALSE(std::filesystem::exists(file));
    }
    PageSetup page;
    page.nominalPixel = nan;
    VectorWorkstation ws(dir / "no_pixel.svg", VectorFormat::Svg, page);
    REQUIRE_THROWS_WITH(ws.update(sampleScene()), Catch::Contains("nominal pixel"));
}

}  // namespace test_vector_files
