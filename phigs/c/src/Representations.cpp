// Representations: the polyline, polymarker, text, interior, edge, pattern and colour tables
// of a workstation, its colour model, and their inquiries (SET and REALIZED values).

#include "Inquiry.h"
#include "StoreBuffer.h"
#include "WorkstationAccess.h"
#include "phigs.h"
#include "phigs/ws/Realization.h"
#include "phigs/ws/WorkstationErrors.h"

using namespace phigs;
using phigs::c::inquire;

namespace {

/// INQUIRE ... REPRESENTATION of table `table` into `rep` (NULL: nothing is written).
template <class Bundle, class Out>
void answerBundle(Pint ws_id, Pint index, const Pinq_type& type, Pint* err, Out* rep,
                  BundleTable<Bundle> WorkstationTables::*table) {
    inquire(err, [&](Phigs& p) {
        const Bundle b = c::inquiredBundle(p, ws_id, index, type, table);
        if (rep) *rep = c::cBundle(b);
    });
}

/// INQUIRE LIST OF ... INDICES: the defined indices of one table, ascending.
template <class Indices>
void answerIndices(Pint ws_id, Pint length, Pint start, Pint* err, Pint_list* inds, Pint* total,
                   Indices&& of) {
    inquire(err, [&](Phigs& p) {
        c::answerList(of(c::inquiredWorkstation(p, ws_id)), length, start, inds, total);
    });
}

}  // namespace

extern "C" {

void pset_line_rep(Pint ws_id, Pint index, const Pline_bundle* b) {
    c::onOpenWorkstation(Pfn_set_line_rep, ws_id, [&](Workstation& ws) {
        c::require(b, "SET POLYLINE REPRESENTATION");
        ws.setPolylineRepresentation(index, c::coreBundle(*b));
    });
}

void pset_marker_rep(Pint ws_id, Pint index, const Pmarker_bundle* b) {
    c::onOpenWorkstation(Pfn_set_marker_rep, ws_id, [&](Workstation& ws) {
        c::require(b, "SET POLYMARKER REPRESENTATION");
        ws.setPolymarkerRepresentation(index, c::coreBundle(*b));
    });
}

void pset_text_rep(Pint ws_id, Pint index, const Ptext_bundle* b) {
    c::onOpenWorkstation(Pfn_set_text_rep, ws_id, [&](Workstation& ws) {
        const char* function = "SET TEXT REPRESENTATION";
        c::require(b, function);
        ws.setTextRepresentation(index, c::coreBundle(*b, function));
    });
}

void pset_int_rep(Pint ws_id, Pint index, const Pint_bundle* b) {
    c::onOpenWorkstation(Pfn_set_int_rep, ws_id, [&](Workstation& ws) {
        const char* function = "SET INTERIOR REPRESENTATION";
        c::require(b, function);
        ws.setInteriorRepresentation(index, c::coreBundle(*b, function));
    });
}

void pset_edge_rep(Pint ws_id, Pint index, const Pedge_bundle* b) {
    c::onOpenWorkstation(Pfn_set_edge_rep, ws_id, [&](Workstation& ws) {
        const char* function = "SET EDGE REPRESENTATION";
        c::require(b, function);
        ws.setEdgeRepresentation(index, c::coreBundle(*b, function));
    });
}

void pset_pat_rep(Pint ws_id, Pint index, const Ppat_rep* rep) {
    c::onOpenWorkstation(Pfn_set_pat_rep, ws_id, [&](Workstation& ws) {
        const char* function = "SET PATTERN REPRESENTATION";
        c::require(rep, function);
        if (index < 1) throw Error(errors::PatternIndexBelowOne, function, "index " + std::to_string(index));
        ws.setPatternRepresentation(index, c::corePattern(*rep, function));
    });
}

void pset_colr_rep(Pint ws_id, Pint index, const Pcolr_rep* rep) {
    c::onOpenWorkstation(Pfn_set_colr_rep, ws_id, [&](Workstation& ws) {
        c::require(rep, "SET COLOUR REPRESENTATION");
        ws.setColourRepresentation(index, c::colourComponents(*rep, ws.colourModel()));  // in its model
    });
}

void pset_colr_model(Pint ws_id, Pint model) {
    c::onOpenWorkstation(Pfn_set_colr_model, ws_id, [&](Workstation& ws) { ws.setColourModel(model); });
}

void pinq_line_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err, Pline_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerBundle(ws_id, index, type, err, rep, &WorkstationTables::polylines);
}

void pinq_marker_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err, Pmarker_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerBundle(ws_id, index, type, err, rep, &WorkstationTables::polymarkers);
}

void pinq_text_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err, Ptext_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerBundle(ws_id, index, type, err, rep, &WorkstationTables::texts);
}

void pinq_int_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err, Pint_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerBundle(ws_id, index, type, err, rep, &WorkstationTables::interiors);
}

void pinq_edge_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err, Pedge_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerBundle(ws_id, index, type, err, rep, &WorkstationTables::edges);
}

void pinq_pat_rep(Pint ws_id, Pint index, Pinq_type type, Pstore store, Pint* err, Ppat_rep** rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    inquire(err, [&](Phigs& p) {
        const PatternRepresentation pattern = c::inquiredPattern(p, ws_id, index, type);
        Phigs_store& s = c::storeOf(store);
        c::require(rep, "INQUIRE PATTERN REPRESENTATION");
        *rep = c::answerPattern(pattern, s);
    });
}

void pinq_colr_rep(Pint ws_id, Pint index, Pinq_type type, Pint* err, Pcolr_rep* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    inquire(err, [&](Phigs& p) {
        const Workstation& ws = c::inquiredWorkstation(p, ws_id);
        if (index < 0) throw Error(errors::ColourIndexBelowZero, "inquiry", "index " + std::to_string(index));
        const bool realize = c::realizedWanted(type);
        const ColourTable& colours = ws.tables().colours;
        if (!colours.defined(index) && !realize)
            throw Error(errors::RepresentationNotDefined, "inquiry", "colour " + std::to_string(index));
        // In the workstation's current colour model: SET converts the entry from the model it was
        // given in (exact when the same), REALIZED the RGB drawn (clamped; an undefined index as 1).
        const auto model = static_cast<ColourModel>(ws.colourModel());
        const Colour given = colours.given(index);
        const glm::dvec3 v = realize                ? fromRgb(model, colours.get(index))
                             : given.model == model ? given.rgb
                                                    : fromRgb(model, toRgb(given.model, given.rgb));
        if (rep) *rep = c::cColour(v, ws.colourModel());
    });
}

void pinq_colr_model(Pint ws_id, Pint* err, Pint* model) {
    if (!c::somewhereToAnswer(err, model)) return;
    inquire(err, [&](Phigs& p) {
        const Workstation& ws = c::inquiredWorkstation(p, ws_id);
        if (model) *model = ws.colourModel();
    });
}

void pinq_list_line_inds(Pint ws_id, Pint length, Pint start, Pint* err, Pint_list* inds, Pint* total) {
    if (!c::somewhereToAnswer(err, inds, total)) return;
    answerIndices(ws_id, length, start, err, inds, total,
                  [](const Workstation& ws) { return ws.tables().polylines.definedIndices(); });
}

void pinq_list_marker_inds(Pint ws_id, Pint length, Pint start, Pint* err, Pint_list* inds, Pint* total) {
    if (!c::somewhereToAnswer(err, inds, total)) return;
    answerIndices(ws_id, length, start, err, inds, total,
                  [](const Workstation& ws) { return ws.tables().polymarkers.definedIndices(); });
}

void pinq_list_text_inds(Pint ws_id, Pint length, Pint start, Pint* err, Pint_list* inds, Pint* total) {
    if (!c::somewhereToAnswer(err, inds, total)) return;
    answerIndices(ws_id, length, start, err, inds, total,
                  [](const Workstation& ws) { return ws.tables().texts.definedIndices(); });
}

void pinq_list_int_inds(Pint ws_id, Pint length, Pint start, Pint* err, Pint_list* inds, Pint* total) {
    if (!c::somewhereToAnswer(err, inds, total)) return;
    answerIndices(ws_id, length, start, err, inds, total,
                  [](const Workstation& ws) { return ws.tables().interiors.definedIndices(); });
}

void pinq_list_edge_inds(Pint ws_id, Pint length, Pint start, Pint* err, Pint_list* inds, Pint* total) {
    if (!c::somewhereToAnswer(err, inds, total)) return;
    answerIndices(ws_id, length, start, err, inds, total,
                  [](const Workstation& ws) { return ws.tables().edges.definedIndices(); });
}

void pinq_list_pat_inds(Pint ws_id, Pint length, Pint start, Pint* err, Pint_list* inds, Pint* total) {
    if (!c::somewhereToAnswer(err, inds, total)) return;
    answerIndices(ws_id, length, start, err, inds, total,
                  [](const Workstation& ws) { return ws.patterns().definedIndices(); });
}

void pinq_list_colr_inds(Pint ws_id, Pint length, Pint start, Pint* err, Pint_list* inds, Pint* total) {
    if (!c::somewhereToAnswer(err, inds, total)) return;
    answerIndices(ws_id, length, start, err, inds, total,
                  [](const Workstation& ws) { return ws.tables().colours.definedIndices(); });
}

}  // extern "C"
