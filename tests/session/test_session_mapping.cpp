// MAP CURVE accounts for every part: mapped, clipped at an edge (with boundary walks), or lost
// and named on the message line and in the summary; MAP PREVIEW shows every part.
#include "SessionTestSupport.h"

#include "geom/Evaluate.h"

#include <glm/geometric.hpp>

namespace test_session_mapping {

using session_test::Driver;

using session_test::componentIndex;
using session_test::pickOn;

namespace {

const acsynt::Component& component(const acsynt::Session& s, const std::string& name) {
    return s.models().current().components[std::size_t(componentIndex(s, name))];
}

/// DEFINE POINT on `name` at (u, w) seen from above in the plan view, accepted, the marker
/// moved as the demo moves it (`demo`: the patch centre, w at 0.55 of the patch, one step east),
/// then DONE.
void definePoint(Driver& d, const std::string& name, double u, double w, bool demo = false) {
    d.run({"choice DEFINE_POINT"});
    const glm::dvec3 p = geom::evaluate(component(d.session, name).surface, u, w);
    d.pickAt(p, 1);
    REQUIRE(d.session.message() == "SELECT REFERENCE PATCH TO MAP");
    d.pickAt(p, 1);
    d.run({"choice ACCEPT"});
    REQUIRE(d.session.reference());
    REQUIRE(d.session.reference()->component == componentIndex(d.session, name));
    if (demo)
        d.run({"choice CENTRE device 2", session_test::markerValuator(d.session, 2, 0.55),
               "choice EAST device 2"});
    d.run({"choice DONE device 2"});
}

/// The w of the (u = 0.5) section point of `name` facing up most.
double topW(const acsynt::Session& s, const std::string& name) {
    double best = 0, bestZ = -2;
    for (int k = 0; k < 64; ++k) {
        const double w = (k + 0.5) / 64;
        const double z = geom::normal(component(s, name).surface, 0.5, w).z;
        if (z > bestZ) bestZ = z, best = w;
    }
    return best;
}

/// Every part of the last mapping is mapped, clipped with boundary walks, or lost and named.
void checkEveryPartAccounted(const Driver& d, std::size_t& lost) {
    const acsynt::MappingRecord& m = d.session.mappings().back();
    const std::string message = d.session.message(), summary = d.session.summary();
    INFO("message: " << message);
    REQUIRE(m.partReports.size() == m.parts);
    std::size_t loops = 0, walks = 0;
    for (const acsynt::PartReport& p : m.partReports) {
        INFO("part " << p.name << " " << acsynt::outcomeName(p.outcome) << ": " << p.reason);
        loops += p.loops;
        walks += p.boundaryWalks;
        switch (p.outcome) {
            case acsynt::PartOutcome::Mapped:
                CHECK(p.loops >= 1);
                CHECK(p.boundaryWalks == 0);
                break;
            case acsynt::PartOutcome::Clipped:
                CHECK(p.loops >= 1);
                CHECK(p.boundaryWalks >= 1);
                CHECK(message.find(p.name) != std::string::npos);
                CHECK(summary.find("part " + p.name + ": clipped") != std::string::npos);
                break;
            case acsynt::PartOutcome::Lost:
                ++lost;
                CHECK(p.loops == 0);
                CHECK(!p.reason.empty());
                CHECK(message.find("LOST: ") != std::string::npos);
                CHECK(message.find(p.name + " (") != std::string::npos);
                CHECK(summary.find("part " + p.name + ": lost: " + p.reason) != std::string::npos);
                break;
        }
    }
    CHECK(loops == m.loops);
    CHECK(walks == m.boundaryWalks);
    // Every loop lies inside the component's parameter rectangle (open directions) and on it.
    const acsynt::Component& comp = component(d.session, m.component);
    for (std::size_t k = 0; k < m.uvPolylines.size(); ++k)
        for (std::size_t i = 0; i < m.uvPolylines[k].size(); i += 7) {
            const glm::dvec2 uv = m.uvPolylines[k][i];
            CHECK(uv.x >= -1e-9);
            CHECK(uv.x <= 1 + 1e-9);
            if (!comp.closedW) CHECK((uv.y >= -1e-9 && uv.y <= 1 + 1e-9));
        }
}

}  // namespace

TEST_CASE("MAP CURVE: the logo at scales 1 and 2 on each shipped model maps, clips or names every part") {
    for (const std::string model : {"transport.acm", "fighter.acm"}) {
        Driver d("curve_map_every_part");
        d.run({"choice FILE", "choice READ_MODEL", "string " + model, "choice RETURN", "choice VIEW",
               "choice FOUR_VIEWS", "choice RETURN", "choice CURVE_MAP"});
        REQUIRE(d.session.models().size() == 1);
        std::size_t lost = 0, clipped = 0, mapped = 0;
        for (const std::string scale : {"1", "2"}) {
            d.run({"choice LOAD_CURVE", "string acslogo.crv " + scale});
            struct Place {
                std::string component;
                double u, w;
                bool demo = false;
            };
            const double fuselageTop = topW(d.session, "fuselage");
            for (const Place& p : {Place{"right_wing", 0.5, 0.38, true}, Place{"right_wing", 0.15, 0.25},
                                   Place{"right_wing", 0.85, 0.1}, Place{"fuselage", 0.5, fuselageTop}}) {
                INFO(model << " scale " << scale << " on " << p.component << " at u " << p.u << " w " << p.w);
                definePoint(d, p.component, p.u, p.w, p.demo);
                d.run({"choice MAP_PREVIEW"});
                const std::string preview = d.session.message();
                CHECK(preview.find("PROJECTION LINES") != std::string::npos);
                const std::size_t before = d.session.mappings().size();
                d.run({"choice MAP_CURVE"});
                REQUIRE(d.session.mappings().size() == before + 1);
                // The preview announced the same parts clipped and lost as the mapping.
                const std::string message = d.session.message();
                CHECK(preview.substr(preview.find("LINES") + 5) == message.substr(message.find("PARTS") + 5));
                checkEveryPartAccounted(d, lost);
                for (const auto& r : d.session.mappings().back().partReports) {
                    clipped += r.outcome == acsynt::PartOutcome::Clipped;
                    mapped += r.outcome == acsynt::PartOutcome::Mapped;
                }
                if (scale == "1" && p.demo && model == "transport.acm") {
                    // Where the demo puts it, the whole logo lands on the transport's wing at
                    // scale 1 (it hangs over the leading edge): nothing is lost.
                    for (const auto& r : d.session.mappings().back().partReports)
                        CHECK(r.outcome != acsynt::PartOutcome::Lost);
                }
            }
        }
        CHECK(clipped >= 8);  // parts over the leading and trailing edges, the root and the tip
        CHECK(mapped + clipped >= 20);
        CHECK_FALSE(d.logHasError());
    }
}

TEST_CASE("MAP CURVE: the logo at scale 2 over the transport's wing edges, clipped, and its preview") {
    Driver d("curve_map_clipped");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN", "choice CURVE_MAP", "choice LOAD_CURVE",
           "string acslogo.crv 2"});
    definePoint(d, "right_wing", 0.5, 0.38);
    d.run({"choice MAP_PREVIEW"});
    const std::string preview = d.session.message();
    CHECK(preview.find("CLIPPED: ") != std::string::npos);
    d.run({"choice MAP_CURVE"});
    const std::string message = d.session.message();
    const acsynt::MappingRecord& m = d.session.mappings().back();
    CHECK(m.parts == 5);
    CHECK(m.loops >= 5);
    CHECK(m.boundaryWalks >= 5);
    CHECK(message.find("CLIPPED: A_TRIANGLE, O_RING, SQUARE, TEARDROP, SWOOSH") != std::string::npos);
    d.run({"choice RETURN", "choice VIEW", "choice CENTRE_ON_MARKER", "valuator 4 2", "choice RETURN"});
    session_test::compareWithReference(d.picture(), "curve_map_clipped_logo");
}

TEST_CASE("DEFINE POINT: the pad before a patch is accepted names the step still to take") {
    Driver d("define_point_steps");
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN", "choice VIEW",
           "choice FOUR_VIEWS", "choice RETURN", "choice CURVE_MAP"});
    d.run({"choice EAST device 2"});
    CHECK(d.session.message() == "NO REFERENCE PATCH: USE DEFINE POINT FIRST");
    d.run({"choice DEFINE_POINT", "choice EAST device 2"});
    CHECK(d.session.message() == "NO REFERENCE PATCH YET: PICK A COMPONENT, THEN A PATCH");
    const glm::dvec3 p = geom::evaluate(component(d.session, "right_wing").surface, 0.5, 0.3);
    d.pickAt(p, 1);
    d.run({"choice NORTH device 2"});
    CHECK(d.session.message() == "NO REFERENCE PATCH YET: PICK A PATCH OF THE COMPONENT");
    d.pickAt(p, 1);
    d.run({"choice WEST device 2"});
    CHECK(d.session.message() == "NO REFERENCE PATCH YET: ACCEPT OR REJECT THE PATCH PICKED");
    d.run({"choice ACCEPT", "choice WEST device 2"});
    CHECK(d.session.reference());
}

}  // namespace test_session_mapping
