// The session's two geometric operations: MAP CURVE (and its preview) and SURF_REDN.
#include "acsynt/session/Session.h"

#include "SessionShared.h"

#include "acsynt/ModelFile.h"
#include "geom/DataReduction.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/curvemap/SurfaceDomain.h"
#include "phigs/core/Error.h"
#include "phigs/input/ScriptInputSource.h"
#include "phigs/view/ViewMatrices.h"
#include "phigs/ws/EchoStructures.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace acsynt {

using namespace phigs;
using namespace session_detail;

void Session::mapCurve(bool previewOnly) {
    if (core_.curves.empty()) {
        fail("NO CURVE LOADED: USE LOAD CURVE FIRST");
        return;
    }
    if (core_.reference && core_.phase == Phase::MoveMarker) {
        fail("THE REFERENCE POINT IS NOT PLACED: DONE ON THE POINTER PAD PLACES IT");
        return;
    }
    if (!core_.reference || core_.phase != Phase::Placed) {
        fail("NO REFERENCE POINT: USE DEFINE POINT AND DONE FIRST");
        return;
    }
    const Model& model = core_.models.current();
    const Component& comp = model.components[std::size_t(core_.reference->component)];
    if (!previewOnly) say("CALCULATING INTERSECTIONS, PLEASE WAIT...");
    if (!previewOnly && showNow_) showNow_();
    geom::curvemap::Placement placement = core_.placement;
    placement.reference = {core_.reference->u, core_.reference->w};
    placement.offset = 0.5;
    geom::curvemap::MapOptions options;
    options.tolerance = 2e-3;
    std::vector<std::string> names;
    if (core_.curveModel)
        for (const auto& part : core_.curveModel->parts) names.push_back(part.name);
    const ComponentMapping mapped = mapOnComponent(comp, core_.curves, names, placement, options);
    const geom::curvemap::MapResult& result = mapped.result;
    if (previewOnly) {
        previewMapping(mapped);
        return;
    }
    say("DRAWING MAPPED CURVE...");
    SessionState before = core_.state();
    MappingRecord record;
    record.model = model.name;
    record.component = comp.name;
    record.curveFile = core_.curveFile;
    record.reference = *core_.reference;
    record.parts = result.parts.size();
    record.partReports = mapped.parts;
    for (std::size_t i = 0; i < result.parts.size(); ++i) {
        const auto& part = result.parts[i];
        record.loopsPerPart.push_back(part.loops.size());
        record.loops += part.loops.size();
        for (const auto& loop : part.loops) {
            record.boundaryWalks += loop.boundaryWalks;
            record.polylines.push_back(loop.points);
            record.uvPolylines.push_back(loop.uv);
        }
        for (const auto& issue : part.issues)
            core_.log.push_back("mapping " + mapped.parts[i].name + ": " + issue);
    }
    core_.mappings.push_back(std::move(record));
    core_.remember(std::move(before), "MAP CURVE " + core_.curveFile + " ON " + comp.name);
    core_.previewLines.clear();
    core_.previewClipped.clear();
    core_.previewLost.clear();
    core_.mappedSincePlaced = true;  // the mapped figure is shown with the model, without the placed curve
    core_.style.onlyComponent = core_.style.colourfulComponent = core_.style.highlightComponent = -1;
    modelPicture_.restyle(model, core_.style);
    drawOverlay();
    drawMapped(false);
    const auto& r = core_.mappings.back();
    say("MAPPED " + r.curveFile + " ON " + r.component + ": " + std::to_string(r.loops) + " LOOPS IN " +
        std::to_string(r.parts) + " PARTS" + partsNotice(r.partReports));
}

void Session::previewMapping(const ComponentMapping& mapped) {
    // Projection lines of the parts that map (yellow) or are clipped (orange); the placed outline
    // of a part that maps nothing (red), so that every part shows.
    core_.previewLines.clear();
    core_.previewClipped.clear();
    core_.previewLost.clear();
    std::size_t lines = 0;
    for (std::size_t i = 0; i < mapped.result.parts.size(); ++i) {
        const auto& part = mapped.result.parts[i];
        const PartOutcome outcome = mapped.parts[i].outcome;
        if (outcome == PartOutcome::Lost) {
            std::vector<glm::dvec3> outline;
            const geom::Curve& c = core_.curves[i];
            for (int k = 0; k <= 200; ++k)
                outline.push_back(mapped.result.frame.toModel(
                    geom::evaluate(c, c.domainStart() + (c.domainEnd() - c.domainStart()) * k / 200)));
            core_.previewLost.push_back(std::move(outline));
            continue;
        }
        auto& into = outcome == PartOutcome::Clipped ? core_.previewClipped : core_.previewLines;
        for (const auto& loop : part.loops)
            for (std::size_t k = 0; k < loop.points.size();
                 k += std::max<std::size_t>(1, loop.points.size() / 24))
                if (!std::isnan(loop.curveParameters[k])) {
                    into.push_back({loop.projectedFrom[k], loop.points[k]});
                    ++lines;
                }
    }
    drawOverlay();
    say("MAP PREVIEW: " + std::to_string(lines) + " PROJECTION LINES" + partsNotice(mapped.parts));
}

// ---- SURF_REDN

namespace {

/// BY COUNT: what was removed in each direction asked for, when that is fewer than asked, and why.
std::string fewerThanAsked(const ReductionRecord& r) {
    if (r.mode != "count") return "";
    std::string out;
    const auto direction = [&](const char* name, std::size_t removed, std::size_t after) {
        if (removed >= r.count) return;
        // A cubic keeps at least 4 control points (no interior knot) across a direction.
        const std::string why = after <= 4 ? "NO INTERIOR KNOT LEFT" : "THE OTHERS ARE NOT REMOVABLE";
        out += "; ONLY " + std::to_string(removed) + " OF " + std::to_string(r.count) + " KNOTS REMOVED IN " +
               name + " (" + why + ")";
    };
    if (r.direction != "W") direction("U", r.removedU, r.countUAfter);
    if (r.direction != "U") direction("W", r.removedW, r.countWAfter);
    return out;
}

/// The curves mapped on the original go with the reduced model: those on other components as
/// they are, those on the reduced one through their (u, w) onto its new surface (knot removal
/// keeps the parameters), their reference points onto its patches. Returns how many were moved onto
/// the reduced surface.
std::size_t carryMappings(SessionCore& core, const ReductionRecord& record, const Component& target) {
    std::size_t carried = 0, moved = 0;
    const std::size_t mappingCount = core.mappings.size();
    for (std::size_t i = 0; i < mappingCount; ++i) {
        if (core.mappings[i].model != record.model) continue;
        MappingRecord m = core.mappings[i];
        m.model = record.reducedModel;
        // The reference point keeps its (u, w); its patch is the reduced surface's patch there
        // (removed knots merge patches, so the old number may name another patch or none).
        if (m.reference.patch > 0 && m.reference.component == record.componentIndex)
            if (const Patch* p = target.patches.find(m.reference.u, m.reference.w))
                m.reference.patch = p->number;
        if (m.component == record.component) {
            const auto domain = geom::curvemap::surfaceDomain(target.surface, target.closedU, target.closedW);
            for (std::size_t l = 0; l < m.uvPolylines.size(); ++l)
                for (std::size_t k = 0; k < m.uvPolylines[l].size(); ++k) {
                    const glm::dvec2 uv = domain.wrap(m.uvPolylines[l][k]);
                    m.polylines[l][k] = geom::evaluate(target.surface, uv.x, uv.y);
                }
            ++moved;
        }
        core.mappings.push_back(std::move(m));
        ++carried;
    }
    if (carried > 0)
        core.log.push_back("reduction: " + std::to_string(carried) + " mapped curves carried to " +
                           record.reducedModel);
    return moved;
}

}  // namespace

void Session::reduce(int componentIndex, double tolerance, std::size_t count) {
    SessionState before = core_.state();
    const Model& original = core_.models.current();
    const Component& comp = original.components.at(std::size_t(componentIndex));
    geom::ReductionOptions options;
    if (count > 0)
        options.maxRemovals = count;
    else
        options.tolerance = tolerance;
    const geom::ReductionDirection direction = core_.reductionDirection == "U" ? geom::ReductionDirection::U
                                               : core_.reductionDirection == "W"
                                                   ? geom::ReductionDirection::V
                                                   : geom::ReductionDirection::Both;
    // Knots in W run round each cross section; knots in U run along the component, across the
    // sections: removing one takes a section out.
    if (count > 0)
        say("REMOVE " + std::to_string(count) + " KNOTS " +
            (direction == geom::ReductionDirection::Both ? "IN U AND " + std::to_string(count) + " IN W"
             : direction == geom::ReductionDirection::V
                 ? std::string("FROM EACH CROSS SECTION")
                 : "IN U (" + std::to_string(count) + " CROSS SECTIONS FEWER)"));
    if (showNow_) showNow_();
    geom::SurfaceReduction reduced = geom::reduceSurface(comp.surface, direction, options);
    if (reduced.removedU == 0 && reduced.removedV == 0) {
        // Nothing to show for it: no new model, and no error (rounding) reported as a result.
        say(count > 0 ? "NO KNOT CAN BE REMOVED: THE MODEL IS UNCHANGED"
                      : "NO KNOT CAN BE REMOVED WITHIN " + number(tolerance, 3) + ": THE MODEL IS UNCHANGED");
        return;
    }
    PatchList patches = buildPatches(reduced.surface);  // may throw: nothing is changed yet

    ReductionRecord record;
    record.model = original.name;
    record.component = comp.name;
    record.componentIndex = componentIndex;
    record.direction = core_.reductionDirection;
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
    // Its name: NAME_Rn (REDUCED_n past 20 characters), n counting the reductions, or the next
    // one free (a model read back from a saved file may hold the name).
    std::string name;
    for (std::size_t n = core_.reductions.size() + 1; name.empty() || core_.models.contains(name); ++n) {
        name = original.name + "_R" + std::to_string(n);
        if (name.size() > 20) name = "REDUCED_" + std::to_string(n);
    }
    const auto copied = core_.models.copyCurrent(name);
    if (!copied.done) {
        fail(copied.message);
        return;
    }
    Component& target = core_.models.current().components[std::size_t(componentIndex)];
    target.surface = std::move(reduced.surface);
    target.patches = std::move(patches);
    record.reducedModel = core_.models.current().name;
    core_.reductions.push_back(record);
    const std::size_t moved = carryMappings(core_, record, target);
    core_.remember(std::move(before), "REDUCTION OF " + record.component);
    showModel();
    const std::string done = core_.reductionDirection == "U" ? "DATA REDUCTION IN U DIRECTION COMPLETE"
                             : core_.reductionDirection == "W"
                                 ? "DATA REDUCTION IN W DIRECTION COMPLETE"
                                 : "DATA REDUCTION IN U AND W DIRECTIONS COMPLETE";
    say(done + ": " + std::to_string(record.countUBefore * record.countWBefore) + " -> " +
        std::to_string(record.countUAfter * record.countWAfter) + " CONTROL POINTS, MAX ERROR " +
        number(record.maxError, 3) +
        (moved > 0 ? ", " + std::to_string(moved) + " MAPPED CURVES MOVED ONTO THE REDUCED SURFACE" : "") +
        fewerThanAsked(record));
}

}  // namespace acsynt
