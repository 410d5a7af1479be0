// Echo structures on a window workstation under Xvfb, clicked with real X events (XTest): a
// click in the menu panel chooses, a drag in the slider sets the value, and the redrawn
// structures show it in the presented picture.
#include "RenderTestSupport.h"
#include "VirtualDisplay.h"
#include "phigs/Phigs.h"
#include "phigs/vk/WorkstationDisplay.h"
#include "phigs/ws/EchoStructures.h"

#if defined(PHIGS_HAVE_XTEST)
#include "phigs/window/GlfwInputSource.h"
#include "phigs/window/GlfwWindow.h"

#include <GLFW/glfw3.h>

#include <chrono>

// Last: Xlib defines macros (None, True, Status) that would break the headers above.
#include <X11/Xlib.h>
#include <X11/extensions/XTest.h>

namespace test_echo_window {

using namespace phigs;
using namespace render_test;
using namespace std::chrono_literals;

namespace {

/// Real pointer events through the X server, at window pixels.
class Pointer {
public:
    explicit Pointer(GLFWwindow* window) : display_(XOpenDisplay(nullptr)) {
        REQUIRE(display_);
        glfwGetWindowPos(window, &x_, &y_);
    }
    ~Pointer() { XCloseDisplay(display_); }
    void moveTo(glm::dvec2 p) {
        XTestFakeMotionEvent(display_, -1, x_ + int(p.x), y_ + int(p.y), 0), flush();
    }
    void button(bool down) { XTestFakeButtonEvent(display_, 1, down ? True : False, 0), flush(); }

private:
    void flush() { XFlush(display_); }
    Display* display_;
    int x_ = 0, y_ = 0;
};

}  // namespace

TEST_CASE("echo window: real clicks on the toolkit's panel and slider deliver choice and value",
          "[render][window][echo]") {
    VirtualDisplay virtualDisplay;
    Phigs phigs;
    phigs.open();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::Window);
    GlfwWindow window(256, 192, "phigs echo test");
    // The test keeps the workstation's 1024 x 768 display surface (not the window's drawable),
    // shown at a quarter pixel per device unit.
    vk::DisplaySettings settings;
    settings.window = &window;
    settings.readBack = true;
    vk::WorkstationDisplay display(ws, lavapipeWithValidation(), settings);
    {
        GlfwInputSource source(window);
        InputQueue queue;
        ws.connectInput(source, queue);
        WorkstationInput& input = ws.input();
        // Rows of 20 pixels; the slider inside the workstation window's 192 x 192 pixels.
        input.initialise(InputClass::Choice, 1,
                         choicePanelInitialisation({"Wing", "Tail", "Body"}, {10, 90, 10, 70, 0, 1}));
        input.initialise(InputClass::Valuator, 1,
                         valuatorSliderInitialisation(0, 10, 5, {100, 180, 150, 170, 0, 1}));
        input.setMode(InputClass::Choice, 1, OperatingMode::Event);
        input.setMode(InputClass::Valuator, 1, OperatingMode::Event);
        const EchoLayout layout = input.echoLayout();
        const EchoStyle style;
        auto show = [&](int choice, double value) {
            buildChoicePanel(phigs.store(), 100, layout.panels.at(0), choice, display.mapping(), style);
            buildValuatorSlider(phigs.store(), 101, layout.sliders.at(0), value, "Span", display.mapping(),
                                style);
            ws.postStructure(100, 1.0);
            ws.postStructure(101, 1.0);
            REQUIRE(display.update());
            return display.image();
        };
        const Image before = show(1, 5.0);
        REQUIRE(before.width == 256);
        CHECK(shows(before, {14, 20}, style.current));
        CHECK(shows(before, {140, 160}, style.current));

        // Let the server map the window before pointing at it.
        const auto until = std::chrono::steady_clock::now() + 500ms;
        while (std::chrono::steady_clock::now() < until) glfwWaitEventsTimeout(0.02);
        Pointer pointer(window.handle());
        pointer.moveTo({50, 62});  // Body
        pointer.button(true);
        pointer.button(false);
        const auto chosen = queue.awaitEvent(3s);
        REQUIRE(chosen);
        CHECK(chosen->inputClass == InputClass::Choice);
        CHECK(std::get<ChoiceMeasure>(chosen->measure).choice == 3);

        // Drag the knob to x = 168 (8.5): the value follows the pointer before the release.
        auto valueAfter = [&](auto act) {
            act();
            const auto valued = queue.awaitEvent(3s);
            REQUIRE(valued);
            CHECK(valued->inputClass == InputClass::Valuator);
            return std::get<ValuatorMeasure>(valued->measure).value;
        };
        CHECK(valueAfter([&] {
                  pointer.moveTo({110, 160});
                  pointer.button(true);
              }) == Approx(1.25));
        CHECK(valueAfter([&] { pointer.moveTo({140, 161}); }) == Approx(5.0));
        CHECK(valueAfter([&] { pointer.moveTo({168, 160}); }) == Approx(8.5));
        pointer.button(false);  // the value at the release is the one already delivered
        CHECK_FALSE(queue.awaitEvent(300ms));

        const Image after = show(3, 8.5);
        CHECK(shows(after, {14, 20}, style.box));
        CHECK(shows(after, {14, 60}, style.current));
        CHECK(shows(after, {168, 160}, style.current));
        CHECK(shows(after, {125, 160}, style.track));
    }
    requireNoValidationMessages(display.context());
}
#endif

}  // namespace test_echo_window
