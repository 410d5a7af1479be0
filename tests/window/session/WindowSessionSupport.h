#pragma once
// A design session in a GLFW window under a virtual X server of its own, shown through the
// program's WindowPresentation and driven by real X events (XTest): pointer motion, buttons
// and keys, as a user's would arrive.

#include "../../render/RenderTestSupport.h"
#include "../../render/VirtualDisplay.h"
#include "acsynt/session/Session.h"
#include "acsynt/session/ViewNavigation.h"
#include "acsynt/session/WindowPresentation.h"
#include "phigs/vk/WorkstationDisplay.h"
#include "phigs/window/GlfwInputSource.h"
#include "phigs/window/GlfwWindow.h"

#include <GLFW/glfw3.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <string>

// Last: Xlib defines macros (None, True, Status) that would break the headers above.
#include <X11/Xlib.h>
#include <X11/extensions/XTest.h>
#include <X11/keysym.h>
// Xlib's event-type macros share names with phigs::window_event types.
#undef KeyPress
#undef ButtonPress
#undef ButtonRelease

namespace window_test {

using namespace std::chrono_literals;

inline acsynt::SessionSettings windowSettings(int width, int height) {
    acsynt::SessionSettings s;
    s.width = width;
    s.height = height;
    s.workstationType = phigs::WorkstationType::Window;
    s.outputDirectory = std::filesystem::path(PHIGS_TEST_OUTPUT_DIR) / "window_session";
    std::filesystem::create_directories(s.outputDirectory);
    return s;
}

inline phigs::vk::DisplaySettings onWindow(phigs::GlfwWindow& window) {
    phigs::vk::DisplaySettings d;
    d.window = &window;
    return d;
}

/// The session, its window, display and presentation, and an X connection for XTest.
class WindowSession {
public:
    WindowSession(int width, int height)
        : server_("1920x1200x24"),
          window(std::uint32_t(width), std::uint32_t(height), "acsynt window test"),
          source(window),
          session(windowSettings(width, height), source),
          display(session.workstation(), render_test::lavapipeWithValidation(), onWindow(window)),
          presentation(session, window, display),
          navigation(session, [this](const phigs::WindowEvent& e) { source.deliver(e); }),
          x_(XOpenDisplay(nullptr)) {
        REQUIRE(x_);
        // The program's wiring: the window's events go to the views' navigation first.
        source.setEventFilter([this](const phigs::WindowEvent& e) { return navigation.handle(e); });
        settle(300ms);  // let the server map the window before pointing at it
    }
    ~WindowSession() {
        source.setEventFilter({});
        XCloseDisplay(x_);
    }
    WindowSession(const WindowSession&) = delete;
    WindowSession& operator=(const WindowSession&) = delete;

    /// Runs the program's loop body for `time`.
    void settle(std::chrono::milliseconds time) {
        const auto until = std::chrono::steady_clock::now() + time;
        while (std::chrono::steady_clock::now() < until) presentation.step(10ms);
    }
    /// Runs it until `done()` or 10 s (a loaded machine); false on the time limit.
    template <class Done>
    bool stepUntil(Done done) {
        const auto until = std::chrono::steady_clock::now() + 10s;
        while (!done()) {
            if (std::chrono::steady_clock::now() > until) return false;
            presentation.step(10ms);
        }
        return true;
    }

    void moveTo(glm::dvec2 p) {
        int x = 0, y = 0;
        glfwGetWindowPos(window.handle(), &x, &y);
        XTestFakeMotionEvent(x_, -1, x + int(std::lround(p.x)), y + int(std::lround(p.y)), 0);
        XFlush(x_);
    }
    /// X button 1 left, 2 middle, 4 and 5 the wheel away and towards the user.
    void button(bool down, unsigned int which = 1) {
        XTestFakeButtonEvent(x_, which, down ? 1 : 0, 0);
        XFlush(x_);
    }
    /// One wheel notch away from the user (true) or towards.
    void wheel(bool away) {
        button(true, away ? 4 : 5);
        button(false, away ? 4 : 5);
    }
    /// A key with Control held.
    void controlKey(KeySym symbol) {
        const KeyCode control = XKeysymToKeycode(x_, XK_Control_L);
        REQUIRE(control != 0);
        XTestFakeKeyEvent(x_, control, 1, 0);
        key(symbol);
        XTestFakeKeyEvent(x_, control, 0, 3);
        XFlush(x_);
    }
    /// A left click at `p`, handled once the session's log grows.
    void click(glm::dvec2 p) {
        const std::size_t before = session.log().size();
        moveTo(p);
        button(true);
        button(false);
        CHECK(stepUntil([&] { return session.log().size() > before; }));
        settle(30ms);
    }
    void key(KeySym symbol) {
        const KeyCode code = XKeysymToKeycode(x_, symbol);
        REQUIRE(code != 0);
        // Apart by a few milliseconds, as keys a hand presses: GLFW drops a second press of a
        // key with the same server time stamp as the first (its input-method duplicate filter).
        XTestFakeKeyEvent(x_, code, 1, 3);
        XTestFakeKeyEvent(x_, code, 0, 3);
        XFlush(x_);
    }
    /// Types lower-case letters, digits and '.', with the pointer over the window (X gives
    /// the keyboard to the window under the pointer when no window manager runs).
    void type(const std::string& text) {
        for (char c : text) {
            const std::string name = c == '.' ? "period" : std::string(1, c);
            const KeySym symbol = XStringToKeysym(name.c_str());
            REQUIRE(symbol != NoSymbol);
            key(symbol);
        }
    }
    /// Asks the window for a new size and steps until the session's screen has it.
    bool resize(int width, int height) {
        window.resize(std::uint32_t(width), std::uint32_t(height));
        return stepUntil(
            [&] { return session.layout().width == width && session.layout().height == height; });
    }

private:
    render_test::VirtualDisplay server_;

public:
    phigs::GlfwWindow window;
    phigs::GlfwInputSource source;
    acsynt::Session session;
    phigs::vk::WorkstationDisplay display;
    acsynt::WindowPresentation presentation;
    acsynt::ViewNavigation navigation;

private:
    Display* x_;
};

}  // namespace window_test
