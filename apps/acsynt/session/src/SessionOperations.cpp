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
    if (!previewOnly && showNow_) showNow_();
    geom::curvemap::Placement placement = placement_;
    placement.reference = {reference_->u, reference_->w};
    placement.offset = 0.5;
    geom::curvemap::MapOptions options;
    options.tolerance = 2e-3;
    std::vector<std::string> names;
    if (curveModel_)
        for (const auto& part : curveModel_->parts) names.push_back(part.name);
    const ComponentMapping mapped = mapOnComponent(comp, curves_, names, placement, options);
    const geom::curvemap::MapResult& result = mapped.result;
    if (previewOnly) {
        previewMapping(mapped);
        return;
    }
    say("DRAWING MAPPED CURVE...");
    SessionState before = state();
    MappingRecord record;
    record.model = model.name;
    record.component = comp.name;
    record.curveFile = curveFile_;
    record.reference = *reference_;
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
            log_.push_back("mapping " + mapped.parts[i].name + ": " + issue);
    }
    mappings_.push_back(std::move(record));
    remember(std::move(before), "MAP CURVE " + curveFile_ + " ON " + comp.name);
    previewLines_.clear();
    previewClipped_.clear();
    previewLost_.clear();
    mappedSincePlaced_ = true;  // the mapped figure is shown with the model, without the placed curve
    style_.onlyComponent = style_.colourfulComponent = style_.highlightComponent = -1;
    modelPicture_.restyle(model, style_);
    drawOverlay();
    drawMapped(false);
    const auto& r = mappings_.back();
    say("MAPPED " + r.curveFile + " ON " + r.component + ": " + std::to_string(r.loops) + " LOOPS IN " +
        std::to_string(r.parts) + " PARTS" + partsNotice(r.partReports));
}

void Session::previewMapping(const ComponentMapping& mapped) {
    // Projection lines of the parts that map (yellow) or are clipped (orange); the placed outline
    // of a part that maps nothing (red), so that every part shows.
    previewLines_.clear();
    previewClipped_.clear();
    previewLost_.clear();
    std::size_t lines = 0;
    for (std::size_t i = 0; i < mapped.result.parts.size(); ++i) {
        const auto& part = mapped.result.parts[i];
        const PartOutcome outcome = mapped.parts[i].outcome;
        if (outcome == PartOutcome::Lost) {
            std::vector<glm::dvec3> outline;
            const geom::Curve& c = curves_[i];
            for (int k = 0; k <= 200; ++k)
                outline.push_back(mapped.result.frame.toModel(
                    geom::evaluate(c, c.domainStart() + (c.domainEnd() - c.domainStart()) * k / 200)));
            previewLost_.push_back(std::move(outline));
            continue;
        }
        auto& into = outcome == PartOutcome::Clipped ? previewClipped_ : previewLines_;
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

}  // namespace

void Session::reduce(int componentIndex, double tolerance, std::size_t count) {
    SessionState before = state();
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
    if (showNow_) showNow_();
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
    // The curves mapped on the original go with the reduced model: those on other components as
    // they are, those on the reduced one through their (u, w) onto its new surface (knot
    // removal keeps the parameters).
    std::size_t carried = 0, moved = 0;
    const std::size_t mappingCount = mappings_.size();
    for (std::size_t i = 0; i < mappingCount; ++i) {
        if (mappings_[i].model != record.model) continue;
        MappingRecord m = mappings_[i];
        m.model = record.reducedModel;
        if (m.component == record.component) {
            const auto domain = geom::curvemap::surfaceDomain(target.surface, target.closedU, target.closedW);
            for (std::size_t l = 0; l < m.uvPolylines.size(); ++l)
                for (std::size_t k = 0; k < m.uvPolylines[l].size(); ++k) {
                    const glm::dvec2 uv = domain.wrap(m.uvPolylines[l][k]);
                    m.polylines[l][k] = geom::evaluate(target.surface, uv.x, uv.y);
                }
            ++moved;
        }
        mappings_.push_back(std::move(m));
        ++carried;
    }
    if (carried > 0)
        log_.push_back("reduction: " + std::to_string(carried) + " mapped curves carried to " +
                       record.reducedModel);
    remember(std::move(before), "REDUCTION OF " + record.component);
    showModel();
    const std::string done = reductionDirection_ == "U"   ? "DATA REDUCTION IN U DIRECTION COMPLETE"
                             : reductionDirection_ == "W" ? "DATA REDUCTION IN W DIRECTION COMPLETE"
                                                          : "DATA REDUCTION IN U AND W DIRECTIONS COMPLETE";
    say(done + ": " + std::to_string(record.countUBefore * record.countWBefore) + " -> " +
        std::to_string(record.countUAfter * record.countWAfter) + " CONTROL POINTS, MAX ERROR " +
        number(record.maxError, 3) +
        (moved > 0 ? ", " + std::to_string(moved) + " MAPPED CURVES MOVED ONTO THE REDUCED SURFACE" : "") +
        fewerThanAsked(record));
}

}  // namespace acsynt
