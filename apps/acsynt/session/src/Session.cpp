#include "acsynt/session/Session.h"

#include "acsynt/ModelFile.h"
#include "geom/DataReduction.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "phigs/core/Error.h"
#include "phigs/input/EchoStructures.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/view/ViewMatrices.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace acsynt {

using namespace phigs;

namespace {

const char* const title = "ACSYNT B-SPLINE MODULE V1.2.2";
const std::vector<std::string> mainItems{"FILE", "VIEW", "CURVE_MAP", "SURF_REDN", "MODELS", "EXIT"};
const std::vector<std::string> fileItems{"RETURN",   "READ_MODEL", "READ_CURVE_FILE", "SAVE_MODEL", "ARCHIVE",
                                         "RETRIEVE", "EXIT"};
const std::vector<std::string> viewItems{"RETURN",  "ONE_VIEW", "FOUR_VIEWS",       "SHADE",     "WIREFRAME",
                                         "HULL_ON", "HULL_OFF", "CENTRE_ON_MARKER", "RESET_VIEW"};
const std::vector<std::string> curveItems{"RETURN",       "LOAD_CURVE",  "DEFINE_POINT", "FLIP_CURVE",
                                          "ROTATE_CURVE", "MAP_PREVIEW", "MAP_CURVE",    "DISPLAY_ALL"};
const std::vector<std::string> confirmItems{"ACCEPT", "REJECT"};
const std::vector<std::string> reductionItems{"RETURN",       "REDUCE_U", "REDUCE_W", "REDUCE_U&W",
                                              "BY_TOLERANCE", "BY_COUNT", "ERROR_MAP"};
const std::vector<std::string> modelItems{"RETURN", "NEXT_MODEL", "PREVIOUS_MODEL",
                                          "LIST",   "NAME_MODEL", "DELETE_MODEL"};
const std::vector<std::string> padItems{"NORTH_WEST", "NORTH",      "NORTH_EAST", "WEST",       "CENTRE",
                                        "EAST",       "SOUTH_WEST", "SOUTH",      "SOUTH_EAST", "DONE"};
const char* const sliderNames[] = {"U", "W", "ROTATE", "ZOOM"};
const double sliderLow[] = {0, 0, -180, 0.25};
const double sliderHigh[] = {1, 1, 180, 8};

/// How a menu alternative is shown: underscores as blanks (SURF_REDN keeps its name).
std::string shown(const std::string& item) {
    if (item == "SURF_REDN") return item;
    std::string s = item;
    std::replace(s.begin(), s.end(), '_', ' ');
    return s;
}

std::string number(double v, int digits = 6) {
    std::ostringstream out;
    out.precision(digits);
    out << v;
    return out.str();
}

Element colourAttr(ElementType type, const glm::dvec3& rgb) {
    return ColourAttribute{type, Colour::fromRgb(rgb)};
}

Element textAt(const glm::dvec3& at, const std::string& s) {
    return TextElement{at, {1, 0, 0}, {0, 1, 0}, s, false};
}

}  // namespace

Session::Session(SessionSettings settings, InputSource& source)
    : settings_(std::move(settings)),
      layout_(settings_.width, settings_.height),
      source_(source),
      modelPicture_((phigs_.open(), phigs_.store())) {
    setupWorkstation();
    setupDevices();
    mainMenu();
    say("SELECT MENU ITEM");
}

Session::~Session() = default;

std::set<std::string> Session::directives() {
    return {"snapshot", "summary"};
}

void Session::setupWorkstation() {
    workstation_ = &phigs_.openWorkstation(1, settings_.workstationType);
    Workstation& ws = *workstation_;
    // The screen shows the whole display surface: the viewport is all of it, the window has its shape.
    const glm::dvec2 display = ws.description().displaySize;
    if (std::abs(display.x * layout_.height - display.y * layout_.width) > display.x)
        throw std::invalid_argument(
            "a " + std::to_string(layout_.width) + " x " + std::to_string(layout_.height) +
            " screen does not have the shape of the display surface (" + std::to_string(int(display.x)) +
            " x " + std::to_string(int(display.y)) + ")");
    ws.setWorkstationWindow({0, 0, 0}, {1, display.y / display.x, 1});
    ws.setWorkstationViewport({0, 0, 0}, {display.x, display.y, 1});
    ws.setHlhsrMode(1);
    ws.setPickFilter(NameSetFilter{{structures::pickableName, structures::buttonName}, {}});
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
    ws.postStructure(structures::geometry, 0.5);
    ws.postStructure(structures::menu, 0.8);
    ws.postStructure(structures::pad, 0.8);
    for (int d = 1; d <= 4; ++d) ws.postStructure(structures::sliders + d - 1, 0.8);
    ws.postStructure(structures::message, 0.9);
    mapping_.emplace(ws.display(), std::uint32_t(layout_.width), std::uint32_t(layout_.height));
    updateViews();
}

void Session::setupDevices() {
    interaction_ = std::make_unique<WorkstationInteraction>(*workstation_, source_, queue_);
    interaction_->setSurfaceSize(std::uint32_t(layout_.width), std::uint32_t(layout_.height));
    input_ = &interaction_->input();
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

    for (int d = 1; d <= 4; ++d) {
        DeviceInitialisation v;
        v.initial = ValuatorMeasure{d == 4 ? 1.0 : d == 3 ? -135.0 : 0.0};
        v.promptEchoType = 2;
        v.echoVolume = layout_.slider(d).echoVolume();
        v.valuatorLow = sliderLow[d - 1];
        v.valuatorHigh = sliderHigh[d - 1];
        input_->initialise(InputClass::Valuator, d, v);
        input_->setMode(InputClass::Valuator, d, OperatingMode::Event);
    }

    DeviceInitialisation s;
    s.initial = StringMeasure{};
    input_->initialise(InputClass::String, 1, s);
    input_->setMode(InputClass::String, 1, OperatingMode::Event);
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
    if (present_) present_(picture());
    return !finished_;
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
        fail(e.what());
    }
}

void Session::directive(const action::Directive& d, const InputAction& a) {
    const std::string where = source_.position();
    if (d.arguments.size() != 1) {
        fail(where + ": '" + a.text + "': expected " + d.name + " NAME");
        return;
    }
    std::filesystem::create_directories(settings_.outputDirectory);
    if (d.name == "snapshot") {
        const auto file = settings_.outputDirectory / (d.arguments[0] + ".png");
        if (!snapshot_) {
            fail("NO PICTURE OUTPUT FOR SNAPSHOT " + d.arguments[0]);
            return;
        }
        picture();
        snapshot_(file);
        pictures_.push_back(file);
        log_.push_back("snapshot " + file.string());
    } else if (d.name == "summary") {
        const auto file = settings_.outputDirectory / (d.arguments[0] + ".txt");
        std::ofstream(file) << summary();
        log_.push_back("summary " + file.string());
    }
}

// ---- menus

void Session::mainMenu() {
    setMenu("MAIN", mainItems);
}

void Session::choose(std::string item) {
    log_.push_back("choice " + item);
    if (phase_ == Phase::AcceptReject) {
        if (item == "ACCEPT") {
            const Component& comp = models_.current().components[std::size_t(pickedComponent_)];
            const Patch& p = comp.patches.patches[std::size_t(lastPick_->patch - 1)];
            reference_ = ReferencePoint{pickedComponent_, p.number, p.u0, p.w0};
            phase_ = Phase::MoveMarker;
            setMenu("CURVE MAP", curveItems);
            drawOverlay();
            say("MOVE THE MARKER WITH THE POINTER VALUATOR, THEN DONE");
        } else {
            style_.colourfulComponent = pickedComponent_;
            style_.highlightComponent = -1;
            modelPicture_.restyle(models_.current(), style_);
            phase_ = Phase::SelectPatch;
            setMenu("CURVE MAP", curveItems);
            say("SELECT REFERENCE PATCH TO MAP");
        }
        return;
    }
    awaiting_ = Awaiting::Nothing;
    if (menuTitle_ == "MAIN") {
        if (item == "FILE") setMenu("FILE", fileItems);
        if (item == "VIEW") setMenu("VIEW", viewItems);
        if (item == "MODELS") setMenu("MODELS", modelItems);
        if (item == "CURVE_MAP" && requireModel()) setMenu("CURVE MAP", curveItems);
        if (item == "SURF_REDN" && requireModel()) setMenu("SURF_REDN", reductionItems);
        if (item == "EXIT") {
            say("EXIT");
            finished_ = true;
        }
        if (!finished_) say("SELECT MENU ITEM");
        return;
    }
    if (item == "RETURN") {
        if (menuTitle_ == "CURVE MAP" && phase_ != Phase::Placed) {
            // An unfinished DEFINE POINT is abandoned; a placed reference point is kept.
            phase_ = Phase::None;
            reference_.reset();
            style_.onlyComponent = style_.colourfulComponent = style_.highlightComponent = -1;
            if (!models_.empty()) modelPicture_.restyle(models_.current(), style_);
            drawOverlay();
        }
        if (menuTitle_ == "SURF_REDN" && phase_ == Phase::SelectReduction) phase_ = Phase::None;
        mainMenu();
        say("SELECT MENU ITEM");
        return;
    }
    if (menuTitle_ == "FILE") fileMenu(item);
    if (menuTitle_ == "VIEW") viewMenu(item);
    if (menuTitle_ == "CURVE MAP") curveMenu(item);
    if (menuTitle_ == "SURF_REDN") reductionMenu(item);
    if (menuTitle_ == "MODELS") modelsMenu(item);
}

void Session::prompt(const std::string& s, Awaiting what) {
    awaiting_ = what;
    say(s);
}

bool Session::requireModel() {
    if (!models_.empty()) return true;
    fail("NO GEOMETRY FILE FOUND!");
    return false;
}

void Session::fileMenu(const std::string& item) {
    if (item == "READ_MODEL") prompt("ENTER MODEL FILE NAME", Awaiting::ModelFile);
    if (item == "READ_CURVE_FILE") prompt("ENTER CURVE FILE NAME [SCALE]", Awaiting::CurveFile);
    if (item == "SAVE_MODEL" && requireModel())
        prompt("ENTER FILE NAME TO SAVE THE MODEL", Awaiting::SaveFile);
    if (item == "ARCHIVE" && requireModel()) prompt("ENTER ARCHIVE FILE NAME", Awaiting::ArchiveFile);
    if (item == "RETRIEVE") prompt("ENTER ARCHIVE FILE NAME TO RETRIEVE", Awaiting::RetrieveFile);
    if (item == "EXIT") {
        say("EXIT");
        finished_ = true;
    }
}

void Session::viewMenu(const std::string& item) {
    if (item == "ONE_VIEW") fourViews_ = false;
    if (item == "FOUR_VIEWS") fourViews_ = true;
    if (item == "SHADE") style_.shaded = true;
    if (item == "WIREFRAME") style_.shaded = false;
    if (item == "HULL_ON") style_.hull = true;
    if (item == "HULL_OFF") style_.hull = false;
    if (item == "RESET_VIEW") {
        azimuth_ = -135;
        zoom_ = 1;
        viewCentre_.reset();
    }
    if (item == "CENTRE_ON_MARKER") {
        if (!reference_) {
            fail("NO REFERENCE POINT: USE DEFINE POINT FIRST");
            return;
        }
        const Component& comp = models_.current().components[std::size_t(reference_->component)];
        viewCentre_ = geom::evaluate(comp.surface, reference_->u, reference_->w);
    }
    if (!models_.empty()) modelPicture_.restyle(models_.current(), style_);
    updateViews();
    say(shown(item) + " DONE");
}

void Session::curveMenu(const std::string& item) {
    if (item == "LOAD_CURVE") {
        prompt("ENTER CURVE FILE NAME [SCALE]", Awaiting::CurveFile);
    } else if (item == "DEFINE_POINT") {
        phase_ = Phase::SelectComponent;
        reference_.reset();
        previewLines_.clear();
        style_.onlyComponent = style_.colourfulComponent = style_.highlightComponent = -1;
        modelPicture_.restyle(models_.current(), style_);
        drawOverlay();
        say("SELECT COMPONENT FOR MAPPING");
    } else if (item == "FLIP_CURVE") {
        placement_.flipped = !placement_.flipped;
        mappedSincePlaced_ = false;
        drawOverlay();
        say(placement_.flipped ? "CURVE FLIPPED" : "CURVE UNFLIPPED");
    } else if (item == "ROTATE_CURVE") {
        placement_.quarterTurns = (placement_.quarterTurns + 1) % 4;
        mappedSincePlaced_ = false;
        drawOverlay();
        say("CURVE ROTATED TO " + std::to_string(90 * placement_.quarterTurns) + " DEGREES");
    } else if (item == "MAP_PREVIEW") {
        mapCurve(true);
    } else if (item == "MAP_CURVE") {
        mapCurve(false);
    } else if (item == "DISPLAY_ALL") {
        style_.onlyComponent = style_.colourfulComponent = style_.highlightComponent = -1;
        modelPicture_.restyle(models_.current(), style_);
        drawMapped(true);
        std::size_t n = 0;
        for (const auto& m : mappings_) n += m.model == models_.current().name;
        say("DISPLAYING " + std::to_string(n) + " MAPPED CURVES");
    }
}

void Session::reductionMenu(const std::string& item) {
    if (item == "BY_TOLERANCE" || item == "BY_COUNT") {
        reductionByCount_ = item == "BY_COUNT";
        say(reductionByCount_ ? "REDUCTION BY NUMBER OF KNOTS" : "REDUCTION TO A TOLERANCE");
    } else if (item == "REDUCE_U" || item == "REDUCE_W" || item == "REDUCE_U&W") {
        reductionDirection_ = item == "REDUCE_U" ? "U" : item == "REDUCE_W" ? "W" : "U&W";
        phase_ = Phase::SelectReduction;
        say("SELECT COMPONENT TO REDUCE");
    } else if (item == "ERROR_MAP") {
        if (reductions_.empty() || reductions_.back().reducedModel != models_.current().name) {
            fail("NO REDUCTION OF THE CURRENT MODEL TO SHOW");
            return;
        }
        style_.errorMapComponent = style_.errorMapComponent < 0 ? reductions_.back().componentIndex : -1;
        drawErrorMap();
        modelPicture_.restyle(models_.current(), style_);
        say(style_.errorMapComponent >= 0
                ? "ERROR MAP: BLUE 0 TO RED " + number(reductions_.back().maxError, 3)
                : "ERROR MAP OFF");
    }
}

void Session::modelsMenu(const std::string& item) {
    ModelList::Outcome outcome;
    if (item == "NEXT_MODEL") {
        say("CHANGING CURRENT MODEL TO NEXT MODEL");
        outcome = models_.next();
    } else if (item == "PREVIOUS_MODEL") {
        say("CHANGING CURRENT MODEL TO PREVIOUS MODEL");
        outcome = models_.previous();
    } else if (item == "LIST") {
        std::string list = "MODELS:";
        for (std::size_t i = 0; i < models_.size(); ++i)
            list += " " + models_.at(i).name + (i == models_.currentIndex() ? "*" : "");
        say(models_.empty() ? "NO GEOMETRY FILE FOUND!" : list);
        return;
    } else if (item == "NAME_MODEL") {
        if (requireModel()) prompt("PLEASE ENTER MODEL NAME", Awaiting::ModelName);
        return;
    } else if (item == "DELETE_MODEL") {
        if (!requireModel()) return;
        const std::string name = models_.current().name;
        outcome = models_.removeCurrent();
        if (outcome.done) {
            std::erase_if(mappings_, [&](const MappingRecord& m) { return m.model == name; });
            outcome.message = "MODEL " + name + " DELETED" +
                              (models_.empty() ? "" : ".  CURRENT MODEL NAME = " + models_.current().name);
        }
    }
    if (outcome.done) {
        showModel();
        say(outcome.message);
    } else {
        fail(outcome.message);
    }
}

// ---- input of each class

void Session::text(const std::string& input) {
    const Awaiting what = awaiting_;
    awaiting_ = Awaiting::Nothing;
    log_.push_back("string " + input);
    switch (what) {
        case Awaiting::Nothing:
            fail("NO TEXT EXPECTED: '" + input + "'");
            break;
        case Awaiting::ModelFile:
            readModel(input);
            break;
        case Awaiting::CurveFile:
            readCurve(input);
            break;
        case Awaiting::SaveFile:
            saveModel(input);
            break;
        case Awaiting::ArchiveFile:
            archive(input, false);
            break;
        case Awaiting::RetrieveFile:
            archive(input, true);
            break;
        case Awaiting::ModelName: {
            const std::string old = models_.current().name;
            const auto outcome = models_.rename(input);
            if (!outcome.done) {
                fail(outcome.message);
                break;
            }
            for (auto& m : mappings_)
                if (m.model == old) m.model = models_.current().name;
            say(outcome.message);
            break;
        }
        case Awaiting::Tolerance:
        case Awaiting::Count: {
            std::istringstream in(input);
            double value = 0;
            if (!(in >> value) || !(value > 0) || !std::isfinite(value) ||
                (what == Awaiting::Count && value != std::floor(value))) {
                fail("BAD INPUT IN SRF_REDUCTION: '" + input + "'");
                break;
            }
            if (what == Awaiting::Tolerance)
                reduce(reductionComponent_, value, 0);
            else
                reduce(reductionComponent_, 0, std::size_t(value));
            break;
        }
    }
}

void Session::pick(const PickMeasure& measure) {
    if (measure.status != InputStatus::Ok) {
        if (phase_ != Phase::None) say("NOTHING PICKED: TRY AGAIN");
        return;
    }
    // A pad button: its structure is the pad, its pick id the button.
    for (const PickPathItem& level : measure.path)
        if (level.structureId == structures::pad) {
            padButton(level.pickId);
            return;
        }
    const auto picked = ModelPicture::fromPath(measure.path);
    if (!picked) return;
    lastPick_ = picked;
    lastPickDetail_ = measure.surface;
    const Model& model = models_.current();
    const Component& comp = model.components.at(std::size_t(picked->component));
    std::string where = comp.name + " PATCH " + std::to_string(picked->patch);
    if (measure.surface)
        where += " AT U = " + number(measure.surface->uv.x) + " W = " + number(measure.surface->uv.y);
    log_.push_back("picked " + where);
    switch (phase_) {
        case Phase::SelectComponent:
            pickedComponent_ = picked->component;
            style_.onlyComponent = style_.colourfulComponent = picked->component;
            style_.highlightComponent = -1;
            modelPicture_.restyle(model, style_);
            phase_ = Phase::SelectPatch;
            say("SELECT REFERENCE PATCH TO MAP");
            break;
        case Phase::SelectPatch:
            if (picked->component != pickedComponent_) {
                fail("PICK A PATCH OF " + model.components[std::size_t(pickedComponent_)].name);
                break;
            }
            style_.colourfulComponent = -1;
            style_.highlightComponent = picked->component;
            style_.highlightPatch = picked->patch;
            modelPicture_.restyle(model, style_);
            phase_ = Phase::AcceptReject;
            setMenu("CURVE MAP", confirmItems);
            say("ACCEPT OR REJECT PATCH");
            break;
        case Phase::SelectReduction:
            phase_ = Phase::None;
            reductionComponent_ = picked->component;
            if (reductionByCount_)
                prompt(std::string("ENTER NUMBER OF KNOTS TO BE REMOVED IN ") +
                           (reductionDirection_ == "W" ? "W DIRECTION" : "U DIRECTION"),
                       Awaiting::Count);
            else
                prompt("ENTER TOLERANCE FOR " + comp.name, Awaiting::Tolerance);
            break;
        default:
            say("PICKED " + where);
    }
}

void Session::padButton(int button) {
    if (!reference_ || (phase_ != Phase::MoveMarker && phase_ != Phase::Placed)) {
        fail("NO REFERENCE PATCH: USE DEFINE POINT FIRST");
        return;
    }
    const Component& comp = models_.current().components[std::size_t(reference_->component)];
    const Patch& p = comp.patches.patches[std::size_t(reference_->patch - 1)];
    if (button == 10) {
        phase_ = Phase::Placed;
        mappedSincePlaced_ = false;
        style_.onlyComponent = style_.highlightComponent = -1;
        modelPicture_.restyle(models_.current(), style_);
        drawOverlay();
        say("REFERENCE POINT U = " + number(reference_->u) + " W = " + number(reference_->w));
        return;
    }
    const double du = (p.u1 - p.u0) / 8, dw = (p.w1 - p.w0) / 8;
    // Rows of the compass: w increases upwards, u to the right (seed Table 2).
    static const int stepU[] = {-1, 0, 1, -1, 0, 1, -1, 0, 1};
    static const int stepW[] = {1, 1, 1, 0, 0, 0, -1, -1, -1};
    if (button == 5)
        moveMarker((p.u0 + p.u1) / 2, (p.w0 + p.w1) / 2);
    else
        moveMarker(reference_->u + stepU[button - 1] * du, reference_->w + stepW[button - 1] * dw);
    log_.push_back("pad " + padItems[std::size_t(button - 1)]);
}

void Session::valuator(int device, double value) {
    if (device == 1 || device == 2) {
        if (!reference_ || (phase_ != Phase::MoveMarker && phase_ != Phase::Placed)) {
            fail("NO REFERENCE PATCH: USE DEFINE POINT FIRST");
            return;
        }
        const Component& comp = models_.current().components[std::size_t(reference_->component)];
        const Patch& p = comp.patches.patches[std::size_t(reference_->patch - 1)];
        if (device == 1)
            moveMarker(p.u0 + value * (p.u1 - p.u0), reference_->w);
        else
            moveMarker(reference_->u, p.w0 + value * (p.w1 - p.w0));
    } else if (device == 3) {
        azimuth_ = value;
        updateViews();
    } else if (device == 4) {
        zoom_ = value;
        updateViews();
    }
    drawScreen();
}

void Session::moveMarker(double u, double w) {
    const Component& comp = models_.current().components[std::size_t(reference_->component)];
    const Patch& p = comp.patches.patches[std::size_t(reference_->patch - 1)];
    reference_->u = std::clamp(u, p.u0, p.u1);
    reference_->w = std::clamp(w, p.w0, p.w1);
    drawOverlay();
    message_ = "MARKER AT U = " + number(reference_->u) + " W = " + number(reference_->w);
    drawScreen();
}

// ---- files

std::filesystem::path Session::findInput(const std::string& name) const {
    const std::filesystem::path path(name);
    if (path.is_absolute() || std::filesystem::exists(path)) return path;
    for (const auto& dir : settings_.searchPath)
        if (std::filesystem::exists(dir / path)) return dir / path;
    return path;
}

std::filesystem::path Session::outputPath(const std::string& name) const {
    const std::filesystem::path path(name);
    if (path.is_absolute()) return path;
    std::filesystem::create_directories(settings_.outputDirectory);
    return settings_.outputDirectory / path;
}

void Session::readModel(const std::string& name) {
    Model model = loadModel(findInput(name));  // all or nothing: throws before anything changes
    viewCentre_.reset();
    for (std::size_t i = 0; i < models_.size(); ++i)
        if (models_.at(i).name == model.name) {
            fail("A MODEL NAMED " + model.name + " IS ALREADY LOADED");
            return;
        }
    const std::string modelName = model.name;
    const std::size_t patches = model.patchCount(), components = model.components.size();
    models_.add(std::move(model));
    showModel();
    say("MODEL " + modelName + " READ: " + std::to_string(components) + " COMPONENTS, " +
        std::to_string(patches) + " PATCHES");
}

void Session::readCurve(const std::string& input) {
    std::istringstream in(input);
    std::string name;
    double scale = 1.0;
    in >> name;
    if (!(in >> scale)) scale = 1.0;
    if (name.empty() || !(scale > 0) || !std::isfinite(scale)) {
        fail("BAD INPUT IN CURVE MAP: '" + input + "'");
        return;
    }
    geom::CurveModel model = geom::readCurveFile(findInput(name));
    std::vector<geom::Curve> curves = geom::interpolateModel(model);
    for (auto& c : curves)
        for (auto& p : c.points) p *= scale;
    curveModel_ = std::move(model);
    curves_ = std::move(curves);
    curveFile_ = std::filesystem::path(name).filename().string();
    curveScale_ = scale;
    drawOverlay();
    say("CURVE MODEL " + curveFile_ + " LOADED: " + std::to_string(curves_.size()) + " PARTS");
}

void Session::saveModel(const std::string& name) {
    const auto path = outputPath(name);
    std::ostringstream text;
    writeAircraftDescription(text, models_.current().description);
    std::ofstream out(path);
    if (!(out << text.str()) || !out.flush()) {
        fail("CANNOT WRITE " + path.string());
        return;
    }
    say("MODEL SAVED TO " + path.string());
}

void Session::archive(const std::string& name, bool retrieve) {
    const auto path = retrieve ? findInput(name) : outputPath(name);
    if (retrieve && !std::filesystem::exists(path)) {
        fail("ARCHIVE FILE " + path.string() + " NOT FOUND");
        return;
    }
    phigs_.openArchiveFile(1, path);
    try {
        if (retrieve) {
            phigs_.setConflictResolution(ConflictResolution::Update, ConflictResolution::Update);
            const auto ids = phigs_.archiveContents(1);
            phigs_.retrieveAllStructures(1);
            phigs_.closeArchiveFile(1);
            say("RETRIEVED " + std::to_string(ids.size()) + " STRUCTURES FROM " + path.string());
        } else {
            phigs_.archiveStructureNetworks(1, {structures::modelRoot});
            const auto ids = phigs_.archiveContents(1);
            phigs_.closeArchiveFile(1);
            say("ARCHIVED " + std::to_string(ids.size()) + " STRUCTURES TO " + path.string());
        }
    } catch (...) {
        phigs_.closeArchiveFile(1);
        throw;
    }
}

// ---- the model on the screen

void Session::showModel() {
    style_.onlyComponent = style_.colourfulComponent = style_.highlightComponent = -1;
    style_.errorMapComponent = -1;
    reference_.reset();
    previewLines_.clear();
    phase_ = Phase::None;
    if (models_.empty()) {
        modelPicture_.clear();
        rewriteStructure(phigs_.store(), structures::modelRoot, {});
    } else {
        modelPicture_.build(models_.current(), style_);
    }
    drawMapped(false);
    drawErrorMap();
    drawOverlay();
    updateViews();
}

void Session::updateViews() {
    glm::dvec3 lo(-1), hi(1);
    if (!models_.empty()) {
        lo = glm::dvec3(1e300);
        hi = glm::dvec3(-1e300);
        for (const Component& c : models_.current().components)
            for (const glm::dvec3& p : c.surface.points) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
    }
    const glm::dvec3 centre = viewCentre_.value_or((lo + hi) / 2.0);
    const double radius = std::max(glm::length(hi - lo) / 2, 1e-6);
    const double az = glm::radians(azimuth_), el = glm::radians(25.0);
    struct Direction {
        glm::dvec3 normal, up;
    };
    const Direction oblique{{std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)},
                            {0, 0, 1}};
    const Direction directions[] = {
        {{0, 0, 1}, {-1, 0, 0}}, {{-1, 0, 0}, {0, 0, 1}}, {{0, -1, 0}, {0, 0, 1}}, oblique};
    std::vector<Element> geometry;
    for (int v = 1; v <= (fourViews_ ? 4 : 1); ++v) {
        const Direction& d = fourViews_ ? directions[v - 1] : oblique;
        const PixelBox b = layout_.viewBox(v, fourViews_);
        const glm::dvec3 npcMin = npc({b.x0, b.y1}, 0), npcMax = npc({b.x1, b.y0}, 1);
        ViewMapping mapping;
        const double aspect = (npcMax.x - npcMin.x) / (npcMax.y - npcMin.y);
        const double half = radius * (fourViews_ && v < 4 ? 0.9 : 0.75) / zoom_;
        const glm::dvec2 halfSize =
            aspect >= 1 ? glm::dvec2(half * aspect, half) : glm::dvec2(half, half / aspect);
        mapping.windowMin = -halfSize;
        mapping.windowMax = halfSize;
        mapping.viewportMin = npcMin;
        mapping.viewportMax = npcMax;
        mapping.projectionReferencePoint = {0, 0, 4 * radius};
        mapping.backPlaneDistance = -2 * radius;
        mapping.frontPlaneDistance = 2 * radius;
        ViewRepresentation view;
        view.orientation = evaluateViewOrientationMatrix(centre, d.normal, d.up);
        view.mapping = evaluateViewMappingMatrix(mapping);
        view.clipMin = npcMin;
        view.clipMax = npcMax;
        workstation_->setViewRepresentation(v, view);
        geometry.push_back(viewIndex(v));
        geometry.push_back(executeStructure(structures::modelRoot));
    }
    // The view frames, drawn in NPC.
    geometry.push_back(viewIndex(0));
    geometry.push_back(addNamesToSet({structures::lineName}));
    geometry.push_back(colourAttr(ElementType::PolylineColour, {0.35, 0.4, 0.55}));
    for (int v = 1; v <= (fourViews_ ? 4 : 1); ++v)
        geometry.push_back(polyline3(outline(layout_.viewBox(v, fourViews_))));
    rewriteStructure(phigs_.store(), structures::geometry, geometry);
}

glm::dvec2 Session::pixelOf(const glm::dvec3& world, int view) {
    const ViewRepresentation& v = workstation_->tables().views.get(view);
    glm::dvec4 p = v.mapping * v.orientation * glm::dvec4(world, 1.0);
    p /= p.w;
    return mapping_->toPixels(glm::dvec3(p));
}

std::vector<glm::dvec3> Session::outline(const PixelBox& b) const {
    return {npc({b.x0, b.y0}), npc({b.x1, b.y0}), npc({b.x1, b.y1}), npc({b.x0, b.y1}), npc({b.x0, b.y0})};
}

void Session::drawScreen() {
    auto& store = phigs_.store();
    const ScreenLayout& l = layout_;
    const double unit = 1.0 / mapping_->pixelsPerNpc;  // one pixel in NPC

    // The menu panel of choice device 1 and the sliders of valuators 1-4: phigs echo structures.
    std::vector<std::string> labels;
    for (const auto& item : menuItems_) labels.push_back(shown(item));
    buildChoicePanel(store, structures::menu,
                     ChoicePanel{1, l.menuFor(menuItems_.size()).echoVolume(), labels}, 0, *mapping_);
    double values[4] = {0, 0, azimuth_, zoom_};
    if (reference_) {
        const Patch& p = models_.current()
                             .components[std::size_t(reference_->component)]
                             .patches.patches[std::size_t(reference_->patch - 1)];
        values[0] = (reference_->u - p.u0) / (p.u1 - p.u0);
        values[1] = (reference_->w - p.w0) / (p.w1 - p.w0);
    }
    for (int d = 1; d <= 4; ++d) {
        const ValuatorSlider slider{d, l.slider(d).echoVolume(), sliderLow[d - 1], sliderHigh[d - 1]};
        buildValuatorSlider(store, structures::sliders + d - 1, slider,
                            std::clamp(values[d - 1], sliderLow[d - 1], sliderHigh[d - 1]),
                            sliderNames[d - 1], *mapping_);
    }

    // The pointer-valuator pad: pickable buttons (pick id = button), live while the marker moves.
    const bool padLive = phase_ == Phase::MoveMarker || phase_ == Phase::Placed;
    std::vector<Element> pad{
        viewIndex(0), IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)},
        RealAttribute{ElementType::CharacterHeight, 0.25 * (l.pad.y1 - l.pad.y0) / 4 * unit},
        AlignmentAttribute{ElementType::TextAlignment, 2, 3}, addNamesToSet({structures::buttonName})};
    static const char* const arrows[] = {"NW", "N", "NE", "W", "[]", "E", "SW", "S", "SE", "DONE"};
    for (int button = 1; button <= 10; ++button) {
        const PixelBox b = l.padButton(button);
        pad.push_back(pickId(button));
        pad.push_back(colourAttr(ElementType::InteriorColour,
                                 padLive ? glm::dvec3(0.2, 0.3, 0.2) : glm::dvec3(0.1, 0.1, 0.12)));
        auto corners = outline(b);
        corners.pop_back();
        pad.push_back(fillArea3(corners));
        pad.push_back(
            colourAttr(ElementType::TextColour, padLive ? glm::dvec3(0.7, 1, 0.7) : glm::dvec3(0.4)));
        pad.push_back(textAt(npc(b.centre()), arrows[button - 1]));
    }
    rewriteStructure(store, structures::pad, pad);

    // Title, menu name, current model and the message line.
    const PixelBox& m = l.message;
    const double rowHeight = (m.y1 - m.y0) / 2;
    std::string heading = std::string(title) + "   MENU: " + shown(menuTitle_);
    if (!models_.empty()) heading += "   MODEL: " + models_.current().name;
    std::vector<Element> msg{viewIndex(0),
                             addNamesToSet({structures::lineName}),
                             RealAttribute{ElementType::CharacterHeight, 0.45 * rowHeight * unit},
                             AlignmentAttribute{ElementType::TextAlignment, 1, 3},
                             colourAttr(ElementType::PolylineColour, {0.35, 0.4, 0.55}),
                             polyline3(outline(m)),
                             colourAttr(ElementType::TextColour, {0.6, 0.75, 1.0}),
                             textAt(npc({m.x0 + 6, m.y0 + rowHeight * 0.5}), heading),
                             colourAttr(ElementType::TextColour, {1.0, 1.0, 0.55}),
                             textAt(npc({m.x0 + 6, m.y0 + rowHeight * 1.5}), message_)};
    rewriteStructure(store, structures::message, msg);
}

std::vector<geom::Curve> Session::placedCurves() const {
    return curves_;
}

void Session::drawOverlay() {
    std::vector<Element> e{addNamesToSet({structures::lineName})};
    if (reference_ && !models_.empty()) {
        const Component& comp = models_.current().components[std::size_t(reference_->component)];
        const glm::dvec3 at = geom::evaluate(comp.surface, reference_->u, reference_->w);
        e.push_back(IndexAttribute{ElementType::MarkerType, int(MarkerType::Circle)});
        e.push_back(RealAttribute{ElementType::MarkerSizeScaleFactor, 2.0});
        e.push_back(colourAttr(ElementType::PolymarkerColour, {1, 0.2, 0.2}));
        e.push_back(polymarker3({at}));
        if (phase_ == Phase::Placed && !mappedSincePlaced_) {
            geom::curvemap::Placement placement = placement_;
            placement.reference = {reference_->u, reference_->w};
            placement.offset = 0.5;
            const auto frame = geom::curvemap::placementFrame(comp.surface, placement);
            const double length = 1.5;
            e.push_back(RealAttribute{ElementType::LinewidthScaleFactor, 2.0});
            e.push_back(colourAttr(ElementType::PolylineColour, {0.1, 1.0, 0.2}));  // u tangent: green
            e.push_back(polyline3({frame.surfacePoint, frame.surfacePoint + length * frame.tangentU}));
            e.push_back(colourAttr(ElementType::PolylineColour, {0.75, 0.2, 1.0}));  // w tangent: purple
            e.push_back(polyline3({frame.surfacePoint, frame.surfacePoint + length * frame.tangentW}));
            e.push_back(colourAttr(ElementType::PolylineColour, {1, 1, 1}));  // normal: white
            e.push_back(polyline3({frame.surfacePoint, frame.surfacePoint + length * frame.z}));
            e.push_back(RealAttribute{ElementType::AnnotationTextCharacterHeight, 0.012});
            e.push_back(colourAttr(ElementType::TextColour, {0.1, 1.0, 0.2}));
            e.push_back(AnnotationTextElement{
                frame.surfacePoint + length * frame.tangentU, {0.004, 0.004, 0}, "U", false});
            e.push_back(colourAttr(ElementType::TextColour, {0.75, 0.2, 1.0}));
            e.push_back(AnnotationTextElement{
                frame.surfacePoint + length * frame.tangentW, {0.004, 0.004, 0}, "W", false});
            e.push_back(RealAttribute{ElementType::LinewidthScaleFactor, 1.0});
            // The placed curve above the patch.
            e.push_back(colourAttr(ElementType::PolylineColour, {0.3, 0.9, 1.0}));
            for (const geom::Curve& c : curves_) {
                std::vector<glm::dvec3> points;
                const int n = 200;
                for (int k = 0; k <= n; ++k) {
                    const double t = c.domainStart() + (c.domainEnd() - c.domainStart()) * k / n;
                    points.push_back(frame.toModel(geom::evaluate(c, t)));
                }
                e.push_back(polyline3(points));
            }
        }
    }
    e.push_back(colourAttr(ElementType::PolylineColour, {0.9, 0.9, 0.4}));
    for (const auto& line : previewLines_) e.push_back(polyline3(line));
    rewriteStructure(phigs_.store(), structures::overlay, e);
}

void Session::mapCurve(bool previewOnly) {
    if (curves_.empty()) {
        fail("NO CURVE LOADED: USE LOAD CURVE FIRST");
        return;
    }
    if (!reference_ || phase_ != Phase::Placed) {
        fail("NO REFERENCE POINT: USE DEFINE POINT AND DONE FIRST");
        return;
    }
    const Model& model = models_.current();
    const Component& comp = model.components[std::size_t(reference_->component)];
    if (!previewOnly) say("CALCULATING INTERSECTIONS, PLEASE WAIT...");
    if (!previewOnly && present_) present_(picture());
    geom::curvemap::CurveMapper mapper(comp.surface, comp.closedU, comp.closedW);
    geom::curvemap::Placement placement = placement_;
    placement.reference = {reference_->u, reference_->w};
    placement.offset = 0.5;
    geom::curvemap::MapOptions options;
    options.tolerance = 2e-3;
    const geom::curvemap::MapResult result = mapper.map(curves_, placement, options);
    if (previewOnly) {
        previewLines_.clear();
        for (const auto& part : result.parts)
            for (const auto& loop : part.loops)
                for (std::size_t k = 0; k < loop.points.size();
                     k += std::max<std::size_t>(1, loop.points.size() / 24))
                    if (!std::isnan(loop.curveParameters[k]))
                        previewLines_.push_back({loop.projectedFrom[k], loop.points[k]});
        drawOverlay();
        say("MAP PREVIEW: " + std::to_string(previewLines_.size()) + " PROJECTION LINES");
        return;
    }
    say("DRAWING MAPPED CURVE...");
    MappingRecord record;
    record.model = model.name;
    record.component = comp.name;
    record.curveFile = curveFile_;
    record.reference = *reference_;
    record.parts = result.parts.size();
    for (const auto& part : result.parts) {
        record.loopsPerPart.push_back(part.loops.size());
        record.loops += part.loops.size();
        for (const auto& loop : part.loops) {
            record.boundaryWalks += loop.boundaryWalks;
            record.polylines.push_back(loop.points);
        }
        for (const auto& issue : part.issues) log_.push_back("mapping: " + issue);
    }
    mappings_.push_back(std::move(record));
    previewLines_.clear();
    mappedSincePlaced_ = true;  // the mapped figure is shown with the model, without the placed curve
    style_.onlyComponent = style_.colourfulComponent = style_.highlightComponent = -1;
    modelPicture_.restyle(model, style_);
    drawOverlay();
    drawMapped(false);
    const auto& r = mappings_.back();
    say("MAPPED " + r.curveFile + " ON " + r.component + ": " + std::to_string(r.loops) + " LOOPS IN " +
        std::to_string(r.parts) + " PARTS");
}

void Session::drawMapped(bool all) {
    std::vector<Element> e{addNamesToSet({structures::lineName}),
                           RealAttribute{ElementType::LinewidthScaleFactor, 2.0}};
    if (!models_.empty()) {
        const std::string& name = models_.current().name;
        for (std::size_t i = 0; i < mappings_.size(); ++i) {
            const MappingRecord& m = mappings_[i];
            if (m.model != name || (!all && i + 1 != mappings_.size())) continue;
            e.push_back(colourAttr(ElementType::PolylineColour,
                                   i % 2 ? glm::dvec3(1.0, 0.25, 0.15) : glm::dvec3(0.1, 0.3, 1.0)));
            for (const auto& line : m.polylines) e.push_back(polyline3(line));
        }
    }
    rewriteStructure(phigs_.store(), structures::mapped, e);
}

void Session::drawErrorMap() {
    std::vector<Element> e;
    if (style_.errorMapComponent >= 0 && !reductions_.empty() && !models_.empty()) {
        const ReductionRecord& r = reductions_.back();
        const Component& comp = models_.current().components[std::size_t(r.componentIndex)];
        const auto& d = r.deviation;
        QuadrilateralMeshElement mesh;
        mesh.rows = int(d.u.size());
        mesh.columns = int(d.v.size());
        const double top = std::max(d.maxError, 1e-12);
        for (std::size_t i = 0; i < d.u.size(); ++i)
            for (std::size_t j = 0; j < d.v.size(); ++j) {
                mesh.points.push_back(geom::evaluate(comp.surface, d.u[i], d.v[j]));
                const double t = std::clamp(d.error[i * d.v.size() + j] / top, 0.0, 1.0);
                // Blue (no error) through green to red (the largest error).
                const glm::dvec3 c =
                    t < 0.5 ? glm::mix(glm::dvec3(0.1, 0.2, 1.0), glm::dvec3(0.1, 0.9, 0.2), t * 2)
                            : glm::mix(glm::dvec3(0.1, 0.9, 0.2), glm::dvec3(1.0, 0.1, 0.1), t * 2 - 1);
                mesh.vertexColours.push_back(Colour::fromRgb(c));
            }
        e.push_back(IndexAttribute{ElementType::InteriorStyle, int(InteriorStyle::Solid)});
        e.push_back(IndexAttribute{ElementType::InteriorShadingMethod, int(ShadingMethod::Colour)});
        e.push_back(std::move(mesh));
    }
    rewriteStructure(phigs_.store(), structures::errorMap, e);
}

// ---- SURF_REDN

void Session::reduce(int componentIndex, double tolerance, std::size_t count) {
    const Model& original = models_.current();
    const Component& comp = original.components.at(std::size_t(componentIndex));
    geom::ReductionOptions options;
    if (count > 0)
        options.maxRemovals = count;
    else
        options.tolerance = tolerance;
    const geom::ReductionDirection direction = reductionDirection_ == "U"   ? geom::ReductionDirection::U
                                               : reductionDirection_ == "W" ? geom::ReductionDirection::V
                                                                            : geom::ReductionDirection::Both;
    if (count > 0) say("REMOVE " + std::to_string(count) + " KNOTS FROM EACH CROSS SECTION");
    if (present_) present_(picture());
    geom::SurfaceReduction reduced = geom::reduceSurface(comp.surface, direction, options);
    PatchList patches = buildPatches(reduced.surface);  // may throw: nothing is changed yet

    ReductionRecord record;
    record.model = original.name;
    record.component = comp.name;
    record.componentIndex = componentIndex;
    record.direction = reductionDirection_;
    record.mode = count > 0 ? "count" : "tolerance";
    record.tolerance = tolerance;
    record.count = count;
    record.countUBefore = comp.surface.countU;
    record.countWBefore = comp.surface.countV;
    record.countUAfter = reduced.surface.countU;
    record.countWAfter = reduced.surface.countV;
    record.removedU = reduced.removedU;
    record.removedW = reduced.removedV;
    record.maxError = reduced.deviation.maxError;
    record.deviation = reduced.deviation;

    // The reduced version is a new model; the original stays in the list (MODELS).
    std::string name = original.name + "_R" + std::to_string(reductions_.size() + 1);
    if (name.size() > 20) name = "REDUCED_" + std::to_string(reductions_.size() + 1);
    const auto copied = models_.copyCurrent(name);
    if (!copied.done) {
        fail(copied.message);
        return;
    }
    Component& target = models_.current().components[std::size_t(componentIndex)];
    target.surface = std::move(reduced.surface);
    target.patches = std::move(patches);
    record.reducedModel = models_.current().name;
    reductions_.push_back(record);
    showModel();
    const std::string done = reductionDirection_ == "U"   ? "DATA REDUCTION IN U DIRECTION COMPLETE"
                             : reductionDirection_ == "W" ? "DATA REDUCTION IN W DIRECTION COMPLETE"
                                                          : "DATA REDUCTION IN U AND W DIRECTIONS COMPLETE";
    say(done + ": " + std::to_string(record.countUBefore * record.countWBefore) + " -> " +
        std::to_string(record.countUAfter * record.countWAfter) + " CONTROL POINTS, MAX ERROR " +
        number(record.maxError, 3));
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

std::string Session::recording() const {
    std::string out = "# acsynt session recorded\n";
    for (const InputAction& a : input_->history()) out += ScriptInputSource::format(a) + "\n";
    return out;
}

}  // namespace acsynt
