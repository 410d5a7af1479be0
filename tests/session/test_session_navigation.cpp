// Navigation of the views as a window's mouse and keys drive it (rotate on two axes, zoom, pan,
// Ctrl+Z / Ctrl+Y), headless: the views follow, and a recording replays to the same views.
#include "SessionTestSupport.h"

#include "acsynt/session/ModelPicture.h"
#include "acsynt/session/ViewNavigation.h"

namespace test_session_navigation {

using session_test::Driver;
using namespace phigs::window_event;
using phigs::WindowEvent;

namespace {

void loadTransport(Driver& d) {
    d.run({"choice FILE", "choice READ_MODEL", "string transport.acm", "choice RETURN"});
    REQUIRE(d.session.models().size() == 1);
}

}  // namespace

TEST_CASE("navigation: drags rotate on two axes, the wheel zooms, a middle drag pans with the pointer") {
    Driver d("navigation");
    loadTransport(d);
    std::vector<WindowEvent> forwarded;
    acsynt::ViewNavigation nav(d.session, [&](const WindowEvent& e) { forwarded.push_back(e); });
    const glm::dvec2 middle = d.session.layout().viewBox(1, false).centre();

    // A left drag across: azimuth only; up and down: elevation only; both by 0.4 degree a pixel.
    const double az0 = d.session.azimuth(), el0 = d.session.elevation();
    CHECK(nav.handle(ButtonPress{Button::Left, middle, false}));
    CHECK(nav.handle(CursorMove{middle + glm::dvec2(2, 0)}));  // under the threshold: nothing yet
    CHECK(d.session.azimuth() == az0);
    CHECK(nav.handle(CursorMove{middle + glm::dvec2(50, 0)}));
    CHECK(nav.handle(ButtonRelease{Button::Left, middle + glm::dvec2(50, 0)}));
    CHECK(d.session.azimuth() == Approx(az0 - 20));
    CHECK(d.session.elevation() == el0);
    CHECK(forwarded.empty());  // a drag is no pick
    CHECK(nav.handle(ButtonPress{Button::Left, middle, false}));
    CHECK(nav.handle(CursorMove{middle + glm::dvec2(0, 25)}));
    CHECK(nav.handle(CursorMove{middle + glm::dvec2(0, 500)}));  // clamped short of the pole
    CHECK(nav.handle(ButtonRelease{Button::Left, middle + glm::dvec2(0, 500)}));
    CHECK(d.session.elevation() == 89);
    CHECK(d.session.azimuth() == Approx(az0 - 20));

    // A click without a drag goes on to the devices, press and release.
    CHECK(nav.handle(ButtonPress{Button::Left, middle, false}));
    CHECK(nav.handle(ButtonRelease{Button::Left, middle}));
    REQUIRE(forwarded.size() == 2);
    CHECK(std::holds_alternative<ButtonPress>(forwarded[0]));
    // Outside the views: nothing taken.
    const glm::dvec2 menu = d.session.layout().menu.centre();
    CHECK_FALSE(nav.handle(ButtonPress{Button::Left, menu, false}));
    CHECK_FALSE(nav.handle(Scroll{menu, 1}));

    // The wheel: 1.15 a notch, kept within the ZOOM slider's range; the slider follows.
    d.run({"choice VIEW", "choice RESET_VIEW"});
    CHECK(nav.handle(Scroll{middle, 2}));
    CHECK(d.session.zoom() == Approx(1.15 * 1.15));
    for (int i = 0; i < 40; ++i) nav.handle(Scroll{middle, 1});
    CHECK(d.session.zoom() == 8);
    for (int i = 0; i < 80; ++i) nav.handle(Scroll{middle, -1});
    CHECK(d.session.zoom() == 0.25);
    d.run({"choice RESET_VIEW"});

    // A pan drag (middle, or Shift + left): a model point moves with the pointer, to a pixel.
    const glm::dvec3 nose = d.session.models().current().components[0].surface.point(1, 0);
    for (const bool shift : {false, true}) {
        const glm::dvec2 before = d.session.pixelOf(nose, 1);
        const Button b = shift ? Button::Left : Button::Middle;
        CHECK(nav.handle(ButtonPress{b, middle, shift}));
        CHECK(nav.handle(CursorMove{middle + glm::dvec2(30, -12)}));
        CHECK(nav.handle(ButtonRelease{b, middle + glm::dvec2(30, -12)}));
        const glm::dvec2 moved = d.session.pixelOf(nose, 1) - before;
        INFO("shift " << shift << ": moved " << moved.x << " " << moved.y);
        CHECK(moved.x == Approx(30).margin(0.5));
        CHECK(moved.y == Approx(-12).margin(0.5));
    }
    CHECK_FALSE(d.logHasError());
}

TEST_CASE("navigation keys: F1 and H show the help, H is text at a prompt, Ctrl+Z and Ctrl+Y undo and redo") {
    Driver d("navigation_keys");
    acsynt::ViewNavigation nav(d.session, [](const WindowEvent&) {});
    const auto helpElements = [&] {
        return d.session.phigs().store().structure(acsynt::structures::help).elements.size();
    };
    CHECK(helpElements() == 0);
    CHECK(nav.handle(KeyPress{Key::Function, 1}));
    CHECK(d.session.helpShown());
    CHECK(helpElements() > 10);
    session_test::compareWithReference(d.picture(), "help_overlay");
    CHECK(nav.handle(Character{'h'}));
    CHECK_FALSE(d.session.helpShown());
    CHECK(helpElements() == 0);
    CHECK(nav.handle(Character{'H'}));
    CHECK(nav.handle(KeyPress{Key::Escape}));  // Escape hides it too
    CHECK_FALSE(d.session.helpShown());
    CHECK_FALSE(nav.handle(KeyPress{Key::Function, 2}));  // F2.. stay menu choices

    d.run({"choice FILE", "choice READ_MODEL"});
    CHECK_FALSE(nav.handle(Character{'h'}));  // a prompt is open: text
    d.run({"string transport.acm", "choice RETURN", "choice CURVE_MAP"});
    REQUIRE(d.session.models().size() == 1);
    CHECK(nav.handle(KeyPress{Key::Letter, 0, 'Z', true}));
    CHECK(d.session.models().size() == 0);
    CHECK(d.session.message() == "UNDONE: READ MODEL transport");
    CHECK(nav.handle(KeyPress{Key::Letter, 0, 'Y', true}));
    CHECK(d.session.models().size() == 1);
    CHECK(d.session.message() == "REDONE: READ MODEL transport");
    CHECK_FALSE(nav.handle(KeyPress{Key::Letter, 0, 'Q', true}));
}

TEST_CASE("navigation and undo keys are recorded and replay to the same views and summary") {
    std::string recording, summary;
    glm::dvec2 shown;
    double azimuth = 0, elevation = 0, zoom = 0;
    {
        Driver d("navigation_record");
        acsynt::ViewNavigation nav(d.session, [](const WindowEvent&) {});
        loadTransport(d);
        const glm::dvec2 middle = d.session.layout().viewBox(1, false).centre();
        nav.handle(ButtonPress{Button::Left, middle, false});
        nav.handle(CursorMove{middle + glm::dvec2(40, 15)});
        nav.handle(ButtonRelease{Button::Left, middle + glm::dvec2(40, 15)});
        nav.handle(Scroll{middle, 3});
        nav.handle(ButtonPress{Button::Middle, middle, false});
        nav.handle(CursorMove{middle + glm::dvec2(-20, 8)});
        nav.handle(ButtonRelease{Button::Middle, middle + glm::dvec2(-20, 8)});
        d.run({"choice FILE", "choice READ_MODEL", "string fighter.acm"});
        nav.handle(KeyPress{Key::Letter, 0, 'Z', true});
        nav.handle(KeyPress{Key::Letter, 0, 'Z', true});
        nav.handle(KeyPress{Key::Letter, 0, 'Y', true});
        REQUIRE(d.session.models().size() == 1);
        azimuth = d.session.azimuth();
        elevation = d.session.elevation();
        zoom = d.session.zoom();
        recording = d.session.recording();
        summary = d.session.summary();
        shown = d.session.pixelOf({10, 2, 1}, 1);
    }
    INFO(recording);
    CHECK(recording.find("\nview ") != std::string::npos);
    CHECK(recording.find("\nundo\nundo\nredo\n") != std::string::npos);
    phigs::ScriptInputSource script(recording, "recorded", acsynt::Session::directives());
    acsynt::Session replay(Driver::settings("navigation_replay"), script);
    replay.run();
    CHECK(replay.failedLines() == 0);
    CHECK(replay.summary() == summary);
    CHECK(replay.azimuth() == azimuth);
    CHECK(replay.elevation() == elevation);
    CHECK(replay.zoom() == zoom);
    const glm::dvec2 again = replay.pixelOf({10, 2, 1}, 1);
    CHECK(again.x == Approx(shown.x));
    CHECK(again.y == Approx(shown.y));
}

}  // namespace test_session_navigation
