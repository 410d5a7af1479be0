// Clear modes: the pointer pad and the marker valuators work only while DEFINE POINT moves the
// marker; after DONE they are refused with a message and the marker stays.
#include "SessionTestSupport.h"

#include "geom/Evaluate.h"

namespace test_session_modes {

using session_test::Driver;

TEST_CASE("the pointer pad turns off after DONE: pad buttons and marker valuators are refused") {
    Driver d("modes");
    // The empty screen says where to start.
    CHECK(d.session.message() ==
          "SELECT MENU ITEM: START WITH FILE, READ MODEL (transport.acm OR fighter.acm)");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN", "choice CURVE_MAP", "choice DEFINE_POINT"});
    const acsynt::Component* wing = d.session.models().current().find("right_wing");
    REQUIRE(wing);
    const glm::dvec3 p = geom::evaluate(wing->surface, 0.5, 0.38);
    d.pickAt(p, 1);
    d.pickAt(p, 1);
    d.run({"choice ACCEPT", "choice CENTRE device 2"});
    const acsynt::ReferencePoint centre = *d.session.reference();
    d.run({"choice EAST device 2"});
    CHECK(d.session.reference()->u > centre.u);  // live while the marker moves
    d.run({"choice DONE device 2"});
    const acsynt::ReferencePoint placed = *d.session.reference();
    const std::size_t failed = d.session.failedLines();
    d.run({"choice WEST device 2"});
    CHECK(d.session.message() == "THE POINTER PAD IS OFF AFTER DONE: USE DEFINE POINT TO MOVE THE MARKER");
    d.run({session_test::markerValuator(d.session, 1, 0.1)});
    CHECK(d.session.message() == "THE MARKER IS PLACED (DONE): USE DEFINE POINT TO MOVE IT");
    CHECK(d.session.failedLines() == failed + 2);
    CHECK(d.session.reference()->u == placed.u);
    CHECK(d.session.reference()->w == placed.w);
    // Zoom and rotation (valuators 3, 4) still work; MAP CURVE uses the placed marker.
    d.run({"valuator 4 2", "choice LOAD_CURVE", "string circle.crv 0.1", "choice MAP_CURVE"});
    REQUIRE(d.session.mappings().size() == 1);
    CHECK(d.session.mappings()[0].reference.u == placed.u);
}

}  // namespace test_session_modes

namespace test_session_modes {

TEST_CASE("a resized window keeps the text the operator is typing") {
    // Resizing re-initialises the string device for its new echo area; entering EVENT mode again
    // started the typing over from the empty initial string, dropping what was typed.
    session_test::Driver d("modes_resize_typing");
    d.run({"choice FILE"});
    d.source.type("transport.a");
    d.session.resize(800, 600);
    CHECK(d.source.stringEcho().text == "transport.a");
    d.session.resize(640, 480);
    CHECK(d.source.stringEcho().text == "transport.a");
}

}  // namespace test_session_modes
