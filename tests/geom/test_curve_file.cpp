#include "geom/CurveFile.h"
#include "geom/Evaluate.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <filesystem>
#include <sstream>
#include <string>

namespace test_curve_file {

using namespace geom;

namespace {

const std::string kSample = std::string(PHIGS_TEST_DATA_DIR) + "/curvemap/random_circle.crv";

CurveModel parse(const std::string& text) {
    std::istringstream in(text);
    return parseCurveFile(in, "bad.crv");
}

const char* const kGood =
    "CURVE INPUT FILE\n"
    "4\nTRI\nData-Points:\n0 0 0\n1 0 0\n0 1 0\n0 0 0\n"
    "Continuities:\n2\n1\n2\n2\n"
    "Constraints:\n1 -1 0\n";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
    return text;
}

}  // namespace

TEST_CASE("the ACSYNT thesis's RANDOM/CIRCLE sample file reads and interpolates", "[geom][crv]") {
    const CurveModel model = readCurveFile(kSample);
    REQUIRE(model.parts.size() == 2);
    const CurvePart& random = model.parts[0];
    CHECK(random.name == "RANDOM");
    REQUIRE(random.points.size() == 5);
    CHECK(random.points[1] == glm::dvec3(-2, 2, 0));
    CHECK(random.continuities[1] == Continuity::C0);
    CHECK(random.continuities[2] == Continuity::C1);
    REQUIRE(random.constraints.size() == 3);
    CHECK(random.constraints[2] == glm::dvec3(1, 0, 0));
    const CurvePart& circle = model.parts[1];
    CHECK(circle.name == "CIRCLE");
    CHECK(circle.constraints.empty());
    CHECK(circle.points[2] == glm::dvec3(4, 4, 0));

    // Knot counts: 5 + 6 + 2*1 + 1 and 5 + 6; control points = knots - 4.
    const Curve r = interpolatePart(random);
    const Curve c = interpolatePart(circle);
    CHECK(r.knots.size() == 14);
    CHECK(r.points.size() == 10);
    CHECK(c.knots.size() == 11);
    CHECK(c.points.size() == 7);
    // Both close, and the two look "totally different": the all-C2 one stays round (no corner).
    CHECK(glm::length(evaluate(r, r.domainEnd()) - evaluate(r, r.domainStart())) < 1e-12);
    CHECK(glm::length(evaluate(c, c.domainEnd()) - evaluate(c, c.domainStart())) < 1e-12);
    double minRadius = 1e9, maxRadius = 0;
    for (int i = 0; i <= 200; ++i) {
        const double u = c.domainStart() + (c.domainEnd() - c.domainStart()) * i / 200.0;
        const double rad = glm::length(evaluate(c, u));
        minRadius = std::min(minRadius, rad);
        maxRadius = std::max(maxRadius, rad);
    }
    CHECK(maxRadius / minRadius < 1.2);
}

TEST_CASE("curve files round-trip through the writer", "[geom][crv]") {
    CurveModel model = readCurveFile(kSample);
    model.parts[1].points[1] = {-4.1234567890123456, 4.000000000000001, 1e-300};
    const std::filesystem::path out = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "roundtrip.crv";
    writeCurveFile(out, model);
    const CurveModel back = readCurveFile(out);
    REQUIRE(back.parts.size() == 2);
    for (std::size_t p = 0; p < 2; ++p) {
        CHECK(back.parts[p].name == model.parts[p].name);
        CHECK(back.parts[p].points == model.parts[p].points);
        CHECK(back.parts[p].continuities == model.parts[p].continuities);
        CHECK(back.parts[p].constraints == model.parts[p].constraints);
    }
    model.parts[0].constraints.pop_back();
    std::ostringstream sink;
    CHECK_THROWS_WITH(writeCurveFile(sink, model), Catch::Contains("would not read back"));
    CHECK(sink.str().empty());
}

TEST_CASE("bad curve files give errors naming the file, the line and the cause", "[geom][crv]") {
    REQUIRE(parse(kGood).parts.size() == 1);
    CHECK_THROWS_WITH(parse(replaced(kGood, "CURVE INPUT FILE", "CURVE FILE")),
                      "bad.crv:1: expected the title 'CURVE INPUT FILE', found 'CURVE FILE'");
    CHECK_THROWS_WITH(parse(replaced(kGood, "Data-Points:", "Data Points:")),
                      "bad.crv:4: expected the heading 'Data-Points:' in part 'TRI', found 'Data Points:'");
    CHECK_THROWS_WITH(parse(replaced(kGood, "Continuities:", "Continuity:")),
                      Catch::StartsWith("bad.crv:9: expected the heading 'Continuities:'"));
    // A count that is too large runs into the next heading; too small leaves a point over.
    CHECK_THROWS_WITH(parse(replaced(kGood, "4\nTRI", "5\nTRI")),
                      Catch::StartsWith("bad.crv:9: part 'TRI' declares 5 data points but line 5 of them is "
                                        "'Continuities:'"));
    CHECK_THROWS_WITH(parse(replaced(kGood, "4\nTRI", "3\nTRI")),
                      Catch::StartsWith("bad.crv:7: part 'TRI' does not close"));
    CHECK_THROWS_WITH(parse(replaced(kGood, "0 1 0\n0 0 0", "0 1 0\n0 0 0.5")),
                      Catch::StartsWith("bad.crv:8: part 'TRI' does not close"));
    CHECK_THROWS_WITH(parse(replaced(kGood, "2\n1\n2\n2\n", "2\n7\n2\n2\n")),
                      Catch::StartsWith("bad.crv:11: continuity of data point 2 of part 'TRI' is 7"));
    CHECK_THROWS_WITH(
        parse(replaced(kGood, "1 -1 0\n", "None\n")),
        Catch::StartsWith("bad.crv:15: tangent constraint 1 of 1 of part 'TRI': expected three"));
    CHECK_THROWS_WITH(parse(replaced(kGood, "1 -1 0\n", "")),
                      Catch::StartsWith("bad.crv:14: the file ends where tangent constraint 1"));
    CHECK_THROWS_WITH(
        parse(replaced(kGood, "2\n1\n2\n2\n", "2\n2\n2\n2\n")),
        Catch::StartsWith("bad.crv:15: part 'TRI' has only C2 points, so its constraints must be "
                          "'None'"));
    CHECK_THROWS_WITH(parse(replaced(kGood, "0 1 0\n", "0 one 0\n")), Catch::Contains("bad.crv:7:"));
    CHECK_THROWS_WITH(parse(std::string(kGood) + "two\n"),
                      Catch::StartsWith("bad.crv:16: expected the number of data points"));
    CHECK_THROWS_WITH(parse("CURVE INPUT FILE\n"), Catch::Contains("no curve part"));
    CHECK_THROWS_WITH(readCurveFile("/nonexistent/x.crv"),
                      "/nonexistent/x.crv:0: cannot open the curve file");
    try {
        parse(replaced(kGood, "Data-Points:", "Points"));
        FAIL("no error");
    } catch (const CurveFileError& e) {
        CHECK(e.file() == "bad.crv");
        CHECK(e.line() == 4);
    }
}

}  // namespace test_curve_file
