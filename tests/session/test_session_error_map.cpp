// SURF_REDN's error map: colours in absolute units on a fixed scale (or relative to the largest
// error), a colour legend with the scale in model units, ERROR_SCALE's input checked.
#include "SessionTestSupport.h"

#include "acsynt/session/ModelPicture.h"

namespace test_session_error_map {

using session_test::Driver;

namespace {

/// The colour an error of `t` times the scale's top must have: blue, green, red (clamped).
glm::dvec3 expectedColour(double t) {
    t = std::clamp(t, 0.0, 1.0);
    const glm::dvec3 blue(0.1, 0.2, 1.0), green(0.1, 0.9, 0.2), red(1.0, 0.1, 0.1);
    return t < 0.5 ? blue + (green - blue) * (t * 2) : green + (red - green) * (t * 2 - 1);
}

const phigs::QuadrilateralMeshElement& errorMesh(acsynt::Session& s) {
    const phigs::Structure& e = s.phigs().store().structure(acsynt::structures::errorMap);
    for (std::size_t i = 0; i < e.elements.size(); ++i)
        if (const auto* mesh = e.elements.get<phigs::QuadrilateralMeshElement>(i)) return *mesh;
    FAIL("no error mesh drawn");
    throw;
}

std::vector<std::string> legendTexts(acsynt::Session& s) {
    std::vector<std::string> texts;
    const phigs::ElementArena& elements = s.phigs().store().structure(acsynt::structures::legend).elements;
    for (std::size_t i = 0; i < elements.size(); ++i)
        if (const auto* t = elements.get<phigs::TextElement>(i)) texts.push_back(t->text);
    return texts;
}

/// Every vertex of the error mesh has the colour of its measured error on a scale red at `top`.
void requireColoursOnScale(acsynt::Session& s, double top) {
    const acsynt::ReductionRecord& r = s.reductions().back();
    const auto& mesh = errorMesh(s);
    REQUIRE(mesh.vertexColours.size() == r.deviation.error.size());
    for (std::size_t k = 0; k < mesh.vertexColours.size(); ++k) {
        const glm::dvec3 want = expectedColour(r.deviation.error[k] / top);
        INFO("vertex " << k << " error " << r.deviation.error[k]);
        REQUIRE(glm::length(mesh.vertexColours[k].rgb - want) < 1e-9);
    }
}

void reduceComponent(Driver& d, const std::string& name, const std::string& tolerance) {
    const auto& component =
        d.session.models().current().components[std::size_t(session_test::componentIndex(d.session, name))];
    d.run({"choice REDUCE_U&W"});
    d.pickAt(geom::evaluate(component.surface, 0.5, 0.5), 1);
    REQUIRE(d.session.message() == "ENTER TOLERANCE FOR " + name);
    d.run({"string " + tolerance});
}

void reduceFuselage(Driver& d, const std::string& tolerance) {
    reduceComponent(d, "fuselage", tolerance);
}

}  // namespace

TEST_CASE("error map: fixed scale in model units by default, relative on demand, with a legend") {
    Driver d("error_map");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN", "choice SURF_REDN"});
    reduceFuselage(d, "0.01");
    REQUIRE(d.session.reductions().size() == 1);
    const double largest = d.session.reductions()[0].maxError;
    REQUIRE(largest > 1e-3);
    REQUIRE(largest < 1e-2);

    // Fixed: red at 1 cm (the shipped models are in metres), whatever the largest error.
    CHECK(d.session.errorScale() == 0.01);
    d.run({"choice ERROR_MAP"});
    CHECK(d.session.message().rfind("ERROR MAP: BLUE 0 TO RED 10 mm (FIXED SCALE), MAX ERROR ", 0) == 0);
    requireColoursOnScale(d.session, 0.01);
    const auto fixed = legendTexts(d.session);
    REQUIRE(fixed.size() == 5);
    CHECK(fixed[0] == "ERROR, FIXED SCALE");
    CHECK(fixed[1].rfind("MAX ", 0) == 0);
    CHECK(fixed[1].find(" mm") != std::string::npos);
    CHECK(fixed[2] == "0");
    CHECK(fixed[3] == "5 mm");
    CHECK(fixed[4] == "10 mm");
    session_test::compareWithReference(d.picture(), "error_map_legend");
    // With four views the legend stays inside the lower left view (it crossed into the 3D view).
    const acsynt::PixelBox lowerLeft = d.session.layout().viewBox(3, true);
    const phigs::ElementArena& legend =
        d.session.phigs().store().structure(acsynt::structures::legend).elements;
    std::size_t checked = 0;
    for (std::size_t i = 0; i < legend.size(); ++i) {
        std::vector<glm::dvec3> points;
        if (const auto* area = legend.get<phigs::FillAreaElement>(i))
            points.assign(area->points.begin(), area->points.end());
        if (const auto* text = legend.get<phigs::TextElement>(i)) points.push_back(text->position);
        for (const glm::dvec3& p : points) {
            const glm::dvec2 pixel = d.session.pixelOf(p, 0);
            INFO("legend element " << i << " at pixel " << pixel.x << ", " << pixel.y);
            CHECK(lowerLeft.contains(pixel));
            ++checked;
        }
    }
    CHECK(checked > 100);

    // Relative: red at the largest error, the legend's top says what that is.
    d.run({"choice ERROR_SCALE"});
    CHECK(d.session.message() == "ENTER ERROR MAP SCALE: A LENGTH (RED AT IT, FIXED) OR RELATIVE");
    d.run({"string relative"});
    CHECK(d.session.errorScale() == 0);
    CHECK(d.session.message().find("(RELATIVE SCALE)") != std::string::npos);
    requireColoursOnScale(d.session, largest);
    CHECK(legendTexts(d.session)[0] == "ERROR, RELATIVE SCALE");

    // A fixed scale below the largest error: the top tick says errors beyond it show red.
    d.run({"choice ERROR_SCALE", "string 1e-3"});
    CHECK(d.session.errorScale() == 1e-3);
    requireColoursOnScale(d.session, 1e-3);
    CHECK(legendTexts(d.session)[4] == ">1 mm");

    // Bad scales are refused with a message; the scale stays.
    for (const std::string bad : {"abc", "-2", "0", "1e999", "nan", "0.002mm", ""}) {
        INFO("'" << bad << "'");
        const std::size_t failed = d.session.failedLines();
        d.run({"choice ERROR_SCALE", "string " + bad});
        CHECK(d.session.message().rfind("BAD INPUT IN ERROR SCALE: '", 0) == 0);
        CHECK(d.session.failedLines() == failed + 1);
        CHECK(d.session.errorScale() == 1e-3);
    }

    // The legend goes with the map.
    d.run({"choice ERROR_MAP"});
    CHECK(d.session.message() == "ERROR MAP OFF");
    CHECK(legendTexts(d.session).empty());
}

TEST_CASE("error map: on a fixed scale an error has one colour whatever the reduction's largest error") {
    Driver d("error_map_fixed");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN", "choice SURF_REDN"});
    // Two reductions whose largest errors differ by orders of magnitude (the fuselage has no knot
    // to remove within 1e-3; the wing has).
    reduceFuselage(d, "0.01");
    d.run({"choice MODELS", "choice PREVIOUS_MODEL", "choice RETURN", "choice SURF_REDN"});
    reduceComponent(d, "right_wing", "1e-4");
    REQUIRE(d.session.reductions().size() == 2);
    REQUIRE(d.session.reductions()[1].maxError < d.session.reductions()[0].maxError / 50);
    d.run({"choice ERROR_MAP"});
    requireColoursOnScale(d.session, 0.01);  // a few micrometres: blue, not red
    const auto& mesh = errorMesh(d.session);
    for (const auto& c : mesh.vertexColours) REQUIRE(c.rgb.x < 0.2);
}

TEST_CASE("error map: each reduced model shows its own reduction, not only the last one made") {
    // ERROR_MAP answered NO REDUCTION for a model made by any but the session's last reduction.
    Driver d("error_map_each");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice SURF_REDN"});
    reduceFuselage(d, "0.01");
    d.run({"choice RETURN", "choice MODELS", "choice PREVIOUS_MODEL", "choice RETURN", "choice SURF_REDN"});
    reduceComponent(d, "right_wing", "1e-4");
    REQUIRE(d.session.reductions().size() == 2);
    const acsynt::ReductionRecord& first = d.session.reductions()[0];
    REQUIRE(d.session.reductions()[1].reducedModel == "transport_R2");
    d.run({"choice RETURN", "choice MODELS", "choice PREVIOUS_MODEL", "choice RETURN"});
    REQUIRE(d.session.models().current().name == first.reducedModel);
    d.run({"choice SURF_REDN", "choice ERROR_MAP"});
    CHECK(d.session.message().rfind("ERROR MAP: BLUE 0 TO RED", 0) == 0);
    // The fuselage's errors (up to 0.01) on the default scale, red at 10 mm; the wing's are
    // micrometres.
    const auto& colours = errorMesh(d.session).vertexColours;
    REQUIRE(colours.size() == first.deviation.error.size());
    for (std::size_t k = 0; k < colours.size(); ++k)
        REQUIRE(glm::length(colours[k].rgb - expectedColour(first.deviation.error[k] / 0.01)) < 1e-9);
    // On the model that was reduced (made by no reduction) the map is not drawn.
    d.run({"choice RETURN", "choice MODELS", "choice PREVIOUS_MODEL", "choice RETURN"});
    REQUIRE(d.session.models().current().name == "transport");
    CHECK(d.session.phigs().store().structure(acsynt::structures::errorMap).elements.empty());
}

TEST_CASE("error map: a renamed reduced model keeps its map, a deleted one's name does not bring it back") {
    Driver d("error_map_names");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice SURF_REDN"});
    reduceFuselage(d, "0.01");
    d.run({"choice ERROR_MAP", "choice RETURN", "choice MODELS", "choice NAME_MODEL", "string renamed",
           "choice RETURN", "choice SURF_REDN", "choice ERROR_SCALE", "string 0.01"});
    CHECK(d.session.message().rfind("ERROR MAP: BLUE 0 TO RED", 0) == 0);
    CHECK(errorMesh(d.session).vertexColours.size() == d.session.reductions()[0].deviation.error.size());
    // Deleted, and its name given to another model: that model has no reduction to show.
    d.run({"choice ERROR_MAP", "choice RETURN", "choice MODELS", "choice DELETE_MODEL", "choice RETURN",
           "choice FILE", "choice READ_MODEL", "string fighter.acm", "choice RETURN", "choice MODELS",
           "choice NAME_MODEL", "string renamed", "choice RETURN", "choice SURF_REDN", "choice ERROR_MAP"});
    CHECK(d.session.message() == "NO REDUCTION OF THE CURRENT MODEL TO SHOW");
    CHECK(d.session.phigs().store().structure(acsynt::structures::errorMap).elements.empty());
}

TEST_CASE("bad numbers in every prompt are refused with a message and change nothing") {
    Driver d("prompts");
    d.run({"choice FILE", "choice READ_MODEL", "string fighter.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN", "choice SURF_REDN"});
    const auto& fuselage = d.session.models().current().components[0];
    const glm::dvec3 top = geom::evaluate(fuselage.surface, 0.5, 0.5);
    struct Case {
        const char* mode;
        std::string input;
    };
    const Case cases[] = {{"BY_TOLERANCE", "0.01abc"}, {"BY_TOLERANCE", "nan"}, {"BY_TOLERANCE", "1e999"},
                          {"BY_TOLERANCE", "-0.01"},   {"BY_TOLERANCE", ""},    {"BY_TOLERANCE", "0.01 0.02"},
                          {"BY_COUNT", "2.5"},         {"BY_COUNT", "3x"},      {"BY_COUNT", "0"},
                          {"BY_COUNT", "-3"},          {"BY_COUNT", "inf"}};
    for (const Case& c : cases) {
        INFO(c.mode << " '" << c.input << "'");
        const std::size_t failed = d.session.failedLines();
        d.run({std::string("choice ") + c.mode, "choice REDUCE_U"});
        d.pickAt(top, 1);
        d.run({"string " + c.input});
        CHECK(d.session.message().rfind("BAD INPUT IN SRF_REDUCTION: '", 0) == 0);
        CHECK(d.session.failedLines() == failed + 1);
        CHECK(d.session.reductions().empty());
        CHECK(d.session.models().size() == 1);
    }
    // The curve scale: a number and nothing after it.
    d.run({"choice RETURN", "choice CURVE_MAP"});
    for (const std::string bad : {"circle.crv 0.1x", "circle.crv -1", "circle.crv nan", "circle.crv 1 2"}) {
        INFO(bad);
        d.run({"choice LOAD_CURVE", "string " + bad});
        CHECK(d.session.message().rfind("BAD INPUT IN CURVE MAP: '", 0) == 0);
    }
    // Well-formed numbers with blanks or a plus sign are taken.
    d.run({"choice RETURN", "choice SURF_REDN", "choice BY_COUNT", "choice REDUCE_U"});
    d.pickAt(top, 1);
    d.run({"string  +2 "});
    REQUIRE(d.session.reductions().size() == 1);
    CHECK(d.session.reductions()[0].count == 2);
}

}  // namespace test_session_error_map
