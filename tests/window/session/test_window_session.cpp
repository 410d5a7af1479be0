// The design session in a window that the user resizes, types into and leaves idle, driven by
// real X events under Xvfb: after each resize every drawn menu row chooses its item, a click
// on a known surface point picks it, a slider drag moves the value before the release; typed
// text echoes on the message line; an idle window blocks on events.
#include "WindowSessionSupport.h"

#include "acsynt/session/ModelPicture.h"
#include "geom/Evaluate.h"
#include "phigs/input/EchoLayout.h"
#include "phigs/ws/EchoStructures.h"

#include <ctime>
#include <random>

using namespace window_test;

namespace {

/// The row of menu item `item` as the session's current layout draws it.
std::pair<glm::dvec2, glm::dvec2> menuRow(const acsynt::Session& session, const std::string& item) {
    const auto& items = session.menuItems();
    const auto it = std::find(items.begin(), items.end(), item);
    REQUIRE(it != items.end());
    const phigs::ChoicePanel panel{1, session.layout().menuFor(items.size()).echoVolume(), items};
    return panel.row(int(it - items.begin()) + 1);
}

void chooseMenu(WindowSession& w, const std::string& item) {
    const auto [a, b] = menuRow(w.session, item);
    w.click((a + b) / 2.0);
}

/// FILE > READ_MODEL with the transport's file name typed into the window.
void readTransport(WindowSession& w) {
    chooseMenu(w, "FILE");
    chooseMenu(w, "READ_MODEL");
    w.moveTo({300, 300});  // the keyboard goes to the window under the pointer
    w.type("transport.acm");
    w.key(XK_Return);
    REQUIRE(w.stepUntil([&] { return w.session.models().size() == 1; }));
}

/// Surface parameters near (u, w) whose point lies exactly on pixel `pixel` of view 1 (Newton
/// on the pixel map), so a click there, which X makes at whole pixels, has a known answer.
glm::dvec2 parametersAtPixel(acsynt::Session& session, const geom::Surface& surface, glm::dvec2 uw,
                             glm::dvec2 pixel) {
    auto at = [&](glm::dvec2 p) { return session.pixelOf(geom::evaluate(surface, p.x, p.y), 1); };
    for (int i = 0; i < 20; ++i) {
        const glm::dvec2 f = at(uw) - pixel;
        if (glm::length(f) < 1e-9) break;
        const double h = 1e-6;
        const glm::dvec2 du = (at(uw + glm::dvec2(h, 0)) - at(uw)) / h;
        const glm::dvec2 dw = (at(uw + glm::dvec2(0, h)) - at(uw)) / h;
        const double det = du.x * dw.y - du.y * dw.x;
        REQUIRE(std::abs(det) > 1e-12);
        uw -= glm::dvec2(dw.y * f.x - dw.x * f.y, -du.y * f.x + du.x * f.y) / det;
    }
    REQUIRE(glm::length(at(uw) - pixel) < 1e-6);
    return uw;
}

double processSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

}  // namespace

TEST_CASE("window session: typed text echoes on the message line, Backspace edits, Escape cancels") {
    WindowSession w(800, 600);
    // The string device's echo, drawn by the toolkit in its echo area on the message line.
    auto echoed = [&] {
        const phigs::EchoState echo = w.session.workstation().echoState();
        return echo.empty() ? std::string() : echo.strings.at(0).shown();
    };
    chooseMenu(w, "FILE");
    chooseMenu(w, "READ_MODEL");
    REQUIRE(w.session.message() == "ENTER MODEL FILE NAME");
    w.moveTo({300, 300});  // the keyboard goes to the window under the pointer
    w.type("transpotr");
    REQUIRE(w.stepUntil([&] { return echoed() == "transpotr_"; }));
    w.key(XK_BackSpace);
    w.key(XK_BackSpace);
    const bool edited = w.stepUntil([&] { return echoed() == "transpo_"; });
    INFO(echoed());
    REQUIRE(edited);
    w.type("rt.acm");
    INFO(echoed());
    REQUIRE(w.stepUntil([&] { return echoed() == "transport.acm_"; }));
    // The echo is what the renderer draws: the display's echo state, on the message line.
    w.settle(30ms);
    CHECK(w.display.echo() == w.session.workstation().echoState());
    const phigs::EchoVolume& area = w.display.echo().strings.at(0).area;
    const acsynt::PixelBox& line = w.session.layout().message;
    CHECK(area.xmin >= line.x0);
    CHECK(area.xmax <= line.x1);
    CHECK(area.ymin >= line.y0);
    CHECK(area.ymax <= line.y1);
    CHECK(w.session.messageLine() == "ENTER MODEL FILE NAME");  // the prompt stays on its left
    w.key(XK_Return);
    REQUIRE(w.stepUntil([&] { return w.session.models().size() == 1; }));
    CHECK(echoed().empty());  // accepted: the echo is gone
    CHECK(w.session.models().current().name == "transport");

    chooseMenu(w, "READ_MODEL");
    w.moveTo({300, 300});
    w.type("abc");
    REQUIRE(w.stepUntil([&] { return echoed() == "abc_"; }));
    w.key(XK_Escape);
    REQUIRE(w.stepUntil([&] { return w.session.message() == "CANCELLED"; }));
    CHECK(echoed() == "cancelled");
    w.type("x");  // typed with nothing asked for: echoed, and Enter reaches no prompt
    w.key(XK_Return);
    w.settle(200ms);
    CHECK(w.session.models().size() == 1);
    phigs::vk::Context& context = w.display.context();
    render_test::requireNoValidationMessages(context);
}

TEST_CASE("window session: after resizes, menu rows, surface picks and slider drags follow the window") {
    WindowSession w(1024, 768);
    readTransport(w);
    chooseMenu(w, "RETURN");
    REQUIRE(w.session.menuTitle() == "MAIN");

    const std::pair<const char*, const char*> rows[] = {{"FILE", "FILE"},
                                                        {"VIEW", "VIEW"},
                                                        {"CURVE_MAP", "CURVE MAP"},
                                                        {"SURF_REDN", "SURF_REDN"},
                                                        {"MODELS", "MODELS"}};
    const phigs::EchoStyle style;
    for (const auto& [width, height] :
         {std::pair{1280, 1024}, std::pair{1600, 900}, std::pair{1500, 1000}, std::pair{800, 600}}) {
        INFO("window " << width << " x " << height);
        REQUIRE(w.resize(width, height));
        CHECK(w.session.workstation().displaySize() == glm::dvec2(width, height));
        CHECK(w.display.width() == std::uint32_t(width));

        // (a) every drawn menu row chooses its item: the row is drawn where the click lands.
        for (const auto& [item, title] : rows) {
            const auto [a, b] = menuRow(w.session, item);
            const phigs::Image& shown = w.display.capture();
            REQUIRE(shown.width == std::uint32_t(width));
            CHECK(render_test::shows(shown, {a.x + 3, (a.y + b.y) / 2}, style.box));
            chooseMenu(w, item);
            CHECK(w.session.menuTitle() == title);
            chooseMenu(w, "RETURN");
            CHECK(w.session.menuTitle() == "MAIN");
        }

        // (b) a click on a known surface point picks that component, patch and (u, w).
        const acsynt::Component& wing = w.session.models().current().components[1];
        REQUIRE(wing.name == "right_wing");
        const glm::dvec2 target = glm::round(w.session.pixelOf(geom::evaluate(wing.surface, 0.5, 0.3), 1));
        const glm::dvec2 uw = parametersAtPixel(w.session, wing.surface, {0.5, 0.3}, target);
        w.click(target);
        REQUIRE(w.session.lastPick());
        CHECK(w.session.lastPick()->component == 1);
        const acsynt::Patch* patch = wing.patches.find(uw.x, uw.y);
        REQUIRE(patch);
        CHECK(w.session.lastPick()->patch == patch->number);
        REQUIRE(w.session.lastPickDetail());
        CHECK(std::abs(w.session.lastPickDetail()->uv.x - uw.x) < 1e-3);
        CHECK(std::abs(w.session.lastPickDetail()->uv.y - uw.y) < 1e-3);

        // (c) a drag in the rotation slider changes the value before the release.
        const acsynt::PixelBox slider = w.session.layout().slider(3);
        const phigs::ValuatorSlider model{3, slider.echoVolume(), -180, 180};
        const glm::dvec2 from{slider.x0 + 0.3 * (slider.x1 - slider.x0), slider.centre().y};
        const glm::dvec2 to{slider.x0 + 0.7 * (slider.x1 - slider.x0), slider.centre().y};
        w.moveTo(from);
        w.button(true);
        CHECK(w.stepUntil(
            [&] { return w.session.valuatorValue(3) == Approx(model.valueAt(glm::round(from))); }));
        w.moveTo(to);
        CHECK(
            w.stepUntil([&] { return w.session.valuatorValue(3) == Approx(model.valueAt(glm::round(to))); }));
        w.button(false);  // released where the value already is
        w.settle(50ms);
        CHECK(w.session.valuatorValue(3) == Approx(model.valueAt(glm::round(to))));
    }
    chooseMenu(w, "EXIT");
    CHECK(w.session.finished());
    for (const auto& line : w.session.log()) {
        INFO(line);
        CHECK(line.rfind("ERROR: ", 0) != 0);
    }
    render_test::requireNoValidationMessages(w.display.context());
}

TEST_CASE("window session: a window made too small for its areas goes on, and works again when larger") {
    // Menu panel, pad and sliders shrink to a pixel or to nothing; the devices are initialised
    // again on every resize and must not refuse (PHIGS refuses an empty echo volume).
    WindowSession w(1024, 768);
    readTransport(w);
    std::mt19937 random(7);
    std::uniform_int_distribution<int> side(1, 60);
    for (int trial = 0; trial < 6; ++trial) {
        const int width = trial == 0 ? 1 : side(random), height = trial == 0 ? 1 : side(random);
        INFO("window " << width << " x " << height);
        REQUIRE(w.resize(width, height));
        CHECK(w.session.workstation().displaySize() == glm::dvec2(width, height));
    }
    REQUIRE(w.resize(800, 600));
    chooseMenu(w, "RETURN");
    chooseMenu(w, "VIEW");
    CHECK(w.session.menuTitle() == "VIEW");
    for (const auto& line : w.session.log()) {
        INFO(line);
        CHECK(line.rfind("ERROR: ", 0) != 0);
    }
    render_test::requireNoValidationMessages(w.display.context());
}

TEST_CASE("window session: an idle window blocks on events and draws nothing") {
    WindowSession w(1024, 768);
    readTransport(w);
    w.settle(500ms);
    const std::uint64_t frames = w.presentation.frames();
    const double cpu0 = processSeconds();
    const auto wall0 = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() - wall0 < 5s) w.presentation.step(1s);  // the program's wait
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    const double share = (processSeconds() - cpu0) / wall;
    WARN("idle window: " << share * 100 << " % of a core over " << wall << " s");
    CHECK(share < 0.02);
    CHECK(w.presentation.frames() == frames);  // nothing changed: nothing drawn
}

TEST_CASE("window session: a drag rotates the 3D view, the wheel zooms, F1 shows help, Ctrl+Z undoes") {
    WindowSession w(1024, 768);
    readTransport(w);
    chooseMenu(w, "RETURN");
    w.settle(100ms);
    const phigs::Image before = w.display.capture();

    // A left drag in the view: 0.4 degree a pixel across (azimuth) and up and down (elevation).
    const glm::dvec2 start = glm::round(w.session.layout().geometry.centre());
    const double az0 = w.session.azimuth(), el0 = w.session.elevation();
    w.moveTo(start);
    w.button(true);
    w.settle(30ms);
    for (int i = 1; i <= 5; ++i) {
        w.moveTo(start + glm::dvec2(12 * i, -4 * i));
        w.settle(15ms);
    }
    w.button(false);
    REQUIRE(w.stepUntil([&] { return w.session.azimuth() == Approx(az0 - 0.4 * 60); }));
    CHECK(w.session.elevation() == Approx(el0 - 0.4 * 20));
    CHECK_FALSE(w.session.lastPick());  // a drag is no pick
    w.settle(100ms);
    const phigs::Image rotated = w.display.capture();
    CHECK(render_test::differingPixels(before, rotated, 24) > 1000);

    // The wheel zooms by 1.15 a notch, in and out.
    const double zoom0 = w.session.zoom();
    w.moveTo(start);
    w.wheel(true);
    REQUIRE(w.stepUntil([&] { return w.session.zoom() == Approx(zoom0 * 1.15); }));
    w.wheel(false);
    w.wheel(false);
    REQUIRE(w.stepUntil([&] { return w.session.zoom() == Approx(zoom0 / 1.15); }));

    // A middle drag pans: a model point follows the pointer.
    const glm::dvec3 nose = w.session.models().current().components[0].surface.point(1, 0);
    const glm::dvec2 seen = w.session.pixelOf(nose, 1);
    w.moveTo(start);
    w.button(true, 2);
    w.settle(30ms);
    w.moveTo(start + glm::dvec2(-40, 25));
    w.settle(30ms);
    w.button(false, 2);
    REQUIRE(w.stepUntil(
        [&] { return glm::length(w.session.pixelOf(nose, 1) - seen - glm::dvec2(-40, 25)) < 1; }));

    // F1 shows the help over the views, H hides it.
    w.key(XK_F1);
    REQUIRE(w.stepUntil([&] { return w.session.helpShown(); }));
    w.settle(100ms);
    const phigs::Image help = w.display.capture();
    // The overlay's box near its top right corner, clear of its text.
    const acsynt::PixelBox& g = w.session.layout().geometry;
    CHECK(render_test::shows(help, {g.x1 - 0.06 * (g.x1 - g.x0), g.y0 + 0.07 * (g.y1 - g.y0)},
                             glm::dvec3(0.08, 0.1, 0.2)));
    CHECK(w.session.menuTitle() == "MAIN");  // F1 is not menu item 1 here
    w.type("h");
    REQUIRE(w.stepUntil([&] { return !w.session.helpShown(); }));

    // Ctrl+Z undoes the model read, Ctrl+Y brings it back.
    w.controlKey(XK_z);
    REQUIRE(w.stepUntil([&] { return w.session.models().empty(); }));
    w.controlKey(XK_y);
    REQUIRE(w.stepUntil([&] { return w.session.models().size() == 1; }));
    for (const auto& line : w.session.log()) {
        INFO(line);
        CHECK(line.rfind("ERROR: ", 0) != 0);
    }
    render_test::requireNoValidationMessages(w.display.context());
}
