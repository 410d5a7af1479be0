// What a session script adds to the devices' input (the directives: snapshot, summary,
// hardcopy, pick_surface, view, undo, redo), the text summary and the recording.
#include "acsynt/session/Session.h"

#include "SessionShared.h"

#include "geom/Evaluate.h"
#include "phigs/input/ScriptInputSource.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace acsynt {

using namespace phigs;
using namespace session_detail;

namespace {

/// An action as a recording writes it: its script line, after a comment where the line reads
/// back as another action (a typed string loses the blanks at its ends); a line the script
/// would refuse (a control character, too long) kept only as a comment, which the replay skips.
std::string recordedLine(const InputAction& action) {
    const std::string line = ScriptInputSource::format(action);
    if (ScriptInputSource::readsBack(action)) return line + "\n";
    try {
        if (ScriptInputSource(line, "recording", Session::directives()).actions().size() == 1)
            return "# the next line does not hold the action exactly as the operator made it\n" + line + "\n";
    } catch (const ScriptError&) {
    }
    const std::string head = "# no script line holds this action: ";
    std::string shown = line.substr(0, ScriptInputSource::kMaxScriptLineLength - head.size());
    for (char& c : shown)
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t') c = '?';
    return head + shown + "\n";
}

/// `name` with `extension` (".png") added, unless it already ends in it (in any case).
std::string withExtension(const std::string& name, const std::string& extension) {
    const bool has =
        name.size() > extension.size() &&
        std::equal(extension.begin(), extension.end(), name.end() - std::ptrdiff_t(extension.size()),
                   [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
    return has ? name : name + extension;
}

}  // namespace

void Session::directive(const action::Directive& d, const InputAction& a) {
    // A directive fails as a menu command does: its line named, the session going on.
    reportingFailures([&] { applyDirective(d, a); });
    // Directives run inside one wait for input, several in a row: a script run stops at its first
    // failing line here too, before the next one runs (--keep-going carries on).
    if (core_.settings.stopAtFirstError && core_.failedLines > 0)
        throw InputExhausted(source_.position() + ": stopped at the first failing line");
}

void Session::applyDirective(const action::Directive& d, const InputAction& a) {
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
    if (d.name == "pick_nothing") {
        if (!d.arguments.empty()) {
            fail(where + ": '" + a.text + "': expected pick_nothing alone");
            return;
        }
        // A recorded miss is a miss on any screen (the pixel it was at may show the model there).
        handle(EventReport{core_.workstation->id(), InputClass::Pick, 1, PickMeasure{}, false});
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
        const auto file = outputPath(withExtension(d.arguments[0], ".png"));
        if (!snapshot_) {
            fail("NO PICTURE OUTPUT FOR SNAPSHOT " + d.arguments[0]);
            return;
        }
        picture();
        snapshot_(file);
        pictures_.push_back(file);
        core_.log.push_back("snapshot " + file.string());
    } else if (d.name == "hardcopy") {
        writeHardcopy(d.arguments[0]);
    } else if (d.name == "summary") {
        const auto file = outputPath(withExtension(d.arguments[0], ".txt"), true);
        std::ofstream out(file);
        if (!(out << summary()) || !out.flush()) throw std::runtime_error("CANNOT WRITE " + file.string());
        noteSaved(file);
        core_.log.push_back("summary " + file.string());
    }
}

// ---- reports

std::string Session::summary() const {
    std::ostringstream out;
    out.precision(10);
    out << "ACSYNT session summary\n";
    for (std::size_t i = 0; i < core_.models.size(); ++i) {
        const Model& m = core_.models.at(i);
        out << "model " << m.name << (i == core_.models.currentIndex() ? " (current)" : "") << ": "
            << m.components.size() << " components, " << m.patchCount() << " patches\n";
    }
    static const std::vector<Component> none;
    const std::vector<Component>& components =
        core_.models.empty() ? none : core_.models.current().components;
    if (core_.lastPick && std::size_t(core_.lastPick->component) < components.size()) {
        out << "last pick: " << components[std::size_t(core_.lastPick->component)].name << " patch "
            << core_.lastPick->patch;
        if (core_.lastPickDetail)
            out << " at u " << core_.lastPickDetail->uv.x << " w " << core_.lastPickDetail->uv.y;
        out << "\n";
    }
    if (core_.reference && std::size_t(core_.reference->component) < components.size()) {
        const Component& c = components[std::size_t(core_.reference->component)];
        out << "reference point: " << c.name << " patch " << core_.reference->patch << " u "
            << core_.reference->u << " w " << core_.reference->w << "\n";
    }
    for (std::size_t i = 0; i < core_.mappings.size(); ++i) {
        const MappingRecord& m = core_.mappings[i];
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
    for (std::size_t i = 0; i < core_.reductions.size(); ++i) {
        const ReductionRecord& r = core_.reductions[i];
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
    out << "message: " << core_.message << "\n";
    return out.str();
}

void Session::recordAs(std::string line, std::string comment) {
    if (!core_.input || core_.input->history().empty()) return;
    recordedAs_[core_.input->history().size() - 1] = {std::move(line), std::move(comment)};
}

std::string Session::recording() const {
    std::string out = "# acsynt session recorded on a " + std::to_string(layout_.width) + " x " +
                      std::to_string(layout_.height) +
                      " screen: menu rows and pad buttons by name, picks on surfaces by component,\n"
                      "# patch and (u, w), replayed where that point shows then\n";
    const auto& history = core_.input->history();
    auto extra = extraLines_.begin();
    for (std::size_t i = 0; i <= history.size(); ++i) {
        for (; extra != extraLines_.end() && extra->first <= i; ++extra) out += extra->second + "\n";
        if (i == history.size()) break;
        const auto it = recordedAs_.find(i);
        if (it == recordedAs_.end()) {
            out += recordedLine(history[i]);
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
    const int views = core_.fourViews ? 4 : 1;
    // The first field that is wrong, named.
    std::string wrong;
    if (!patch || *patch != std::floor(*patch) || *patch < 1)
        wrong = "PATCH '" + a[1] + "' IS NOT A WHOLE NUMBER FROM 1";
    else if (!u)
        wrong = "U '" + a[2] + "' IS NOT A NUMBER";
    else if (!w)
        wrong = "W '" + a[3] + "' IS NOT A NUMBER";
    else if (!view || *view != std::floor(*view) || *view < 1 || *view > views)
        wrong = "VIEW '" + a[4] + "' IS NOT 1.." + std::to_string(views);
    if (!wrong.empty()) {
        fail("BAD RECORDED PICK '" + line + "': " + wrong + " (COMPONENT PATCH U W VIEW)");
        return;
    }
    if (!requireModel()) return;
    const Model& model = core_.models.current();
    const auto comp = std::find_if(model.components.begin(), model.components.end(),
                                   [&](const Component& c) { return c.name == a[0]; });
    if (comp == model.components.end()) {
        fail("RECORDED PICK: MODEL " + model.name + " HAS NO COMPONENT " + a[0]);
        return;
    }
    if (*patch > double(comp->patches.size())) {
        fail("RECORDED PICK: " + a[0] + " HAS " + std::to_string(comp->patches.size()) + " PATCHES, NOT " +
             a[1]);
        return;
    }
    const geom::Surface& surface = comp->surface;
    if (!(*u >= surface.domainStartU() && *u <= surface.domainEndU() && *w >= surface.domainStartV() &&
          *w <= surface.domainEndV())) {
        fail("BAD RECORDED PICK '" + line + "': U AND W OF " + a[0] + " LIE IN [" +
             number(surface.domainStartU(), 6) + ", " + number(surface.domainEndU(), 6) + "] AND [" +
             number(surface.domainStartV(), 6) + ", " + number(surface.domainEndV(), 6) + "]");
        return;
    }
    const glm::dvec2 pixel = pixelOf(geom::evaluate(surface, *u, *w), int(*view));
    picture();
    PickMeasure measure = core_.workstation->measurer().pick(pixel, core_.input->device(InputClass::Pick, 1));
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
    handle(EventReport{core_.workstation->id(), InputClass::Pick, 1, measure, false});
    pickView_ = 0;
}

}  // namespace acsynt
