// Real X events: the XTest extension moves the pointer and presses the button on the virtual
// X server, GLFW reads them in glfwWaitEventsTimeout, and the pick device receives the pick.

#include "phigs/input/WorkstationInput.h"
#include "phigs/pick/DrawListMeasurer.h"
#include "phigs/window/GlfwInputSource.h"

#include <GLFW/glfw3.h>
#include <catch2/catch.hpp>

#include <chrono>

// Last: Xlib defines macros (None, True, Status) that would break the headers above.
#include <X11/Xlib.h>
#include <X11/extensions/XTest.h>

namespace test_window_xtest {

using namespace phigs;
using namespace std::chrono_literals;

TEST_CASE("window: real X pointer and button events reach the pick device", "[window]") {
    REQUIRE(glfwInit() == GLFW_TRUE);
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    GLFWwindow* window = glfwCreateWindow(100, 100, "xtest pick", nullptr, nullptr);
    REQUIRE(window);
    // Point at the window only once the server has mapped it: its first Expose event reaches
    // GLFW's refresh callback (a fixed wait could be too short on a loaded machine).
    static bool exposed = false;
    exposed = false;
    glfwSetWindowRefreshCallback(window, [](GLFWwindow*) { exposed = true; });
    const auto until = std::chrono::steady_clock::now() + 10s;
    while (!exposed && std::chrono::steady_clock::now() < until) glfwWaitEventsTimeout(0.02);
    REQUIRE(exposed);
    int wx = 0, wy = 0;
    glfwGetWindowPos(window, &wx, &wy);

    DrawList list;
    list.views.push_back(DrawView{});
    list.viewportMax = {100.0, 100.0, 1.0};
    list.displaySize = {100.0, 100.0};
    DrawPolymarker marker;
    marker.points = {{0.25, 0.75, 0.5}};  // pixel (25, 25)
    DrawItem item;
    item.primitive = marker;
    item.source = DrawSource({{9, 4, 2}});
    list.items.push_back(item);
    DrawListMeasurer measurer(list);
    {
        GlfwInputSource source(window);
        InputQueue queue;
        WorkstationInput input(1, source, measurer, queue);
        input.setMode(InputClass::Pick, 1, OperatingMode::Event);

        // A connection of our own to the same server: XTest events are server-wide.
        Display* display = XOpenDisplay(nullptr);
        REQUIRE(display);
        XTestFakeMotionEvent(display, -1, wx + 25, wy + 25, 0);
        XTestFakeButtonEvent(display, 1, True, 0);
        XTestFakeButtonEvent(display, 1, False, 0);
        XFlush(display);
        XCloseDisplay(display);

        const auto e = queue.awaitEvent(3s);
        REQUIRE(e);
        CHECK(e->inputClass == InputClass::Pick);
        const auto& pick = std::get<PickMeasure>(e->measure);
        CHECK(pick.status == InputStatus::Ok);
        CHECK(pick.path == std::vector<PickPathItem>{{9, 4, 2}});
    }
    glfwDestroyWindow(window);
    glfwTerminate();
}

}  // namespace test_window_xtest
