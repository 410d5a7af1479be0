// The .crv reader's limits, each just below (read) and just above (refused at the line that
// breaks it, quickly and in little memory), and the other bad inputs that once misled.

#include "PeakMemory.h"
#include "geom/CurveFile.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include <sys/stat.h>  // mkfifo

namespace test_curve_file_limits {

namespace {

/// One closed part of `count` points on a circle (the last repeats the first), all C2.
std::string part(std::size_t count, const std::string& name = "ring") {
    std::ostringstream out;
    out << count << "\n" << name << "\nData-Points:\n";
    for (std::size_t i = 0; i < count; ++i) {
        const double a = 2.0 * M_PI * double(i % (count - 1)) / double(count - 1);
        out << std::cos(a) << " " << std::sin(a) << " 0\n";
    }
    out << "Continuities:\n";
    for (std::size_t i = 0; i < count; ++i) out << "2\n";
    out << "Constraints:\nNone\n";
    return out.str();
}

geom::CurveModel parse(const std::string& text) {
    std::istringstream in(text);
    return geom::parseCurveFile(in, "limits.crv");
}

/// Parses `text` expecting a refusal whose message contains `expected`, fast and small.
void requireRefused(const std::string& text, const std::string& expected) {
    const std::string message = test_support::cheapRefusal<geom::CurveFileError>([&] { parse(text); });
    INFO(message);
    CHECK(message.find(expected) != std::string::npos);
}

}  // namespace

TEST_CASE("curve file: points per part at the limit read, one more is refused at its count",
          "[curvefile][limits]") {
    const std::string title = "CURVE INPUT FILE\n";
    const geom::CurveModel model = parse(title + part(geom::kCurveFileMaxPointsPerPart));
    REQUIRE(model.parts.size() == 1);
    CHECK(model.parts[0].points.size() == geom::kCurveFileMaxPointsPerPart);
    CHECK(geom::interpolatePart(model.parts[0]).points.size() >= geom::kCurveFileMaxPointsPerPart);
    requireRefused(title + part(geom::kCurveFileMaxPointsPerPart + 1), "limits.crv:2: a part of 1001");
    // A count far beyond the data that follows allocates nothing for it.
    requireRefused(title + "999999999999\nbig\nData-Points:\n0 0 0\n", "the limit is 1000 per part");
}

TEST_CASE("curve file: points per file and parts per file at their limits", "[curvefile][limits]") {
    std::string text = "CURVE INPUT FILE\n";
    const std::size_t perPart = geom::kCurveFileMaxPoints / 10;
    for (int i = 0; i < 10; ++i) text += part(perPart, "p" + std::to_string(i));
    CHECK(parse(text).parts.size() == 10);
    requireRefused(text + part(4), "declare 10004 data points; the limit is 10000 per file");

    std::string many = "CURVE INPUT FILE\n";
    for (std::size_t i = 0; i < geom::kCurveFileMaxParts; ++i) many += part(4, "t" + std::to_string(i));
    CHECK(parse(many).parts.size() == geom::kCurveFileMaxParts);
    requireRefused(many + part(4), "more than 256 parts");
}

TEST_CASE("curve file: long lines, control characters and directories are refused by name",
          "[curvefile][limits]") {
    const std::string longest(geom::kCurveFileMaxLineLength - 1, ' ');
    CHECK(parse("CURVE INPUT FILE" + longest.substr(16) + " \n" + part(4)).parts.size() == 1);
    requireRefused("CURVE INPUT FILE\n" + std::string(geom::kCurveFileMaxLineLength + 1, 'x') + "\n",
                   "limits.crv:2: the line is longer than the limit of 1024");
    // A NUL byte is named with its column; the message is whole (nothing cut at the NUL).
    requireRefused(std::string("CURVE INPUT FILE\n4\nri") + '\0' + "ng\n",
                   "limits.crv:3: control character 0x00 at column 3");
    const auto folder = std::filesystem::temp_directory_path();
    try {
        geom::readCurveFile(folder);
        FAIL("a directory was read as a curve file");
    } catch (const geom::CurveFileError& e) {
        CHECK(std::string(e.what()).find("is a directory") != std::string::npos);
        CHECK(e.line() == 0);
    }
    // A FIFO no one writes to would block the read for ever: refused before it is opened.
    const auto fifo = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "curve_file.fifo";
    std::filesystem::create_directories(fifo.parent_path());
    std::filesystem::remove(fifo);
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    try {
        geom::readCurveFile(fifo);
        FAIL("a FIFO was read as a curve file");
    } catch (const geom::CurveFileError& e) {
        CHECK(std::string(e.what()).find("is not a regular file") != std::string::npos);
    }
    std::filesystem::remove(fifo);
}

TEST_CASE("curve file: points too far apart for a double chord are refused, not read past the knots",
          "[curvefile][limits]") {
    // Found by fuzz_crv: a chord past ~1e154 overflowed to inf and the span search ran off the knots.
    for (const char* far : {"1e200", "1e300", "1.5e154"}) {
        const std::string text = std::string("CURVE INPUT FILE\n4\nT\nData-Points:\n0 0 0\n1 0 0\n0 ") + far +
                                 " 0\n0 0 0\nContinuities:\n0\n0\n0\n0\nConstraints:\n" +
                                 "0 0 0\n0 0 0\n0 0 0\n0 0 0\n0 0 0\n0 0 0\n0 0 0\n0 0 0\n";
        INFO(far);
        // The reader refuses it at the far point's line; a part built by hand, at interpolation.
        requireRefused(text, "limits.crv:7: data point 3 of part 'T' is too far from the ones before");
        geom::CurvePart part;
        part.name = "T";
        part.points = {{0, 0, 0}, {1, 0, 0}, {0, std::stod(far), 0}, {0, 0, 0}};
        part.continuities.assign(4, geom::Continuity::C0);
        part.constraints.assign(8, glm::dvec3(0.0));
        CHECK_THROWS_WITH(geom::interpolateModel(geom::CurveModel{{part}}),
                          Catch::Contains("not a finite number above the one before"));
    }
    // A part whose name line is missing took the heading as its name.
    requireRefused("CURVE INPUT FILE\n4\nData-Points:\n0 0 0\n1 0 0\n0 1 0\n0 0 0\n",
                   "limits.crv:3: the part declared at line 2 has no name");
}

}  // namespace test_curve_file_limits
