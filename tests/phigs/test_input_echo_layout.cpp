#include "InputFakes.h"

#include "phigs/input/EchoLayout.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/input/WindowEventMapper.h"
#include "phigs/input/WorkstationInput.h"

#include <catch2/catch.hpp>

namespace test_input_echo_layout {

using namespace phigs;
using namespace phigs::window_event;
using phigs::test::FakeMeasurer;
using phigs::test::IdleSource;

/// Choice device initialisation: a two-row menu panel (Open, Save) over pixels 0..100 x 0..40.
DeviceInitialisation openSaveMenu() {
    return choicePanelInitialisation({"Open", "Save"}, {0, 100, 0, 40, 0, 1});
}

TEST_CASE("input echo: a choice panel stacks its alternatives in equal rows", "[input]") {
    const ChoicePanel p{2, {10, 110, 20, 80, 0, 1}, {"Wing", "Fuselage", "Tail"}};
    CHECK(p.choiceAt({50, 25}) == 1);
    CHECK(p.choiceAt({50, 45}) == 2);
    CHECK(p.choiceAt({50, 79}) == 3);
    CHECK(p.choiceAt({50, 80}) == 3);  // the bottom edge belongs to the last row
    CHECK_FALSE(p.choiceAt({5, 45}));
    CHECK_FALSE(p.choiceAt({50, 81}));
    const auto [topLeft, bottomRight] = p.row(2);
    CHECK(topLeft == glm::dvec2(10, 40));
    CHECK(bottomRight == glm::dvec2(110, 60));
}

TEST_CASE("input echo: a slider maps position to value along its long axis", "[input]") {
    const ValuatorSlider across{1, {0, 200, 0, 20, 0, 1}, -1.0, 3.0};
    CHECK(across.valueAt({0, 10}) == -1.0);
    CHECK(across.valueAt({100, 10}) == 1.0);
    CHECK(across.valueAt({250, 10}) == 3.0);  // clamped
    CHECK(across.knobAt(2.0) == 150.0);
    const ValuatorSlider upright{1, {0, 20, 0, 100, 0, 1}, 0.0, 10.0};
    CHECK(upright.valueAt({10, 100}) == 0.0);  // bottom is low
    CHECK(upright.valueAt({10, 25}) == 7.5);
    CHECK(upright.knobAt(7.5) == 25.0);
}

TEST_CASE("input echo: slider drags set values while dragged, clicks elsewhere (panels too) pick",
          "[input]") {
    WindowEventMapper m;
    EchoLayout layout;
    layout.panels.push_back({3, {0, 100, 0, 40, 0, 1}, {"Open", "Save"}});
    layout.sliders.push_back({2, {0, 100, 50, 60, 0, 1}, 0.0, 100.0});
    m.setLayout(layout);
    auto a = m.handle(ButtonPress{Button::Left, {50, 30}, false});
    REQUIRE(a);
    CHECK(std::holds_alternative<action::Pick>(a->what));      // WorkstationInput makes it the choice
    a = m.handle(ButtonPress{Button::Left, {10, 55}, false});  // starts the drag: the value there
    REQUIRE(a);
    CHECK(std::get<action::Valuator>(a->what).value == 10.0);
    a = m.handle(CursorMove{{40, 55}});  // before the release
    REQUIRE(a);
    CHECK(std::get<action::Valuator>(a->what).value == 40.0);
    CHECK_FALSE(m.handle(CursorMove{{40, 59}}));  // across the track: the value stays
    a = m.handle(ButtonRelease{Button::Left, {75, 58}});
    REQUIRE(a);
    CHECK(std::get<action::Valuator>(a->what).device == 2);
    CHECK(std::get<action::Valuator>(a->what).value == 75.0);
    a = m.handle(ButtonPress{Button::Left, {50, 90}, false});
    REQUIRE(a);
    CHECK(std::holds_alternative<action::Pick>(a->what));
}

TEST_CASE("input echo: initialising menu and slider devices gives the source its layout", "[input]") {
    IdleSource source;
    FakeMeasurer measurer;
    InputQueue queue;
    WorkstationInput input(1, source, measurer, queue);
    CHECK(input.echoLayout().empty());
    input.initialise(InputClass::Choice, 2, openSaveMenu());
    // In REQUEST mode with no request the panel takes no clicks: the source gets it in EVENT mode.
    CHECK(input.echoLayout().panels.size() == 1);
    CHECK(source.layout.panels.empty());
    input.setMode(InputClass::Choice, 2, OperatingMode::Event);
    REQUIRE(source.layout.panels.size() == 1);
    CHECK(source.layout.panels[0].device == 2);
    CHECK(source.layout.panels[0].alternatives == std::vector<std::string>{"Open", "Save"});
    DeviceInitialisation v = valuatorSliderInitialisation(0, 10, 5, {0, 100, 50, 60, 0, 1});
    input.initialise(InputClass::Valuator, 4, v);
    CHECK(source.layout.sliders.empty());
    input.setMode(InputClass::Valuator, 4, OperatingMode::Sample);
    REQUIRE(source.layout.sliders.size() == 1);
    CHECK(source.layout.sliders[0].device == 4);
    CHECK(source.layout.sliders[0].high == 10);
    // Type 1 (the implementation's own echo) draws nothing.
    input.setMode(InputClass::Valuator, 4, OperatingMode::Request);
    v.promptEchoType = 1;
    input.initialise(InputClass::Valuator, 4, v);
    input.setMode(InputClass::Valuator, 4, OperatingMode::Sample);
    CHECK(source.layout.sliders.empty());
    CHECK(source.layout.panels.size() == 1);
}

TEST_CASE("input echo: a pick or locator click inside a panel or slider chooses or sets the value",
          "[input]") {
    ScriptInputSource source("pick 50 30\nlocator 50 10\npick 75 55\npick 50 90\n", "echo.txt");
    FakeMeasurer measurer;
    InputQueue queue;
    WorkstationInput input(1, source, measurer, queue);
    input.initialise(InputClass::Choice, 2, openSaveMenu());
    DeviceInitialisation v = valuatorSliderInitialisation(0, 10, 5, {0, 100, 50, 60, 0, 1});
    input.initialise(InputClass::Valuator, 4, v);
    input.setMode(InputClass::Choice, 2, OperatingMode::Event);
    input.setMode(InputClass::Valuator, 4, OperatingMode::Event);
    input.setMode(InputClass::Pick, 1, OperatingMode::Event);
    input.setMode(InputClass::Locator, 1, OperatingMode::Event);
    for (int i = 0; i < 4; ++i) input.pump(std::chrono::milliseconds(0));
    auto e = queue.awaitEvent(std::chrono::milliseconds(0));
    REQUIRE(e);
    CHECK(e->inputClass == InputClass::Choice);
    CHECK(e->device == 2);
    CHECK(std::get<ChoiceMeasure>(e->measure).choice == 2);
    e = queue.awaitEvent(std::chrono::milliseconds(0));
    REQUIRE(e);
    CHECK(std::get<ChoiceMeasure>(e->measure).choice == 1);
    e = queue.awaitEvent(std::chrono::milliseconds(0));
    REQUIRE(e);
    CHECK(e->inputClass == InputClass::Valuator);
    CHECK(std::get<ValuatorMeasure>(e->measure).value == Approx(7.5));
    // Outside them a click is a pick and a locator, as ever.
    e = queue.awaitEvent(std::chrono::milliseconds(0));
    REQUIRE(e);
    CHECK(e->inputClass == InputClass::Pick);
    CHECK(e->moreSimultaneous);
}

TEST_CASE("input echo: a click on the panel of a device that takes no input is the pick it was", "[input]") {
    // Clicks inside an idle device's panel (REQUEST mode, no request: not drawn) became choices
    // nobody took: a pick requested over that part of the picture never came.
    ScriptInputSource source("pick 50 30\n", "idle.txt");
    FakeMeasurer measurer;
    InputQueue queue;
    WorkstationInput input(1, source, measurer, queue);
    input.initialise(InputClass::Choice, 2, openSaveMenu());
    input.initialise(InputClass::Valuator, 4, valuatorSliderInitialisation(0, 10, 5, {0, 100, 25, 35, 0, 1}));
    const auto [status, measure] = input.request(InputClass::Pick, 1);
    CHECK(status == InputStatus::Ok);
    CHECK(std::holds_alternative<PickMeasure>(measure));
    // Requested, the same click chooses.
    ScriptInputSource clicks("pick 50 30\n", "request.txt");
    WorkstationInput requesting(1, clicks, measurer, queue);
    requesting.initialise(InputClass::Choice, 2, openSaveMenu());
    const auto [chosen, choice] = requesting.request(InputClass::Choice, 2);
    CHECK(chosen == InputStatus::Ok);
    CHECK(std::get<ChoiceMeasure>(choice).choice == 2);
}

}  // namespace test_input_echo_layout
