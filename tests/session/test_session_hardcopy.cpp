// FILE > HARDCOPY and the `hardcopy NAME` directive: the session's views as PDF, SVG and EPS,
// vectors only, and (rasterised) the same picture as the screen's geometry area.
#include "SessionTestSupport.h"

#include "../support/VectorRaster.h"

#include <cmath>
#include <fstream>

namespace test_session_hardcopy {

using session_test::Driver;

namespace {

/// The screen's geometry area cut out of a screen picture.
phigs::Image crop(const phigs::Image& image, std::uint32_t x0, std::uint32_t y0, std::uint32_t width,
                  std::uint32_t height) {
    phigs::Image out(width, height);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x)
            std::copy_n(image.pixel(x0 + x, y0 + y), 4, out.pixel(x, y));
    return out;
}

/// The geometry area (less its outer frame) of a PDF hardcopy rasterised so that one screen
/// pixel is one pixel, and of the screen's picture.
std::pair<phigs::Image, phigs::Image> areaPictures(Driver& d, const std::filesystem::path& pdf) {
    const acsynt::PixelBox area = d.session.layout().geometry;
    const double shownX0 = std::max(area.x0 - 1, 0.0), shownY0 = std::max(area.y0 - 1, 0.0);
    const double shownWidth = std::min(area.x1 + 1, double(session_test::width)) - shownX0;
    const double shownHeight = std::min(area.y1 + 1, double(session_test::height)) - shownY0;
    const glm::dvec2 page{841.8898, 595.2756};  // A4 landscape, the default page
    const double pointsPerPixel = std::min(page.x / shownWidth, page.y / shownHeight);
    const auto pageWidth = std::uint32_t(std::lround(page.x / pointsPerPixel));
    const auto pageHeight = std::uint32_t(std::lround(page.y / pointsPerPixel));
    const phigs::Image printed = vector_test::rasterisePdf(pdf, pageWidth, pageHeight);
    // The page pixel of screen pixel (shownX0, shownY0), and the area less its outer frame.
    const double originX = (pageWidth - shownWidth) / 2, originY = (pageHeight - shownHeight) / 2;
    const auto x0 = std::uint32_t(std::lround(area.x0)) + 2, y0 = std::uint32_t(std::lround(area.y0)) + 2;
    const auto width = std::uint32_t(std::lround(area.x1 - area.x0)) - 4;
    const auto height = std::uint32_t(std::lround(area.y1 - area.y0)) - 4;
    const phigs::Image fromPdf = crop(printed, std::uint32_t(std::lround(originX + x0 - shownX0)),
                                      std::uint32_t(std::lround(originY + y0 - shownY0)), width, height);
    const phigs::Image fromScreen = crop(d.picture(), x0, y0, width, height);
    phigs::writePng(fromPdf, pdf.string() + ".area.png");
    phigs::writePng(fromScreen, pdf.string() + ".screen.png");
    return {fromPdf, fromScreen};
}

/// The hardcopy's geometry area and the screen's must agree within a pixel.
void requireSamePicture(Driver& d, const std::filesystem::path& pdf) {
    const auto [fromPdf, fromScreen] = areaPictures(d, pdf);
    const std::uint32_t width = fromPdf.width, height = fromPdf.height;
    const vector_test::Overlap overlap =
        vector_test::drawnOverlap(fromPdf, fromScreen, {0.02f, 0.03f, 0.08f});
    INFO(pdf.string() << ": " << overlap.drawnA << " drawn pixels in the PDF, " << overlap.drawnB
                      << " on the screen; shares " << overlap.aInB << ", " << overlap.bInA);
    CHECK(overlap.drawnB > width * height / 20);  // the model, not a blank area
    CHECK(overlap.worst() >= 0.95);
}

}  // namespace

TEST_CASE("FILE > HARDCOPY writes the four views as a vector PDF that looks like the screen") {
    Driver d("hardcopy_views");
    std::filesystem::remove_all(session_test::outputDirectory("hardcopy_views"));
    d.run({"choice FILE", "choice HARDCOPY"});
    CHECK(d.session.message() == "NO GEOMETRY FILE FOUND!");
    CHECK(d.session.hardcopies().empty());
    d.run({"choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW", "choice FOUR_VIEWS",
           "choice RETURN", "choice FILE", "choice HARDCOPY"});
    CHECK(d.session.message() == "ENTER HARDCOPY FILE NAME (.pdf, .svg, .eps)");
    d.run({"string views.pdf"});
    const auto pdf = session_test::outputDirectory("hardcopy_views") / "views.pdf";
    INFO(d.session.message());
    CHECK(d.session.message() == "PDF HARDCOPY OF FOUR VIEWS WRITTEN TO " + pdf.string());
    REQUIRE(d.session.hardcopies() == std::vector<std::filesystem::path>{pdf});
    CHECK(vector_test::pdfImageCount(pdf) == 0);
    CHECK(vector_test::pdfInfo(pdf, "Pages") == "1");
    requireSamePicture(d, pdf);
    CHECK(d.session.failedLines() == 1);  // the HARDCOPY without a model
}

/// Pixels of a clear red: in a reduction's error map, only the top of the legend's colour bar.
std::size_t redPixels(const phigs::Image& image) {
    std::size_t count = 0;
    for (std::uint32_t y = 0; y < image.height; ++y)
        for (std::uint32_t x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.pixel(x, y);
            count += p[0] > 200 && p[1] < 80 && p[2] < 80;
        }
    return count;
}

TEST_CASE("a hardcopy of the error map carries its colour legend, as the screen shows it") {
    Driver d("hardcopy_legend");
    std::filesystem::remove_all(session_test::outputDirectory("hardcopy_legend"));
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice SURF_REDN",
           "choice BY_TOLERANCE", "choice REDUCE_U&W"});
    session_test::pickOn(d, "fuselage", 0.5, 0.3);
    d.run({"string 0.01", "choice ERROR_MAP", "hardcopy legend.pdf"});
    const auto pdf = session_test::outputDirectory("hardcopy_legend") / "legend.pdf";
    REQUIRE(std::filesystem::exists(pdf));
    const auto [fromPdf, fromScreen] = areaPictures(d, pdf);
    const std::size_t onScreen = redPixels(fromScreen), onPaper = redPixels(fromPdf);
    INFO(onScreen << " red pixels on the screen, " << onPaper << " in the PDF");
    CHECK(onScreen > 20);
    CHECK(onPaper > onScreen / 2);
    CHECK(onPaper < onScreen * 2);
}

TEST_CASE("the hardcopy directive writes PDF, SVG and EPS of one view, bad names are refused") {
    Driver d("hardcopy_directive");
    const auto out = session_test::outputDirectory("hardcopy_directive");
    std::filesystem::remove_all(out);
    d.run({"choice FILE", "choice READ_MODEL", "string fighter.acm", "choice RETURN"});
    d.run({"hardcopy one.pdf", "hardcopy one.svg", "hardcopy one.eps"});
    CHECK(d.session.failedLines() == 0);
    REQUIRE(d.session.hardcopies().size() == 3);
    requireSamePicture(d, out / "one.pdf");
    std::ifstream svg(out / "one.svg");
    const std::string svgText{std::istreambuf_iterator<char>(svg), {}};
    CHECK(svgText.find("<svg") != std::string::npos);
    CHECK(svgText.find("<image") == std::string::npos);
    std::ifstream eps(out / "one.eps");
    std::string firstLine;
    std::getline(eps, firstLine);
    CHECK(firstLine.rfind("%!PS-Adobe-3.0 EPSF-3.0", 0) == 0);

    // The wireframe style prints hidden-line: its lines lie on the shaded picture.
    d.run({"choice VIEW", "choice WIREFRAME", "choice RETURN", "hardcopy lines.pdf"});
    REQUIRE(d.session.hardcopies().size() == 4);
    const phigs::Image shaded = vector_test::rasterisePdf(out / "one.pdf", 421, 298);
    const phigs::Image lines = vector_test::rasterisePdf(out / "lines.pdf", 421, 298);
    const vector_test::Overlap o = vector_test::drawnOverlap(lines, shaded, {0.02f, 0.03f, 0.08f});
    CHECK(o.aInB > 0.95);  // its lines lie on the shaded picture

    const std::size_t failed = d.session.failedLines();
    d.run({"hardcopy one.png"});
    CHECK(d.session.message().find("one.png") != std::string::npos);
    d.run({"hardcopy ../outside.pdf"});
    CHECK(d.session.message().find("MUST BE A FILE NAME INSIDE THE OUTPUT DIRECTORY") != std::string::npos);
    d.run({"hardcopy"});
    CHECK(d.session.failedLines() == failed + 3);
    CHECK_FALSE(std::filesystem::exists(out / "one.png"));
    CHECK_FALSE(std::filesystem::exists(out.parent_path() / "outside.pdf"));
    CHECK(d.session.hardcopies().size() == 4);
}

TEST_CASE("a hardcopy runs the program's hook before writing, freed screen images come back") {
    Driver d("hardcopy_hook");
    const auto out = session_test::outputDirectory("hardcopy_hook");
    std::filesystem::remove_all(out);
    d.run({"choice FILE", "choice READ_MODEL", "string fighter.acm", "choice RETURN"});
    // The geometry area: the message line below it says what the hardcopy wrote.
    const acsynt::PixelBox g = d.session.layout().geometry;
    const auto geometry = [&](const phigs::Image& screen) {
        return crop(screen, std::uint32_t(g.x0), std::uint32_t(g.y0), std::uint32_t(g.x1 - g.x0),
                    std::uint32_t(g.y1 - g.y0));
    };
    const phigs::Image before = geometry(d.picture());
    int calls = 0;
    bool writtenBefore = true;
    d.session.setBeforeHardcopy([&] {
        ++calls;
        writtenBefore = std::filesystem::exists(out / "one.pdf");
        d.display->releaseImages();
    });
    d.run({"hardcopy one.pdf"});
    CHECK(d.session.failedLines() == 0);
    CHECK(calls == 1);
    CHECK_FALSE(writtenBefore);
    CHECK(std::filesystem::exists(out / "one.pdf"));
    CHECK(geometry(d.picture()).rgba == before.rgba);
}

}  // namespace test_session_hardcopy
