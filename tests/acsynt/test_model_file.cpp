#include "acsynt/Model.h"
#include "acsynt/ModelFile.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>

namespace test_model_file {

using namespace acsynt;

namespace {

const char* const goodFile = R"(# a small test model
acsynt-model 1
model tiny

component fuselage body
  colour 0.5 0.5 0.5
  points 8
  sections 4
  station nose 0 0 0 0 0 2
  station mid 1 0.5 0.5 0.4 0 2
  station mid 3 0.5 0.5 0.4 0 2.5
  station aft 4 0.2 0.2 0.2 0.1 2
end

component wing wing_r
  points 9
  sections 4
  mirror wing_l
  airfoil 2412 0012
  position 1.2 0.4 0
  root_chord 1.5
  taper 0.5
  span 2
  sweep 20
  dihedral 4
  twist -2
end

component nacelle pod
  points 8
  sections 4
  position 1 1 -0.5
  profile 0 0.2
  profile 0.3 0.25
  profile 0.8 0.25
  profile 1.0 0.15
end
)";

/// The good file with line `line` (1-based) replaced by `text`.
std::string withLine(int line, const std::string& text) {
    std::istringstream in(goodFile);
    std::string out, l;
    for (int n = 1; std::getline(in, l); ++n) out += (n == line ? text : l) + "\n";
    return out;
}

/// Parses and builds `text`; returns the error, failing the test if there was none.
ModelFileError errorOf(const std::string& text) {
    try {
        std::istringstream in(text);
        buildModel(parseAircraftDescription(in, "bad.acm"), "bad.acm");
    } catch (const ModelFileError& e) {
        return e;
    }
    FAIL("no ModelFileError for:\n" << text);
    return ModelFileError("", 0, "");
}

void checkError(const std::string& text, int line, const std::string& reasonPart) {
    const ModelFileError e = errorOf(text);
    INFO(e.what());
    REQUIRE(e.file() == "bad.acm");
    REQUIRE(e.line() == line);
    REQUIRE(std::string(e.what()).rfind("bad.acm:" + std::to_string(line) + ": ", 0) == 0);
    REQUIRE(e.reason().find(reasonPart) != std::string::npos);
}

}  // namespace

TEST_CASE("a good description is read with all its values", "[acsynt][file]") {
    std::istringstream in(goodFile);
    const AircraftDescription d = parseAircraftDescription(in, "good.acm");
    REQUIRE(d.name == "tiny");
    REQUIRE(d.components.size() == 3);
    const auto& body = std::get<FuselageShape>(d.components[0].shape);
    REQUIRE(body.stations.size() == 4);
    REQUIRE(body.stations[2].exponent == 2.5);
    REQUIRE(body.stations[3].part == FuselagePart::Afterbody);
    const auto& wing = std::get<LiftingSurfaceShape>(d.components[1].shape);
    REQUIRE(d.components[1].mirrorName == "wing_l");
    REQUIRE(wing.tipAirfoil.code == "0012");
    REQUIRE(wing.twist == -2.0);
    REQUIRE(wing.incidence == 0.0);
    REQUIRE(d.components[1].colour == glm::dvec3(1.0));
    REQUIRE(std::get<NacelleShape>(d.components[2].shape).profile[1].radius == 0.25);
    const Model m = buildModel(d);
    REQUIRE(m.components.size() == 4);
    REQUIRE(m.components[2].name == "wing_l");
}

TEST_CASE("a written description reads back to the same model", "[acsynt][file]") {
    std::istringstream in(goodFile);
    const AircraftDescription d = parseAircraftDescription(in, "good.acm");
    std::ostringstream out;
    writeAircraftDescription(out, d);
    std::istringstream back(out.str());
    const AircraftDescription e = parseAircraftDescription(back, "written.acm");
    const Model a = buildModel(d), b = buildModel(e);
    REQUIRE(a.components.size() == b.components.size());
    for (std::size_t i = 0; i < a.components.size(); ++i) {
        REQUIRE(a.components[i].name == b.components[i].name);
        REQUIRE(a.components[i].colour == b.components[i].colour);
        REQUIRE(a.components[i].sections.points == b.components[i].sections.points);
        REQUIRE(a.components[i].surface.points == b.components[i].surface.points);
    }
}

TEST_CASE("lines end at LF, CR LF or a lone CR, mixed in one file", "[acsynt][file]") {
    std::istringstream mixed("a\rb\r\nc\n\r\nd");
    std::vector<std::string> lines;
    for (std::string line; readTextLine(mixed, line);) lines.push_back(line);
    REQUIRE(lines == std::vector<std::string>{"a", "b", "c", "", "d"});
    // A byte-order mark (as Windows editors write) was read as text: "found '\xEF\xBB\xBF'".
    std::string withMark = "\xEF\xBB\xBF";
    withMark.append(goodFile);
    std::istringstream marked(withMark);
    CHECK(buildModel(parseAircraftDescription(marked, "marked.acm")).components.size() == 4);
    // A description written on any system reads the same, and its faults keep their line numbers.
    auto withEnds = [](std::string text, const std::string& end) {
        for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + end.size()))
            text.replace(at, 1, end);
        return text;
    };
    for (const std::string end : {"\r\n", "\r"}) {
        std::istringstream in(withEnds(goodFile, end));
        const Model m = buildModel(parseAircraftDescription(in, "other.acm"));
        REQUIRE(m.components.size() == 4);
        REQUIRE(m.components[2].name == "wing_l");
        const ModelFileError e = errorOf(withEnds(withLine(11, "  station mid 3 0.5 0.5 0.4 0 2.5 7"), end));
        CHECK(e.line() == 11);
        CHECK(e.reason().find("unexpected '7'") != std::string::npos);
    }
}

TEST_CASE("every fault in a description names the file, the line and the reason", "[acsynt][file]") {
    checkError(withLine(11, "  station mid 3 0.5 0.5 0.4 0 2.5 7"), 11, "unexpected '7'");
    checkError(withLine(11, "  station mid 0.5 0.5 0.5 0.4 0 2.5"), 11, "does not increase");
    checkError(withLine(11, "  station mid 1 0.5 0.5 0.4 0 2.5"), 11, "does not increase");
    checkError(withLine(11, "  station nose 3 0.5 0.5 0.4 0 2.5"), 11, "comes after a later part");
    checkError(withLine(11, "  station mid 3 nan 0.5 0.4 0 2.5"), 11, "not a finite number");
    checkError(withLine(11, "  station mid 3 0.5 inf 0.4 0 2.5"), 11, "not a finite number");
    checkError(withLine(11, "  station mid 3 0.5 0.5x 0.4 0 2.5"), 11, "not a number");
    checkError(withLine(11, "  station mid 3 0.5 0.5"), 11, "missing value");
    checkError(withLine(11, "  station mid 3 0 0 0 0 2"), 11, "only the first and last");
    checkError(withLine(11, "  station mid 3 0.5 0 0.4 0 2"), 11, "all be positive");
    checkError(withLine(11, "  wingspan 3"), 11, "unknown keyword 'wingspan'");
    checkError(withLine(7, "  points 8 9"), 7, "unexpected '9'");
    checkError(withLine(7, "  points"), 7, "missing value");
    checkError(withLine(7, "  points 3"), 7, "4 to");
    checkError(withLine(7, "  points 8.5"), 7, "not a whole number");
    checkError(withLine(7, "  points 1000000000000"), 7,
               "'1000000000000' is out of range (-2147483648 to 2147483647)");
    checkError(withLine(8, "  sections 5"), 13, "declares 5 sections but lists 4 stations");
    checkError(withLine(8, "  sections 3"), 8, "4 to");
    checkError(withLine(8, "  # no sections"), 13, "lacks 'sections'");
    checkError(withLine(6, "  colour 0.5 1.5 0.5"), 6, "outside [0, 1]");
    checkError(withLine(5, "component blimp body"), 5, "unknown component kind 'blimp'");
    checkError(withLine(5, "component fuselage a_name_longer_than_twenty"), 5, "1 to 20");
    checkError(withLine(13, ""), 15, "not closed with 'end'");
    checkError(withLine(1, "acsynt-model 2"), 1, "version 2 is not supported");
    checkError(withLine(1, "model tiny"), 1, "must start with 'acsynt-model 1'");
    checkError(withLine(3, "model"), 3, "missing value");
    checkError(withLine(16, "  points 8"), 16, "odd number");
    checkError(withLine(19, "  airfoil 2412 12"), 19, "exactly 4 digits");
    checkError(withLine(19, "  airfoil 2400"), 19, "zero thickness");
    checkError(withLine(19, "  # no airfoil"), 27, "lacks 'airfoil'");
    checkError(withLine(18, "  mirror body"), 15, "'body' is used twice");
    checkError(withLine(18, "  mirror wing_r"), 18, "a name of its own");
    checkError(withLine(22, "  span 0"), 22, "span must be positive");
    checkError(withLine(23, "  sweep 85"), 23, "outside [-80, 80]");
    checkError(withLine(24, "  span 2"), 24, "'span' is given twice");
    checkError(withLine(35, "  profile 0.2 0.25"), 35, "does not increase");
    checkError(withLine(35, "  profile 0.3 -0.25"), 35, "outside");
    checkError(withLine(35, "  profile 0.5 0"), 35, "radius 0");
    checkError(withLine(33, "  mirror"), 33, "missing value");
    checkError(std::string(goodFile).substr(0, std::string(goodFile).rfind("end")), 36, "missing 'end'");
    checkError("", 0, "empty");
    checkError("acsynt-model 1\nmodel empty\n", 2, "no components");
    checkError("acsynt-model 1\ncomponent wing w\n", 2, "'model NAME' must come before");
}

TEST_CASE("a file that cannot be opened is an error naming it", "[acsynt][file]") {
    try {
        readAircraftDescription("/nonexistent/plane.acm");
        FAIL("no error");
    } catch (const ModelFileError& e) {
        REQUIRE(e.file() == "/nonexistent/plane.acm");
        REQUIRE(e.reason() == "cannot open the file");
    }
}

TEST_CASE("damaged files give a ModelFileError or a whole model, never anything else", "[acsynt][file]") {
    std::ifstream file(ACSYNT_DATA_DIR "/transport.acm");
    std::vector<std::string> lines;
    for (std::string l; std::getline(file, l);) lines.push_back(l);
    REQUIRE(lines.size() > 50);
    const std::vector<std::string> replacements{"",
                                                "end",
                                                "component wing x",
                                                "  points 1e400",
                                                "  sections -4",
                                                "  station mid 1 1 1 1 1 nan",
                                                "  profile 99 1",
                                                "  mirror fin"};
    int errors = 0, models = 0;
    auto attempt = [&](const std::string& text) {
        std::istringstream in(text);
        try {
            const Model m = buildModel(parseAircraftDescription(in, "damaged.acm"), "damaged.acm");
            REQUIRE(!m.components.empty());
            ++models;
        } catch (const ModelFileError& e) {
            REQUIRE(e.file() == "damaged.acm");
            REQUIRE(e.line() >= (text.empty() ? 0 : 1));
            REQUIRE(e.line() <= static_cast<int>(lines.size()) + 1);
            ++errors;
        }
    };
    for (std::size_t cut = 0; cut < lines.size(); ++cut) {
        std::string truncated, replaced;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            if (i < cut) truncated += lines[i] + "\n";
            replaced += (i == cut ? replacements[cut % replacements.size()] : lines[i]) + "\n";
        }
        attempt(truncated);
        attempt(replaced);
    }
    REQUIRE(errors > static_cast<int>(lines.size()));
    REQUIRE(models > 0);
}

}  // namespace test_model_file
