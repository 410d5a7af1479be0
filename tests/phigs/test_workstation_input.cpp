// The logical input devices a workstation owns, measured on its picture (no GPU: the pixels
// are the workstation's device coordinates unless its output or the test says otherwise), and
// the string echo it hands its output.
#include "phigs/Phigs.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/input/WindowEventMapper.h"

#include "InputFakes.h"

#include <catch2/catch.hpp>

#include <deque>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <random>

namespace test_workstation_input {

using namespace phigs;

namespace {

/// Workstation 1 (display 1024 x 768, viewport the whole display, window the unit square: 768
/// pixels per NPC unit) with view 1 on the left half of NPC showing world scaled by 1/2, and
/// structure 1 holding a square in view 1 (pick id 3) and one in view 0 (pick id 4).
struct Rig {
    Phigs phigs;
    Workstation* ws = nullptr;
    Rig() {
        phigs.open();
        auto& store = phigs.store();
        store.openStructure(1);
        store.insert(addNamesToSet({1}));
        store.insert(IndexAttribute{ElementType::InteriorStyle, 1});
        store.insert(viewIndex(1));
        store.insert(pickId(3));
        store.insert(fillArea3({{0.1, 0.1, 0}, {0.5, 0.1, 0}, {0.5, 0.5, 0}, {0.1, 0.5, 0}}));
        store.insert(viewIndex(0));
        store.insert(pickId(4));
        store.insert(fillArea3({{0.7, 0.1, 0}, {0.9, 0.1, 0}, {0.9, 0.3, 0}, {0.7, 0.3, 0}}));
        store.closeStructure();
        ws = &phigs.openWorkstation(1, WorkstationType::Window);
        ViewRepresentation left;
        left.mapping = glm::scale(glm::dmat4(1.0), glm::dvec3(0.5, 0.5, 1.0));
        left.clipMax = {0.5, 1.0, 1.0};
        ws->setViewRepresentation(1, left);
        ws->postStructure(1, 0.5);
        ws->input().setPickFilter(1, {1}, {});
    }
};

}  // namespace

TEST_CASE("workstation input: the locator honours the view table's input priority", "[input][wiring]") {
    Rig rig;
    // NPC (0.2, 0.25) is pixel (153.6, 768 - 192) = (153.6, 576) from the top left.
    ScriptInputSource script("locator 153.6 576\nlocator 153.6 576\nlocator 691.2 576\n", "loc.txt");
    InputQueue queue;
    rig.ws->connectInput(script, queue);
    auto locate = [&] {
        auto [status, measure] = rig.ws->input().request(InputClass::Locator, 1);
        REQUIRE(status == InputStatus::Ok);
        return std::get<LocatorMeasure>(measure);
    };
    // View 0 comes first initially and holds every point.
    LocatorMeasure a = locate();
    CHECK(a.viewIndex == 0);
    CHECK(a.position.x == Approx(0.2));
    CHECK(a.position.y == Approx(0.25));
    // SET VIEW TRANSFORMATION INPUT PRIORITY on the workstation reaches the measurer.
    rig.ws->setViewTransformationInputPriority(1, 0, true);
    a = locate();
    CHECK(a.viewIndex == 1);
    CHECK(a.position.x == Approx(0.4));
    CHECK(a.position.y == Approx(0.5));
    a = locate();  // NPC x 0.9 is outside view 1's clip limits
    CHECK(a.viewIndex == 0);
    CHECK(a.position.x == Approx(0.9));
}

TEST_CASE("workstation input: a pick filter starts empty, so nothing is pickable (ISO 9592)",
          "[input][wiring]") {
    Phigs phigs;
    phigs.open();
    auto& store = phigs.store();
    store.openStructure(1);
    store.insert(IndexAttribute{ElementType::InteriorStyle, 1});  // solid: picked inside
    store.insert(addNamesToSet({1, 2}));
    store.insert(pickId(3));
    store.insert(fillArea3({{0.1, 0.1, 0}, {0.5, 0.1, 0}, {0.5, 0.5, 0}, {0.1, 0.5, 0}}));
    store.closeStructure();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::Window);
    ws.postStructure(1, 0.5);
    // NPC (0.25, 0.25) on the 1024 x 768 display, four times.
    ScriptInputSource script("pick 192 576\npick 192 576\npick 192 576\npick 192 576\n", "picks");
    InputQueue queue;
    ws.connectInput(script, queue);
    auto picked = [&] { return ws.input().request(InputClass::Pick, 1).first == InputStatus::Ok; };
    CHECK(ws.input().device(InputClass::Pick, 1).pickInclusion.empty());
    CHECK_FALSE(picked());  // named, under the cursor, but the inclusion set is empty
    ws.input().setPickFilter(1, {2}, {});
    CHECK(picked());
    ws.input().setPickFilter(1, {2}, {1});  // the exclusion set wins
    CHECK_FALSE(picked());
    ws.input().setPickFilter(1, {}, {});
    CHECK_FALSE(picked());
}

TEST_CASE("workstation input: picks see the current structures and the surface size", "[input][wiring]") {
    Rig rig;
    // Square 1 is drawn at NPC (0.05 .. 0.25); square 2 at NPC (0.7 .. 0.9) x (0.1 .. 0.3).
    ScriptInputSource script("pick 115.2 652.8\npick 614.4 614.4\npick 115.2 652.8\npick 300 400\n",
                             "pick.txt");
    InputQueue queue;
    rig.ws->connectInput(script, queue);
    auto pick = [&] {
        auto [status, measure] = rig.ws->input().request(InputClass::Pick, 1);
        return status == InputStatus::Ok ? std::get<PickMeasure>(measure).path : std::vector<PickPathItem>{};
    };
    CHECK(pick() == std::vector<PickPathItem>{{1, 5, 3}});
    CHECK(pick() == std::vector<PickPathItem>{{1, 8, 4}});
    // Delete the first square: the next pick at its place finds nothing.
    auto& store = rig.phigs.store();
    store.openStructure(1);
    store.setElementPointer(5);
    store.deleteElement();
    store.closeStructure();
    CHECK(pick().empty());
    // On a surface of half the size (512 x 384 pixels, half a pixel per device unit), pixel
    // (300, 400) lies below the bottom edge; pixel (200, 300) is device (400, 168).
    rig.ws->measurer().setSurfaceSize(512, 384);
    CHECK(pick().empty());
    CHECK(rig.ws->measurer().toNpc({200, 300}).x == Approx(400.0 / 768.0));
    CHECK(rig.ws->measurer().toNpc({200, 300}).y == Approx(168.0 / 768.0));
    // A surface that changes (a resized window) is asked at each measure.
    std::uint32_t width = 1024, height = 768;
    rig.ws->measurer().setSurfaceSize([&] { return std::pair{width, height}; });
    CHECK(rig.ws->measurer().toNpc({400, 368}).y == Approx(400.0 / 768.0));
    width = 2048, height = 1536;
    CHECK(rig.ws->measurer().toNpc({400, 368}).y == Approx((1536.0 - 368.0) / 2.0 / 768.0));
}

TEST_CASE("workstation output seam: the picture with the echo, input through the drawable's size",
          "[ws][wiring]") {
    /// An output in memory: keeps the last picture, reports the drawable it is told.
    struct MemoryOutput : WorkstationOutput {
        DrawList last;
        int presents = 0;
        DrawableSize size{512, 384};
        bool present(const DrawList& picture) override {
            last = picture;
            ++presents;
            return true;
        }
        DrawableSize drawableSize() const override { return size; }
    };
    Rig rig;
    Workstation& ws = *rig.ws;
    CHECK_FALSE(ws.present());  // nothing attached
    CHECK(ws.drawableSize() == DrawableSize{1024, 768});
    MemoryOutput out;
    ws.attachOutput(&out);
    REQUIRE(ws.present());
    REQUIRE(out.last.items.size() == 2);
    CHECK_FALSE(out.last.items[1].highlighted());
    ws.setEcho({out.last.items[1].source.path()});
    REQUIRE(ws.present());
    CHECK(out.presents == 2);
    CHECK_FALSE(out.last.items[0].highlighted());
    CHECK(out.last.items[1].highlighted());
    CHECK_FALSE(ws.display().items[1].highlighted());  // the workstation's own picture is untouched
    // Input maps through the output's drawable: 512 x 384 pixels, half a pixel per device unit.
    test::IdleSource source;
    InputQueue queue;
    ws.connectInput(source, queue);
    CHECK(ws.measurer().toNpc({200, 300}).x == Approx(400.0 / 768.0));
    out.size = {2048, 1536};  // resized: asked at each measure
    CHECK(ws.measurer().toNpc({400, 368}).y == Approx((1536.0 - 368.0) / 2.0 / 768.0));
    out.size = {0, 0};  // minimised: one pixel per device unit meanwhile
    CHECK(ws.measurer().toNpc({400, 368}).y == Approx(400.0 / 768.0));
    ws.attachOutput(nullptr);
    CHECK_FALSE(ws.present());
}

TEST_CASE("workstation output seam: a workstation and its outputs may go in either order", "[ws][wiring]") {
    // An application's own output (a vk::WorkstationDisplay made as the examples make it) may be
    // destroyed after CLOSE WORKSTATION, or before it while still attached; one destroyed goes
    // back to the output OPEN WORKSTATION made. (ASan in CI checks that nothing freed is touched.)
    struct MemoryOutput : WorkstationOutput {
        bool present(const DrawList&) override { return true; }
        DrawableSize drawableSize() const override { return {64, 64}; }
    };
    Rig rig;
    {
        MemoryOutput alone;
        rig.ws->attachOutput(&alone);
    }
    CHECK(rig.ws->output() == nullptr);  // destroyed while attached, no output of its own
    auto opened = std::make_unique<MemoryOutput>();
    WorkstationOutput* made = opened.get();
    rig.ws->ownOutput(std::move(opened));
    {
        MemoryOutput extra;
        rig.ws->attachOutput(&extra);
        CHECK(rig.ws->output() == &extra);
    }
    CHECK(rig.ws->output() == made);  // back to OPEN WORKSTATION's output, not to none
    CHECK(rig.ws->present());
    auto late = std::make_unique<MemoryOutput>();
    rig.ws->attachOutput(late.get());
    rig.phigs.closeWorkstation(1);
    late.reset();  // after its workstation
    CHECK(rig.phigs.findWorkstation(1) == nullptr);
}

namespace {

/// A window's keyboard without a window: events through the WindowEventMapper a GLFW source uses.
class TypingSource : public InputSource {
public:
    void post(const WindowEvent& event) {
        if (auto a = mapper.handle(event)) actions.push_back(*a);
    }
    void type(const std::string& text) {
        for (char c : text) post(window_event::Character{char32_t(c)});
    }
    void key(window_event::Key k) { post(window_event::KeyPress{k, 0}); }
    std::optional<InputAction> next(std::chrono::milliseconds) override {
        if (actions.empty()) return std::nullopt;
        InputAction a = actions.front();
        actions.pop_front();
        return a;
    }
    bool exhausted() const override { return false; }
    std::string position() const override { return "keyboard"; }
    StringEcho stringEcho() const override { return mapper.stringEcho(); }
    void startString(const std::string& text) override { mapper.startString(text); }

    WindowEventMapper mapper;
    std::deque<InputAction> actions;
};

/// A keyboard whose keys are pressed when the workstation reads them (during a request).
class LaterTypingSource : public InputSource {
public:
    void type(const std::string& text) {
        for (char c : text) events.push_back(window_event::Character{char32_t(c)});
    }
    void key(window_event::Key k, int times = 1) {
        for (int i = 0; i < times; ++i) events.push_back(window_event::KeyPress{k, 0});
    }
    std::optional<InputAction> next(std::chrono::milliseconds) override {
        while (!events.empty()) {
            const WindowEvent event = events.front();
            events.pop_front();
            if (auto a = mapper.handle(event)) return a;
        }
        return std::nullopt;
    }
    bool exhausted() const override { return false; }
    std::string position() const override { return "keyboard"; }
    StringEcho stringEcho() const override { return mapper.stringEcho(); }
    void startString(const std::string& text) override { mapper.startString(text); }

    WindowEventMapper mapper;
    std::deque<WindowEvent> events;
};

/// An output in memory that keeps the echo it was handed with each picture.
struct EchoOutput : WorkstationOutput {
    std::vector<EchoState> shown;  ///< the echo at each present
    EchoState echo;
    bool deviceEchoes = false;
    bool present(const DrawList&) override {
        shown.push_back(echo);
        return true;
    }
    DrawableSize drawableSize() const override { return {1024, 768}; }
    void showEcho(const EchoState& e) override { echo = e; }
    bool drawsDeviceEchoes() const override { return deviceEchoes; }
};

DeviceInitialisation stringWithArea(EchoVolume area) {
    DeviceInitialisation s;
    s.initial = StringMeasure{};
    s.echoVolume = area;
    return s;
}

}  // namespace

TEST_CASE("workstation input: OPEN WORKSTATION makes the devices, connecting gives them a source",
          "[input][wiring]") {
    Rig rig;
    Workstation& ws = *rig.ws;
    CHECK(ws.input().counts().valuator == ws.description().inputDevices.valuator);
    // No source yet: the devices take INITIALIZE and SET MODE; REQUEST is refused (250).
    ws.input().initialise(InputClass::Valuator, 2,
                          valuatorSliderInitialisation(0, 4, 3, {0, 10, 0, 10, 0, 1}));
    ws.input().setMode(InputClass::Valuator, 2, OperatingMode::Sample);
    CHECK(std::get<ValuatorMeasure>(ws.input().sample(InputClass::Valuator, 2)).value == 3.0);
    try {
        ws.input().request(InputClass::Locator, 1);
        FAIL("REQUEST without a source");
    } catch (const Error& e) {
        CHECK(e.number() == errors::DeviceNotAvailable);
    }
    {
        ScriptInputSource script("valuator 2 1.5\n", "v.txt");
        InputQueue queue;
        ws.connectInput(script, queue);
        CHECK(queue.awaitEvent(std::chrono::milliseconds(0)) == std::nullopt);  // sample mode: no report
        CHECK(std::get<ValuatorMeasure>(ws.input().sample(InputClass::Valuator, 2)).value == 1.5);
    }  // the queue goes first: the workstation keeps its devices, unconnected
    CHECK(ws.input().source() == nullptr);
    CHECK(std::get<ValuatorMeasure>(ws.input().sample(InputClass::Valuator, 2)).value == 1.5);

    // An OUTPUT workstation has no logical input devices.
    Workstation& pdf = rig.phigs.openWorkstation(2, WorkstationType::PdfFile);
    CHECK(pdf.description().category == WorkstationCategory::Output);
    try {
        pdf.input().device(InputClass::Locator, 1);
        FAIL("a locator on an OUTPUT workstation");
    } catch (const Error& e) {
        CHECK(e.number() == errors::DeviceNotAvailable);
    }
}

TEST_CASE("workstation input: a string device's initial string is the text the operator edits",
          "[input][echo]") {
    // The window started every string empty: Enter alone gave "", not the initial string, and
    // the echo area did not show it (ISO 9592: the initial string is the measure the operator
    // starts from).
    Rig rig;
    Workstation& ws = *rig.ws;
    LaterTypingSource keys;
    InputQueue queue;
    ws.connectInput(keys, queue);
    DeviceInitialisation setup = stringWithArea({500, 1000, 700, 740, 0, 1});
    setup.initial = StringMeasure{"default.dat"};
    ws.input().initialise(InputClass::String, 1, setup);
    using window_event::Key;
    auto requested = [&] {
        const auto [status, measure] = ws.input().request(InputClass::String, 1);
        CHECK(status == InputStatus::Ok);
        return std::get<StringMeasure>(measure).text;
    };
    keys.key(Key::Enter);
    CHECK(requested() == "default.dat");
    keys.key(Key::Backspace, 3);
    keys.type("txt");
    keys.key(Key::Enter);
    CHECK(requested() == "default.txt");
    // Each request starts from the initial string again, whatever was typed before it.
    keys.mapper.startString("left over");
    keys.type("2");
    keys.key(Key::Enter);
    CHECK(requested() == "default.dat2");
    // EVENT mode starts from it too, and so does the echo.
    ws.input().setMode(InputClass::String, 1, OperatingMode::Event);
    CHECK(keys.stringEcho().text == "default.dat");
    keys.key(Key::Backspace, 4);
    keys.key(Key::Enter);
    const auto report = queue.awaitEvent(std::chrono::milliseconds(0));
    REQUIRE(report);
    CHECK(std::get<StringMeasure>(report->measure).text == "default");
}

TEST_CASE("workstation echo: typed text reaches the string device's echo area through the output",
          "[input][echo]") {
    Rig rig;
    Workstation& ws = *rig.ws;
    EchoOutput out;
    ws.attachOutput(&out);
    TypingSource keys;
    InputQueue queue;
    ws.connectInput(keys, queue);
    const EchoVolume area{500, 1000, 700, 740, 0, 1};
    ws.input().initialise(InputClass::String, 1, stringWithArea(area));
    using window_event::Key;

    // REQUEST mode and no request: the device is not active, nothing echoes.
    keys.type("ab");
    CHECK_FALSE(queue.awaitEvent(std::chrono::milliseconds(0)));
    CHECK(ws.echoState().empty());
    keys.key(Key::Escape);
    CHECK_FALSE(queue.awaitEvent(std::chrono::milliseconds(0)));

    // EVENT mode: each edit is presented with the echo, without the application presenting.
    ws.input().setMode(InputClass::String, 1, OperatingMode::Event);
    std::string model;
    std::mt19937 random(7);
    const std::string alphabet = "abcdefghijklmnopqrstuvwxyz0123456789._-";
    for (int step = 0; step < 400; ++step) {
        const int what = int(random() % 10);
        out.shown.clear();
        if (what < 6) {
            const char c = alphabet[random() % alphabet.size()];
            keys.type(std::string(1, c));
            model += c;
        } else if (what < 8) {
            keys.key(Key::Backspace);
            if (!model.empty()) model.pop_back();
        } else if (what < 9) {
            keys.key(Key::Enter);
            const auto report = queue.awaitEvent(std::chrono::milliseconds(0));
            REQUIRE(report);
            CHECK(std::get<StringMeasure>(report->measure).text == model);
            model.clear();
            CHECK(ws.echoState().empty());  // accepted: the area is empty again
            continue;
        } else {
            keys.key(Key::Escape);
            CHECK_FALSE(queue.awaitEvent(std::chrono::milliseconds(0)));  // a break nobody requested
            model.clear();
            REQUIRE(ws.echoState().strings.size() == 1);
            CHECK(ws.echoState().strings[0].shown() == "cancelled");
            continue;
        }
        CHECK_FALSE(queue.awaitEvent(std::chrono::milliseconds(0)));
        const EchoState now = ws.echoState();
        if (model.empty()) {
            CHECK(now.empty());
            continue;
        }
        REQUIRE(now.strings.size() == 1);
        CHECK(now.strings[0].shown() == model + "_");
        CHECK(now.strings[0].area.xmin == area.xmin);
        REQUIRE(out.shown.size() == 1);  // presented once, with the echo it draws
        CHECK(out.shown.back() == now);
    }

    // Echo off, another prompt/echo type or no echo area: nothing shows.
    keys.type("x");
    CHECK_FALSE(queue.awaitEvent(std::chrono::milliseconds(0)));
    CHECK_FALSE(ws.echoState().empty());
    ws.input().setMode(InputClass::String, 1, OperatingMode::Event, EchoSwitch::NoEcho);
    CHECK(ws.echoState().empty());
    ws.input().setMode(InputClass::String, 1, OperatingMode::Event);
    keys.type("x");
    CHECK_FALSE(queue.awaitEvent(std::chrono::milliseconds(0)));
    // An area too small for a line of text (the default one of 1 x 1 pixels) shows nothing.
    // (Entering EVENT mode starts the typing over from the initial string, here empty.)
    ws.input().setMode(InputClass::String, 1, OperatingMode::Request);
    ws.input().initialise(InputClass::String, 1, stringWithArea({500, 1000, 700, 705, 0, 1}));
    ws.input().setMode(InputClass::String, 1, OperatingMode::Event);
    keys.type("x");
    CHECK_FALSE(queue.awaitEvent(std::chrono::milliseconds(0)));
    CHECK(ws.echoState().empty());
    ws.input().setMode(InputClass::String, 1, OperatingMode::Request);
    ws.input().initialise(InputClass::String, 1, stringWithArea({500, 1000, 700, 740, 0, 1}));
    ws.input().setMode(InputClass::String, 1, OperatingMode::Event);
    keys.type("x");
    CHECK_FALSE(queue.awaitEvent(std::chrono::milliseconds(0)));
    CHECK_FALSE(ws.echoState().empty());
}

TEST_CASE("workstation echo: an output that draws device echoes gets the active panels, sliders and pick",
          "[input][echo]") {
    Rig rig;
    Workstation& ws = *rig.ws;
    EchoOutput out;
    out.deviceEchoes = true;
    ws.attachOutput(&out);
    ws.input().initialise(
        InputClass::Choice, 1,
        choicePanelInitialisation({"Wing", "Tail", "Body", "Fin"}, {10, 90, 10, 70, 0, 1}, 2));
    ws.input().initialise(InputClass::Valuator, 1,
                          valuatorSliderInitialisation(0, 10, 5, {100, 180, 150, 170, 0, 1}));
    // Random choices and values, then a pick of the square with pick id 4 (NPC (0.8, 0.2)) and
    // one of nothing, then the request's choice.
    std::mt19937 random(23);
    std::vector<std::pair<int, double>> steps;
    std::string script;
    for (int i = 0; i < 30; ++i) {
        steps.push_back({1 + int(random() % 4), double(random() % 1001) / 100.0});
        script += "choice " + std::to_string(steps.back().first) + "\nvaluator 1 " +
                  std::to_string(steps.back().second) + "\n";
    }
    script += "pick 614.4 614.4\npick 1000 20\nchoice 3\n";
    ScriptInputSource source(script, "echoes.txt");
    InputQueue queue;
    ws.connectInput(source, queue);

    // REQUEST mode and no request: nothing is active.
    CHECK(ws.echoState().empty());
    // SET MODE shows the panel and slider at once, at their initial measures.
    out.shown.clear();
    ws.input().setMode(InputClass::Choice, 1, OperatingMode::Event);
    ws.input().setMode(InputClass::Valuator, 1, OperatingMode::Event);
    REQUIRE_FALSE(out.shown.empty());
    REQUIRE(out.shown.back().choices.size() == 1);
    REQUIRE(out.shown.back().valuators.size() == 1);
    CHECK(out.shown.back().choices[0].current == 2);
    CHECK(out.shown.back().choices[0].panel.alternatives.size() == 4);
    CHECK(out.shown.back().valuators[0].value == 5.0);
    for (const auto& [choice, value] : steps) {
        REQUIRE(queue.awaitEvent(std::chrono::milliseconds(0)));
        CHECK(out.shown.back().choices.at(0).current == choice);
        REQUIRE(queue.awaitEvent(std::chrono::milliseconds(0)));
        CHECK(out.shown.back().valuators.at(0).value == Approx(value));
        CHECK(out.shown.back() == ws.echoState());
    }

    // The pick echo: the picked square's item, highlighted by appendEchoes; a miss clears it.
    ws.input().setMode(InputClass::Pick, 1, OperatingMode::Event);
    CHECK(ws.echoState().picked.empty());
    REQUIRE(queue.awaitEvent(std::chrono::milliseconds(0)));
    const EchoState picked = out.shown.back();
    REQUIRE(picked.picked.size() == 1);
    DrawList shown = ws.display();
    appendEchoes(shown, picked, WorkstationMapping(shown, 1024, 768));
    int highlighted = 0;
    for (const DrawItem& item : shown.items)
        if (item.context->highlighted) {
            ++highlighted;
            CHECK(item.source.path() == picked.picked[0]);
            CHECK(item.context->viewIndex == 0);
        }
    CHECK(highlighted == 1);
    REQUIRE(queue.awaitEvent(std::chrono::milliseconds(0)));
    CHECK(out.shown.back().picked.empty());

    // Echo off, or an output that does not draw device echoes: none.
    ws.input().setMode(InputClass::Valuator, 1, OperatingMode::Event, EchoSwitch::NoEcho);
    ws.input().setMode(InputClass::Pick, 1, OperatingMode::Request);
    CHECK(ws.echoState().valuators.empty());
    CHECK(ws.echoState().choices.size() == 1);
    out.deviceEchoes = false;
    CHECK(ws.echoState().empty());
    out.deviceEchoes = true;

    // A REQUEST shows its panel while it waits (the initial alternative), and not after.
    ws.input().setMode(InputClass::Choice, 1, OperatingMode::Request);
    CHECK(ws.echoState().empty());
    out.shown.clear();
    const auto [status, measure] = ws.input().request(InputClass::Choice, 1);
    CHECK(status == InputStatus::Ok);
    CHECK(std::get<ChoiceMeasure>(measure).choice == 3);
    REQUIRE(out.shown.size() >= 2);
    REQUIRE(out.shown.front().choices.size() == 1);
    CHECK(out.shown.front().choices[0].current == 2);
    CHECK(out.shown.back().empty());
    ws.attachOutput(nullptr);
}

TEST_CASE("workstation echo: panels and sliders drawn over the picture fill their echo areas",
          "[input][echo]") {
    Rig rig;
    const DrawList& picture = rig.ws->display();
    const EchoStyle style;
    std::mt19937 random(5);
    for (int i = 0; i < 40; ++i) {
        const std::uint32_t width = 300 + random() % 1500, height = 200 + random() % 1000;
        const WorkstationMapping mapping(picture, width, height);
        const double x0 = random() % (width / 2), y0 = random() % (height / 2);
        const EchoVolume area{x0, x0 + 40 + random() % (width / 2), y0, y0 + 30 + random() % (height / 2), 0,
                              1};
        const int count = 1 + int(random() % 6), current = int(random() % (count + 1));
        ChoicePanel panel{1, area, std::vector<std::string>(std::size_t(count), "alternative")};
        EchoState echo;
        echo.choices.push_back({panel, current});
        DrawList shown = picture;
        appendEchoes(shown, echo, mapping, style);
        // Per alternative a box, its outline and its name: each box inside its row.
        REQUIRE(shown.items.size() == picture.items.size() + 3 * std::size_t(count));
        for (int n = 1; n <= count; ++n) {
            const DrawItem& item = shown.items[picture.items.size() + 3 * std::size_t(n - 1)];
            const auto* box = primitiveIf<DrawFillArea>(item.primitive);
            REQUIRE(box);
            CHECK_FALSE(item.pickable());
            const auto [topLeft, bottomRight] = panel.row(n);
            for (const glm::dvec3& corner : box->contours.at(0)) {
                const glm::dvec2 p = mapping.toPixels(corner);
                CHECK(p.x >= topLeft.x - 1e-6);
                CHECK(p.x <= bottomRight.x + 1e-6);
                CHECK(p.y >= topLeft.y - 1e-6);
                CHECK(p.y <= bottomRight.y + 1e-6);
            }
            const glm::vec3 expected(n == current ? style.current : style.box);
            CHECK(box->interior->colour == expected);
        }
        // A slider: the track fills the area, the knob sits at the value.
        const double value = double(random() % 101) / 10.0;
        EchoState slider;
        slider.valuators.push_back({ValuatorSlider{1, area, 0.0, 10.0}, value});
        shown = picture;
        appendEchoes(shown, slider, mapping, style);
        REQUIRE(shown.items.size() == picture.items.size() + 5);
        const auto* knob = primitiveIf<DrawFillArea>(shown.items[picture.items.size() + 2].primitive);
        REQUIRE(knob);
        glm::dvec2 centre(0.0);
        for (const glm::dvec3& corner : knob->contours.at(0)) centre += mapping.toPixels(corner) / 4.0;
        const bool horizontal = area.xmax - area.xmin >= area.ymax - area.ymin;
        CHECK((horizontal ? centre.x : centre.y) ==
              Approx(slider.valuators[0].slider.knobAt(value)).margin(1e-6));
    }
}

TEST_CASE("workstation echo: the echo is drawn inside its echo area, over the picture", "[input][echo]") {
    Rig rig;
    const DrawList& picture = rig.ws->display();
    std::mt19937 random(11);
    for (int i = 0; i < 50; ++i) {
        const std::uint32_t width = 200 + random() % 2000, height = 150 + random() % 1500;
        const WorkstationMapping mapping(picture, width, height);
        const double x0 = random() % (width / 2), y0 = random() % (height / 2);
        const double lineHeight = 8 + random() % 60;
        const EchoVolume area{x0, x0 + 4 * lineHeight + random() % (width / 2), y0, y0 + lineHeight, 0, 1};
        EchoState echo;
        echo.strings.push_back({1, area, "name.acm", i % 2 == 0});
        DrawList shown = picture;
        appendEchoes(shown, echo, mapping);
        REQUIRE(shown.items.size() == picture.items.size() + 3);
        const auto* box = primitiveIf<DrawFillArea>(shown.items[picture.items.size()].primitive);
        const auto* text = primitiveIf<DrawText>(shown.items.back().primitive);
        REQUIRE(box);
        REQUIRE(text);
        CHECK(text->text == (i % 2 == 0 ? "cancelled" : "name.acm_"));
        for (const glm::dvec3& corner : box->contours.at(0)) {
            const glm::dvec2 p = mapping.toPixels(corner);
            CHECK(std::min(std::abs(p.x - area.xmin), std::abs(p.x - area.xmax)) < 1e-6);
            CHECK(std::min(std::abs(p.y - area.ymin), std::abs(p.y - area.ymax)) < 1e-6);
        }
        const glm::dvec2 at = mapping.toPixels(text->position);
        CHECK(at.x > area.xmin);
        CHECK(at.x < area.xmin + 0.2 * (area.ymax - area.ymin) + 3);
        CHECK(at.y == Approx((area.ymin + area.ymax) / 2));
        CHECK(mapping.pixelsPerNpc * text->style->height == Approx(0.45 * (area.ymax - area.ymin)));
        for (std::size_t k = picture.items.size(); k < shown.items.size(); ++k)
            CHECK_FALSE(shown.items[k].pickable());
    }
}

}  // namespace test_workstation_input
