// PHIGS PLUS representations of the bundle and pattern tables: SET ... REPRESENTATION PLUS, their
// inquiries (SET and REALIZED values) and the predefined ones, on the same tables as the plain
// functions (Representations.cpp): the core holds general colours.

#include "Inquiry.h"
#include "PlusBundleAccess.h"
#include "StoreBuffer.h"
#include "WorkstationAccess.h"
#include "phigs.h"

using namespace phigs;
using phigs::c::inquire;

namespace {

/// INQUIRE ... REPRESENTATION PLUS of table `table` into `rep` (NULL: nothing is written).
template <class Bundle, class Out>
void answerPlus(Pint ws_id, Pint index, const Pinq_type& type, Pint* err, Out* rep,
                BundleTable<Bundle> WorkstationTables::*table) {
    inquire(err, [&](Phigs& p) {
        const Bundle b = c::inquiredBundle(p, ws_id, index, type, table);
        if (rep) *rep = c::plusBundle(b);
    });
}

/// INQUIRE PREDEFINED ... REPRESENTATION PLUS: entry `index` (from 1) of the type's list `list`.
template <class Bundle, class Out>
void answerPredefinedPlus(Pint ws_type, Pint index, Pint* err, Out* rep,
                          std::vector<Bundle> PredefinedRepresentations::*list) {
    inquire(err, [&](Phigs&) {
        const Bundle& b =
            c::predefinedEntry(c::predefinedOf(ws_type).*list, index, 1, errors::BundleIndexBelowOne);
        if (rep) *rep = c::plusBundle(b);
    });
}

}  // namespace

extern "C" {

void pset_line_rep_plus(Pint ws_id, Pint index, const Pline_bundle_plus* rep) {
    c::onOpenWorkstation(Pfn_set_line_rep_plus, ws_id, [&](Workstation& ws) {
        const char* function = "SET POLYLINE REPRESENTATION PLUS";
        c::require(rep, function);
        ws.setPolylineRepresentation(index, c::coreBundle(*rep, function));
    });
}

void pset_marker_rep_plus(Pint ws_id, Pint index, const Pmarker_bundle_plus* rep) {
    c::onOpenWorkstation(Pfn_set_marker_rep_plus, ws_id, [&](Workstation& ws) {
        const char* function = "SET POLYMARKER REPRESENTATION PLUS";
        c::require(rep, function);
        ws.setPolymarkerRepresentation(index, c::coreBundle(*rep, function));
    });
}

void pset_text_rep_plus(Pint ws_id, Pint index, const Ptext_bundle_plus* rep) {
    c::onOpenWorkstation(Pfn_set_text_rep_plus, ws_id, [&](Workstation& ws) {
        const char* function = "SET TEXT REPRESENTATION PLUS";
        c::require(rep, function);
        ws.setTextRepresentation(index, c::coreBundle(*rep, function));
    });
}

void pset_int_rep_plus(Pint ws_id, Pint index, const Pint_bundle_plus* rep) {
    c::onOpenWorkstation(Pfn_set_int_rep_plus, ws_id, [&](Workstation& ws) {
        const char* function = "SET INTERIOR REPRESENTATION PLUS";
        c::require(rep, function);
        ws.setInteriorRepresentation(index, c::coreBundle(*rep, function));
    });
}

void pset_edge_rep_plus(Pint ws_id, Pint index, const Pedge_bundle_plus* rep) {
    c::onOpenWorkstation(Pfn_set_edge_rep_plus, ws_id, [&](Workstation& ws) {
        const char* function = "SET EDGE REPRESENTATION PLUS";
        c::require(rep, function);
        ws.setEdgeRepresentation(index, c::coreBundle(*rep, function));
    });
}

void pset_pat_rep_plus(Pint ws_id, Pint index, const Ppat_rep_plus* rep) {
    c::onOpenWorkstation(Pfn_set_pat_rep_plus, ws_id, [&](Workstation& ws) {
        const char* function = "SET PATTERN REPRESENTATION PLUS";
        c::require(rep, function);
        if (index < 1) throw Error(errors::PatternIndexBelowOne, function, "index " + std::to_string(index));
        ws.setPatternRepresentation(index, c::corePattern(*rep, function));
    });
}

void pinq_line_rep_plus(Pint ws_id, Pint index, Pinq_type type, Pint* err, Pline_bundle_plus* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPlus(ws_id, index, type, err, rep, &WorkstationTables::polylines);
}

void pinq_marker_rep_plus(Pint ws_id, Pint index, Pinq_type type, Pint* err, Pmarker_bundle_plus* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPlus(ws_id, index, type, err, rep, &WorkstationTables::polymarkers);
}

void pinq_text_rep_plus(Pint ws_id, Pint index, Pinq_type type, Pint* err, Ptext_bundle_plus* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPlus(ws_id, index, type, err, rep, &WorkstationTables::texts);
}

void pinq_int_rep_plus(Pint ws_id, Pint index, Pinq_type type, Pint* err, Pint_bundle_plus* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPlus(ws_id, index, type, err, rep, &WorkstationTables::interiors);
}

void pinq_edge_rep_plus(Pint ws_id, Pint index, Pinq_type type, Pint* err, Pedge_bundle_plus* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPlus(ws_id, index, type, err, rep, &WorkstationTables::edges);
}

void pinq_pat_rep_plus(Pint ws_id, Pint index, Pinq_type type, Pstore store, Pint* err, Ppat_rep_plus** rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    inquire(err, [&](Phigs& p) {
        const PatternRepresentation pattern = c::inquiredPattern(p, ws_id, index, type);
        Phigs_store& s = c::storeOf(store);
        c::require(rep, "INQUIRE PATTERN REPRESENTATION PLUS");
        *rep = c::answerPatternPlus(pattern, c::inquiredWorkstation(p, ws_id).tables().colours, s);
    });
}

void pinq_pred_line_rep_plus(Pint ws_type, Pint index, Pint* err, Pline_bundle_plus* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPredefinedPlus(ws_type, index, err, rep, &PredefinedRepresentations::polylines);
}

void pinq_pred_marker_rep_plus(Pint ws_type, Pint index, Pint* err, Pmarker_bundle_plus* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPredefinedPlus(ws_type, index, err, rep, &PredefinedRepresentations::polymarkers);
}

void pinq_pred_text_rep_plus(Pint ws_type, Pint index, Pint* err, Ptext_bundle_plus* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPredefinedPlus(ws_type, index, err, rep, &PredefinedRepresentations::texts);
}

void pinq_pred_int_rep_plus(Pint ws_type, Pint index, Pint* err, Pint_bundle_plus* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPredefinedPlus(ws_type, index, err, rep, &PredefinedRepresentations::interiors);
}

void pinq_pred_edge_rep_plus(Pint ws_type, Pint index, Pint* err, Pedge_bundle_plus* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPredefinedPlus(ws_type, index, err, rep, &PredefinedRepresentations::edges);
}

void pinq_pred_pat_rep_plus(Pint ws_type, Pint index, Pstore store, Pint* err, Ppat_rep_plus** rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    inquire(err, [&](Phigs&) {
        const PatternRepresentation& pattern =
            c::predefinedEntry(c::predefinedOf(ws_type).patterns, index, 1, errors::PatternIndexBelowOne);
        Phigs_store& s = c::storeOf(store);
        c::require(rep, "INQUIRE PREDEFINED PATTERN REPRESENTATION PLUS");
        *rep = c::answerPatternPlus(pattern, ColourTable{}, s);  // the predefined colours
    });
}

}  // extern "C"
