#include "PickScenes.h"

#include "phigs/pick/Picker.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace test_pick_scenes {

using namespace phigs;
using phigs::test::item;
using phigs::test::square;
using phigs::test::unitList;

namespace {

/// Root 10 executes 20 (element 3, pick id 1), which executes 30 (element 5, pick id 2),
/// whose element 7 (pick id 9) is a polyline along y = 0.5.
DrawList threeLevelScene() {
    DrawList list = unitList();
    DrawPolyline line;
    line.points = {{0.1, 0.5, 0.5}, {0.9, 0.5, 0.5}};
    list.items.push_back(item(line, {{10, 3, 1}, {20, 5, 2}, {30, 7, 9}}));
    return list;
}

}  // namespace

TEST_CASE("pick: a polyline is hit within the aperture and missed outside it", "[pick]") {
    const DrawList list = threeLevelScene();
    const Picker picker;
    CHECK(picker.pick(list, {0.5, 0.505}, {0.01}).status == InputStatus::Ok);
    CHECK(picker.pick(list, {0.5, 0.52}, {0.01}).status == InputStatus::None);
    CHECK(picker.pick(list, {0.5, 0.52}, {0.03}).status == InputStatus::Ok);
    // Past the end of the line.
    CHECK(picker.pick(list, {0.95, 0.5}, {0.01}).status == InputStatus::None);
}

TEST_CASE("pick: the path lists structure, element and pick id in both orders and depths", "[pick]") {
    const DrawList list = threeLevelScene();
    const Picker picker;
    const PickPathItem top{10, 3, 1}, middle{20, 5, 2}, bottom{30, 7, 9};

    PickOptions o;
    o.order = PathOrder::TopFirst;
    CHECK(picker.pick(list, {0.5, 0.5}, o).path == std::vector<PickPathItem>{top, middle, bottom});
    o.depth = 1;
    CHECK(picker.pick(list, {0.5, 0.5}, o).path == std::vector<PickPathItem>{top});
    o.depth = 2;
    CHECK(picker.pick(list, {0.5, 0.5}, o).path == std::vector<PickPathItem>{top, middle});

    o.order = PathOrder::BottomFirst;
    o.depth = 0;
    CHECK(picker.pick(list, {0.5, 0.5}, o).path == std::vector<PickPathItem>{bottom, middle, top});
    o.depth = 1;
    CHECK(picker.pick(list, {0.5, 0.5}, o).path == std::vector<PickPathItem>{bottom});
    o.depth = 2;
    CHECK(picker.pick(list, {0.5, 0.5}, o).path == std::vector<PickPathItem>{bottom, middle});
    o.depth = 5;  // deeper than the path: all of it
    CHECK(picker.pick(list, {0.5, 0.5}, o).path.size() == 3);
}

TEST_CASE("pick: hits are ordered nearest first and the nearest wins", "[pick]") {
    DrawList list = unitList();
    list.items.push_back(item(square(0.2, 0.8, 0.3), {{1, 1, 11}}));  // back
    list.items.push_back(item(square(0.3, 0.7, 0.9), {{1, 2, 12}}));  // front
    list.items.push_back(item(square(0.1, 0.9, 0.6), {{1, 3, 13}}));  // middle
    const Picker picker;
    const auto hits = picker.hits(list, {0.5, 0.5}, 0.001);
    REQUIRE(hits.size() == 3);
    CHECK(hits[0].item == 1);
    CHECK(hits[1].item == 2);
    CHECK(hits[2].item == 0);
    CHECK(hits[0].depth == Approx(0.9));
    CHECK(picker.pick(list, {0.5, 0.5}, {0.001}).path.back().pickId == 12);
    // Outside the front square the middle one is nearest.
    CHECK(picker.pick(list, {0.25, 0.5}, {0.001}).path.back().pickId == 13);
}

TEST_CASE("pick: equal depth goes to the item drawn later", "[pick]") {
    DrawList list = unitList();
    list.items.push_back(item(square(0.2, 0.8, 0.5), {{1, 1, 1}}));
    list.items.push_back(item(square(0.2, 0.8, 0.5), {{1, 2, 2}}));
    CHECK(Picker().pick(list, {0.5, 0.5}, {0.001}).path.back().elementNumber == 2);
}

TEST_CASE("pick: items the pick filter excludes are not picked and do not hide others", "[pick]") {
    DrawList list = unitList();
    list.items.push_back(item(square(0.2, 0.8, 0.3), {{1, 1, 1}}));
    list.items.push_back(item(square(0.2, 0.8, 0.9), {{1, 2, 2}}));
    list.items[1].context.edit().pickable = false;
    const Picker picker;
    CHECK(picker.pick(list, {0.5, 0.5}, {0.001}).path.back().pickId == 1);
    list.items[0].context.edit().pickable = false;
    CHECK(picker.pick(list, {0.5, 0.5}, {0.001}).status == InputStatus::None);
}

TEST_CASE("pick: fill area sets use the even-odd rule and hollow ones only their boundary", "[pick]") {
    DrawList list = unitList();
    DrawFillArea ring = square(0.2, 0.8, 0.5);
    ring.contours.push_back({{0.4, 0.4, 0.5}, {0.6, 0.4, 0.5}, {0.6, 0.6, 0.5}, {0.4, 0.6, 0.5}});
    list.items.push_back(item(ring, {{1, 1, 0}}));
    const Picker picker;
    CHECK(picker.pick(list, {0.3, 0.3}, {0.001}).status == InputStatus::Ok);
    CHECK(picker.pick(list, {0.5, 0.5}, {0.001}).status == InputStatus::None);  // in the hole
    CHECK(picker.pick(list, {0.5, 0.5}, {0.15}).status == InputStatus::Ok);     // aperture reaches the ring
    CHECK(picker.pick(list, {0.9, 0.9}, {0.001}).status == InputStatus::None);

    editPrimitive<DrawFillArea>(list.items[0].primitive).interior.edit().style = InteriorStyle::Hollow;
    CHECK(picker.pick(list, {0.3, 0.3}, {0.001}).status == InputStatus::None);
    CHECK(picker.pick(list, {0.2, 0.3}, {0.001}).status == InputStatus::Ok);  // on the outer edge
    CHECK(picker.pick(list, {0.4, 0.5}, {0.001}).status == InputStatus::Ok);  // on the hole's edge

    auto& empty = editPrimitive<DrawFillArea>(list.items[0].primitive);
    empty.interior.edit().style = InteriorStyle::Empty;
    CHECK(picker.pick(list, {0.2, 0.3}, {0.001}).status == InputStatus::None);
    empty.edges.edit().visible = true;
    CHECK(picker.pick(list, {0.2, 0.3}, {0.001}).status == InputStatus::Ok);
}

TEST_CASE("pick: a tilted fill area reports the depth of its plane under the aperture", "[pick]") {
    DrawList list = unitList();
    DrawFillArea f;
    f.contours = {{{0.0, 0.0, 0.0}, {1.0, 0.0, 1.0}, {1.0, 1.0, 1.0}, {0.0, 1.0, 0.0}}};  // z = x
    f.interior.edit().style = InteriorStyle::Solid;
    list.items.push_back(item(f, {{1, 1, 0}}));
    const auto hits = Picker().hits(list, {0.25, 0.5}, 0.001);
    REQUIRE(hits.size() == 1);
    CHECK(hits[0].depth == Approx(0.25).margin(1e-12));
}

TEST_CASE("pick: fill areas whose signed areas cancel are picked on their plane", "[pick]") {
    // A tilted bow-tie (z = x) and two squares wound against each other: Newell's normal cancels,
    // the even-odd rule fills both, so they are picked, at the depth of their plane.
    DrawList list = unitList();
    DrawFillArea bowTie;
    bowTie.contours = {{{0.1, 0.1, 0.1}, {0.5, 0.5, 0.5}, {0.5, 0.1, 0.5}, {0.1, 0.5, 0.1}}};
    bowTie.interior.edit().style = InteriorStyle::Solid;
    list.items.push_back(item(bowTie, {{1, 1, 0}}));
    DrawFillArea pair;
    pair.contours = {{{0.6, 0.6, 0.4}, {0.7, 0.6, 0.4}, {0.7, 0.7, 0.4}, {0.6, 0.7, 0.4}},
                     {{0.8, 0.6, 0.4}, {0.8, 0.7, 0.4}, {0.9, 0.7, 0.4}, {0.9, 0.6, 0.4}}};
    pair.interior.edit().style = InteriorStyle::Solid;
    list.items.push_back(item(pair, {{2, 1, 0}}));
    const Picker picker;
    const auto lobe = picker.hits(list, {0.15, 0.3}, 0.001);  // the left lobe, away from its edges
    REQUIRE(lobe.size() == 1);
    CHECK(lobe[0].depth == Approx(0.15).margin(1e-12));
    CHECK(picker.pick(list, {0.3, 0.15}, {0.001}).status == InputStatus::None);  // between the lobes
    CHECK(picker.pick(list, {0.65, 0.65}, {0.001}).path.front().structureId == 2);
    CHECK(picker.pick(list, {0.85, 0.65}, {0.001}).path.front().structureId == 2);
}

TEST_CASE("pick: polymarkers are hit within the aperture widened by the marker size", "[pick]") {
    DrawList list = unitList();
    DrawPolymarker m;
    m.points = {{0.2, 0.2, 0.5}, {0.7, 0.7, 0.5}};
    m.style.edit().scale = 2.0f;  // 14 pixels = 0.14 NPC on a 100 pixel viewport: half size 0.07
    list.items.push_back(item(m, {{1, 4, 3}}));
    const Picker picker;
    CHECK(picker.pick(list, {0.7, 0.7}, {0.001}).status == InputStatus::Ok);
    CHECK(picker.pick(list, {0.76, 0.7}, {0.001}).status == InputStatus::Ok);
    CHECK(picker.pick(list, {0.78, 0.7}, {0.001}).status == InputStatus::None);
    CHECK(picker.pick(list, {0.45, 0.45}, {0.01}).status == InputStatus::None);  // between markers
}

TEST_CASE("pick: text is picked by its box", "[pick]") {
    DrawList list = unitList();
    DrawText t;
    t.text = "WING";  // four character boxes of 0.1 x 0.1
    t.position = {0.2, 0.3, 0.5};
    t.style.edit().height = 0.1;
    list.items.push_back(item(t, {{1, 2, 0}}));
    const Picker picker;
    CHECK(picker.pick(list, {0.25, 0.35}, {0.001}).status == InputStatus::Ok);
    CHECK(picker.pick(list, {0.59, 0.39}, {0.001}).status == InputStatus::Ok);
    CHECK(picker.pick(list, {0.61, 0.35}, {0.001}).status == InputStatus::None);
    CHECK(picker.pick(list, {0.3, 0.41}, {0.001}).status == InputStatus::None);

    // Centred horizontally and half-way vertically.
    auto& centred = editPrimitive<DrawText>(list.items[0].primitive);
    centred.style.edit().horizontal = HorizontalAlignment::Centre;
    centred.style.edit().vertical = VerticalAlignment::Half;
    CHECK(picker.pick(list, {0.05, 0.27}, {0.001}).status == InputStatus::Ok);
    CHECK(picker.pick(list, {0.41, 0.3}, {0.001}).status == InputStatus::None);

    // Annotation text: the box lives in NPC at an offset from the projected reference point.
    DrawText a;
    a.text = "AB";
    a.annotation = true;
    a.position = {0.5, 0.5, 0.5};
    a.annotationOffset = {0.1, 0.2, 0.0};
    a.style.edit().height = 0.05;
    list.items = {item(a, {{1, 3, 0}})};
    CHECK(picker.pick(list, {0.65, 0.72}, {0.001}).status == InputStatus::Ok);
    CHECK(picker.pick(list, {0.55, 0.55}, {0.001}).status == InputStatus::None);
}

TEST_CASE("pick: curves are picked along their tessellation", "[pick]") {
    DrawList list = unitList();
    DrawCurve c;
    c.points = {{0.1, 0.1, 0.5}, {0.5, 0.9, 0.5}, {0.9, 0.1, 0.5}};
    list.items.push_back(item(c, {{2, 1, 4}}));
    const Picker picker;
    CHECK(picker.pick(list, {0.3, 0.5}, {0.005}).status == InputStatus::Ok);
    CHECK(picker.pick(list, {0.5, 0.5}, {0.005}).status == InputStatus::None);
}

TEST_CASE("pick: meshes are picked by their triangles with interpolated depth", "[pick]") {
    DrawList list = unitList();
    auto mesh = std::make_shared<MeshData>();
    mesh->positions = {{0.1f, 0.1f, 0.2f}, {0.9f, 0.1f, 0.2f}, {0.1f, 0.9f, 0.8f}};
    mesh->triangles = {0, 1, 2};
    DrawMesh m;
    m.mesh = mesh;
    m.interior.edit().style = InteriorStyle::Solid;
    list.items.push_back(item(m, {{3, 2, 5}}));
    const Picker picker;
    const auto hits = picker.hits(list, {0.2, 0.5}, 0.001);
    REQUIRE(hits.size() == 1);
    CHECK(hits[0].depth == Approx(0.2 + 0.6 * 0.5).epsilon(1e-6));
    CHECK_FALSE(hits[0].surface.has_value());
    CHECK(picker.pick(list, {0.8, 0.8}, {0.001}).status == InputStatus::None);
    CHECK(picker.pick(list, {0.8, 0.8}, {0.35}).status == InputStatus::Ok);
}

TEST_CASE("pick: modelling and viewing transformations are applied", "[pick]") {
    DrawList list = unitList();
    DrawItem i = item(square(0.0, 0.2, 0.0), {{1, 1, 0}});
    i.context.edit().modelTransform = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.0, 0.5));
    list.items.push_back(i);
    list.views[0].orientation = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.5, 0.0));
    const Picker picker;
    CHECK(picker.pick(list, {0.6, 0.6}, {0.001}).status == InputStatus::Ok);
    CHECK(picker.pick(list, {0.1, 0.1}, {0.001}).status == InputStatus::None);
}

TEST_CASE("pick: view clipping and the workstation window limit what can be picked", "[pick]") {
    DrawList list = unitList();
    list.items.push_back(item(square(0.1, 0.9, 0.5), {{1, 1, 0}}));
    list.views[0].clipMin = {0.0, 0.0, 0.0};
    list.views[0].clipMax = {0.5, 1.0, 1.0};
    const Picker picker;
    CHECK(picker.pick(list, {0.3, 0.5}, {0.001}).status == InputStatus::Ok);
    CHECK(picker.pick(list, {0.7, 0.5}, {0.001}).status == InputStatus::None);
    list.views[0].clipXY = false;
    CHECK(picker.pick(list, {0.7, 0.5}, {0.001}).status == InputStatus::Ok);

    // Depth clipping: a square behind the back plane.
    list.views[0].clipMin.z = 0.6;
    CHECK(picker.pick(list, {0.3, 0.5}, {0.001}).status == InputStatus::None);
    list.views[0].clipBack = false;
    CHECK(picker.pick(list, {0.3, 0.5}, {0.001}).status == InputStatus::Ok);

    list.windowMax = {0.5, 0.5, 1.0};
    CHECK(picker.pick(list, {0.3, 0.3}, {0.001}).status == InputStatus::Ok);
    CHECK(picker.pick(list, {0.3, 0.7}, {0.001}).status == InputStatus::None);
}

TEST_CASE("pick: each item is picked in its own view", "[pick]") {
    DrawList list = unitList();
    DrawView shifted;
    shifted.orientation = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.0, 0.0));
    list.views.push_back(shifted);
    DrawItem i = item(square(0.0, 0.2, 0.5), {{1, 1, 0}});
    i.context.edit().viewIndex = 1;
    list.items.push_back(i);
    const Picker picker;
    CHECK(picker.pick(list, {0.6, 0.1}, {0.001}).status == InputStatus::Ok);
    CHECK(picker.pick(list, {0.1, 0.1}, {0.001}).status == InputStatus::None);
}

TEST_CASE("pick: echo highlights every item of the picked element instance", "[pick]") {
    DrawList list = unitList();
    list.items.push_back(item(square(0.2, 0.8, 0.5), {{1, 2, 0}, {5, 4, 7}}));
    DrawPolyline edges;
    edges.points = {{0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}};
    list.items.push_back(item(edges, {{1, 2, 0}, {5, 4, 7}}));                  // same element
    list.items.push_back(item(square(0.2, 0.8, 0.1), {{1, 2, 0}, {5, 6, 7}}));  // another element
    list.items.push_back(item(square(0.2, 0.8, 0.1), {{1, 3, 0}, {5, 4, 7}}));  // another instance
    const Picker picker;
    const auto hit = picker.nearest(list, {0.5, 0.5}, 0.001);
    REQUIRE(hit);
    CHECK(hit->item == 0);
    CHECK(echoItems(list, *hit) == std::vector<std::size_t>{0, 1});
    // Prompt/echo type 2: the whole structure instance (structure 5 under element 2 of 1).
    CHECK(echoItems(list, *hit, true) == std::vector<std::size_t>{0, 1, 2});
}

TEST_CASE("pick: a perspective view picks what lies under the point on screen", "[pick]") {
    DrawList list = unitList();
    // Eye at z = 2 looking down -z; the far square is bigger in world but smaller on screen.
    const glm::dmat4 proj = glm::perspective(glm::radians(60.0), 1.0, 0.5, 10.0);
    const glm::dmat4 toNpc = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 0.5)) *
                             glm::scale(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, -0.5));
    list.views[0].mapping = toNpc * proj;
    list.views[0].orientation = glm::lookAt(glm::dvec3(0, 0, 2), glm::dvec3(0.0), glm::dvec3(0, 1, 0));
    list.items.push_back(item(square(-0.5, 0.5, 0.0), {{1, 1, 1}}));   // near square, 2 from the eye
    list.items.push_back(item(square(-2.0, 2.0, -4.0), {{1, 2, 2}}));  // far square, 6 from the eye
    const Picker picker;
    CHECK(picker.pick(list, {0.5, 0.5}, {0.001}).path.back().pickId == 1);
    // Near square spans NPC 0.5 +- 0.5 * 0.5 / (2 tan 30°) = 0.5 +- 0.2165; far: +- 0.2887.
    CHECK(picker.pick(list, {0.74, 0.5}, {0.001}).path.back().pickId == 2);
    CHECK(picker.pick(list, {0.8, 0.5}, {0.001}).status == InputStatus::None);
}

}  // namespace test_pick_scenes
