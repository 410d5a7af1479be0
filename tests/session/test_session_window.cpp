// The interactive session in a GLFW window under a virtual X server (started by the test): real
// X pointer events (XTest) click the menu panel, the surface and the pad and drag a slider, and
// drive DEFINE POINT through the GLFW window input source. Typed text goes in as the window's
// character callbacks deliver it. Without XTest the clicks go in that way too.
#include "SessionTestSupport.h"

#ifdef ACSYNT_HAVE_WINDOW

#include "acsynt/session/WindowPresentation.h"
#include "geom/Evaluate.h"
#include "phigs/vk/WorkstationDisplay.h"
#include "phigs/window/GlfwInputSource.h"
#include "phigs/window/GlfwWindow.h"

#include "../render/VirtualDisplay.h"

#if defined(PHIGS_HAVE_XTEST)
#include <GLFW/glfw3.h>
// Last: Xlib defines macros (None, True, Status) that would break the headers above.
#include <X11/Xlib.h>
#include <X11/extensions/XTest.h>

namespace test_session_window {
// Xlib's event-type macros share names with phigs::window_event types.
#undef KeyPress
#undef ButtonPress
#undef ButtonRelease

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
        XTestFakeMotionEvent(display_, -1, x_ + int(std::lround(p.x)), y_ + int(std::lround(p.y)), 0);
        XFlush(display_);
    }
    void button(bool down) {
        XTestFakeButtonEvent(display_, 1, down ? 1 : 0, 0);
        XFlush(display_);
    }

private:
    Display* display_;
    int x_ = 0, y_ = 0;
};

}  // namespace
#endif

TEST_CASE("interactive session in a window: menu clicks, surface clicks, pad and slider drive DEFINE POINT") {
    using namespace phigs::window_event;
    render_test::VirtualDisplay display;
    phigs::GlfwWindow window(session_test::width, session_test::height, "acsynt test");
    phigs::GlfwInputSource source(window);
    acsynt::SessionSettings settings = session_test::Driver::settings("window");
    settings.workstationType = phigs::WorkstationType::Window;
    acsynt::Session session(settings, source);
    phigs::vk::DisplaySettings surface;
    surface.window = &window;
    phigs::vk::WorkstationDisplay shown(session.workstation(), render_test::lavapipeWithValidation(),
                                        surface);
    acsynt::WindowPresentation presentation(session, window, shown);
    const acsynt::ScreenLayout& layout = session.layout();

    auto settle = [&] {
        for (int i = 0; i < 6; ++i) presentation.step(std::chrono::milliseconds(5));
    };
#if defined(PHIGS_HAVE_XTEST)
    // Clicks are real X events; the session's steps poll GLFW until the click has been handled.
    Pointer pointer(window.handle());
    auto click = [&](glm::dvec2 p) {
        const std::size_t before = session.log().size();
        pointer.moveTo(p);
        pointer.button(true);
        pointer.button(false);
        for (int i = 0; i < 2000 && session.log().size() == before; ++i)  // up to 10 s when loaded
            presentation.step(std::chrono::milliseconds(5));
        settle();
    };
#else
    // Without XTest: the events the window's callbacks would deliver.
    auto click = [&](glm::dvec2 p) {
        source.post(ButtonPress{Button::Left, p, false});
        source.post(ButtonRelease{Button::Left, p});
        settle();
    };
#endif
    auto menu = [&](const std::string& item) {
        const auto& items = session.menuItems();
        const auto it = std::find(items.begin(), items.end(), item);
        REQUIRE(it != items.end());
        const phigs::ChoicePanel panel{1, layout.menuFor(items.size()).echoVolume(), items};
        const auto [a, b] = panel.row(int(it - items.begin()) + 1);
        click((a + b) / 2.0);
    };
    auto type = [&](const std::string& text) {
        for (char c : text) source.post(Character{char32_t(c)});
        source.post(KeyPress{Key::Enter, 0});
        settle();
    };

    menu("FILE");
    CHECK(session.menuTitle() == "FILE");
    menu("READ_MODEL");
    CHECK(session.message() == "ENTER MODEL FILE NAME");
    type("transport.acm");
    REQUIRE(session.models().size() == 1);
    menu("RETURN");
    menu("CURVE_MAP");
    menu("DEFINE_POINT");
    CHECK(session.message() == "SELECT COMPONENT FOR MAPPING");

    const acsynt::Component& wing = session.models().current().components[1];
    REQUIRE(wing.name == "right_wing");
    const glm::dvec3 point = geom::evaluate(wing.surface, 0.5, 0.3);
    click(session.pixelOf(point, 1));
    CHECK(session.message() == "SELECT REFERENCE PATCH TO MAP");
    click(session.pixelOf(point, 1));
    CHECK(session.message() == "ACCEPT OR REJECT PATCH");
    menu("ACCEPT");
    REQUIRE(session.reference());
    const acsynt::Patch* patch = wing.patches.find(0.5, 0.3);
    REQUIRE(patch);
    CHECK(session.reference()->patch == patch->number);

    click(layout.padButton(5).centre());  // the centre button: the middle of the patch
    CHECK(session.reference()->u == Approx((patch->u0 + patch->u1) / 2));
    CHECK(session.reference()->w == Approx((patch->w0 + patch->w1) / 2));
    click(layout.padButton(6).centre());  // east: u up by an eighth
    CHECK(session.reference()->u == Approx((patch->u0 + patch->u1) / 2 + (patch->u1 - patch->u0) / 8));

    // A drag in the W slider: the value at the release point.
    const acsynt::PixelBox slider = layout.slider(2);
    const glm::dvec2 from{slider.x0 + 2, slider.centre().y},
        to{slider.x0 + 0.25 * (slider.x1 - slider.x0), slider.centre().y};
#if defined(PHIGS_HAVE_XTEST)
    const phigs::ValuatorSlider dragged{2, slider.echoVolume(), 0, 1};
    const double wAtRelease = patch->w0 + dragged.valueAt(to) * (patch->w1 - patch->w0);
    pointer.moveTo(from);
    pointer.button(true);
    for (int i = 0; i < 4; ++i) presentation.step(std::chrono::milliseconds(5));
    pointer.moveTo(to);
    pointer.button(false);
    for (int i = 0; i < 2000 && std::abs(session.reference()->w - wAtRelease) > 1e-12; ++i)
        presentation.step(std::chrono::milliseconds(5));
    settle();
#else
    source.post(ButtonPress{Button::Left, from, false});
    source.post(CursorMove{to});
    source.post(ButtonRelease{Button::Left, to});
    settle();
#endif
    const phigs::ValuatorSlider model{2, slider.echoVolume(), 0, 1};
    CHECK(session.reference()->w == Approx(patch->w0 + model.valueAt(to) * (patch->w1 - patch->w0)));

    click(layout.padButton(10).centre());  // DONE
    CHECK(session.message().rfind("REFERENCE POINT U = ", 0) == 0);
    CHECK(presentation.frames() > 10);
    for (const auto& line : session.log()) {
        INFO(line);
        CHECK(line.rfind("ERROR: ", 0) != 0);
    }
    render_test::requireNoValidationMessages(shown.context());
}

#endif

}  // namespace test_session_window
