// SURF_REDN BY COUNT says how many knots it removed when that is fewer than asked, and why.
#include "SessionTestSupport.h"

#include "geom/Evaluate.h"

#include <algorithm>

namespace test_session_reduction_count {

using session_test::Driver;

TEST_CASE("SURF_REDN BY COUNT: asking more knots than the wing's span has says how many and why") {
    Driver d("reduction_count");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN", "choice SURF_REDN", "choice BY_COUNT", "choice REDUCE_U"});
    const acsynt::Model& m = d.session.models().current();
    const acsynt::Component* wing = m.find("right_wing");
    REQUIRE(wing);
    const std::size_t before = wing->surface.countU;  // 6 sections: 2 interior knots
    d.pickAt(geom::evaluate(wing->surface, 0.5, 0.3), 1);
    d.run({"string 5"});
    REQUIRE(d.session.reductions().size() == 1);
    const acsynt::ReductionRecord& r = d.session.reductions()[0];
    CHECK(r.removedU < 5);
    CHECK(r.countUAfter == before - r.removedU);
    const std::string expected = "; ONLY " + std::to_string(r.removedU) + " OF 5 KNOTS REMOVED IN U (";
    CHECK(d.session.message().find(expected) != std::string::npos);
    CHECK(d.session.message().find("REMOVED IN W") == std::string::npos);
    // Undone, then asking for no more than there are says nothing more.
    d.run({"choice RETURN", "choice UNDO", "choice SURF_REDN", "choice BY_COUNT", "choice REDUCE_U"});
    CHECK(d.session.models().size() == 1);
    d.pickAt(geom::evaluate(d.session.models().current().find("right_wing")->surface, 0.5, 0.3), 1);
    d.run({"string 1"});
    CHECK(d.session.message().find("ONLY") == std::string::npos);
}

TEST_CASE("SURF_REDN BY COUNT, REDUCE_U&W: the prompt asks for each direction, both lose that many") {
    Driver d("reduction_count_uw");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN", "choice SURF_REDN", "choice BY_COUNT", "choice REDUCE_U&W"});
    const acsynt::Component* fuselage = d.session.models().current().find("fuselage");
    REQUIRE(fuselage);
    d.pickAt(geom::evaluate(fuselage->surface, 0.5, 0.5), 1);
    CHECK(d.session.message() == "ENTER NUMBER OF KNOTS TO BE REMOVED IN EACH DIRECTION (U AND W)");
    d.run({"string 2"});
    REQUIRE(d.session.reductions().size() == 1);
    const acsynt::ReductionRecord& r = d.session.reductions()[0];
    CHECK(r.removedU == 2);
    CHECK(r.removedW == 2);
    const auto& log = d.session.log();
    CHECK(std::any_of(log.begin(), log.end(), [](const std::string& line) {
        return line.find("REMOVE 2 KNOTS IN U AND 2 IN W") != std::string::npos;
    }));
}

TEST_CASE("SURF_REDN: each direction's count says what it takes out, and nothing removable changes nothing") {
    Driver d("reduction_messages");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN", "choice SURF_REDN"});
    auto said = [&](const std::string& text) {
        const auto& log = d.session.log();
        return std::any_of(log.begin(), log.end(),
                           [&](const std::string& line) { return line.find(text) != std::string::npos; });
    };
    auto pickFuselage = [&] {
        d.pickAt(geom::evaluate(d.session.models().current().find("fuselage")->surface, 0.5, 0.5), 1);
    };
    // U removes knots along the fuselage, across its sections: sections go, not knots of each.
    d.run({"choice BY_COUNT", "choice REDUCE_U"});
    pickFuselage();
    d.run({"string 2"});
    CHECK(said("REMOVE 2 KNOTS IN U (2 CROSS SECTIONS FEWER)"));
    d.run({"choice RETURN", "choice UNDO", "choice SURF_REDN", "choice BY_COUNT", "choice REDUCE_W"});
    pickFuselage();
    d.run({"string 2"});
    CHECK(said("REMOVE 2 KNOTS FROM EACH CROSS SECTION"));
    // Tolerances no knot can be removed within (the fuselage's smallest removal error is about
    // 4e-3): no new model, no error reported, the message says so.
    d.run({"choice RETURN", "choice UNDO", "choice SURF_REDN", "choice BY_TOLERANCE"});
    for (const char* tolerance : {"1e-3", "1e-30"}) {
        const std::size_t models = d.session.models().size(), reductions = d.session.reductions().size();
        d.run({"choice REDUCE_U&W"});
        pickFuselage();
        d.run({std::string("string ") + tolerance});
        CHECK(d.session.message().rfind("NO KNOT CAN BE REMOVED WITHIN ", 0) == 0);
        CHECK(d.session.models().size() == models);
        CHECK(d.session.reductions().size() == reductions);
    }
}

}  // namespace test_session_reduction_count
