#include "PickScenes.h"

#include "phigs/input/ScriptInputSource.h"
#include "phigs/input/WorkstationInput.h"
#include "phigs/pick/DrawListMeasurer.h"

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace test_input_locator {

using namespace phigs;
using phigs::test::item;
using phigs::test::square;
using phigs::test::unitList;

namespace {

/// View 0 covers NPC with world = NPC; view 1 holds the left half of NPC and shows world
/// scaled by 1/10 (orientation) and shifted by 0.25 in x (mapping).
DrawList twoViews() {
    DrawList list = unitList();
    DrawView left;
    left.orientation = glm::scale(glm::dmat4(1.0), glm::dvec3(0.1));
    left.mapping = glm::translate(glm::dmat4(1.0), glm::dvec3(0.25, 0.0, 0.0));
    left.clipMin = {0.0, 0.0, 0.0};
    left.clipMax = {0.5, 1.0, 1.0};
    list.views.push_back(left);
    return list;
}

}  // namespace

TEST_CASE("input locator: positions go back through the workstation and view transformations", "[input]") {
    DrawList list = twoViews();
    DrawListMeasurer m(list);
    // Pixel (20, 70) on a 100 pixel viewport, y down: NPC (0.2, 0.3).
    const auto npc = m.toNpc({20, 70});
    CHECK(npc.x == Approx(0.2));
    CHECK(npc.y == Approx(0.3));

    // View 0 has the highest input priority at first, and holds every point.
    LocatorMeasure a = m.locate({20, 70});
    CHECK(a.viewIndex == 0);
    CHECK(a.position.x == Approx(0.2));
    CHECK(a.position.y == Approx(0.3));

    // Raise view 1 above view 0: points in its clip limits now map through it.
    list.viewInputPriority = {1, 0};
    a = m.locate({20, 70});
    CHECK(a.viewIndex == 1);
    CHECK(a.position.x == Approx((0.2 - 0.25) * 10.0));
    CHECK(a.position.y == Approx(3.0));
    // Outside view 1's clip limits view 0 still answers.
    a = m.locate({80, 70});
    CHECK(a.viewIndex == 0);
    CHECK(a.position.x == Approx(0.8));

    // A 3D locator: the NPC depth given to 2D positions maps back too.
    m.setLocatorDepth(0.5);
    CHECK(m.locate({20, 70}).position.z == Approx(5.0));

    // Lower it again.
    list.viewInputPriority = {0, 1};
    CHECK(m.locate({20, 70}).viewIndex == 0);
}

TEST_CASE("input locator: the workstation window maps onto the viewport with one scale", "[input]") {
    DrawList list = unitList();
    list.windowMin = {0.0, 0.0, 0.0};
    list.windowMax = {0.5, 1.0, 1.0};  // half as wide as high on a square viewport
    list.viewportMax = {200.0, 100.0, 1.0};
    list.displaySize = {200.0, 100.0};
    DrawListMeasurer m(list);
    // Scale is min(200/0.5, 100/1) = 100 pixels per NPC unit.
    const auto npc = m.toNpc({50, 75});
    CHECK(npc.x == Approx(0.5));
    CHECK(npc.y == Approx(0.25));
    // The same display on a surface of 400 x 300 pixels: 2 pixels per device unit, the
    // display's 200 x 100 at the bottom left.
    m.setSurfaceSize(400, 300);
    CHECK(m.toNpc({100, 250}).x == Approx(0.5));
    CHECK(m.toNpc({100, 250}).y == Approx(0.25));
}

TEST_CASE("input locator: a stroke uses the one view that holds all its points", "[input]") {
    DrawList list = twoViews();
    list.viewInputPriority = {1, 0};
    DrawListMeasurer m(list);
    StrokeMeasure s = m.stroke({{10, 90}, {40, 90}});
    CHECK(s.viewIndex == 1);
    REQUIRE(s.points.size() == 2);
    CHECK(s.points[1].x == Approx((0.4 - 0.25) * 10));
    s = m.stroke({{10, 90}, {60, 90}});  // crosses out of view 1
    CHECK(s.viewIndex == 0);
    CHECK(s.points[1].x == Approx(0.6));
}

TEST_CASE("input pick: a scripted pick goes through the measurer with the device's settings", "[input]") {
    DrawList list = unitList();
    list.items.push_back(item(square(0.2, 0.8, 0.5), {{7, 2, 1}, {8, 4, 5}}));
    DrawPolyline edge;
    edge.points = {{0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}};
    list.items.push_back(item(edge, {{7, 2, 1}, {8, 4, 5}}));
    DrawListMeasurer measurer(list);
    ScriptInputSource script("pick 50 50\npick 50 50\npick 95 5\n", "pick.txt");
    InputQueue queue;
    WorkstationInput input(1, script, measurer, queue);

    auto [status, measure] = input.request(InputClass::Pick, 1);
    CHECK(status == InputStatus::Ok);
    CHECK(std::get<PickMeasure>(measure).path == std::vector<PickPathItem>{{7, 2, 1}, {8, 4, 5}});
    CHECK(measurer.lastEcho() == std::vector<std::size_t>{0, 1});

    DeviceInitialisation p;
    p.initial = PickMeasure{};
    p.pathOrder = PathOrder::BottomFirst;
    input.initialise(InputClass::Pick, 1, p);
    input.setPickPathDepth(1, 1);
    input.setMode(InputClass::Pick, 1, OperatingMode::Event, EchoSwitch::NoEcho);
    const auto e = queue.awaitEvent(std::chrono::milliseconds(0));
    REQUIRE(e);
    CHECK(std::get<PickMeasure>(e->measure).path == std::vector<PickPathItem>{{8, 4, 5}});
    CHECK(measurer.lastEcho().empty());
    const auto miss = queue.awaitEvent(std::chrono::milliseconds(0));
    REQUIRE(miss);
    CHECK(std::get<PickMeasure>(miss->measure).status == InputStatus::None);
}

TEST_CASE("input pick: a pick device can see its own filtered draw list", "[input]") {
    DrawList display = unitList();
    display.items.push_back(item(square(0.2, 0.8, 0.5), {{1, 1, 1}}));
    DrawList filtered = display;
    filtered.items[0].context.edit().pickable = false;
    DrawListMeasurer measurer(display);
    measurer.setPickListProvider([&](const InputDevice& d) -> const DrawList& {
        return d.pickExclusion.count(1) ? filtered : display;
    });
    InputDevice d;
    d.inputClass = InputClass::Pick;
    CHECK(measurer.pick({50, 50}, d).status == InputStatus::Ok);
    d.pickExclusion = {1};
    CHECK(measurer.pick({50, 50}, d).status == InputStatus::None);
}

TEST_CASE("input locator: a perspective view maps back to the point under the cursor", "[input]") {
    DrawList list = unitList();
    const glm::dmat4 proj = glm::perspective(glm::radians(60.0), 1.0, 0.5, 10.0);
    const glm::dmat4 toNpc = glm::translate(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 0.5)) *
                             glm::scale(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, -0.5));
    list.views[0].mapping = toNpc * proj;
    list.views[0].orientation = glm::lookAt(glm::dvec3(1, 2, 3), glm::dvec3(0.0), glm::dvec3(0, 1, 0));
    DrawListMeasurer m(list);
    m.setLocatorDepth(0.7);
    const LocatorMeasure a = m.locate({30, 60});
    const glm::dvec4 back = list.views[0].mapping * list.views[0].orientation * glm::dvec4(a.position, 1.0);
    CHECK(back.x / back.w == Approx(0.3).margin(1e-12));
    CHECK(back.y / back.w == Approx(0.4).margin(1e-12));
    CHECK(back.z / back.w == Approx(0.7).margin(1e-12));
}

}  // namespace test_input_locator
