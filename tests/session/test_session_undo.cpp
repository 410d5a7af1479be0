// UNDO and REDO of model changes (read, reference point, mapping, reduction, flip, rotate,
// rename, delete), and mapped curves carried to a reduced model.
#include "SessionTestSupport.h"

#include "geom/Evaluate.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace test_session_undo {

using session_test::Driver;

using session_test::componentIndex;
using session_test::pickOn;

namespace {

void mapLogo(Driver& d) {
    d.run({"choice CURVE_MAP", "choice LOAD_CURVE", "string acslogo.crv 0.45", "choice DEFINE_POINT"});
    pickOn(d, "right_wing", 0.5, 0.38);
    pickOn(d, "right_wing", 0.5, 0.38);
    d.run({"choice ACCEPT", "choice DONE device 2", "choice MAP_CURVE", "choice RETURN"});
}

void reduce(Driver& d, const std::string& component, const std::string& tolerance) {
    d.run({"choice SURF_REDN", "choice BY_TOLERANCE", "choice REDUCE_U&W"});
    pickOn(d, component, 0.5, 0.3);
    d.run({"string " + tolerance, "choice RETURN"});
}

}  // namespace

TEST_CASE("an UNDO from a model's menu that leaves no model goes back to MAIN and drops what was pending") {
    Driver d("undo_menus");
    // From CURVE MAP, taking back the only model: the menu has nothing to work on.
    d.run({"choice FILE", "choice READ_MODEL", "string fighter.acm", "choice RETURN", "choice CURVE_MAP",
           "undo"});
    CHECK(d.session.models().empty());
    CHECK(d.session.menuTitle() == "MAIN");
    CHECK(d.session.message() == "UNDONE: READ MODEL fighter");
    d.run({"choice CURVE_MAP"});
    CHECK(d.session.message() == "NO GEOMETRY FILE FOUND!");
    // A reduction's tolerance prompt belongs to the state taken back: the typed answer reduces
    // nothing (the pick was on the model that went).
    d.run({"choice FILE", "choice READ_MODEL", "string fighter.acm", "choice READ_MODEL",
           "string transport.acm", "choice RETURN", "choice SURF_REDN", "choice BY_TOLERANCE",
           "choice REDUCE_U&W"});
    session_test::pickOn(d, "fuselage", 0.5, 0.3);
    CHECK(d.session.typing());
    d.run({"undo"});
    CHECK_FALSE(d.session.typing());
    CHECK(d.session.menuTitle() != "MAIN");  // fighter is still there
    d.run({"string 0.01"});
    CHECK(d.session.reductions().empty());
    CHECK(d.session.models().size() == 1);
}

TEST_CASE("UNDO and REDO step through reading, mapping and reducing, and a new change clears REDO") {
    Driver d("undo");
    d.run({"choice UNDO"});
    CHECK(d.session.message() == "NOTHING TO UNDO");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN"});
    CHECK(d.session.undoCount() == 1);
    mapLogo(d);
    CHECK(d.session.undoCount() == 3);  // read, reference point, mapping
    REQUIRE(d.session.mappings().size() == 1);
    const acsynt::MappingRecord logo = d.session.mappings()[0];
    reduce(d, "fuselage", "0.01");
    REQUIRE(d.session.models().size() == 2);
    const acsynt::Model reduced = d.session.models().current();
    // The logo is carried to the reduced model (on the wing, untouched, so the same points).
    REQUIRE(d.session.mappings().size() == 2);
    CHECK(d.session.mappings()[1].model == reduced.name);
    CHECK(d.session.mappings()[1].polylines == logo.polylines);

    d.run({"choice UNDO"});
    CHECK(d.session.message() == "UNDONE: REDUCTION OF fuselage");
    CHECK(d.session.models().size() == 1);
    CHECK(d.session.models().current().name == "transport");
    CHECK(d.session.mappings().size() == 1);
    CHECK(d.session.reductions().empty());
    d.run({"choice UNDO"});
    CHECK(d.session.message() == "UNDONE: MAP CURVE acslogo.crv ON right_wing");
    CHECK(d.session.mappings().empty());
    CHECK(d.session.redoCount() == 2);

    d.run({"choice REDO"});
    CHECK(d.session.message() == "REDONE: MAP CURVE acslogo.crv ON right_wing");
    REQUIRE(d.session.mappings().size() == 1);
    CHECK(d.session.mappings()[0].polylines == logo.polylines);
    d.run({"choice REDO"});
    CHECK(d.session.message() == "REDONE: REDUCTION OF fuselage");
    REQUIRE(d.session.models().size() == 2);
    const acsynt::Component& a = reduced.components[std::size_t(componentIndex(reduced, "fuselage"))];
    const acsynt::Model& back = d.session.models().current();
    const acsynt::Component& b = back.components[std::size_t(componentIndex(back, "fuselage"))];
    CHECK(back.name == reduced.name);
    CHECK(a.surface.points == b.surface.points);
    CHECK(a.surface.knotsU == b.surface.knotsU);
    d.run({"choice REDO"});
    CHECK(d.session.message() == "NOTHING TO REDO");

    // Flip and rotate are changes too; a new change after an UNDO clears what REDO had.
    d.run({"choice CURVE_MAP", "choice FLIP_CURVE", "choice RETURN", "choice UNDO"});
    CHECK(d.session.message() == "UNDONE: FLIP CURVE");
    CHECK(d.session.redoCount() == 1);
    d.run({"choice CURVE_MAP", "choice ROTATE_CURVE", "choice RETURN"});
    CHECK(d.session.redoCount() == 0);
    d.run({"choice UNDO"});
    CHECK(d.session.message() == "UNDONE: ROTATE CURVE");

    // Rename and delete, undone in turn.
    d.run({"choice MODELS", "choice NAME_MODEL", "string renamed", "choice DELETE_MODEL", "choice RETURN"});
    CHECK(d.session.models().size() == 1);
    d.run({"choice UNDO"});
    CHECK(d.session.message() == "UNDONE: DELETE MODEL");
    CHECK(d.session.models().size() == 2);
    CHECK(d.session.models().current().name == "renamed");
    d.run({"choice UNDO"});
    CHECK(d.session.message() == "UNDONE: NAME MODEL");
    CHECK(d.session.models().current().name == reduced.name);
    CHECK_FALSE(d.logHasError());
}

TEST_CASE("UNDO of DONE gives the marker back to the pad: DONE places it again and MAP CURVE maps") {
    Driver d("undo_done");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN", "choice CURVE_MAP", "choice LOAD_CURVE",
           "string circle.crv 0.1", "choice DEFINE_POINT"});
    pickOn(d, "right_wing", 0.5, 0.38);
    pickOn(d, "right_wing", 0.5, 0.38);
    d.run({"choice ACCEPT", "choice DONE device 2", "undo"});
    CHECK(d.session.message() == "UNDONE: REFERENCE POINT");
    REQUIRE(d.session.reference());
    const double u = d.session.reference()->u;
    d.run({"choice MAP_CURVE"});
    CHECK(d.session.message() == "THE REFERENCE POINT IS NOT PLACED: DONE ON THE POINTER PAD PLACES IT");
    CHECK(d.session.mappings().empty());
    d.run({"choice EAST device 2"});  // the pad moves the marker again
    CHECK(d.session.reference()->u > u);
    d.run({"choice DONE device 2", "choice MAP_CURVE"});
    CHECK(d.session.mappings().size() == 1);
    // UNDO of the mapping and of DONE, then REDO of DONE: the point is placed again.
    d.run({"undo", "undo", "redo"});
    CHECK(d.session.message() == "REDONE: REFERENCE POINT");
    d.run({"choice MAP_CURVE"});
    CHECK(d.session.mappings().size() == 1);
}

TEST_CASE("a reduction of the mapped component moves its mapped curves onto the reduced surface") {
    Driver d("undo_carry");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN"});
    mapLogo(d);
    REQUIRE(d.session.mappings().size() == 1);
    const acsynt::MappingRecord logo = d.session.mappings()[0];
    reduce(d, "right_wing", "0.001");
    // The reduction's message (before RETURN) says the logo moved with the wing.
    const auto& log = d.session.log();
    CHECK(std::any_of(log.begin(), log.end(), [](const std::string& line) {
        return line.rfind("DATA REDUCTION", 0) == 0 &&
               line.find("1 MAPPED CURVES MOVED ONTO THE REDUCED SURFACE") != std::string::npos;
    }));
    REQUIRE(d.session.mappings().size() == 2);
    const acsynt::MappingRecord& carried = d.session.mappings()[1];
    const acsynt::Model& model = d.session.models().current();
    CHECK(carried.model == model.name);
    const acsynt::Component& wing = model.components[std::size_t(componentIndex(model, "right_wing"))];
    const double maxError = d.session.reductions().back().maxError;
    CHECK(carried.uvPolylines == logo.uvPolylines);
    for (std::size_t l = 0; l < carried.polylines.size(); ++l)
        for (std::size_t k = 0; k < carried.polylines[l].size(); ++k) {
            const glm::dvec2 uv = carried.uvPolylines[l][k];
            CHECK(glm::length(carried.polylines[l][k] - geom::evaluate(wing.surface, uv.x, uv.y)) < 1e-12);
            CHECK(glm::length(carried.polylines[l][k] - logo.polylines[l][k]) <=
                  std::max(2 * maxError, 2e-3));
        }
}

}  // namespace test_session_undo
