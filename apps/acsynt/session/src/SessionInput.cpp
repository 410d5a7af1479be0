// The input of each device class: menu choices (through the menu tables), prompt answers,
// picks, the pad and the valuators.
#include "acsynt/session/Session.h"

#include "acsynt/session/ModelStateFile.h"

#include "SessionShared.h"

#include "acsynt/session/ConfirmMenu.h"

#include "acsynt/ModelFile.h"
#include "acsynt/session/ModelExchange.h"
#include "geom/DataReduction.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
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

void Session::choose(const std::string& item) {
    core_.log.push_back("choice " + item);
    recordAs("choice " + item);
    menu_->dispatch(item, *this);
}

void Session::prompt(const std::string& s, Awaiting what) {
    core_.awaiting = what;
    core_.prompt = s;
    say(s);
}

bool Session::requireModel() {
    if (!core_.models.empty()) return true;
    fail("NO GEOMETRY FILE FOUND!");
    return false;
}

void Session::setErrorScale(const std::string& input) {
    std::string word = input;
    std::erase(word, ' ');
    std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return std::toupper(c); });
    if (word == "RELATIVE") {
        core_.errorScale = 0;
    } else {
        const auto value = parseNumber(input);
        if (!value || !(*value > 0)) {
            fail("BAD INPUT IN ERROR SCALE: '" + input + "': expected a positive length or RELATIVE");
            return;
        }
        core_.errorScale = *value;
    }
    drawErrorMap();
    if (core_.style.errorMapComponent >= 0)
        say(core_.errorMapLine());
    else
        say(core_.errorScale > 0 ? "ERROR MAP SCALE FIXED: RED AT " + lengthText(core_.errorScale)
                                 : "ERROR MAP SCALE RELATIVE: RED AT THE LARGEST ERROR");
}

// ---- input of each class

void Session::text(const std::string& input) {
    const Awaiting what = core_.awaiting;
    core_.awaiting = Awaiting::Nothing;
    core_.log.push_back("string " + input);
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
        case Awaiting::ModelName:
            renameModel(input);
            break;
        case Awaiting::ErrorScale:
            setErrorScale(input);
            break;
        case Awaiting::Tolerance:
        case Awaiting::Count:
            reductionAnswer(input, what == Awaiting::Count);
            break;
    }
}

void Session::renameModel(const std::string& input) {
    SessionState before = core_.state();
    const std::string old = core_.models.current().name;
    const auto outcome = core_.models.rename(input);
    if (!outcome.done) {
        fail(outcome.message);
        return;
    }
    for (auto& m : core_.mappings)
        if (m.model == old) m.model = core_.models.current().name;
    // The reduction that made it stays its reduction (ERROR_MAP finds it by name).
    for (ReductionRecord& r : core_.reductions)
        if (!r.modelDeleted && r.reducedModel == old) r.reducedModel = core_.models.current().name;
    core_.remember(std::move(before), "NAME MODEL");
    say(outcome.message);
}

void Session::reductionAnswer(const std::string& input, bool count) {
    const auto value = parseNumber(input);
    if (!value || !(*value > 0) || (count && (*value != std::floor(*value) || *value > 1e9))) {
        fail("BAD INPUT IN SRF_REDUCTION: '" + input + "': expected " +
             (count ? "a whole number of knots, 1 to 1000000000" : "a positive length"));
        return;
    }
    if (!count)
        reduce(core_.reductionComponent, *value, 0);
    else
        reduce(core_.reductionComponent, 0, std::size_t(*value));
}

void Session::missedPick() {
    const auto& history = core_.input->history();
    if (const auto* click = history.empty() ? nullptr : std::get_if<action::Pick>(&history.back().what)) {
        const glm::dvec2 at = click->position;
        // A script's pick is a pixel of the screen: one off it is a mistake in the script, not
        // a miss of the model.
        if (!(at.x >= 0 && at.x <= layout_.width && at.y >= 0 && at.y <= layout_.height)) {
            fail("PICK AT " + number(at.x) + " " + number(at.y) + " IS OFF THE " +
                 std::to_string(layout_.width) + " X " + std::to_string(layout_.height) + " SCREEN");
            return;
        }
        // Recorded as a miss: its pixel may show the model on a screen of another size.
        recordAs("pick_nothing", "nothing picked at pixel " + number(at.x, 5) + " " + number(at.y, 5) +
                                     " of " + std::to_string(layout_.width) + " x " +
                                     std::to_string(layout_.height));
    }
    if (core_.phase != Phase::None) say("NOTHING PICKED: TRY AGAIN");
}

void Session::pick(const PickMeasure& measure) {
    if (measure.status != InputStatus::Ok) return missedPick();
    // A pad button: its structure is the pad, its pick id the button.
    for (const PickPathItem& level : measure.path)
        if (level.structureId == structures::pad) {
            padButton(level.pickId);
            return;
        }
    const auto picked = ModelPicture::fromPath(measure.path);
    if (!picked || core_.models.empty() ||
        std::size_t(picked->component) >= core_.models.current().components.size())
        return;
    core_.lastPick = picked;
    core_.lastPickDetail = measure.surface;
    const Model& model = core_.models.current();
    const Component& comp = model.components.at(std::size_t(picked->component));
    std::string where = comp.name + " PATCH " + std::to_string(picked->patch);
    if (measure.surface)
        where += " AT U = " + number(measure.surface->uv.x) + " W = " + number(measure.surface->uv.y);
    core_.log.push_back("picked " + where);
    recordPick(*picked, measure);
    switch (core_.phase) {
        case Phase::SelectComponent:
            core_.pickedComponent = picked->component;
            core_.style.onlyComponent = core_.style.colourfulComponent = picked->component;
            core_.style.highlightComponent = -1;
            modelPicture_.restyle(model, core_.style);
            core_.phase = Phase::SelectPatch;
            say("SELECT REFERENCE PATCH TO MAP");
            break;
        case Phase::SelectPatch:
            if (picked->component != core_.pickedComponent) {
                fail("PICK A PATCH OF " + model.components[std::size_t(core_.pickedComponent)].name);
                break;
            }
            core_.style.colourfulComponent = -1;
            core_.style.highlightComponent = picked->component;
            core_.style.highlightPatch = picked->patch;
            modelPicture_.restyle(model, core_.style);
            core_.phase = Phase::AcceptReject;
            openMenu(confirmMenuTable());
            say("ACCEPT OR REJECT PATCH");
            break;
        case Phase::SelectReduction:
            core_.phase = Phase::None;
            core_.reductionComponent = picked->component;
            if (core_.reductionByCount)
                prompt(std::string("ENTER NUMBER OF KNOTS TO BE REMOVED IN ") +
                           (core_.reductionDirection == "W"   ? "W DIRECTION"
                            : core_.reductionDirection == "U" ? "U DIRECTION"
                                                              : "EACH DIRECTION (U AND W)"),
                       Awaiting::Count);
            else
                prompt("ENTER TOLERANCE FOR " + comp.name, Awaiting::Tolerance);
            break;
        default:
            say("PICKED " + where);
    }
}

std::string Session::noMarkerYet() const {
    // Inside DEFINE POINT (a component or patch still to pick, or the patch to accept) the next
    // step is there, not DEFINE POINT again.
    switch (core_.phase) {
        case Phase::SelectComponent:
            return "NO REFERENCE PATCH YET: PICK A COMPONENT, THEN A PATCH";
        case Phase::SelectPatch:
            return "NO REFERENCE PATCH YET: PICK A PATCH OF THE COMPONENT";
        case Phase::AcceptReject:
            return "NO REFERENCE PATCH YET: ACCEPT OR REJECT THE PATCH PICKED";
        default:
            return "NO REFERENCE PATCH: USE DEFINE POINT FIRST";
    }
}

void Session::padButton(int button) {
    recordAs("choice " + padItems[std::size_t(button - 1)] + " device 2");
    if (core_.reference && core_.phase == Phase::Placed) {
        fail("THE POINTER PAD IS OFF AFTER DONE: USE DEFINE POINT TO MOVE THE MARKER");
        return;
    }
    if (!core_.reference || core_.phase != Phase::MoveMarker) {
        fail(noMarkerYet());
        return;
    }
    const Component& comp = core_.models.current().components[std::size_t(core_.reference->component)];
    const Patch& p = comp.patches.patches[std::size_t(core_.reference->patch - 1)];
    if (button == 10) {
        core_.remember(core_.state(), "REFERENCE POINT");
        core_.phase = Phase::Placed;
        core_.mappedSincePlaced = false;
        core_.style.onlyComponent = core_.style.highlightComponent = -1;
        modelPicture_.restyle(core_.models.current(), core_.style);
        drawOverlay();
        say("REFERENCE POINT U = " + number(core_.reference->u) + " W = " + number(core_.reference->w));
        return;
    }
    const double du = (p.u1 - p.u0) / 8, dw = (p.w1 - p.w0) / 8;
    // Rows of the compass: w increases upwards, u to the right (Table 2 of the ACSYNT curve-mapping thesis).
    static const int stepU[] = {-1, 0, 1, -1, 0, 1, -1, 0, 1};
    static const int stepW[] = {1, 1, 1, 0, 0, 0, -1, -1, -1};
    if (button == 5)
        moveMarker((p.u0 + p.u1) / 2, (p.w0 + p.w1) / 2);
    else
        moveMarker(core_.reference->u + stepU[button - 1] * du, core_.reference->w + stepW[button - 1] * dw);
    core_.log.push_back("pad " + padItems[std::size_t(button - 1)]);
}

void Session::valuator(int device, double value) {
    if (device == 1 || device == 2) {
        if (core_.reference && core_.phase == Phase::Placed) {
            fail("THE MARKER IS PLACED (DONE): USE DEFINE POINT TO MOVE IT");
            return;
        }
        if (!core_.reference || core_.phase != Phase::MoveMarker) {
            fail(noMarkerYet());
            return;
        }
        // The component's own u or w; moveMarker keeps it inside the reference patch.
        if (device == 1)
            moveMarker(value, core_.reference->w);
        else
            moveMarker(core_.reference->u, value);
    } else if (device == 3) {
        core_.azimuth = value;
        updateViews();
    } else if (device == 4) {
        core_.zoom = value;
        updateViews();
    }
    drawScreen();
}

void Session::moveMarker(double u, double w) {
    const Component& comp = core_.models.current().components[std::size_t(core_.reference->component)];
    const Patch& p = comp.patches.patches[std::size_t(core_.reference->patch - 1)];
    core_.reference->u = std::clamp(u, p.u0, p.u1);
    core_.reference->w = std::clamp(w, p.w0, p.w1);
    drawOverlay();
    core_.message = "MARKER AT U = " + number(core_.reference->u) + " W = " + number(core_.reference->w);
    drawScreen();
}

void Session::recordPick(const PickedPatch& picked, const PickMeasure& measure) {
    if (!measure.surface || picked.patch < 1) return;  // recorded as it came
    // The view: the one the click was in, or the replayed pick's.
    int view = pickView_;
    const auto& history = core_.input->history();
    if (!history.empty())
        if (const auto* click = std::get_if<action::Pick>(&history.back().what))
            for (int v = 1; v <= (core_.fourViews ? 4 : 1); ++v)
                if (layout_.viewBox(v, core_.fourViews).contains(click->position)) view = v;
    if (view < 1) return;
    const Component& comp = core_.models.current().components.at(std::size_t(picked.component));
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

}  // namespace acsynt
