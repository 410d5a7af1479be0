// The session's two geometric operations: MAP CURVE (and its preview) and SURF_REDN.
#include "acsynt/session/Session.h"

#include "SessionShared.h"

#include "acsynt/ModelFile.h"
#include "geom/DataReduction.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
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
            record.uvPolylines.push_back(loop.uv);
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
    showModel();
    const std::string done = reductionDirection_ == "U"   ? "DATA REDUCTION IN U DIRECTION COMPLETE"
                             : reductionDirection_ == "W" ? "DATA REDUCTION IN W DIRECTION COMPLETE"
                                                          : "DATA REDUCTION IN U AND W DIRECTIONS COMPLETE";
    say(done + ": " + std::to_string(record.countUBefore * record.countWBefore) + " -> " +
        std::to_string(record.countUAfter * record.countWAfter) + " CONTROL POINTS, MAX ERROR " +
        number(record.maxError, 3));
}

}  // namespace acsynt
