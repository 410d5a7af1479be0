#include "acsynt/Model.h"
#include "acsynt/ModelFile.h"
#include "acsynt/ModelList.h"

#include <catch2/catch.hpp>

namespace test_models {

using namespace acsynt;

namespace {

struct Expected {
    const char* name;
    ComponentKind kind;
    std::size_t sections, points, patchesU, patchesW;
};

void checkComponents(const Model& m, const std::vector<Expected>& expected) {
    REQUIRE(m.components.size() == expected.size());
    std::size_t total = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const Component& c = m.components[i];
        const Expected& e = expected[i];
        INFO(c.name);
        REQUIRE(c.name == e.name);
        REQUIRE(c.kind == e.kind);
        REQUIRE(c.sections.sectionCount == e.sections);
        REQUIRE(c.sections.pointsPerSection == e.points);
        REQUIRE(c.patches.countU == e.patchesU);
        REQUIRE(c.patches.countW == e.patchesW);
        REQUIRE(c.closedW == (e.kind == ComponentKind::Fuselage || e.kind == ComponentKind::Nacelle));
        total += e.patchesU * e.patchesW;
    }
    REQUIRE(m.patchCount() == total);
}

}  // namespace

TEST_CASE("the shipped transport loads with its components and patches", "[acsynt][models]") {
    const Model m = loadModel(ACSYNT_DATA_DIR "/transport.acm");
    REQUIRE(m.name == "transport");
    using K = ComponentKind;
    checkComponents(m, {{"fuselage", K::Fuselage, 13, 16, 10, 16},
                        {"right_wing", K::Wing, 6, 17, 3, 14},
                        {"left_wing", K::Wing, 6, 17, 3, 14},
                        {"right_htail", K::HorizontalTail, 5, 13, 2, 10},
                        {"left_htail", K::HorizontalTail, 5, 13, 2, 10},
                        {"fin", K::VerticalTail, 5, 13, 2, 10},
                        {"right_engine", K::Nacelle, 6, 12, 3, 12},
                        {"left_engine", K::Nacelle, 6, 12, 3, 12}});
    REQUIRE(m.patchCount() == 376);
    // Mirror images: the same points with y negated.
    const Component& r = *m.find("right_wing");
    const Component& l = *m.find("left_wing");
    for (std::size_t i = 0; i < r.sections.sectionCount; ++i)
        for (std::size_t j = 0; j < r.sections.pointsPerSection; ++j) {
            const glm::dvec3 a = r.sections.at(i, j),
                             b = l.sections.at(i, r.sections.pointsPerSection - 1 - j);
            REQUIRE(a.x == b.x);
            REQUIRE(a.y == -b.y);
            REQUIRE(a.z == b.z);
        }
    // The fin stands up: its tip is above its root.
    const Component& fin = *m.find("fin");
    REQUIRE(fin.sections.at(4, 0).z > fin.sections.at(0, 0).z + 5.0);
    // The nose is a point section.
    const Component& f = *m.find("fuselage");
    for (std::size_t j = 0; j < 16; ++j) REQUIRE(f.sections.at(0, j) == glm::dvec3(0.0, 0.0, -0.3));
}

TEST_CASE("the shipped fighter loads with its components and patches", "[acsynt][models]") {
    const Model m = loadModel(ACSYNT_DATA_DIR "/fighter.acm");
    REQUIRE(m.name == "fighter");
    using K = ComponentKind;
    checkComponents(m, {{"fuselage", K::Fuselage, 11, 16, 8, 16},
                        {"right_wing", K::Wing, 5, 13, 2, 10},
                        {"left_wing", K::Wing, 5, 13, 2, 10},
                        {"right_htail", K::HorizontalTail, 4, 11, 1, 8},
                        {"left_htail", K::HorizontalTail, 4, 11, 1, 8},
                        {"fin", K::VerticalTail, 4, 11, 1, 8}});
    REQUIRE(m.patchCount() == 192);
}

TEST_CASE("the model list steps, lists, renames, copies and deletes", "[acsynt][models]") {
    ModelList list;
    REQUIRE(list.empty());
    REQUIRE_THROWS_AS(list.current(), std::logic_error);
    REQUIRE(list.next().message == "NO GEOMETRY FILE FOUND!");
    list.add(loadModel(ACSYNT_DATA_DIR "/transport.acm"));
    list.add(loadModel(ACSYNT_DATA_DIR "/fighter.acm"));
    REQUIRE(list.currentIndex() == 1);
    REQUIRE(list.names() == std::vector<std::string>{"transport", "fighter"});

    ModelList::Outcome o = list.next();
    REQUIRE_FALSE(o.done);
    REQUIRE(o.message == "NEXT MODEL DOES NOT EXIST");
    o = list.previous();
    REQUIRE(o.done);
    REQUIRE(o.message == "MODEL CHANGE COMPLETE.  CURRENT MODEL NAME = transport");
    REQUIRE(list.previous().message == "PREVIOUS MODEL DOES NOT EXIST");
    REQUIRE(list.current().name == "transport");

    REQUIRE_FALSE(list.rename("has space").done);
    REQUIRE_FALSE(list.rename("").done);
    REQUIRE_FALSE(list.rename("a_name_that_is_too_long").done);
    REQUIRE(list.current().name == "transport");
    // Names are unique: another model's is refused (its own is no change).
    o = list.rename("fighter");
    REQUIRE_FALSE(o.done);
    REQUIRE(o.message == "BAD INPUT IN MODELS: A MODEL NAMED fighter IS LOADED (NAMES ARE UNIQUE)");
    REQUIRE(list.current().name == "transport");
    REQUIRE(list.rename("transport").done);
    REQUIRE(list.contains("fighter"));
    REQUIRE_FALSE(list.contains("airliner"));
    o = list.rename("airliner");
    REQUIRE(o.done);
    REQUIRE(o.message == "CURRENT MODEL NAMED airliner");
    REQUIRE_FALSE(list.copyCurrent("fighter").done);

    // A copy for a reduced version: appended, current, independent of the original.
    o = list.copyCurrent("airliner_r");
    REQUIRE(o.done);
    REQUIRE(list.names() == std::vector<std::string>{"airliner", "fighter", "airliner_r"});
    REQUIRE(list.currentIndex() == 2);
    list.current().components[0].surface.points[0].x += 1.0;
    REQUIRE(list.at(0).components[0].surface.points[0].x != list.at(2).components[0].surface.points[0].x);
    REQUIRE(list.current().sourceFile.empty());

    REQUIRE(list.select(1).message == "MODEL CHANGE COMPLETE.  CURRENT MODEL NAME = fighter");
    REQUIRE_FALSE(list.select(7).done);
    o = list.removeCurrent();
    REQUIRE(o.message == "MODEL fighter DELETED.  CURRENT MODEL NAME = airliner");
    REQUIRE(list.names() == std::vector<std::string>{"airliner", "airliner_r"});
    list.removeCurrent();
    REQUIRE(list.current().name == "airliner_r");
    o = list.removeCurrent();
    REQUIRE(o.message == "MODEL airliner_r DELETED.  NO MODEL LEFT");
    REQUIRE(list.empty());
}

TEST_CASE("a model that cannot be lofted is an error at its component line", "[acsynt][models]") {
    // The parser lets no such description through, so it is built here: a fuselage whose
    // sections are all points has no extent round the sections.
    AircraftDescription d;
    d.name = "bad";
    ComponentDescription c;
    c.name = "needle";
    c.kind = ComponentKind::Fuselage;
    c.points = 8;
    c.line = 42;
    FuselageShape f;
    for (int i = 0; i < 4; ++i) f.stations.push_back({FuselagePart::Mid, double(i), 0, 0, 0, 0, 2, 43 + i});
    c.shape = f;
    d.components.push_back(c);
    try {
        buildModel(d, "needle.acm");
        FAIL("no error");
    } catch (const ModelFileError& e) {
        INFO(e.what());
        REQUIRE(e.file() == "needle.acm");
        REQUIRE(e.line() == 42);
        REQUIRE(e.reason().find("'needle' cannot be lofted") != std::string::npos);
    }
}

}  // namespace test_models
