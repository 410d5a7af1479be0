// The session: PHIGS and its workstation, the devices, the panel's menu, the event loop.
#include "acsynt/session/Session.h"

#include "SessionShared.h"

#include "acsynt/session/MainMenu.h"

#include "acsynt/ModelFile.h"
#include "acsynt/session/ModelPicture.h"
#include "geom/DataReduction.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "phigs/core/Error.h"
#include "phigs/hardcopy/VectorOutput.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/view/ViewMatrices.h"
#include "phigs/ws/EchoStructures.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace acsynt {

using namespace phigs;
using namespace session_detail;

Session::Session(SessionSettings settings, InputSource& source)
    : core_(std::move(settings)),
      layout_(core_.settings.width, core_.settings.height),
      source_(source),
      modelPicture_((phigs_.open(), phigs_.store())) {
    setupWorkstation();
    setupDevices();
    openMenu(mainMenuTable());
    // The empty screen's hint: where to start.
    say("SELECT MENU ITEM: START WITH FILE, READ MODEL (transport.acm OR fighter.acm)");
}

Session::~Session() = default;

std::set<std::string> Session::directives() {
    return {"snapshot", "summary", "hardcopy", "pick_surface", "pick_nothing", "view", "undo", "redo"};
}

void Session::setupWorkstation() {
    hardcopy::registerOutputs(phigs_.outputs());
    if (core_.settings.registerOutputs) core_.settings.registerOutputs(phigs_.outputs());
    core_.workstation = &phigs_.openWorkstation(1, core_.settings.workstationType, core_.settings.connection);
    Workstation& ws = *core_.workstation;
    fitWorkstation();
    ws.setHlhsrMode(1);
    ws.setPickFilter(NameSetFilter{{structures::pickableName, structures::buttonName}, {}});
    ws.input().setPickFilter(1, {structures::pickableName, structures::buttonName}, {});
    Light sun;
    sun.type = LightType::Directional;
    sun.colour = glm::vec3(0.85f);
    sun.direction = glm::normalize(glm::dvec3(0.4, 0.6, -1.0));
    ws.setLightSourceRepresentation(2, sun);
    Light ambient;
    ambient.colour = glm::vec3(0.8f);
    ws.setLightSourceRepresentation(1, ambient);
    ws.setColourRepresentation(0, {0.02, 0.03, 0.08});

    auto& store = phigs_.store();
    rewriteStructure(store, structures::modelRoot, {});
    rewriteStructure(store, structures::mapped, {});
    rewriteStructure(store, structures::overlay, {});
    rewriteStructure(store, structures::errorMap, {});
    rewriteStructure(store, structures::legend, {});
    rewriteStructure(store, structures::help, {});
    ws.postStructure(structures::geometry, 0.5);
    ws.postStructure(structures::menu, 0.8);
    ws.postStructure(structures::pad, 0.8);
    for (int d = 1; d <= 4; ++d) ws.postStructure(structures::sliders + d - 1, 0.8);
    ws.postStructure(structures::message, 0.9);
    ws.postStructure(structures::legend, 0.85);
    ws.postStructure(structures::help, 0.95);
    updateViews();
}

void Session::fitWorkstation() {
    Workstation& ws = *core_.workstation;
    if (layout_.width < 1 || layout_.height < 1)
        throw std::invalid_argument("an empty screen of " + std::to_string(layout_.width) + " x " +
                                    std::to_string(layout_.height) + " pixels");
    // A window's display surface is its drawable, one device unit per pixel.
    if (ws.type() == WorkstationType::Window)
        ws.setDisplaySize({double(layout_.width), double(layout_.height)});
    // The screen shows the whole display surface: the viewport is all of it, the window has its shape.
    const glm::dvec2 display = ws.displaySize();
    if (std::abs(display.x * layout_.height - display.y * layout_.width) > display.x)
        throw std::invalid_argument(
            "a " + std::to_string(layout_.width) + " x " + std::to_string(layout_.height) +
            " screen does not have the shape of the display surface (" + std::to_string(int(display.x)) +
            " x " + std::to_string(int(display.y)) + ")");
    const double longer = std::max(display.x, display.y);
    ws.setWorkstationWindow({0, 0, 0}, {display.x / longer, display.y / longer, 1});
    ws.setWorkstationViewport({0, 0, 0}, {display.x, display.y, 1});
    mapping_.emplace(ws.display(), std::uint32_t(layout_.width), std::uint32_t(layout_.height));
}

void Session::resize(int width, int height) {
    if (width == layout_.width && height == layout_.height) return;
    const ScreenLayout before = layout_;
    layout_ = ScreenLayout(width, height);
    try {
        fitWorkstation();
    } catch (...) {
        layout_ = before;
        throw;
    }
    core_.settings.width = width;
    core_.settings.height = height;
    core_.workstation->measurer().setSurfaceSize(std::uint32_t(width), std::uint32_t(height));
    initialiseSliders();
    initialiseString();
    openMenu(*menu_);  // the panel's rows move with the layout; redraws the screen
    drawLegend();
    drawHelp();
    updateViews();
}

void Session::setupDevices() {
    // The workstation owns the devices; script lines are pixels of the session's screen.
    core_.workstation->connectInput(source_, queue_);
    core_.workstation->measurer().setSurfaceSize(std::uint32_t(layout_.width), std::uint32_t(layout_.height));
    core_.input = &core_.workstation->input();
    core_.input->setDirectiveHandler(
        [this](const action::Directive& d, const InputAction& a) { directive(d, a); });
    // A line no device takes (a device the workstation lacks) is refused like any other, as it is
    // read, naming its line; not dropped in silence.
    core_.input->setIgnoredHandler([this](const std::string& message) { fail(message); });

    DeviceInitialisation pickSetup;
    pickSetup.initial = PickMeasure{};
    pickSetup.pickAperture = 0.004;
    core_.input->initialise(InputClass::Pick, 1, pickSetup);
    core_.input->setMode(InputClass::Pick, 1, OperatingMode::Event);

    DeviceInitialisation pad;
    pad.initial = ChoiceMeasure{InputStatus::Ok, 1};
    pad.choiceStrings = padItems;
    core_.input->initialise(InputClass::Choice, 2, pad);
    core_.input->setMode(InputClass::Choice, 2, OperatingMode::Event);

    initialiseSliders();
    initialiseString();
}

void Session::initialiseString() {
    // The echo area: the right half of the message line's second row (the toolkit draws the
    // text typed there once the row can hold it).
    const PixelBox& m = layout_.message;
    DeviceInitialisation s;
    s.initial = StringMeasure{};
    // Whatever a script's string line can hold is taken whole (and a recording of what is typed
    // replays): a string cut at the device's default 256 bytes lost what came after (a curve's
    // scale after a long path) without a word.
    s.bufferSize = ScriptInputSource::kMaxScriptLineLength - std::string_view("string ").size();
    s.echoVolume =
        PixelBox{(m.x0 + m.x1) / 2, (m.y0 + m.y1) / 2, m.x1, std::max(m.y1, m.y0 + 2)}.echoVolume();
    // Re-entering EVENT mode starts the typing over (from the empty initial string): what the
    // operator was typing when the window was resized is put back.
    const StringEcho typed = source_.stringEcho();
    core_.input->setMode(InputClass::String, 1, OperatingMode::Request);
    core_.input->initialise(InputClass::String, 1, s);
    core_.input->setMode(InputClass::String, 1, OperatingMode::Event);
    if (!typed.text.empty() && !typed.cancelled) source_.startString(typed.text);
}

glm::dvec2 Session::sliderRange(int d) const {
    if ((d == 1 || d == 2) && core_.reference && !core_.models.empty()) {
        const Patch& p = core_.models.current()
                             .components[std::size_t(core_.reference->component)]
                             .patches.patches[std::size_t(core_.reference->patch - 1)];
        return d == 1 ? glm::dvec2(p.u0, p.u1) : glm::dvec2(p.w0, p.w1);
    }
    return {sliderLow[d - 1], sliderHigh[d - 1]};
}

void Session::initialiseSliders() {
    for (int d = 1; d <= 4; ++d) {
        const glm::dvec2 range = sliderRange(d);
        double value = d == 1   ? (core_.reference ? core_.reference->u : range.x)
                       : d == 2 ? (core_.reference ? core_.reference->w : range.x)
                       : d == 3 ? core_.azimuth
                                : core_.zoom;
        DeviceInitialisation v;
        v.initial = ValuatorMeasure{std::clamp(value, range.x, range.y)};
        v.promptEchoType = 2;
        v.echoVolume = layout_.slider(d).echoVolume();
        v.valuatorLow = range.x;
        v.valuatorHigh = range.y;
        // INITIALIZE VALUATOR needs REQUEST mode.
        core_.input->setMode(InputClass::Valuator, d, OperatingMode::Request);
        core_.input->initialise(InputClass::Valuator, d, v);
        core_.input->setMode(InputClass::Valuator, d, OperatingMode::Event);
        sliderRanges_[d - 1] = range;
    }
}

void Session::openMenu(const MenuTable& table) {
    menu_ = &table;
    menuItems_ = table.names();
    // INITIALIZE CHOICE needs REQUEST mode; the panel is the menu area, one row per item.
    core_.input->setMode(InputClass::Choice, 1, OperatingMode::Request);
    DeviceInitialisation menu;
    menu.initial = ChoiceMeasure{InputStatus::Ok, 1};
    menu.promptEchoType = 3;
    menu.echoVolume = layout_.menuFor(menuItems_.size()).echoVolume();
    menu.choiceStrings = menuItems_;
    core_.input->initialise(InputClass::Choice, 1, menu);  // hands the panels to the source
    core_.input->setMode(InputClass::Choice, 1, OperatingMode::Event);
    drawScreen();
}

void Session::say(const std::string& s) {
    core_.say(s);
    drawScreen();
}

void Session::fail(const std::string& s) {
    core_.fail(s);
    drawScreen();
}

const DrawList& Session::picture() {
    return core_.workstation->display();
}

void Session::run() {
    while (step(std::chrono::milliseconds(100))) {
    }
}

bool Session::step(std::chrono::milliseconds timeout) {
    if (core_.finished) return false;
    picture();  // the measurer picks on the current picture
    try {
        std::optional<EventReport> report = queue_.awaitEvent(timeout);
        if (report) handle(*report);
    } catch (const InputExhausted&) {
        endOfInput();
    } catch (const phigs::Error& e) {
        fail(e.what());
    } catch (const ScriptError& e) {
        fail(e.what());
    }
    if (!core_.finished && source_.exhausted() && queue_.size() == 0) endOfInput();
    if (core_.settings.stopAtFirstError && core_.failedLines > 0) core_.finished = true;
    followStringEcho();
    return !core_.finished;
}

void Session::endOfInput() {
    core_.finished = true;
    // A script that ends with a prompt open leaves its last command undone: that fails (a window
    // closed at a prompt is the user's choice).
    if (core_.awaiting != Awaiting::Nothing &&
        core_.settings.workstationType != phigs::WorkstationType::Window)
        fail("THE SCRIPT ENDED AT THE PROMPT '" + core_.prompt + "' WITH NO ANSWER");
}

void Session::followStringEcho() {
    const StringEcho echo = source_.stringEcho();
    if (echo.edits == echoEdits_) return;
    echoEdits_ = echo.edits;
    if (echo.cancelled) {
        core_.awaiting = Awaiting::Nothing;  // Escape: the prompt is withdrawn, and the line says so
        say("CANCELLED");
    }
}

double Session::valuatorValue(int device) const {
    return std::get<ValuatorMeasure>(core_.input->device(InputClass::Valuator, device).current).value;
}

std::string Session::messageLine() const {
    return core_.message;
}

void Session::handle(const EventReport& report) {
    reportingFailures([&] {
        if (const auto* c = std::get_if<ChoiceMeasure>(&report.measure)) {
            if (c->status != InputStatus::Ok) {
                fail(report.device == 1 ? "NO MENU ITEM CHOSEN (CHOICE 0): THE ITEMS ARE 1.." +
                                              std::to_string(menuItems_.size())
                                        : "NO PAD BUTTON CHOSEN (CHOICE 0)");
                return;
            }
            if (report.device == 1)
                choose(menuItems_.at(std::size_t(c->choice - 1)));
            else if (report.device == 2)
                padButton(c->choice);
        } else if (const auto* p = std::get_if<PickMeasure>(&report.measure)) {
            pick(*p);
        } else if (const auto* v = std::get_if<ValuatorMeasure>(&report.measure)) {
            valuator(report.device, v->value);
        } else if (const auto* s = std::get_if<StringMeasure>(&report.measure)) {
            text(s->text);
        }
    });
}

void Session::reportingFailures(const std::function<void()>& command) {
    try {
        command();
    } catch (const ModelFileError& e) {
        fail(e.what());
    } catch (const geom::GeometryError& e) {
        fail(e.what());
    } catch (const phigs::Error& e) {
        fail(e.what());
    } catch (const std::runtime_error& e) {
        // Other bad input (a retrieved archive that does not match the model, ...): reported, not
        // fatal. Logic errors are not caught here: they are bugs, and must not pass as messages.
        fail(e.what());
    } catch (const std::invalid_argument& e) {
        fail(e.what());
    }
}

}  // namespace acsynt
