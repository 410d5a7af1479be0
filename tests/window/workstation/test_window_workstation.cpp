// A window workstation under a virtual X server of its own, driven by real X events (XTest):
// the string device echoes what is typed in its echo area, drawn by the toolkit and read back
// from the presented picture; minimised and restored, the workstation keeps its devices and
// draws again at the window's new size.
#include "../../render/RenderTestSupport.h"
#include "../../render/VirtualDisplay.h"
#include "phigs/Phigs.h"
#include "phigs/vk/WorkstationDisplay.h"
#include "phigs/window/GlfwInputSource.h"
#include "phigs/window/GlfwWindow.h"
#include "phigs/window/WindowOutputs.h"

#include <GLFW/glfw3.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <cstring>
#include <random>
#include <string>
#include <vector>

// Last: Xlib defines macros (None, True, Status) that would break the headers above.
#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XTest.h>
#include <X11/keysym.h>

using namespace phigs;
using namespace std::chrono_literals;

namespace {

constexpr const char* title = "phigs workstation window test";
const glm::dvec3 red{1.0, 0.0, 0.0};

/// The top-level window named `name` (no window manager reparents it under Xvfb).
Window namedWindow(Display* display, const char* name) {
    Window root = 0, parent = 0, *children = nullptr;
    unsigned count = 0;
    XQueryTree(display, DefaultRootWindow(display), &root, &parent, &children, &count);
    Window found = 0;
    for (unsigned i = 0; i < count && !found; ++i) {
        char* title = nullptr;
        if (XFetchName(display, children[i], &title) && title) {
            if (std::strcmp(title, name) == 0) found = children[i];
            XFree(title);
        }
    }
    if (children) XFree(children);
    REQUIRE(found != 0);
    return found;
}

/// The X server as the operator and, for minimising, as the window manager (Xvfb runs none):
/// pointer, buttons and keys through XTest; iconify and restore as ICCCM window managers do
/// (unmap or map, and WM_STATE).
class XServer {
public:
    XServer() : display_(XOpenDisplay(nullptr)) { REQUIRE(display_); }
    ~XServer() { XCloseDisplay(display_); }
    XServer(const XServer&) = delete;
    XServer& operator=(const XServer&) = delete;

    void moveTo(GLFWwindow* window, glm::dvec2 p) {
        int x = 0, y = 0;
        glfwGetWindowPos(window, &x, &y);
        XTestFakeMotionEvent(display_, -1, x + int(std::lround(p.x)), y + int(std::lround(p.y)), 0);
        XFlush(display_);
    }
    void click() {
        XTestFakeButtonEvent(display_, 1, 1, 0);
        XTestFakeButtonEvent(display_, 1, 0, 0);
        XFlush(display_);
    }
    void key(KeySym symbol) {
        const KeyCode code = XKeysymToKeycode(display_, symbol);
        REQUIRE(code != 0);
        // A few milliseconds apart: GLFW drops a second press with the same server time stamp.
        XTestFakeKeyEvent(display_, code, 1, 3);
        XTestFakeKeyEvent(display_, code, 0, 3);
        XFlush(display_);
    }
    /// Lower-case letters, digits and '.'.
    void type(const std::string& text) {
        for (char c : text) {
            const KeySym symbol = XStringToKeysym(c == '.' ? "period" : std::string(1, c).c_str());
            REQUIRE(symbol != NoSymbol);
            key(symbol);
        }
    }
    /// Moves to each point and clicks there, all sent before the client reads any of them.
    void clickBurst(GLFWwindow* window, const std::vector<glm::dvec2>& points) {
        int x = 0, y = 0;
        glfwGetWindowPos(window, &x, &y);
        for (const glm::dvec2& p : points) {
            XTestFakeMotionEvent(display_, -1, x + int(std::lround(p.x)), y + int(std::lround(p.y)), 0);
            XTestFakeButtonEvent(display_, 1, 1, 0);
            XTestFakeButtonEvent(display_, 1, 0, 0);
        }
        XSync(display_, False);
    }
    /// The user (the window manager) resizes the window.
    void resize(unsigned width, unsigned height) {
        XResizeWindow(display_, window(), width, height), XSync(display_, False);
    }
    /// The user closes the window from the window manager (ICCCM WM_DELETE_WINDOW).
    void close() {
        XEvent e{};
        e.xclient.type = ClientMessage;
        e.xclient.window = window();
        e.xclient.message_type = XInternAtom(display_, "WM_PROTOCOLS", False);
        e.xclient.format = 32;
        e.xclient.data.l[0] = long(XInternAtom(display_, "WM_DELETE_WINDOW", False));
        e.xclient.data.l[1] = CurrentTime;
        XSendEvent(display_, e.xclient.window, False, NoEventMask, &e);
        XSync(display_, False);
    }
    void iconify() { setState(IconicState), XUnmapWindow(display_, window()), XFlush(display_); }
    void restore() { XMapWindow(display_, window()), setState(NormalState), XFlush(display_); }

private:
    /// The test window, a child of the root (no window manager reparents it).
    Window window() { return namedWindow(display_, title); }
    void setState(long state) {
        const Atom wmState = XInternAtom(display_, "WM_STATE", False);
        const long data[2] = {state, 0};
        XChangeProperty(display_, window(), wmState, wmState, 32, PropModeReplace,
                        reinterpret_cast<const unsigned char*>(data), 2);
    }

    Display* display_;
};

/// Workstation 1 in a 480 x 320 window, its display surface the drawable: structure 1 holds a
/// red square (pick id 5) over NPC (0.1 .. 0.4)^2; the string device echoes on the bottom line.
struct WindowRig {
    render_test::VirtualDisplay server;
    Phigs phigs;
    Workstation* ws = nullptr;
    GlfwWindow window{480, 320, title};
    std::unique_ptr<vk::WorkstationDisplay> display;
    GlfwInputSource source{window};
    InputQueue queue;
    XServer x;
    std::vector<EventReport> reports;
    const EchoVolume echoArea{20, 460, 270, 306, 0, 1};

    WindowRig() {
        phigs.open();
        auto& store = phigs.store();
        store.openStructure(1);
        store.insert(IndexAttribute{ElementType::InteriorStyle, 1});
        store.insert(ColourAttribute{ElementType::InteriorColour, Colour::fromRgb(red)});
        store.insert(pickId(5));
        store.insert(addNamesToSet({1}));
        store.insert(fillArea3({{0.1, 0.1, 0}, {0.4, 0.1, 0}, {0.4, 0.4, 0}, {0.1, 0.4, 0}}));
        store.closeStructure();
        ws = &phigs.openWorkstation(1, WorkstationType::Window);
        fit();
        ws->postStructure(1, 0.5);
        ws->input().setPickFilter(1, {1}, {});  // starts empty (ISO 9592): nothing pickable
        vk::DisplaySettings settings;
        settings.window = &window;
        settings.readBack = true;
        display =
            std::make_unique<vk::WorkstationDisplay>(*ws, render_test::lavapipeWithValidation(), settings);
        ws->connectInput(source, queue);
        DeviceInitialisation string;
        string.initial = StringMeasure{};
        string.echoVolume = echoArea;
        ws->input().initialise(InputClass::String, 1, string);
        ws->input().setMode(InputClass::String, 1, OperatingMode::Event);
        ws->input().setMode(InputClass::Pick, 1, OperatingMode::Event);
        REQUIRE(display->update());
        pumpFor(400ms);  // let the server map the window before pointing at it
    }
    ~WindowRig() { ws->disconnectInput(); }

    /// The display surface is the drawable (3:2 here), the workstation window its shape in NPC.
    void fit() {
        const VkExtent2D size = window.drawableSize();
        ws->setDisplaySize({double(size.width), double(size.height)});
        ws->setWorkstationWindow({0, 0, 0}, {1, double(size.height) / size.width, 1});
        ws->setWorkstationViewport({0, 0, 0}, {double(size.width), double(size.height), 1});
    }
    /// Pumps the window's events into the devices (AWAIT EVENT) for `time`, keeping reports.
    void pumpFor(std::chrono::milliseconds time) {
        const auto until = std::chrono::steady_clock::now() + time;
        while (std::chrono::steady_clock::now() < until)
            if (auto r = queue.awaitEvent(10ms)) reports.push_back(*r);
    }
    /// Pumps until `done()` or 10 s (a loaded machine); false on the time limit.
    template <class Done>
    bool pumpUntil(Done done) {
        const auto until = std::chrono::steady_clock::now() + 10s;
        while (!done()) {
            if (std::chrono::steady_clock::now() > until) return false;
            if (auto r = queue.awaitEvent(10ms)) reports.push_back(*r);
        }
        return true;
    }
    std::string echoed() const {
        const EchoState e = ws->echoState();
        return e.empty() ? std::string() : e.strings.at(0).shown();
    }
};

/// Pixels of the echo area where `picture` and `reference` differ (a channel off by more than 24).
std::size_t differingInArea(const Image& picture, const Image& reference, const EchoVolume& a) {
    REQUIRE(picture.width == reference.width);
    REQUIRE(picture.height == reference.height);
    std::size_t count = 0;
    for (std::uint32_t y = std::uint32_t(a.ymin); y < std::uint32_t(a.ymax); ++y)
        for (std::uint32_t x = std::uint32_t(a.xmin); x < std::uint32_t(a.xmax); ++x) {
            const std::uint8_t *p = picture.pixel(x, y), *q = reference.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                if (std::abs(int(p[c]) - int(q[c])) > 24) {
                    ++count;
                    break;
                }
        }
    return count;
}

}  // namespace

TEST_CASE("window workstation: typed text echoes in the string device's echo area, drawn by the toolkit",
          "[window][echo]") {
    WindowRig rig;
    // The reference: the same picture drawn offscreen with an echo state given by the test.
    Workstation& offscreen = rig.phigs.openWorkstation(2, WorkstationType::OffscreenImage);
    offscreen.setDisplaySize({480, 320});
    offscreen.setWorkstationWindow({0, 0, 0}, {1, 320.0 / 480.0, 1});
    offscreen.setWorkstationViewport({0, 0, 0}, {480, 320, 1});
    offscreen.postStructure(1, 0.5);
    vk::DisplaySettings size;
    size.width = 480, size.height = 320;
    vk::WorkstationDisplay reference(offscreen, rig.display->context(), size);
    auto drawn = [&](const std::string& text, bool cancelled) {
        EchoState echo;
        if (!text.empty() || cancelled) echo.strings.push_back({1, rig.echoArea, text, cancelled});
        reference.showEcho(echo);
        REQUIRE(reference.present(offscreen.shownPicture()));
        return reference.image();
    };
    // The picture shows exactly the echo typed so far: read back, it matches the toolkit's
    // drawing of that text and not of one character less.
    auto shows = [&](const std::string& text, const std::string& less, bool cancelled = false) {
        const Image& picture = rig.display->image();
        CHECK(differingInArea(picture, drawn(text, cancelled), rig.echoArea) <= 4);
        CHECK(differingInArea(picture, drawn(less, false), rig.echoArea) > 20);
    };

    rig.x.moveTo(rig.window.handle(), {240, 160});  // the keyboard goes to the window under the pointer
    rig.x.type("wing.acm");
    REQUIRE(rig.pumpUntil([&] { return rig.echoed() == "wing.acm_"; }));
    rig.pumpFor(50ms);
    CHECK(rig.display->echo() == rig.ws->echoState());  // what the renderer draws
    shows("wing.acm", "wing.ac");
    rig.x.key(XK_BackSpace);
    REQUIRE(rig.pumpUntil([&] { return rig.echoed() == "wing.ac_"; }));
    rig.pumpFor(50ms);
    shows("wing.ac", "wing.a");
    rig.x.type("m");
    rig.x.key(XK_Return);
    REQUIRE(rig.pumpUntil([&] { return !rig.reports.empty(); }));
    CHECK(rig.reports.back().inputClass == InputClass::String);
    CHECK(std::get<StringMeasure>(rig.reports.back().measure).text == "wing.acm");
    CHECK(rig.echoed().empty());
    rig.pumpFor(50ms);
    shows("", "wing.acm");  // accepted: the area is empty again

    rig.x.type("x");
    rig.x.key(XK_Escape);
    REQUIRE(rig.pumpUntil([&] { return rig.echoed() == "cancelled"; }));
    rig.pumpFor(50ms);
    shows("", "x", true);
    CHECK(rig.reports.size() == 1);  // Escape delivers nothing
    render_test::requireNoValidationMessages(rig.display->context());
}

TEST_CASE("window workstation: minimised and restored, it keeps its devices and draws at the new size",
          "[window][resize]") {
    WindowRig rig;
    rig.ws->input().initialise(InputClass::Valuator, 1,
                               valuatorSliderInitialisation(0, 10, 3, {300, 460, 20, 40, 0, 1}));
    rig.ws->input().setMode(InputClass::Valuator, 1, OperatingMode::Sample);
    REQUIRE(rig.display->image().width == 480);
    CHECK(render_test::shows(rig.display->image(), {120, 200}, red));  // NPC (0.25, 0.25)

    const std::uint64_t damage = rig.window.damage();
    rig.x.iconify();
    REQUIRE(rig.pumpUntil([&] { return rig.window.iconified(); }));
    CHECK(rig.ws->drawableSize() == DrawableSize{0, 0});
    CHECK_FALSE(rig.display->update());  // nothing to draw on, and no error
    CHECK_FALSE(rig.ws->present());
    // Input maps through the display surface meanwhile; the devices keep modes and measures.
    const glm::dvec3 npc = rig.ws->measurer().toNpc({120, 200});
    CHECK(npc.x == Approx(0.25));
    CHECK(npc.y == Approx(0.25));
    CHECK(rig.ws->input().device(InputClass::Pick, 1).mode == OperatingMode::Event);
    CHECK(std::get<ValuatorMeasure>(rig.ws->input().sample(InputClass::Valuator, 1)).value == 3.0);

    rig.window.resize(600, 400);  // resized while minimised: 3:2 still
    rig.pumpFor(100ms);
    rig.x.restore();
    REQUIRE(rig.pumpUntil([&] {
        return !rig.window.iconified() && rig.ws->drawableSize() == DrawableSize{600, 400};
    }));
    CHECK(rig.window.damage() > damage);
    rig.fit();  // the display surface follows the drawable, as a program does
    REQUIRE(rig.display->update());
    REQUIRE(rig.display->image().width == 600);
    REQUIRE(rig.display->image().height == 400);
    CHECK(render_test::shows(rig.display->image(), {150, 250}, red));  // NPC (0.25, 0.25) now

    // A real click on the square picks it through the new size.
    rig.pumpFor(200ms);
    rig.reports.clear();
    rig.x.moveTo(rig.window.handle(), {150, 250});
    rig.x.click();
    REQUIRE(rig.pumpUntil([&] {
        return std::any_of(rig.reports.begin(), rig.reports.end(),
                           [](const EventReport& r) { return r.inputClass == InputClass::Pick; });
    }));
    for (const EventReport& r : rig.reports)
        if (r.inputClass == InputClass::Pick) {
            const auto& pick = std::get<PickMeasure>(r.measure);
            REQUIRE(pick.status == InputStatus::Ok);
            REQUIRE(!pick.path.empty());
            CHECK(pick.path.back().pickId == 5);
        }
    CHECK(std::get<ValuatorMeasure>(rig.ws->input().sample(InputClass::Valuator, 1)).value == 3.0);
    render_test::requireNoValidationMessages(rig.display->context());
}

TEST_CASE("window workstation: input maps through the picture it was made on, a closed window ends requests",
          "[window][resize]") {
    WindowRig rig;  // 480 x 320 pixels, the workstation window 1 x 2/3 of NPC over all of it
    rig.ws->input().setMode(InputClass::Locator, 1, OperatingMode::Event);
    // NPC of a pixel as the rig's workstation transformation maps it on a surface `height` high.
    const auto npc = [](glm::dvec2 pixel, double height) {
        return glm::dvec2(pixel.x / 480.0, (height - pixel.y) / 480.0);
    };
    const auto locatorReports = [&] {
        std::vector<glm::dvec2> out;
        for (const EventReport& r : rig.reports)
            if (r.inputClass == InputClass::Locator)
                out.push_back(glm::dvec2(std::get<LocatorMeasure>(r.measure).position));
        return out;
    };
    // A burst of clicks read at once: each is reported where it was made, not where the
    // pointer is when the client reads it.
    std::mt19937 random(12);
    std::vector<glm::dvec2> clicks;
    for (int i = 0; i < 6; ++i)
        clicks.push_back({std::uniform_int_distribution<int>(20, 460)(random),
                          std::uniform_int_distribution<int>(20, 300)(random)});
    rig.x.clickBurst(rig.window.handle(), clicks);
    REQUIRE(rig.pumpUntil([&] { return locatorReports().size() == clicks.size(); }));
    for (std::size_t i = 0; i < clicks.size(); ++i) {
        CHECK(std::abs(locatorReports()[i].x - npc(clicks[i], 320).x) < 2.0 / 480);
        CHECK(std::abs(locatorReports()[i].y - npc(clicks[i], 320).y) < 2.0 / 480);
    }
    // A click, then a resize before the client reads either: the click belongs to the 480 x 320
    // picture it was made on, not to the 320 x 480 window the resize leaves.
    rig.reports.clear();
    const glm::dvec2 at{300, 200};
    rig.x.clickBurst(rig.window.handle(), {at});
    rig.x.resize(320, 480);
    REQUIRE(rig.pumpUntil([&] { return locatorReports().size() == 1; }));
    CHECK(std::abs(locatorReports()[0].x - npc(at, 320).x) < 2.0 / 480);
    CHECK(std::abs(locatorReports()[0].y - npc(at, 320).y) < 2.0 / 480);
    // Made wider by its user than the device can draw, the window shows no picture (no Vulkan
    // object past the device's limits) until it is made smaller again.
    rig.x.resize(GlfwWindow::kMaxSide + 600, 100);
    REQUIRE(rig.pumpUntil([&] { return rig.window.drawableSize().width == GlfwWindow::kMaxSide + 600; }));
    rig.ws->redrawAllStructures();
    CHECK_FALSE(rig.display->update());
    rig.x.resize(400, 300);
    REQUIRE(rig.pumpUntil([&] { return rig.window.drawableSize().width == 400; }));
    CHECK(rig.display->update());
    render_test::requireNoValidationMessages(rig.display->context());
    // Closed by its user, the window ends a pending REQUEST (status NONE), and any made later.
    rig.ws->input().setMode(InputClass::Locator, 1, OperatingMode::Request);
    rig.x.close();
    CHECK(rig.ws->input().request(InputClass::Locator, 1).first != InputStatus::Ok);  // NONE (X defines None)
    CHECK(rig.window.shouldClose());
    CHECK(rig.ws->input().request(InputClass::Locator, 1).first != InputStatus::Ok);  // NONE (X defines None)
}

TEST_CASE("window workstation: a window it opened itself gives each new size to the display surface",
          "[window][resize]") {
    render_test::VirtualDisplay server;
    Phigs phigs;
    phigs.open();
    registerWindowOutputs(phigs.outputs(), render_test::lavapipeWithValidation());
    OutputConnection connection;
    connection.width = 400;
    connection.height = 300;
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::Window, connection);
    ws.followDrawable();
    REQUIRE(ws.displaySize() == glm::dvec2(400, 300));
    REQUIRE(ws.tables().viewportMax == glm::dvec3(400, 300, 1));  // covers the whole surface

    Display* x = XOpenDisplay(nullptr);
    REQUIRE(x);
    const Window window = namedWindow(x, "PHIGS workstation 1");
    std::mt19937 random(20261203);
    for (int i = 0; i < 4; ++i) {
        const int width = std::uniform_int_distribution<int>(120, 630)(random);
        const int height = std::uniform_int_distribution<int>(90, 470)(random);
        XResizeWindow(x, window, unsigned(width), unsigned(height));
        XSync(x, False);
        const DrawableSize wanted{std::uint32_t(width), std::uint32_t(height)};
        const auto until = std::chrono::steady_clock::now() + 10s;
        while (ws.drawableSize() != wanted && std::chrono::steady_clock::now() < until) glfwPollEvents();
        REQUIRE(ws.drawableSize() == wanted);
        CHECK(ws.present());  // the picture is made at the new size
        CHECK(ws.displaySize() == glm::dvec2(width, height));
        CHECK(ws.tables().viewportMax == glm::dvec3(width, height, 1));
    }
    // A viewport that covers part of the surface stays where it is through a resize.
    ws.setWorkstationViewport({10, 10, 0}, {100, 80, 1});
    XResizeWindow(x, window, 500, 400);
    XSync(x, False);
    const auto until = std::chrono::steady_clock::now() + 10s;
    while (ws.drawableSize() != DrawableSize{500, 400} && std::chrono::steady_clock::now() < until)
        glfwPollEvents();
    CHECK(ws.present());
    CHECK(ws.displaySize() == glm::dvec2(500, 400));
    CHECK(ws.tables().viewportMax == glm::dvec3(100, 80, 1));
    XCloseDisplay(x);
    phigs.closeWorkstation(1);
}
