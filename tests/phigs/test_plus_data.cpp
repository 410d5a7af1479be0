// PHIGS PLUS primitives with data (polyline set, cell array plus, set of fill area sets), the
// rendering colour model and colour mapping: stored, checked, traversed into draw items (no GPU),
// archived and read back, with seeded random members.

#include "ErrorNumber.h"
#include "PostedScene.h"
#include "RandomElements.h"
#include "phigs/Phigs.h"
#include "phigs/store/ArchiveFile.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>

namespace test_plus_data {

using namespace phigs;
using phigs::test::errorOf;
using phigs::testing::randomColour;
using phigs::testing::randomInt;
using phigs::testing::randomPoint;
using phigs::testing::randomPoints;

namespace {

using Scene = phigs::test::PostedScene;

template <class P>
std::vector<const P*> itemsOf(const DrawList& list) {
    std::vector<const P*> out;
    for (const DrawItem& item : list.items)
        if (auto p = primitiveIf<P>(item.primitive)) out.push_back(p);
    return out;
}

SetOfFillAreaSetsElement randomSofas(std::mt19937& rng) {
    SetOfFillAreaSetsElement e;
    const int n = randomInt(rng, 3, 8);
    e.vertices = randomPoints(rng, n);
    if (randomInt(rng, 0, 1))
        for (int i = 0; i < n; ++i) e.vertexColours.push_back(randomColour(rng));
    if (randomInt(rng, 0, 1)) e.vertexNormals = randomPoints(rng, n);
    const bool edges = randomInt(rng, 0, 1) == 1;
    for (int s = randomInt(rng, 0, 3); s > 0; --s) {
        auto& set = e.sets.emplace_back();
        std::vector<std::vector<int>> flags;
        for (int c = randomInt(rng, 1, 2); c > 0; --c) {
            auto& contour = set.emplace_back();
            auto& f = flags.emplace_back();
            for (int k = randomInt(rng, 2, 5); k > 0; --k)
                contour.push_back(randomInt(rng, 0, n - 1)), f.push_back(randomInt(rng, 0, 1));
        }
        if (edges) e.edgeFlags.push_back(std::move(flags));
    }
    if (randomInt(rng, 0, 1))
        for (std::size_t s = 0; s < e.sets.size(); ++s) e.facetColours.push_back(randomColour(rng));
    if (randomInt(rng, 0, 1)) e.facetNormals = randomPoints(rng, static_cast<int>(e.sets.size()));
    return e;
}

Element randomPlusElement(std::mt19937& rng) {
    switch (randomInt(rng, 0, 3)) {
        case 0: {
            PolylineSetWithDataElement e;
            for (int l = randomInt(rng, 0, 3); l > 0; --l)
                e.polylines.push_back(randomPoints(rng, randomInt(rng, 0, 5)));
            if (randomInt(rng, 0, 1))
                for (const auto& line : e.polylines) {
                    auto& colours = e.vertexColours.emplace_back();
                    for (std::size_t i = 0; i < line.size(); ++i) colours.push_back(randomColour(rng));
                }
            return e;
        }
        case 1: {
            CellArrayPlusElement e{randomPoint(rng),     randomPoint(rng),     randomPoint(rng),
                                   randomInt(rng, 0, 4), randomInt(rng, 0, 3), {}};
            for (int k = 0; k < e.columns * e.rows; ++k) e.colours.push_back(randomColour(rng));
            return e;
        }
        case 2:
            return randomSofas(rng);
        default:
            return IndexAttribute{ElementType::RenderingColourModel, randomInt(rng, 0, 4)};
    }
}

ColourMapping pseudoRamp(std::vector<glm::dvec3> colours, glm::dvec3 weights) {
    ColourMapping m;
    m.method = ColourMappingMethod::Pseudo;
    m.weights = weights;
    m.colours = std::move(colours);
    return m;
}

}  // namespace

TEST_CASE("polyline set with data: a segment takes its first vertex's colour", "[plus][traverse]") {
    Scene s;
    PolylineSetWithDataElement e;
    e.polylines = {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}, {{0, 1, 0}, {1, 1, 0}}, {{5, 5, 5}}};
    e.vertexColours = {{Colour::indexed(2), Colour::indexed(2), Colour::indexed(3), Colour::indexed(4)},
                       {Colour::fromRgb({0.5, 0.25, 1}), Colour::indexed(2)},
                       {Colour::indexed(5)}};
    const DrawList list =
        s.draw({e, polylineColourIndex(6), PolylineSetWithDataElement{{e.polylines[0]}, {}}});
    const auto lines = itemsOf<DrawColouredPolyline>(list);
    const auto plain = itemsOf<DrawPolyline>(list);
    // one item per polyline of two points or more, its vertex colours resolved (segment i takes
    // colours[i] under polyline shading NONE); the set without colours in the polyline colour
    REQUIRE(lines.size() == 2);
    REQUIRE(plain.size() == 1);
    CHECK(lines[0]->line.points.size() == 4);
    CHECK(lines[0]->colours.values == std::vector<glm::vec3>{{1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    CHECK_FALSE(lines[0]->colours.interpolated);
    CHECK(lines[1]->colours.values == std::vector<glm::vec3>{{0.5f, 0.25f, 1}, {1, 0, 0}});
    CHECK(plain[0]->points.size() == 4);
    CHECK(plain[0]->style->colour == glm::vec3(0, 1, 1));
}

TEST_CASE("cell array plus draws its general colours as a mesh", "[plus][traverse]") {
    Scene s;
    CellArrayPlusElement e{{0, 0, 0}, {2, 0, 0}, {0, 1, 1},
                           2,         1,         {Colour::indexed(4), Colour::fromRgb({0.5, 0.5, 0})}};
    const auto meshes = itemsOf<DrawMesh>(s.draw({e}));
    REQUIRE(meshes.size() == 1);
    const MeshData& m = *meshes[0]->mesh;
    REQUIRE(m.positions.size() == 8);
    CHECK(m.colours[0] == glm::vec3(0, 0, 1));
    CHECK(m.colours[7] == glm::vec3(0.5f, 0.5f, 0));
    CHECK(m.positions[2] == glm::vec3(1, 1, 1));  // P + (Q - P) / 2 + (R - P)
    CHECK(m.triangles.size() == 12);
}

TEST_CASE("set of fill area sets: one fill area per set, facet colours, edges whose flag is on",
          "[plus][traverse]") {
    Scene s;
    SetOfFillAreaSetsElement e;
    e.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
    e.vertexNormals = std::vector<glm::dvec3>(5, {0, 0, 1});
    e.sets = {{{0, 1, 2, 3}}, {{1, 4, 2}, {0, 1}}};
    e.facetColours = {Colour::indexed(2), Colour::indexed(3)};
    e.edgeFlags = {{{1, 0, 1, 1}}, {{0, 0, 0}, {1, 1}}};
    const DrawList& list = s.draw({IndexAttribute{ElementType::EdgeFlag, 1},
                                   ColourAttribute{ElementType::EdgeColour, Colour::indexed(5)}, e});
    const auto areas = itemsOf<DrawFillArea>(list);
    const auto edges = itemsOf<DrawPolyline>(list);
    REQUIRE(areas.size() == 2);
    CHECK(areas[0]->contours ==
          std::vector<std::vector<glm::dvec3>>{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}});
    CHECK(areas[0]->interior->colour == glm::vec3(1, 0, 0));
    CHECK(areas[1]->interior->colour == glm::vec3(0, 1, 0));
    CHECK(areas[1]->contours.size() == 1);  // the two-vertex contour is dropped
    CHECK(areas[0]->vertexNormals.size() == 1);
    CHECK_FALSE(areas[0]->edges->visible);  // its edges come as polylines
    // set 0: edges 2, 3 and 0 on make one run 2 -> 3 -> 0 -> 1; set 1's triangle has none on
    REQUIRE(edges.size() == 1);
    CHECK(edges[0]->points == std::vector<glm::dvec3>{{1, 1, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}});
    CHECK(edges[0]->style->colour == glm::vec3(1, 1, 0));
    // with the edge flag off no edge is drawn whatever the data says
    const DrawList& off = s.draw({e});
    CHECK(itemsOf<DrawPolyline>(off).empty());
    CHECK(itemsOf<DrawFillArea>(off).size() == 2);
}

TEST_CASE("random sets of fill area sets draw one fill area per set with a contour", "[plus][traverse]") {
    std::mt19937 rng(20261203);
    Scene s;
    for (int round = 0; round < 50; ++round) {
        const SetOfFillAreaSetsElement e = randomSofas(rng);
        REQUIRE(validateElement(e).empty());
        std::size_t expected = 0;
        for (const auto& set : e.sets)
            expected += std::any_of(set.begin(), set.end(), [](const auto& c) { return c.size() >= 3; });
        // Flat shading (NONE, the default) draws each set in one colour: its vertex colours are
        // not drawn; COLOUR interpolates them.
        const bool flat = round % 2 == 0;
        const auto areas = itemsOf<DrawFillArea>(
            s.draw({IndexAttribute{ElementType::InteriorShadingMethod,
                                   int(flat ? ShadingMethod::None : ShadingMethod::Colour)},
                    e}));
        CHECK(areas.size() == expected);
        for (const DrawFillArea* a : areas)
            CHECK(a->vertexColours.size() == (e.vertexColours.empty() || flat ? 0 : a->contours.size()));
    }
}

TEST_CASE("the rendering colour model in force is resolved into each area's interior style",
          "[plus][traverse][colour]") {
    std::mt19937 rng(20261204);
    Scene s;
    SetOfFillAreaSetsElement e;
    e.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    e.sets = {{{0, 1, 2}}};
    for (int round = 0; round < 20; ++round) {
        // Models set between the areas, some outside 1 .. 4 (0, workstation dependent, and
        // unknown ones are drawn as RGB).
        std::vector<Element> elements;
        std::vector<ColourModel> expected;
        int current = 0;
        for (int k = randomInt(rng, 1, 6); k > 0; --k) {
            if (randomInt(rng, 0, 1)) {
                current = randomInt(rng, -1, 6);
                elements.push_back(IndexAttribute{ElementType::RenderingColourModel, current});
            }
            elements.push_back(e);
            expected.push_back(current >= 1 && current <= 4 ? static_cast<ColourModel>(current)
                                                            : ColourModel::Rgb);
        }
        const auto areas = itemsOf<DrawFillArea>(s.draw(elements));
        REQUIRE(areas.size() == expected.size());
        for (std::size_t i = 0; i < areas.size(); ++i)
            CHECK(areas[i]->interior->renderingModel == expected[i]);
    }
}

TEST_CASE("a PSEUDO colour mapping changes the drawn colours, TRUE leaves them", "[plus][traverse][colour]") {
    Scene s;
    s.ws->setColourMappingRepresentation(
        2, pseudoRamp({{0, 0, 0}, {0.5, 0.5, 0.5}, {1, 1, 1}}, {1.0 / 3, 1.0 / 3, 1.0 / 3}));
    ColourMapping n;
    n.method = ColourMappingMethod::PseudoN;
    n.lists = {{0, 3}, {0, 1}, {0, 4}};  // red 1 -> 3, green 1 -> 1, blue 1 -> 4: summed, a colour index
    s.ws->setColourMappingRepresentation(3, n);
    const Element line = polyline3({{0, 0, 0}, {1, 0, 0}});
    TriangleStripElement strip{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                               {Colour::fromRgb({1, 0, 0}), Colour::indexed(3), Colour::fromRgb({1, 1, 1})},
                               {}};
    const DrawList& list =
        s.draw({polylineColourIndex(2), line, IndexAttribute{ElementType::ColourMappingIndex, 2}, line,
                IndexAttribute{ElementType::InteriorShadingMethod, int(ShadingMethod::Colour)}, strip,
                IndexAttribute{ElementType::ColourMappingIndex, 3}, line,
                IndexAttribute{ElementType::ColourMappingIndex, 9}, line});
    const auto lines = itemsOf<DrawPolyline>(list);
    REQUIRE(lines.size() == 4);
    CHECK(lines[0]->style->colour == glm::vec3(1, 0, 0));  // entry 0: TRUE
    CHECK(lines[1]->style->colour == glm::vec3(0.5f));     // red: v = 1/3 -> the middle of the ramp
    CHECK(lines[2]->style->colour == glm::vec3(0, 1, 0));  // red: 3 + 0 + 0, colour 3
    CHECK(lines[3]->style->colour == glm::vec3(1, 0, 0));  // undefined 9 maps as 0
    const auto meshes = itemsOf<DrawMesh>(list);
    REQUIRE(meshes.size() == 1);
    CHECK(meshes[0]->mesh->colours == std::vector<glm::vec3>{glm::vec3(0.5f), glm::vec3(0.5f), glm::vec3(1)});
}

TEST_CASE("light and depth cue colours in a model draw as RGB, an index through the table as it is now",
          "[plus][traverse][colour]") {
    std::mt19937 rng(4411);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int round = 0; round < 30; ++round) {
        Scene s;
        const auto model = static_cast<ColourModel>(randomInt(rng, 1, 4));
        const glm::dvec3 c{unit(rng), unit(rng), unit(rng)};
        Light sun;
        sun.type = LightType::Directional;
        s.ws->setLightSourceRepresentation(2, sun, Colour::inModel(model, c));
        s.ws->setLightSourceRepresentation(3, Light{}, Colour::indexed(9));
        DepthCue cue;
        cue.enabled = true;
        s.ws->setDepthCueRepresentation(1, cue, Colour::indexed(9));
        CHECK(s.ws->tables().givenLightColour(2) == Colour::inModel(model, c));  // kept as given
        CHECK(s.ws->tables().givenDepthCueColour(1) == Colour::indexed(9));
        for (int change = 0; change < 2; ++change) {
            const glm::dvec3 entry{unit(rng), unit(rng), unit(rng)};
            s.ws->setColourRepresentation(9, entry);
            const DrawList& list =
                s.draw({LightSourceStateAttribute{{2, 3}, {}}, IndexAttribute{ElementType::DepthCueIndex, 1},
                        polyline3({{0, 0, 0}, {1, 0, 0}})});
            REQUIRE(list.items.size() == 1);
            const std::vector<Light>& lights = list.lightSets.at(std::size_t(list.items[0].lightSet()));
            REQUIRE(lights.size() == 2);
            const glm::vec3 sunRgb(clampedRgb(model, c));
            CHECK(glm::length(lights[0].colour - sunRgb) < 1e-5f);
            CHECK(lights[1].colour == glm::vec3(entry));
            CHECK(list.depthCues.at(std::size_t(list.items[0].depthCue())).colour == glm::vec3(entry));
        }
    }
    Scene s;
    CHECK(errorOf([&] { s.ws->setLightSourceRepresentation(2, Light{}, Colour::indexed(-1)); }) == 113);
    CHECK(errorOf([&] { s.ws->setDepthCueRepresentation(1, DepthCue{}, Colour::indexed(-2)); }) == 113);
    CHECK_FALSE(s.ws->tables().lights.contains(2));
}

TEST_CASE("a colour mapping change waits for the update under ASTI", "[plus][colour]") {
    Scene s;
    const Element line = polyline3({{0, 0, 0}, {1, 0, 0}});
    s.draw({IndexAttribute{ElementType::ColourMappingIndex, 1}, line});
    s.ws->setDeferralState(DeferralMode::Asti, ModificationMode::Nive);
    s.ws->setColourMappingRepresentation(1, pseudoRamp({{0, 0, 1}}, {1, 0, 0}));
    CHECK(std::get<DrawPolyline>(s.ws->display().items[0].primitive).style->colour == glm::vec3(1));
    CHECK(s.ws->visualState() == VisualState::Deferred);
    s.ws->update(Regeneration::Perform);
    CHECK(std::get<DrawPolyline>(s.ws->display().items[0].primitive).style->colour == glm::vec3(0, 0, 1));
    CHECK(s.ws->tables().colourMappings.get(1).colours.size() == 1);
}

TEST_CASE("PSEUDO and PSEUDO_N entries read a colour's components in their own model", "[plus][colour]") {
    std::mt19937 rng(6203);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    ColourTable colours;
    for (int round = 0; round < 200; ++round) {
        const auto model = static_cast<ColourModel>(randomInt(rng, 1, 4));
        const glm::dvec3 rgb{unit(rng), unit(rng), unit(rng)}, c = fromRgb(model, rgb);
        ColourMappingTable table;
        ColourMapping m = pseudoRamp({}, {unit(rng) / 2, unit(rng) / 2, unit(rng) / 2});
        m.model = model;
        for (int k = randomInt(rng, 1, 6); k > 0; --k) m.colours.push_back({unit(rng), unit(rng), unit(rng)});
        table.set(1, m, nullptr, "test");
        const double v = std::clamp(glm::dot(m.weights, c), 0.0, 1.0) * double(m.colours.size() - 1);
        if (std::abs(v - std::floor(v) - 0.5) > 1e-6) {
            const glm::dvec3 expected = clampedRgb(model, m.colours[std::size_t(std::lround(v))]);
            CHECK(glm::length(table.map(1, rgb, colours) - expected) < 1e-9);
        }
        ColourMapping n;
        n.method = ColourMappingMethod::PseudoN;
        n.model = model;
        double sum = 0.0;
        bool boundary = false;
        for (int k = 0; k < 3; ++k) {
            auto& list = n.lists.emplace_back();
            for (int i = randomInt(rng, 1, 4); i > 0; --i) list.push_back(randomInt(rng, 0, 2));
            const double x = std::clamp(c[k], 0.0, 1.0) * double(list.size() - 1);
            boundary = boundary || std::abs(x - std::floor(x) - 0.5) < 1e-6;
            sum += list[std::size_t(std::lround(x))];
        }
        table.set(2, n, nullptr, "test");
        if (!boundary) CHECK(table.map(2, rgb, colours) == colours.get(int(sum)));
        CHECK(table.get(2).model == model);
    }
    ColourMappingTable table;
    ColourMapping bad = pseudoRamp({{0, 0, 0}}, {1, 0, 0});
    bad.model = static_cast<ColourModel>(5);
    CHECK(errorOf([&] { table.set(1, bad, nullptr, "test"); }) == 110);
}

TEST_CASE("colour mapping representations refuse bad entries and change nothing", "[plus][colour]") {
    Scene s;
    const ColourMappingTable before = s.ws->tables().colourMappings;
    ColourMapping bad = pseudoRamp({}, {1, 0, 0});
    CHECK(errorOf([&] { s.ws->setColourMappingRepresentation(-1, ColourMapping{}); }) == 121);
    CHECK(errorOf([&] { s.ws->setColourMappingRepresentation(1, bad); }) == -207);
    bad.colours = {{0, 1.5, 0}};
    CHECK(errorOf([&] { s.ws->setColourMappingRepresentation(1, bad); }) == 118);
    bad.colours = {{0, 1, 0}}, bad.weights.x = std::nan("");
    CHECK(errorOf([&] { s.ws->setColourMappingRepresentation(1, bad); }) == -207);
    ColourMapping n;
    n.method = ColourMappingMethod::PseudoN;
    n.lists = {{0}, {}, {1}};
    CHECK(errorOf([&] { s.ws->setColourMappingRepresentation(1, n); }) == -207);
    n.method = static_cast<ColourMappingMethod>(4);
    CHECK(errorOf([&] { s.ws->setColourMappingRepresentation(1, n); }) == 126);
    CHECK(s.ws->tables().colourMappings == before);
    for (int i = 1; i < ColourMappingTable::kCapacity; ++i)
        s.ws->setColourMappingRepresentation(i, ColourMapping{});
    CHECK(errorOf([&] { s.ws->setColourMappingRepresentation(99, ColourMapping{}); }) == 103);
}

TEST_CASE("the new elements are checked with a reason naming the fault", "[plus][store]") {
    PolylineSetWithDataElement lines{{{{0, 0, 0}, {1, 0, 0}}}, {{Colour::indexed(1)}}};
    CHECK(validateElement(lines) == "polyline 0 has 1 vertex colours for 2 vertices");
    CellArrayPlusElement cells{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2, 2, {Colour::indexed(1)}};
    CHECK(validateElement(cells) == "cell array has 1 colours for 2 x 2 cells");
    SetOfFillAreaSetsElement sets;
    sets.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    sets.sets = {{{0, 1, 3}}};
    CHECK(validateElement(sets) == "set 0 contour 0: vertex index 3 outside 0..2");
    sets.sets = {{{0, 1, 2}}};
    sets.edgeFlags = {{{1, 2, 0}}};
    CHECK(validateElement(sets) == "set 0 contour 0: edge flag 2 is neither 0 nor 1");
    sets.edgeFlags = {};
    sets.facetColours = {Colour::indexed(1), Colour::indexed(2)};
    CHECK(validateElement(sets) == "2 facet colours for 1 sets");
    Scene s;
    s.store->openStructure(2);
    CHECK(errorOf([&] { s.store->insert(sets); }) == -202);
    CHECK(s.store->elementCount(2) == 0);
}

TEST_CASE("seeded random PHIGS PLUS elements survive the store and the archive", "[plus][archive]") {
    std::mt19937 rng(7919);
    for (int round = 0; round < 40; ++round) {
        std::vector<Element> elements;
        for (int k = randomInt(rng, 1, 8); k > 0; --k) elements.push_back(randomPlusElement(rng));
        Scene s;
        s.draw(elements);  // traversal takes every member
        for (std::size_t k = 0; k < elements.size(); ++k)
            CHECK(s.store->elementAt(1, static_cast<int>(k) + 1) == elements[k]);
        const std::map<int, std::vector<Element>> contents{{1, elements}};
        const std::string text = ArchiveFile::encode(contents);
        CHECK(ArchiveFile::decode(text, "random", nullptr) == contents);
    }
}

TEST_CASE("corrupt PHIGS PLUS archive data is rejected with the reason", "[plus][archive]") {
    SetOfFillAreaSetsElement sets;
    sets.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    sets.sets = {{{0, 1, 2}}};
    std::string text = ArchiveFile::encode({{1, {sets}}});
    const auto at = text.find(" 0 1 2");
    REQUIRE(at != std::string::npos);
    text.replace(at, 6, " 0 1 7");
    try {
        ArchiveFile::decode(text, "corrupt.phar", nullptr);
        FAIL("decoded");
    } catch (const Error& e) {
        CHECK(e.number() == 403);
        CHECK_THAT(e.what(),
                   Catch::Contains("corrupt.phar") && Catch::Contains("vertex index 7 outside 0..2"));
    }
    std::string lines = ArchiveFile::encode(
        {{1, {CellArrayPlusElement{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1, 1, {Colour::indexed(3)}}}}});
    const auto dims = lines.find(" 1 1 ");
    REQUIRE(dims != std::string::npos);
    lines.replace(dims, 5, " 2 1 ");
    CHECK(errorOf([&] { ArchiveFile::decode(lines, "cells.phar", nullptr); }) == 403);
}

}  // namespace test_plus_data
