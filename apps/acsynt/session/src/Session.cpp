// The session: PHIGS and its workstation, the devices, the event loop, directives, reports.
#include "acsynt/session/Session.h"

#include "SessionShared.h"

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

namespace acsynt {

using namespace phigs;
using namespace session_detail;

Session::Session(SessionSettings settings, InputSource& source)
    : settings_(std::move(settings)),
      layout_(settings_.width, settings_.height),
      source_(source),
      modelPicture_((phigs_.open(), phigs_.store())) {
    setupWorkstation();
    setupDevices();
    mainMenu();
    // The empty screen's hint: where to start.
    say("SELECT MENU ITEM: START WITH FILE, READ MODEL (transport.acm OR fighter.acm)");
}

Session::~Session() = default;

std::set<std::string> Session::directives() {
    return {"snapshot", "summary", "hardcopy", "pick_surface", "view", "undo", "redo"};
}

void Session::setupWorkstation() {
    hardcopy::registerOutputs(phigs_.outputs());
    if (settings_.registerOutputs) settings_.registerOutputs(phigs_.outputs());
    workstation_ = &phigs_.openWorkstation(1, settings_.workstationType, settings_.connection);
    Workstation& ws = *workstation_;
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
    Workstation& ws = *workstation_;
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
    settings_.width = width;
    settings_.height = height;
    workstation_->measurer().setSurfaceSize(std::uint32_t(width), std::uint32_t(height));
    initialiseSliders();
    initialiseString();
    setMenu(menuTitle_, menuItems_);  // the panel's rows move with the layout; redraws the screen
    drawLegend();
    drawHelp();
    updateViews();
}

void Session::setupDevices() {
    // The workstation owns the devices; script lines are pixels of the session's screen.
    workstation_->connectInput(source_, queue_);
    workstation_->measurer().setSurfaceSize(std::uint32_t(layout_.width), std::uint32_t(layout_.height));
    input_ = &workstation_->input();
    input_->setDirectiveHandler(
        [this](const action::Directive& d, const InputAction& a) { directive(d, a); });

    DeviceInitialisation pickSetup;
    pickSetup.initial = PickMeasure{};
    pickSetup.pickAperture = 0.004;
    input_->initialise(InputClass::Pick, 1, pickSetup);
    input_->setMode(InputClass::Pick, 1, OperatingMode::Event);

    DeviceInitialisation pad;
    pad.initial = ChoiceMeasure{InputStatus::Ok, 1};
    pad.choiceStrings = padItems;
    input_->initialise(InputClass::Choice, 2, pad);
    input_->setMode(InputClass::Choice, 2, OperatingMode::Event);

    initialiseSliders();
    initialiseString();
}

void Session::initialiseString() {
    // The echo area: the right half of the message line's second row (the toolkit draws the
    // text typed there once the row can hold it).
    const PixelBox& m = layout_.message;
    DeviceInitialisation s;
    s.initial = StringMeasure{};
    s.echoVolume =
        PixelBox{(m.x0 + m.x1) / 2, (m.y0 + m.y1) / 2, m.x1, std::max(m.y1, m.y0 + 2)}.echoVolume();
    input_->setMode(InputClass::String, 1, OperatingMode::Request);
    input_->initialise(InputClass::String, 1, s);
    input_->setMode(InputClass::String, 1, OperatingMode::Event);
}

glm::dvec2 Session::sliderRange(int d) const {
    if ((d == 1 || d == 2) && reference_ && !models_.empty()) {
        const Patch& p = models_.current()
                             .components[std::size_t(reference_->component)]
                             .patches.patches[std::size_t(reference_->patch - 1)];
        return d == 1 ? glm::dvec2(p.u0, p.u1) : glm::dvec2(p.w0, p.w1);
    }
    return {sliderLow[d - 1], sliderHigh[d - 1]};
}

void Session::initialiseSliders() {
    for (int d = 1; d <= 4; ++d) {
        const glm::dvec2 range = sliderRange(d);
        double value = d == 1   ? (reference_ ? reference_->u : range.x)
                       : d == 2 ? (reference_ ? reference_->w : range.x)
                       : d == 3 ? azimuth_
                                : zoom_;
        DeviceInitialisation v;
        v.initial = ValuatorMeasure{std::clamp(value, range.x, range.y)};
        v.promptEchoType = 2;
        v.echoVolume = layout_.slider(d).echoVolume();
        v.valuatorLow = range.x;
        v.valuatorHigh = range.y;
        // INITIALIZE VALUATOR needs REQUEST mode.
        input_->setMode(InputClass::Valuator, d, OperatingMode::Request);
        input_->initialise(InputClass::Valuator, d, v);
        input_->setMode(InputClass::Valuator, d, OperatingMode::Event);
        sliderRanges_[d - 1] = range;
    }
}

void Session::setMenu(const std::string& menuTitle, std::vector<std::string> items) {
    menuTitle_ = menuTitle;
    menuItems_ = std::move(items);
    // INITIALIZE CHOICE needs REQUEST mode; the panel is the menu area, one row per item.
    input_->setMode(InputClass::Choice, 1, OperatingMode::Request);
    DeviceInitialisation menu;
    menu.initial = ChoiceMeasure{InputStatus::Ok, 1};
    menu.promptEchoType = 3;
    menu.echoVolume = layout_.menuFor(menuItems_.size()).echoVolume();
    menu.choiceStrings = menuItems_;
    input_->initialise(InputClass::Choice, 1, menu);  // hands the panels to the source
    input_->setMode(InputClass::Choice, 1, OperatingMode::Event);
    drawScreen();
}

void Session::say(const std::string& s) {
    message_ = s;
    log_.push_back(s);
    drawScreen();
}

void Session::fail(const std::string& s) {
    // One count per input action (a script line), however many errors it causes: actions are
    // told apart by how many the devices had consumed when the error came.
    const std::size_t action = input_ ? input_->history().size() : 0;
    if (failedLines_ == 0 || action != lastFailedAction_) ++failedLines_;
    lastFailedAction_ = action;
    message_ = s;
    log_.push_back("ERROR: " + s);
    drawScreen();
}

const DrawList& Session::picture() {
    return workstation_->display();
}

void Session::run() {
    while (step(std::chrono::milliseconds(100))) {
    }
}

bool Session::step(std::chrono::milliseconds timeout) {
    if (finished_) return false;
    picture();  // the measurer picks on the current picture
    try {
        std::optional<EventReport> report = queue_.awaitEvent(timeout);
        if (report) handle(*report);
    } catch (const InputExhausted&) {
        finished_ = true;
    } catch (const phigs::Error& e) {
        fail(e.what());
    } catch (const ScriptError& e) {
        fail(e.what());
    }
    if (!finished_ && source_.exhausted() && queue_.size() == 0) finished_ = true;
    if (settings_.stopAtFirstError && failedLines_ > 0) finished_ = true;
    followStringEcho();
    return !finished_;
}

void Session::followStringEcho() {
    const StringEcho echo = source_.stringEcho();
    if (echo.edits == echoEdits_) return;
    echoEdits_ = echo.edits;
    if (echo.cancelled) {
        awaiting_ = Awaiting::Nothing;  // Escape: the prompt is withdrawn, and the line says so
        say("CANCELLED");
    }
}

double Session::valuatorValue(int device) const {
    return std::get<ValuatorMeasure>(input_->device(InputClass::Valuator, device).current).value;
}

std::string Session::messageLine() const {
    return message_;
}

void Session::handle(const EventReport& report) {
    try {
        if (const auto* c = std::get_if<ChoiceMeasure>(&report.measure)) {
            if (c->status != InputStatus::Ok) return;
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

void Session::directive(const action::Directive& d, const InputAction& a) {
    const std::string where = source_.position();
    if (d.name == "pick_surface") {
        if (d.arguments.size() != 5) {
            fail(where + ": '" + a.text + "': expected pick_surface COMPONENT PATCH U W VIEW");
            return;
        }
        pickSurface(d.arguments);
        return;
    }
    if (d.name == "view") {
        setView(d.arguments);
        return;
    }
    if (d.name == "undo" || d.name == "redo") {
        if (!d.arguments.empty()) {
            fail(where + ": '" + a.text + "': expected " + d.name + " alone");
            return;
        }
        if (d.name == "undo")
            undo();
        else
            redo();
        return;
    }
    if (d.arguments.size() != 1) {
        fail(where + ": '" + a.text + "': expected " + d.name + " NAME");
        return;
    }
    try {
        writeDirective(d);
    } catch (const std::runtime_error& e) {
        fail(where + ": " + e.what());
    } catch (const std::invalid_argument& e) {
        // A directive's file is refused (outside the output directory, unwritable): reported
        // like any bad line, and the session goes on.
        fail(where + ": " + e.what());
    }
}

void Session::writeDirective(const action::Directive& d) {
    if (d.name == "snapshot") {
        const auto file = outputPath(d.arguments[0] + ".png");
        if (!snapshot_) {
            fail("NO PICTURE OUTPUT FOR SNAPSHOT " + d.arguments[0]);
            return;
        }
        picture();
        snapshot_(file);
        pictures_.push_back(file);
        log_.push_back("snapshot " + file.string());
    } else if (d.name == "hardcopy") {
        writeHardcopy(d.arguments[0]);
    } else if (d.name == "summary") {
        const auto file = outputPath(d.arguments[0] + ".txt");
        std::ofstream out(file);
        if (!(out << summary()) || !out.flush()) throw std::runtime_error("CANNOT WRITE " + file.string());
        log_.push_back("summary " + file.string());
    }
}

// ---- reports

std::string Session::summary() const {
    std::ostringstream out;
    out.precision(10);
    out << "ACSYNT session summary\n";
    for (std::size_t i = 0; i < models_.size(); ++i) {
        const Model& m = models_.at(i);
        out << "model " << m.name << (i == models_.currentIndex() ? " (current)" : "") << ": "
            << m.components.size() << " components, " << m.patchCount() << " patches\n";
    }
    static const std::vector<Component> none;
    const std::vector<Component>& components = models_.empty() ? none : models_.current().components;
    if (lastPick_ && std::size_t(lastPick_->component) < components.size()) {
        out << "last pick: " << components[std::size_t(lastPick_->component)].name << " patch "
            << lastPick_->patch;
        if (lastPickDetail_) out << " at u " << lastPickDetail_->uv.x << " w " << lastPickDetail_->uv.y;
        out << "\n";
    }
    if (reference_ && std::size_t(reference_->component) < components.size()) {
        const Component& c = components[std::size_t(reference_->component)];
        out << "reference point: " << c.name << " patch " << reference_->patch << " u " << reference_->u
            << " w " << reference_->w << "\n";
    }
    for (std::size_t i = 0; i < mappings_.size(); ++i) {
        const MappingRecord& m = mappings_[i];
        out << "mapping " << i + 1 << ": " << m.curveFile << " on " << m.model << "/" << m.component
            << " patch " << m.reference.patch << " marker u " << m.reference.u << " w " << m.reference.w
            << ": " << m.parts << " parts, " << m.loops << " loops (per part";
        for (auto n : m.loopsPerPart) out << " " << n;
        out << "), boundary walks " << m.boundaryWalks << "\n";
        for (const PartReport& p : m.partReports) {
            if (p.outcome == PartOutcome::Mapped) continue;
            out << "  part " << p.name << ": " << (p.outcome == PartOutcome::Clipped ? "clipped" : "lost");
            if (p.outcome == PartOutcome::Clipped)
                out << ", " << p.loops << " loops, boundary walks " << p.boundaryWalks;
            out << ": " << p.reason << "\n";
        }
    }
    for (std::size_t i = 0; i < reductions_.size(); ++i) {
        const ReductionRecord& r = reductions_[i];
        out << "reduction " << i + 1 << ": " << r.model << "/" << r.component << " -> " << r.reducedModel
            << ", " << r.direction << " by " << r.mode;
        if (r.mode == "tolerance")
            out << " " << r.tolerance;
        else
            out << " " << r.count;
        out << ": control points " << r.countUBefore << " x " << r.countWBefore << " = "
            << r.countUBefore * r.countWBefore << " -> " << r.countUAfter << " x " << r.countWAfter << " = "
            << r.countUAfter * r.countWAfter << ", knots removed u " << r.removedU << " w " << r.removedW
            << ", max error " << r.maxError << "\n";
    }
    for (const auto& p : pictures_) out << "picture " << p.string() << "\n";
    out << "message: " << message_ << "\n";
    return out.str();
}

void Session::recordAs(std::string line, std::string comment) {
    if (!input_ || input_->history().empty()) return;
    recordedAs_[input_->history().size() - 1] = {std::move(line), std::move(comment)};
}

std::string Session::recording() const {
    std::string out = "# acsynt session recorded on a " + std::to_string(layout_.width) + " x " +
                      std::to_string(layout_.height) +
                      " screen: menu rows and pad buttons by name, picks on surfaces by component,\n"
                      "# patch and (u, w), replayed where that point shows then\n";
    const auto& history = input_->history();
    auto extra = extraLines_.begin();
    for (std::size_t i = 0; i <= history.size(); ++i) {
        for (; extra != extraLines_.end() && extra->first <= i; ++extra) out += extra->second + "\n";
        if (i == history.size()) break;
        const auto it = recordedAs_.find(i);
        if (it == recordedAs_.end()) {
            out += ScriptInputSource::format(history[i]) + "\n";
            continue;
        }
        if (!it->second.second.empty()) out += "# " + it->second.second + "\n";
        out += it->second.first + "\n";
    }
    return out;
}

void Session::pickSurface(const std::vector<std::string>& a) {
    const std::string line = "pick_surface " + a[0] + " " + a[1] + " " + a[2] + " " + a[3] + " " + a[4];
    const auto patch = parseNumber(a[1]), u = parseNumber(a[2]), w = parseNumber(a[3]),
               view = parseNumber(a[4]);
    const int views = fourViews_ ? 4 : 1;
    if (!patch || !u || !w || !view || *patch != std::floor(*patch) || *view != std::floor(*view) ||
        *view < 1 || *view > views) {
        fail("BAD RECORDED PICK '" + line + "': expected COMPONENT PATCH U W VIEW, VIEW 1.." +
             std::to_string(views));
        return;
    }
    if (!requireModel()) return;
    const Model& model = models_.current();
    const auto comp = std::find_if(model.components.begin(), model.components.end(),
                                   [&](const Component& c) { return c.name == a[0]; });
    if (comp == model.components.end()) {
        fail("RECORDED PICK: MODEL " + model.name + " HAS NO COMPONENT " + a[0]);
        return;
    }
    const glm::dvec2 pixel = pixelOf(geom::evaluate(comp->surface, *u, *w), int(*view));
    picture();
    PickMeasure measure = workstation_->measurer().pick(pixel, input_->device(InputClass::Pick, 1));
    const auto picked = ModelPicture::fromPath(measure.path);
    const int index = int(comp - model.components.begin());
    if (measure.status != InputStatus::Ok || !picked || picked->component != index ||
        picked->patch != int(*patch) || !measure.surface) {
        fail("RECORDED PICK OF " + a[0] + " PATCH " + a[1] + " AT U = " + a[2] + " W = " + a[3] +
             " IS NOT WHAT SHOWS AT PIXEL " + number(pixel.x, 5) + " " + number(pixel.y, 5) + " OF VIEW " +
             a[4] + " NOW");
        return;
    }
    measure.surface->uv = {*u, *w};  // the recorded parameters, exactly
    pickView_ = int(*view);
    handle(EventReport{workstation_->id(), InputClass::Pick, 1, measure, false});
    pickView_ = 0;
}

}  // namespace acsynt
