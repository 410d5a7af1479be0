// Runs under Xvfb (ctest wraps it in xvfb-run): a real GLFW window, events delivered through
// the callbacks GLFW holds, measured on a draw list, received by the application's devices.

#include "phigs/input/ScriptInputSource.h"
#include "phigs/input/WorkstationInput.h"
#include "phigs/pick/DrawListMeasurer.h"
#include "phigs/window/GlfwInputSource.h"

#include <GLFW/glfw3.h>
#include <catch2/catch.hpp>

namespace test_window_input {

using namespace phigs;
using namespace std::chrono_literals;

namespace {

struct Window {
    Window() {
        REQUIRE(glfwInit() == GLFW_TRUE);
        glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
        glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
        handle = glfwCreateWindow(100, 100, "pick test", nullptr, nullptr);
        REQUIRE(handle);
        for (int i = 0; i < 10; ++i) glfwPollEvents();
    }
    ~Window() {
        glfwDestroyWindow(handle);
        glfwTerminate();
    }
    GLFWwindow* handle = nullptr;
};

DrawList squareScene() {
    DrawList list;
    list.views.push_back(DrawView{});
    list.viewportMax = {100.0, 100.0, 1.0};
    list.displaySize = {100.0, 100.0};
    DrawFillArea f;
    f.contours = {{{0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}, {0.8, 0.8, 0.5}, {0.2, 0.8, 0.5}}};
    f.interior.edit().style = InteriorStyle::Solid;
    DrawItem item;
    item.primitive = f;
    item.source = DrawSource({{3, 2, 1}, {4, 6, 8}});
    list.items.push_back(item);
    return list;
}

}  // namespace

TEST_CASE("window: a click in a GLFW window under Xvfb reaches the pick device", "[window]") {
    Window window;
    const DrawList list = squareScene();
    DrawListMeasurer measurer(list);
    GlfwInputSource source(window.handle);
    InputQueue queue;
    WorkstationInput input(1, source, measurer, queue);
    input.setMode(InputClass::Pick, 1, OperatingMode::Event);
    input.setMode(InputClass::Locator, 1, OperatingMode::Event);

    // Nothing happens: AWAIT EVENT times out.
    CHECK_FALSE(queue.awaitEvent(50ms));

    // Move the pointer over the square, then press the button through the callback GLFW holds.
    glfwSetCursorPos(window.handle, 40.0, 30.0);
    const GLFWmousebuttonfun button = glfwSetMouseButtonCallback(window.handle, nullptr);
    glfwSetMouseButtonCallback(window.handle, button);
    REQUIRE(button);
    button(window.handle, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
    button(window.handle, GLFW_MOUSE_BUTTON_LEFT, GLFW_RELEASE, 0);

    const auto pick = queue.awaitEvent(1s);
    REQUIRE(pick);
    CHECK(pick->inputClass == InputClass::Pick);
    CHECK(std::get<PickMeasure>(pick->measure).path == std::vector<PickPathItem>{{3, 2, 1}, {4, 6, 8}});
    CHECK(queue.moreSimultaneousEvents());
    const auto locator = queue.awaitEvent(0ms);
    REQUIRE(locator);
    const auto& at = std::get<LocatorMeasure>(locator->measure).position;
    CHECK(at.x == Approx(0.4));
    CHECK(at.y == Approx(0.7));

    // Outside the square: a pick with status NONE. The motion reaches the source first, as the
    // X server orders it (AWAIT EVENT reads the window's events in before it waits).
    glfwSetCursorPos(window.handle, 90.0, 90.0);
    const GLFWcursorposfun moved = glfwSetCursorPosCallback(window.handle, nullptr);
    glfwSetCursorPosCallback(window.handle, moved);
    REQUIRE(moved);
    moved(window.handle, 90.0, 90.0);
    button(window.handle, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
    const auto miss = queue.awaitEvent(1s);
    REQUIRE(miss);
    CHECK(std::get<PickMeasure>(miss->measure).status == InputStatus::None);
}

TEST_CASE("window: typed characters and Enter satisfy a string request", "[window]") {
    Window window;
    const DrawList list = squareScene();
    DrawListMeasurer measurer(list);
    GlfwInputSource source(window.handle);
    InputQueue queue;
    WorkstationInput input(1, source, measurer, queue);
    const GLFWcharfun character = glfwSetCharCallback(window.handle, nullptr);
    glfwSetCharCallback(window.handle, character);
    const GLFWkeyfun key = glfwSetKeyCallback(window.handle, nullptr);
    glfwSetKeyCallback(window.handle, key);
    REQUIRE(character);
    REQUIRE(key);
    for (char c : std::string("tail")) character(window.handle, static_cast<unsigned>(c));
    key(window.handle, GLFW_KEY_ENTER, 0, GLFW_PRESS, 0);
    const auto [status, measure] = input.request(InputClass::String, 1);
    CHECK(status == InputStatus::Ok);
    CHECK(std::get<StringMeasure>(measure).text == "tail");
}

namespace {

/// Application code: asks for a pick and a choice, knows nothing of where input comes from.
std::pair<std::vector<PickPathItem>, int> pickThenChoose(WorkstationInput& input) {
    const auto pick = input.request(InputClass::Pick, 1);
    const auto choice = input.request(InputClass::Choice, 1);
    return {std::get<PickMeasure>(pick.second).path, std::get<ChoiceMeasure>(choice.second).choice};
}

}  // namespace

TEST_CASE("window: the same application code runs under a script and under a window", "[window]") {
    const DrawList list = squareScene();
    DrawListMeasurer measurer(list);
    InputQueue queue;

    ScriptInputSource script("pick 40 30\nchoice 2\n", "session.txt");
    WorkstationInput scripted(1, script, measurer, queue);
    const auto fromScript = pickThenChoose(scripted);

    Window window;
    GlfwInputSource source(window.handle);
    WorkstationInput interactive(2, source, measurer, queue);
    glfwSetCursorPos(window.handle, 40.0, 30.0);
    const GLFWmousebuttonfun button = glfwSetMouseButtonCallback(window.handle, nullptr);
    glfwSetMouseButtonCallback(window.handle, button);
    const GLFWkeyfun key = glfwSetKeyCallback(window.handle, nullptr);
    glfwSetKeyCallback(window.handle, key);
    button(window.handle, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
    key(window.handle, GLFW_KEY_F2, 0, GLFW_PRESS, 0);
    const auto fromWindow = pickThenChoose(interactive);

    CHECK(fromScript.first == std::vector<PickPathItem>{{3, 2, 1}, {4, 6, 8}});
    CHECK(fromScript.second == 2);
    CHECK(fromWindow == fromScript);
}

TEST_CASE("window: a click in a choice device's menu panel chooses its alternative", "[window]") {
    Window window;
    const DrawList list = squareScene();
    DrawListMeasurer measurer(list);
    GlfwInputSource source(window.handle);
    InputQueue queue;
    WorkstationInput input(1, source, measurer, queue);
    DeviceInitialisation menu;
    menu.initial = ChoiceMeasure{InputStatus::Ok, 1};
    menu.promptEchoType = 3;
    menu.echoVolume = {0, 30, 0, 60, 0, 1};
    menu.choiceStrings = {"Wing", "Fuselage", "Tail"};
    input.initialise(InputClass::Choice, 1, menu);
    glfwSetCursorPos(window.handle, 10.0, 45.0);
    const GLFWmousebuttonfun button = glfwSetMouseButtonCallback(window.handle, nullptr);
    glfwSetMouseButtonCallback(window.handle, button);
    button(window.handle, GLFW_MOUSE_BUTTON_LEFT, GLFW_PRESS, 0);
    const auto [status, measure] = input.request(InputClass::Choice, 1);
    CHECK(status == InputStatus::Ok);
    CHECK(std::get<ChoiceMeasure>(measure).choice == 3);
}

}  // namespace test_window_input
