// The vector hardcopy workstations as files: formats, vectors only (no raster image), page size
// and orientation, one page per update or a document, whole files, errors that name the file.
#include "VectorRaster.h"
#include "phigs/hardcopy/VectorWorkstation.h"
#include "phigs/ws/WorkstationType.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>

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

/// A line, a marker, a filled square and a word over a dark background, world = NPC.
DrawList sampleScene(glm::vec3 squareColour = {0, 0.8f, 1}) {
    DrawList list;
    list.views.push_back(DrawView{});
    list.background = {0.1f, 0.1f, 0.1f};
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
    for (DrawPrimitive p :
         {DrawPrimitive(square), DrawPrimitive(line), DrawPrimitive(marker), DrawPrimitive(text)}) {
        DrawItem item;
        item.primitive = std::move(p);
        list.items.push_back(std::move(item));
    }
    return list;
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

}  // namespace test_vector_files
