// The workstation description tables: what each workstation type (PWST_*) can do, its
// facilities, table sizes, dynamics and predefined representations, and the PHIGS description
// table's modelling clipping facilities.

#include "Inquiry.h"
#include "StoreBuffer.h"
#include "WorkstationAccess.h"
#include "phigs.h"

#include <cmath>
#include <numeric>

using namespace phigs;
using phigs::c::inquire;

namespace {

WorkstationDescription described(Pint ws_type) {
    return c::describedType(ws_type, "inquiry");
}

/// Answers the predefined bundle `index` (from 1) of `ws_type`'s table `table` into `rep`.
template <class T, class Bundle>
void answerPredefinedBundle(Pint ws_type, std::vector<T> PredefinedRepresentations::*table, Pint index,
                            Pint* err, Bundle* rep) {
    inquire(err, [&](Phigs&) {
        const T& b =
            c::predefinedEntry(c::predefinedOf(ws_type).*table, index, 1, errors::BundleIndexBelowOne);
        if (rep) *rep = c::cBundle(b);
    });
}

Pfloat real(double v) {
    return static_cast<Pfloat>(v);
}

}  // namespace

extern "C" {

void pinq_ws_class(Pint ws_type, Pint* err, Pws_class* ws_class) {
    if (!c::somewhereToAnswer(err, ws_class)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        if (ws_class) *ws_class = static_cast<Pws_class>(d.workstationClass);
    });
}

void pinq_disp_space_size3(Pint ws_type, Pint* err, Pdisp_space_size3* size) {
    if (!c::somewhereToAnswer(err, size)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        if (!size) return;
        // Device coordinates are pixels (raster types) or points (vector types): PDC_OTHER.
        size->dc_units = PDC_OTHER;
        size->size_dc = {real(d.displaySize.x), real(d.displaySize.y), 1.0f};
        size->size_raster = {static_cast<Pint>(std::lround(d.displaySize.x)),
                             static_cast<Pint>(std::lround(d.displaySize.y)), 1};
    });
}

void pinq_disp_space_size(Pint ws_type, Pint* err, Pdisp_space_size* size) {
    if (!c::somewhereToAnswer(err, size)) return;
    Pdisp_space_size3 size3{};
    pinq_disp_space_size3(ws_type, err, &size3);
    if (err && *err == 0 && size)
        *size = {size3.dc_units,
                 {size3.size_dc.size_x, size3.size_dc.size_y},
                 {size3.size_raster.size_x, size3.size_raster.size_y}};
}

void pinq_ws_st_table(Pint ws_type, Pint* err, Pws_tables* lengths) {
    if (!c::somewhereToAnswer(err, lengths)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        if (!lengths) return;
        const Pint b = d.bundleTableSize;
        *lengths = {b, b, b, b, b, d.patternTableSize, d.colourTableSize, d.viewTableSize};
    });
}

void pinq_num_disp_pris(Pint ws_type, Pint* err, Pint* num_pris) {
    if (!c::somewhereToAnswer(err, num_pris)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        if (num_pris) *num_pris = d.displayPriorities;
    });
}

void pinq_dyns_ws_attrs(Pint ws_type, Pint* err, Pdyns_ws_attrs* attrs) {
    if (!c::somewhereToAnswer(err, attrs)) return;
    inquire(err, [&](Phigs&) {
        const Pdyn_mod m = static_cast<Pdyn_mod>(described(ws_type).attributeDynamics);
        if (attrs) *attrs = {m, m, m, m, m, m, m, m, m, m, m, m};
    });
}

void pinq_dyns_structs(Pint ws_type, Pint* err, Pdyns_structs* dyns) {
    if (!c::somewhereToAnswer(err, dyns)) return;
    inquire(err, [&](Phigs&) {
        const Pdyn_mod m = static_cast<Pdyn_mod>(described(ws_type).structureDynamics);
        if (dyns) *dyns = {m, m, m, m, m};
    });
}

void pinq_line_facs(Pint ws_type, Pint length, Pint start, Pint* err, Pline_facs* facs, Pint* total) {
    if (!c::somewhereToAnswer(err, facs, total)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        c::answerList(c::oneTo(d.primitives.lineTypes), length, start, facs ? &facs->types : nullptr, total);
        if (!facs) return;
        facs->num_widths = 0;
        facs->nom_width = real(d.primitives.nominalLineWidth);
        facs->min_width = real(d.primitives.minLineWidth);
        facs->max_width = real(d.primitives.maxLineWidth);
        facs->num_pred_inds = c::countOf(predefinedRepresentations(d.type).polylines.size());
    });
}

void pinq_marker_facs(Pint ws_type, Pint length, Pint start, Pint* err, Pmarker_facs* facs, Pint* total) {
    if (!c::somewhereToAnswer(err, facs, total)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        c::answerList(c::oneTo(d.primitives.markerTypes), length, start, facs ? &facs->types : nullptr,
                      total);
        if (!facs) return;
        facs->num_sizes = 0;
        facs->nom_size = real(d.primitives.nominalMarkerSize);
        facs->min_size = real(d.primitives.minMarkerSize);
        facs->max_size = real(d.primitives.maxMarkerSize);
        facs->num_pred_inds = c::countOf(predefinedRepresentations(d.type).polymarkers.size());
    });
}

void pinq_text_facs(Pint ws_type, Pint length, Pint start, Pint* err, Ptext_facs* facs, Pint* total) {
    if (!c::somewhereToAnswer(err, facs, total)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        // Every font in every precision: pair i is font i / 3 + 1 in precision i % 3.
        std::vector<int> pairs(static_cast<std::size_t>(d.textFonts) * 3);
        std::iota(pairs.begin(), pairs.end(), 0);
        std::vector<Pint> room(
            static_cast<std::size_t>(std::clamp<Pint>(length, 0, c::countOf(pairs.size()))));
        Pint_list positions{0, room.data()};
        c::answerList(pairs, length, start, facs ? &positions : nullptr, total);
        if (!facs) return;
        if (positions.num_ints > 0) c::require(facs->font_precs, "INQUIRE TEXT FACILITIES");
        for (Pint i = 0; i < positions.num_ints; ++i)
            facs->font_precs[i] = {room[static_cast<std::size_t>(i)] / 3 + 1,
                                   static_cast<Ptext_prec>(room[static_cast<std::size_t>(i)] % 3)};
        facs->num_font_precs = positions.num_ints;
        facs->num_char_hts = facs->num_char_expans = 0;
        facs->min_char_ht = real(d.minCharHeight);
        facs->max_char_ht = real(d.maxCharHeight);
        facs->min_char_expan = real(d.minCharExpansion);
        facs->max_char_expan = real(d.maxCharExpansion);
        facs->num_pred_inds = c::countOf(predefinedRepresentations(d.type).texts.size());
    });
}

void pinq_int_facs(Pint ws_type, Pint length, Pint start, Pint* err, Pint_facs* facs, Pint* total) {
    if (!c::somewhereToAnswer(err, facs, total)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        c::answerList(c::oneTo(d.primitives.hatchStyles), length, start, facs ? &facs->hatch_styles : nullptr,
                      total);
        if (!facs) return;
        facs->num_int_styles = std::min(d.interiorStyles, 5);
        for (int i = 0; i < facs->num_int_styles; ++i) facs->int_styles[i] = static_cast<Pint_style>(i);
        facs->num_pred_inds = c::countOf(predefinedRepresentations(d.type).interiors.size());
    });
}

void pinq_edge_facs(Pint ws_type, Pint length, Pint start, Pint* err, Pedge_facs* facs, Pint* total) {
    if (!c::somewhereToAnswer(err, facs, total)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        c::answerList(c::oneTo(d.primitives.lineTypes), length, start, facs ? &facs->types : nullptr, total);
        if (!facs) return;
        facs->num_widths = 0;
        facs->nom_width = real(d.primitives.nominalLineWidth);
        facs->min_width = real(d.primitives.minLineWidth);
        facs->max_width = real(d.primitives.maxLineWidth);
        facs->num_pred_inds = c::countOf(predefinedRepresentations(d.type).edges.size());
    });
}

void pinq_pat_facs(Pint ws_type, Pint* err, Pint* num_pred_inds) {
    if (!c::somewhereToAnswer(err, num_pred_inds)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        if (num_pred_inds) *num_pred_inds = c::countOf(predefinedRepresentations(d.type).patterns.size());
    });
}

void pinq_colr_facs(Pint ws_type, Pint* err, Pcolr_facs* facs) {
    if (!c::somewhereToAnswer(err, facs)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        if (facs) *facs = {0, PAVAIL_COLR, c::countOf(predefinedRepresentations(d.type).colours.size())};
    });
}

void pinq_colr_model_facs(Pint ws_type, Pint length, Pint start, Pint* err, Pint_list* models, Pint* total,
                          Pint* def_model) {
    if (!c::somewhereToAnswer(err, models, total, def_model)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        c::answerList(d.colourModels, length, start, models, total);
        if (def_model) *def_model = d.colourModels.front();
    });
}

void pinq_view_facs(Pint ws_type, Pint* err, Pint* num_pred_views) {
    if (!c::somewhereToAnswer(err, num_pred_views)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        if (num_pred_views) *num_pred_views = c::countOf(predefinedRepresentations(d.type).views.size());
    });
}

void pinq_hlhsr_id_facs(Pint ws_type, Pint length, Pint start, Pint* err, Pint_list* ids, Pint* total) {
    if (!c::somewhereToAnswer(err, ids, total)) return;
    inquire(err, [&](Phigs&) {
        described(ws_type);
        c::answerList({0, 1}, length, start, ids, total);  // 0 disables, 1 enables hidden-surface removal
    });
}

void pinq_hlhsr_mode_facs(Pint ws_type, Pint length, Pint start, Pint* err, Pint_list* modes, Pint* total) {
    if (!c::somewhereToAnswer(err, modes, total)) return;
    inquire(err, [&](Phigs&) { c::answerList(described(ws_type).hlhsrModes, length, start, modes, total); });
}

void pinq_anno_facs(Pint ws_type, Pint length, Pint start, Pint* err, Pint_list* styles, Pint* total,
                    Pint* num_char_hts, Pfloat* min_char_ht, Pfloat* max_char_ht) {
    if (!c::somewhereToAnswer(err, styles, total, num_char_hts, min_char_ht, max_char_ht)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = described(ws_type);
        c::answerList({PANNO_STYLE_UNCONNECTED, PANNO_STYLE_LEAD_LINE}, length, start, styles, total);
        if (num_char_hts) *num_char_hts = 0;
        if (min_char_ht) *min_char_ht = real(d.minCharHeight);
        if (max_char_ht) *max_char_ht = real(d.maxCharHeight);
    });
}

void pinq_model_clip_facs(Pint length, Pint start, Pint* err, Pint* num_planes, Pint_list* ops, Pint* total) {
    if (!c::somewhereToAnswer(err, num_planes, ops, total)) return;
    inquire(err, [&](Phigs&) {
        c::answerList({PMC_REPLACE, PMC_INTERSECT}, length, start, ops, total);
        if (num_planes) *num_planes = 64;  // the raster types' limit of distinct half-spaces in a picture
    });
}

void pinq_pred_line_rep(Pint ws_type, Pint index, Pint* err, Pline_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPredefinedBundle(ws_type, &PredefinedRepresentations::polylines, index, err, rep);
}

void pinq_pred_marker_rep(Pint ws_type, Pint index, Pint* err, Pmarker_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPredefinedBundle(ws_type, &PredefinedRepresentations::polymarkers, index, err, rep);
}

void pinq_pred_text_rep(Pint ws_type, Pint index, Pint* err, Ptext_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPredefinedBundle(ws_type, &PredefinedRepresentations::texts, index, err, rep);
}

void pinq_pred_int_rep(Pint ws_type, Pint index, Pint* err, Pint_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPredefinedBundle(ws_type, &PredefinedRepresentations::interiors, index, err, rep);
}

void pinq_pred_edge_rep(Pint ws_type, Pint index, Pint* err, Pedge_bundle* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    answerPredefinedBundle(ws_type, &PredefinedRepresentations::edges, index, err, rep);
}

void pinq_pred_pat_rep(Pint ws_type, Pint index, Pstore store, Pint* err, Ppat_rep** rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    inquire(err, [&](Phigs&) {
        const auto& p =
            c::predefinedEntry(c::predefinedOf(ws_type).patterns, index, 1, errors::PatternIndexBelowOne);
        Phigs_store& s = c::storeOf(store);
        c::require(rep, "INQUIRE PREDEFINED PATTERN REPRESENTATION");
        *rep = c::answerPattern(p, s);
    });
}

void pinq_pred_colr_rep(Pint ws_type, Pint index, Pint* err, Pcolr_rep* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    inquire(err, [&](Phigs&) {
        const auto& rgb =
            c::predefinedEntry(c::predefinedOf(ws_type).colours, index, 0, errors::ColourIndexBelowZero);
        if (rep) *rep = c::cColour(rgb);
    });
}

void pinq_pred_view_rep(Pint ws_type, Pint index, Pint* err, Pview_rep3* rep) {
    if (!c::somewhereToAnswer(err, rep)) return;
    inquire(err, [&](Phigs&) {
        const auto& v =
            c::predefinedEntry(c::predefinedOf(ws_type).views, index, 0, errors::ViewIndexBelowZero);
        if (rep) *rep = c::viewRep3(v);
    });
}

}  // extern "C"
