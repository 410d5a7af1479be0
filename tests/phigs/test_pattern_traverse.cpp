// Interior style PATTERN through traversal and the workstation: the pattern size, reference
// point and vectors elements reach the draw items, EXECUTE STRUCTURE restores them, and the
// picture carries the pattern table with its colours looked up at draw time.
#include "phigs/Phigs.h"
#include "phigs/render/PatternMapping.h"

#include <catch2/catch.hpp>

#include <random>

namespace test_pattern_traverse {

using namespace phigs;

namespace {

const Element square = fillArea3({{0.1, 0.1, 0}, {0.4, 0.1, 0}, {0.4, 0.4, 0}});

PatternAttribute size(glm::dvec2 s) {
    PatternAttribute p;
    p.type = ElementType::PatternSize;
    p.size = s;
    return p;
}
PatternAttribute point(glm::dvec2 r) {
    PatternAttribute p;
    p.type = ElementType::PatternReferencePoint;
    p.referencePoint = {r, 0.0};
    return p;
}
PatternAttribute pointAndVectors(glm::dvec3 r, glm::dvec3 x, glm::dvec3 y) {
    PatternAttribute p;
    p.type = ElementType::PatternReferencePointAndVectors;
    p.referencePoint = r;
    p.vectorX = x;
    p.vectorY = y;
    return p;
}
const PatternPlacement& placementOf(const DrawItem& item) {
    return primitiveAs<DrawFillArea>(item.primitive).interior->pattern;
}

}  // namespace

TEST_CASE("pattern placement: size, reference point and vectors reach the items and are inherited",
          "[traverse][pattern]") {
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    store.openStructure(2);
    store.insert(pointAndVectors({0, 0, 1}, {0, 1, 0}, {-1, 0, 0}));
    store.insert(square);
    store.closeStructure();
    store.openStructure(1);
    store.insert(IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Pattern)});
    store.insert(square);  // traversal defaults
    store.insert(size({0.25, -0.5}));
    store.insert(pointAndVectors({1, 2, 3}, {2, 0, 0}, {1, 1, 0}));
    store.insert(square);
    store.insert(executeStructure(2));  // the child's changes end with it
    store.insert(square);
    store.insert(point({4, 5}));                                     // resets the vectors
    store.insert(size({0.0, 1.0}));                                  // no box: ignored
    store.insert(pointAndVectors({9, 9, 9}, {1, 0, 0}, {2, 0, 0}));  // parallel: ignored
    store.insert(square);
    store.closeStructure();
    ws.postStructure(1, 0.5);
    const DrawList& list = ws.display();
    REQUIRE(list.items.size() == 5);
    CHECK(placementOf(list.items[0]) == PatternPlacement{});
    const PatternPlacement set{{1, 2, 3}, {2, 0, 0}, {1, 1, 0}, {0.25, 0.5}};
    CHECK(placementOf(list.items[1]) == set);
    CHECK(placementOf(list.items[2]) == PatternPlacement{{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}, {0.25, 0.5}});
    CHECK(placementOf(list.items[3]) == set);
    CHECK(placementOf(list.items[4]) == PatternPlacement{{4, 5, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.5}});
    CHECK(primitiveAs<DrawFillArea>(list.items[4].primitive).interior->style == InteriorStyle::Pattern);
}

TEST_CASE("pattern table: the picture carries each pattern's cells through the colour table",
          "[ws][pattern]") {
    Phigs phigs;
    phigs.open();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::OffscreenImage);
    std::mt19937 random(7);
    std::uniform_int_distribution<int> dimension(1, 5), colour(0, 12);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int c = 0; c <= 12; ++c) ws.setColourRepresentation(c, {unit(random), unit(random), unit(random)});
    std::map<int, PatternRepresentation> set;
    for (int k = 0; k < 6; ++k) {
        PatternRepresentation p;
        p.columns = dimension(random);
        p.rows = dimension(random);
        // Indexed cells (the first always) and direct PHIGS PLUS cells.
        p.colours.clear();
        for (int i = 0; i < p.columns * p.rows; ++i)
            p.colours.push_back(i > 0 && unit(random) < 0.25
                                    ? Colour::fromRgb({unit(random), unit(random), unit(random)})
                                    : Colour::indexed(colour(random)));
        const int index = 1 + k * 3;
        ws.setPatternRepresentation(index, p);
        set[index] = p;
    }
    auto check = [&](const DrawList& list) {
        for (const auto& [index, p] : set) {
            INFO("pattern " << index);
            REQUIRE(list.patterns.contains(index));
            const DrawPattern& d = list.patterns.at(index);
            CHECK(d.columns == p.columns);
            CHECK(d.rows == p.rows);
            REQUIRE(d.colours.size() == p.colours.size());
            for (std::size_t i = 0; i < d.colours.size(); ++i) {
                const Colour& c = p.colours[i];
                CHECK(d.colours[i] == glm::vec3(c.direct ? c.rgb : ws.tables().colours.get(c.index)));
            }
        }
    };
    check(ws.display());
    // A new colour representation reaches the cells at the next picture.
    ws.setColourRepresentation(set.begin()->second.colours[0].index, {0.5, 0.25, 0.125});
    check(ws.display());
    int undefined = 1;
    while (ws.patterns().find(undefined)) ++undefined;
    CHECK(render::findPattern(ws.display(), undefined) == &ws.display().patterns.at(1));
}

TEST_CASE("pattern map: cell coordinates follow the box projected onto the primitive's plane",
          "[render][pattern]") {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    DrawPattern pattern{3, 2, std::vector<glm::vec3>(6, glm::vec3(1.0f))};
    for (int trial = 0; trial < 50; ++trial) {
        PatternPlacement p;
        p.referencePoint = {unit(random), unit(random), unit(random)};
        p.vectorX = {unit(random), unit(random), unit(random)};
        p.vectorY = {unit(random), unit(random), unit(random)};
        p.size = {0.5 + unit(random) * 0.4, 0.5 + unit(random) * 0.4};
        const glm::dvec3 normal = glm::normalize(glm::dvec3(unit(random), unit(random), 1.5));
        const glm::dvec3 planePoint(unit(random), unit(random), unit(random));
        const auto map = render::patternMap(p, glm::dmat4(1.0), pattern, planePoint, normal);
        REQUIRE(map);
        // The projected box corner is cell (0, 0); its projected edges advance by the cell counts.
        auto onPlane = [&](glm::dvec3 x) { return x - glm::dot(x - planePoint, normal) * normal; };
        const glm::dvec3 corner = onPlane(p.referencePoint);
        const glm::dvec3 a = onPlane(p.referencePoint + glm::normalize(p.vectorX) * p.size.x) - corner;
        const glm::dvec3 b = onPlane(p.referencePoint + glm::normalize(p.vectorY) * p.size.y) - corner;
        const double s = unit(random), t = unit(random);
        const glm::dvec2 cell = map->at(corner + s * a + t * b);
        CHECK(cell.x == Approx(s * 3).margin(1e-9));
        CHECK(cell.y == Approx(t * 2).margin(1e-9));
        // A point off the plane takes the cell of its orthogonal projection.
        CHECK(glm::length(map->at(corner + s * a + t * b + 0.3 * normal) - cell) < 1e-9);
    }
}

}  // namespace test_pattern_traverse
