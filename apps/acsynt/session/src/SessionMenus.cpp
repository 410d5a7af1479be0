// The session's menus, the input of each device class, and the files it reads and writes.
#include "acsynt/session/Session.h"

#include "acsynt/session/ModelStateFile.h"

#include "SessionShared.h"

#include "acsynt/ModelFile.h"
#include "acsynt/session/ModelExchange.h"
#include "geom/DataReduction.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/exchange/CadFile.h"
#include "phigs/core/Error.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/view/ViewMatrices.h"
#include "phigs/ws/EchoStructures.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace acsynt {

using namespace phigs;
using namespace session_detail;

// ---- menus

void Session::mainMenu() {
    setMenu("MAIN", mainItems);
}

void Session::choose(std::string item) {
    log_.push_back("choice " + item);
    recordAs("choice " + item);
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
        if (item == "UNDO" || item == "REDO") {
            if (item == "UNDO")
                undo();
            else
                redo();
            return;
        }
        if (item == "FILE") setMenu("FILE", fileItems);
        if (item == "VIEW") setMenu("VIEW", viewItems);
        if (item == "MODELS") setMenu("MODELS", modelItems);
        if ((item == "CURVE_MAP" || item == "SURF_REDN") && !requireModel()) return;
        if (item == "CURVE_MAP") setMenu("CURVE MAP", curveItems);
        if (item == "SURF_REDN") setMenu("SURF_REDN", reductionItems);
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
    if (item == "EXPORT" && requireModel())
        prompt("ENTER IGES OR STEP FILE NAME TO EXPORT (.igs, .iges, .stp, .step)", Awaiting::ExportFile);
    if (item == "IMPORT") prompt("ENTER IGES OR STEP FILE NAME TO IMPORT", Awaiting::ImportFile);
    if (item == "HARDCOPY" && requireModel())
        prompt("ENTER HARDCOPY FILE NAME (.pdf, .svg, .eps)", Awaiting::HardcopyFile);
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
        elevation_ = 25;
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
        previewClipped_.clear();
        previewLost_.clear();
        style_.onlyComponent = style_.colourfulComponent = style_.highlightComponent = -1;
        modelPicture_.restyle(models_.current(), style_);
        drawOverlay();
        say("SELECT COMPONENT FOR MAPPING");
    } else if (item == "FLIP_CURVE") {
        remember(state(), "FLIP CURVE");
        placement_.flipped = !placement_.flipped;
        mappedSincePlaced_ = false;
        drawOverlay();
        say(placement_.flipped ? "CURVE FLIPPED" : "CURVE UNFLIPPED");
    } else if (item == "ROTATE_CURVE") {
        remember(state(), "ROTATE CURVE");
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
        say(style_.errorMapComponent >= 0 ? errorMapLine() : "ERROR MAP OFF");
    } else if (item == "ERROR_SCALE") {
        prompt("ENTER ERROR MAP SCALE: A LENGTH (RED AT IT, FIXED) OR RELATIVE", Awaiting::ErrorScale);
    }
}

std::string Session::errorMapLine() const {
    const ReductionRecord& r = reductions_.back();
    return "ERROR MAP: BLUE 0 TO RED " + lengthText(errorMapTop()) +
           (errorScale_ > 0 ? " (FIXED SCALE)" : " (RELATIVE SCALE)") + ", MAX ERROR " +
           lengthText(r.maxError);
}

void Session::setErrorScale(const std::string& input) {
    std::string word = input;
    std::erase(word, ' ');
    std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return std::toupper(c); });
    if (word == "RELATIVE") {
        errorScale_ = 0;
    } else {
        const auto value = parseNumber(input);
        if (!value || !(*value > 0)) {
            fail("BAD INPUT IN ERROR SCALE: '" + input + "': expected a positive length or RELATIVE");
            return;
        }
        errorScale_ = *value;
    }
    drawErrorMap();
    if (style_.errorMapComponent >= 0)
        say(errorMapLine());
    else
        say(errorScale_ > 0 ? "ERROR MAP SCALE FIXED: RED AT " + lengthText(errorScale_)
                            : "ERROR MAP SCALE RELATIVE: RED AT THE LARGEST ERROR");
}

void Session::modelsMenu(const std::string& item) {
    SessionState before = state();
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
        if (item == "DELETE_MODEL") remember(std::move(before), "DELETE MODEL");
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
        case Awaiting::ExportFile:
            exportModel(input);
            break;
        case Awaiting::ImportFile:
            importModel(input);
            break;
        case Awaiting::HardcopyFile:
            writeHardcopy(input);
            break;
        case Awaiting::ArchiveFile:
            archive(input, false);
            break;
        case Awaiting::RetrieveFile:
            archive(input, true);
            break;
        case Awaiting::ModelName: {
            SessionState before = state();
            const std::string old = models_.current().name;
            const auto outcome = models_.rename(input);
            if (!outcome.done) {
                fail(outcome.message);
                break;
            }
            for (auto& m : mappings_)
                if (m.model == old) m.model = models_.current().name;
            remember(std::move(before), "NAME MODEL");
            say(outcome.message);
            break;
        }
        case Awaiting::ErrorScale:
            setErrorScale(input);
            break;
        case Awaiting::Tolerance:
        case Awaiting::Count: {
            const auto value = parseNumber(input);
            if (!value || !(*value > 0) || (what == Awaiting::Count && *value != std::floor(*value))) {
                fail("BAD INPUT IN SRF_REDUCTION: '" + input + "': expected " +
                     (what == Awaiting::Count ? "a whole number of knots, 1 or more" : "a positive length"));
                break;
            }
            if (what == Awaiting::Tolerance)
                reduce(reductionComponent_, *value, 0);
            else
                reduce(reductionComponent_, 0, std::size_t(std::min(*value, 1e9)));
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
    if (!picked || models_.empty() || std::size_t(picked->component) >= models_.current().components.size())
        return;
    lastPick_ = picked;
    lastPickDetail_ = measure.surface;
    const Model& model = models_.current();
    const Component& comp = model.components.at(std::size_t(picked->component));
    std::string where = comp.name + " PATCH " + std::to_string(picked->patch);
    if (measure.surface)
        where += " AT U = " + number(measure.surface->uv.x) + " W = " + number(measure.surface->uv.y);
    log_.push_back("picked " + where);
    recordPick(*picked, measure);
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
    recordAs("choice " + padItems[std::size_t(button - 1)] + " device 2");
    if (reference_ && phase_ == Phase::Placed) {
        fail("THE POINTER PAD IS OFF AFTER DONE: USE DEFINE POINT TO MOVE THE MARKER");
        return;
    }
    if (!reference_ || phase_ != Phase::MoveMarker) {
        fail("NO REFERENCE PATCH: USE DEFINE POINT FIRST");
        return;
    }
    const Component& comp = models_.current().components[std::size_t(reference_->component)];
    const Patch& p = comp.patches.patches[std::size_t(reference_->patch - 1)];
    if (button == 10) {
        remember(state(), "REFERENCE POINT");
        phase_ = Phase::Placed;
        mappedSincePlaced_ = false;
        style_.onlyComponent = style_.highlightComponent = -1;
        modelPicture_.restyle(models_.current(), style_);
        drawOverlay();
        say("REFERENCE POINT U = " + number(reference_->u) + " W = " + number(reference_->w));
        return;
    }
    const double du = (p.u1 - p.u0) / 8, dw = (p.w1 - p.w0) / 8;
    // Rows of the compass: w increases upwards, u to the right (Table 2 of the ACSYNT curve-mapping thesis).
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
        if (reference_ && phase_ == Phase::Placed) {
            fail("THE MARKER IS PLACED (DONE): USE DEFINE POINT TO MOVE IT");
            return;
        }
        if (!reference_ || phase_ != Phase::MoveMarker) {
            fail("NO REFERENCE PATCH: USE DEFINE POINT FIRST");
            return;
        }
        // The component's own u or w; moveMarker keeps it inside the reference patch.
        if (device == 1)
            moveMarker(value, reference_->w);
        else
            moveMarker(reference_->u, value);
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

void Session::recordPick(const PickedPatch& picked, const PickMeasure& measure) {
    if (!measure.surface || picked.patch < 1) return;  // recorded as it came
    // The view: the one the click was in, or the replayed pick's.
    int view = pickView_;
    const auto& history = input_->history();
    if (!history.empty())
        if (const auto* click = std::get_if<action::Pick>(&history.back().what))
            for (int v = 1; v <= (fourViews_ ? 4 : 1); ++v)
                if (layout_.viewBox(v, fourViews_).contains(click->position)) view = v;
    if (view < 1) return;
    const Component& comp = models_.current().components.at(std::size_t(picked.component));
    char uw[80];
    std::snprintf(uw, sizeof uw, "%.17g %.17g", measure.surface->uv.x, measure.surface->uv.y);
    std::string comment = "picked " + comp.name + " patch " + std::to_string(picked.patch) + " at u " +
                          number(measure.surface->uv.x) + " w " + number(measure.surface->uv.y) +
                          " in view " + std::to_string(view);
    if (!history.empty())
        if (const auto* click = std::get_if<action::Pick>(&history.back().what))
            comment += " (pixel " + number(click->position.x, 5) + " " + number(click->position.y, 5) +
                       " of " + std::to_string(layout_.width) + " x " + std::to_string(layout_.height) + ")";
    recordAs("pick_surface " + comp.name + " " + std::to_string(picked.patch) + " " + uw + " " +
                 std::to_string(view),
             comment);
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
    // Files a session writes stay inside the output directory: a script cannot reach further.
    const std::filesystem::path path(name);
    const bool climbs = std::any_of(path.begin(), path.end(), [](const auto& part) { return part == ".."; });
    if (name.empty() || path.is_absolute() || climbs || !path.has_filename())
        throw std::invalid_argument(
            "OUTPUT FILE '" + name +
            "' MUST BE A FILE NAME INSIDE THE OUTPUT DIRECTORY (NOT ABSOLUTE, NO '..')");
    const std::filesystem::path full = settings_.outputDirectory / path;
    std::filesystem::create_directories(full.parent_path());
    if (std::filesystem::is_directory(full))
        throw std::invalid_argument("OUTPUT FILE " + full.string() + " IS A DIRECTORY");
    return full;
}

void Session::readModel(const std::string& name) {
    // All or nothing: both readers throw before anything changes.
    const std::filesystem::path path = findInput(name);
    SessionState before = this->state();
    ModelState state;
    if (isModelStateFile(path))
        state = readModelState(path);
    else
        state.model = loadModel(path);
    viewCentre_.reset();
    // A name already loaded: the model read is renamed NAME_2, NAME_3, ... and the line says so.
    const std::string fileName = state.model.name;
    std::string modelName = fileName;
    const auto loaded = [this](const std::string& n) {
        for (std::size_t i = 0; i < models_.size(); ++i)
            if (models_.at(i).name == n) return true;
        return false;
    };
    for (int k = 2; loaded(modelName) && k < 1000; ++k) {
        const std::string suffix = "_" + std::to_string(k);
        modelName = fileName.substr(0, std::min(fileName.size(), std::size_t(20) - suffix.size())) + suffix;
    }
    if (loaded(modelName)) {
        fail("A MODEL NAMED " + fileName + " IS ALREADY LOADED");
        return;
    }
    state.model.name = modelName;
    for (MappingRecord& m : state.mappings) m.model = modelName;
    const std::size_t patches = state.model.patchCount(), components = state.model.components.size();
    const std::size_t mapped = state.mappings.size();
    models_.add(std::move(state.model));
    for (MappingRecord& m : state.mappings) mappings_.push_back(std::move(m));
    remember(std::move(before), "READ MODEL " + modelName);
    showModel();
    if (mapped > 0) drawMapped(true);
    std::string line = "MODEL " + fileName + " READ";
    if (modelName != fileName) line += " AS " + modelName + " (" + fileName + " IS LOADED)";
    line += ": " + std::to_string(components) + " COMPONENTS, " + std::to_string(patches) + " PATCHES";
    if (mapped > 0) line += ", " + std::to_string(mapped) + " MAPPED CURVES";
    say(line);
}

void Session::readCurve(const std::string& input) {
    // FILE [SCALE]: the scale, when given, must be a whole positive number and the last word.
    std::istringstream in(input);
    std::string name, scaleText, extra;
    in >> name >> scaleText >> extra;
    double scale = 1.0;
    if (!scaleText.empty()) {
        const auto [end, ec] = std::from_chars(scaleText.data(), scaleText.data() + scaleText.size(), scale);
        if (ec != std::errc() || end != scaleText.data() + scaleText.size()) scale = -1.0;
    }
    if (name.empty() || !extra.empty() || !(scale > 0) || !std::isfinite(scale)) {
        fail("BAD INPUT IN CURVE MAP: '" + input + "': expected FILE [SCALE], SCALE a positive number");
        return;
    }
    geom::CurveModel model = geom::readCurveFile(findInput(name));
    std::vector<geom::Curve> curves = geom::interpolateModel(model);
    for (auto& c : curves)
        for (auto& p : c.points) {
            p *= scale;
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                fail("CURVE SCALE " + scaleText + " IS TOO LARGE: THE CURVE IS NOT FINITE");
                return;
            }
        }
    curveModel_ = std::move(model);
    curves_ = std::move(curves);
    curveFile_ = std::filesystem::path(name).filename().string();
    curveScale_ = scale;
    drawOverlay();
    say("CURVE MODEL " + curveFile_ + " LOADED: " + std::to_string(curves_.size()) + " PARTS");
}

void Session::saveModel(const std::string& name) {
    // The current model as it is (reduced surfaces, imported or not) and its mapped curves.
    const auto path = outputPath(name);
    const Model& model = models_.current();
    std::ostringstream text;
    writeModelState(text, model, mappings_);
    std::ofstream out(path);
    if (!(out << text.str()) || !out.flush()) {
        fail("CANNOT WRITE " + path.string());
        return;
    }
    std::size_t mapped = 0;
    for (const MappingRecord& m : mappings_) mapped += m.model == model.name;
    say("MODEL " + model.name + " SAVED TO " + path.string() + ": " +
        std::to_string(model.components.size()) + " COMPONENTS, " + std::to_string(mapped) +
        " MAPPED CURVES");
}

void Session::exportModel(const std::string& name) {
    const auto path = outputPath(name);
    const Model& model = models_.current();
    const geom::exchange::CadModel cad = cadModelOf(model, mappings_);
    geom::exchange::writeCadFile(cad, path);  // ExchangeError (a runtime_error) names the file and cause
    std::size_t curves = 0;
    for (const auto& s : cad.surfaces) curves += s.curves.size();
    say("MODEL " + model.name + " EXPORTED TO " + path.string() + ": " +
        std::to_string(model.components.size()) + " COMPONENTS, " + std::to_string(model.patchCount()) +
        " PATCHES, " + std::to_string(curves) + " MAPPED CURVES");
}

void Session::importModel(const std::string& name) {
    ImportedModel imported =
        importCadModel(findInput(name));  // all or nothing: throws before anything changes
    for (std::size_t i = 0; i < models_.size(); ++i)
        if (models_.at(i).name == imported.model.name) {
            fail("A MODEL NAMED " + imported.model.name + " IS ALREADY LOADED");
            return;
        }
    viewCentre_.reset();
    for (const auto& w : imported.warnings) log_.push_back("import: " + w);
    const std::string modelName = imported.model.name;
    const std::size_t patches = imported.model.patchCount(), components = imported.model.components.size();
    const std::size_t curves = imported.mappings.size();
    models_.add(std::move(imported.model));
    for (auto& m : imported.mappings) mappings_.push_back(std::move(m));
    showModel();
    say("MODEL " + modelName + " IMPORTED: " + std::to_string(components) + " COMPONENTS, " +
        std::to_string(patches) + " PATCHES, " + std::to_string(curves) + " MAPPED CURVES" +
        (imported.warnings.empty()
             ? ""
             : ", " + std::to_string(imported.warnings.size()) + " WARNINGS IN THE LOG"));
}

bool Session::importCadFile(const std::filesystem::path& path) {
    const std::size_t before = failedLines_;
    try {
        importModel(path.string());
    } catch (const std::runtime_error& e) {
        fail(e.what());
    } catch (const std::invalid_argument& e) {
        fail(e.what());
    }
    return failedLines_ == before;
}

void Session::archive(const std::string& name, bool retrieve) {
    const auto path = retrieve ? findInput(name) : outputPath(name);
    if (retrieve && !std::filesystem::exists(path)) {
        fail("ARCHIVE FILE " + path.string() + " NOT FOUND");
        return;
    }
    if (retrieve && std::filesystem::is_directory(path)) {
        fail("ARCHIVE FILE " + path.string() + " IS A DIRECTORY");
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

}  // namespace acsynt
