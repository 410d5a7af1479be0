// Workstation state: deferral and modification modes, requested and current view
// representations, workstation transformation and HLHSR mode, view input priority, the
// highlighting and invisibility filters, and their inquiries.

#include "Inquiry.h"
#include "StoreBuffer.h"
#include "WorkstationAccess.h"
#include "phigs.h"

using namespace phigs;
using phigs::c::inquire;

namespace {

Pupd_st updateState(bool pending) {
    return pending ? PUPD_PEND : PUPD_NOT_PEND;
}

NameSetFilter filterOf(const Pfilter* filter, const char* function) {
    c::require(filter, function);
    const std::vector<int> in = c::ints(&filter->incl_set, function);
    const std::vector<int> out = c::ints(&filter->excl_set, function);
    return NameSetFilter{{in.begin(), in.end()}, {out.begin(), out.end()}};
}

void answerFilter(const std::optional<NameSetFilter>& filter, Pstore store, Pfilter** answer) {
    Phigs_store& s = c::storeOf(store);
    c::require(answer, "inquiry");
    s.clear();
    const NameSetFilter f = filter.value_or(NameSetFilter{});
    s.ints.assign(f.inclusion.begin(), f.inclusion.end());
    s.ints.insert(s.ints.end(), f.exclusion.begin(), f.exclusion.end());
    const Pint in = static_cast<Pint>(f.inclusion.size());
    s.filter.incl_set = {in, s.ints.data()};
    s.filter.excl_set = {static_cast<Pint>(f.exclusion.size()), s.ints.data() + in};
    *answer = &s.filter;
}

}  // namespace

extern "C" {

void pset_disp_upd_st(Pint ws_id, Pdefer_mode def_mode, Pmod_mode mod_mode) {
    c::onOpenWorkstation(Pfn_set_disp_upd_st, ws_id, [&](Workstation& ws) {
        const int d = c::raw(def_mode), m = c::raw(mod_mode);
        if (d < PDEFER_ASAP || d > PDEFER_WAIT || m < PMODE_NIVE || m > PMODE_UQUM)
            throw Error(PE_ENUM_TYPE_INVAL, "SET DISPLAY UPDATE STATE");
        ws.setDeferralState(static_cast<DeferralMode>(d), static_cast<ModificationMode>(m));
    });
}

void pinq_disp_upd_st(Pint ws_id, Pint* err, Pdefer_mode* def_mode, Pmod_mode* mod_mode,
                      Pdisp_surf_empty* disp_empty, Pvisual_st* state) {
    if (!c::somewhereToAnswer(err, def_mode, mod_mode, disp_empty, state)) return;
    inquire(err, [&](Phigs& p) {
        const Workstation& ws = c::inquiredWorkstation(p, ws_id);
        if (def_mode) *def_mode = static_cast<Pdefer_mode>(ws.deferralMode());
        if (mod_mode) *mod_mode = static_cast<Pmod_mode>(ws.modificationMode());
        if (disp_empty) *disp_empty = ws.surfaceEmpty() ? PSURF_EMPTY : PSURF_NOT_EMPTY;
        if (state) *state = static_cast<Pvisual_st>(ws.visualState());
    });
}

void pinq_def_disp_upd_st(Pint ws_type, Pint* err, Pdefer_mode* def_mode, Pmod_mode* mod_mode) {
    if (!c::somewhereToAnswer(err, def_mode, mod_mode)) return;
    inquire(err, [&](Phigs&) {
        const WorkstationDescription d = c::describedType(ws_type, "INQUIRE DEFAULT DISPLAY UPDATE STATE");
        if (def_mode) *def_mode = static_cast<Pdefer_mode>(d.defaultDeferral);
        if (mod_mode) *mod_mode = static_cast<Pmod_mode>(d.defaultModification);
    });
}

void pinq_view_rep(Pint ws_id, Pint view_ind, Pint* err, Pupd_st* upd_st, Pview_rep3* cur_rep,
                   Pview_rep3* req_rep) {
    if (!c::somewhereToAnswer(err, upd_st, cur_rep, req_rep)) return;
    inquire(err, [&](Phigs& p) {
        const Workstation& ws = c::inquiredWorkstation(p, ws_id);
        const char* function = "INQUIRE VIEW REPRESENTATION";
        if (view_ind < 0) throw Error(errors::ViewIndexBelowZero, function);
        const ViewTable& requested = ws.tables().views;
        const ViewTable& current = ws.current().views;
        if (!requested.defined(view_ind) && !current.defined(view_ind))
            throw Error(errors::RepresentationNotDefined, function, "view " + std::to_string(view_ind));
        if (upd_st) *upd_st = updateState(ws.viewUpdatePending(view_ind));
        if (cur_rep) *cur_rep = c::viewRep3(current.get(view_ind));
        if (req_rep) *req_rep = c::viewRep3(requested.get(view_ind));
    });
}

void pinq_ws_tran3(Pint ws_id, Pint* err, Pupd_st* upd_st, Plimit3* req_win, Plimit3* cur_win,
                   Plimit3* req_vp, Plimit3* cur_vp) {
    if (!c::somewhereToAnswer(err, upd_st, req_win, cur_win, req_vp, cur_vp)) return;
    inquire(err, [&](Phigs& p) {
        const Workstation& ws = c::inquiredWorkstation(p, ws_id);
        const WorkstationTables& r = ws.tables();
        const CurrentValues& cur = ws.current();
        if (upd_st) *upd_st = updateState(ws.transformationUpdatePending());
        if (req_win) *req_win = c::limit3(r.windowMin, r.windowMax);
        if (cur_win) *cur_win = c::limit3(cur.windowMin, cur.windowMax);
        if (req_vp) *req_vp = c::limit3(r.viewportMin, r.viewportMax);
        if (cur_vp) *cur_vp = c::limit3(cur.viewportMin, cur.viewportMax);
    });
}

void pinq_ws_tran(Pint ws_id, Pint* err, Pupd_st* upd_st, Plimit* req_win, Plimit* cur_win, Plimit* req_vp,
                  Plimit* cur_vp) {
    if (!c::somewhereToAnswer(err, upd_st, req_win, cur_win, req_vp, cur_vp)) return;
    inquire(err, [&](Phigs& p) {
        const Workstation& ws = c::inquiredWorkstation(p, ws_id);
        const WorkstationTables& r = ws.tables();
        const CurrentValues& cur = ws.current();
        if (upd_st) *upd_st = updateState(ws.transformationUpdatePending());
        if (req_win) *req_win = c::limit2(r.windowMin, r.windowMax);
        if (cur_win) *cur_win = c::limit2(cur.windowMin, cur.windowMax);
        if (req_vp) *req_vp = c::limit2(r.viewportMin, r.viewportMax);
        if (cur_vp) *cur_vp = c::limit2(cur.viewportMin, cur.viewportMax);
    });
}

void pset_hlhsr_mode(Pint ws_id, Pint hlhsr_mode) {
    c::onOpenWorkstation(Pfn_set_hlhsr_mode, ws_id, [&](Workstation& ws) { ws.setHlhsrMode(hlhsr_mode); });
}

void pinq_hlhsr_mode(Pint ws_id, Pint* err, Pupd_st* upd_st, Pint* cur_mode, Pint* req_mode) {
    if (!c::somewhereToAnswer(err, upd_st, cur_mode, req_mode)) return;
    inquire(err, [&](Phigs& p) {
        const Workstation& ws = c::inquiredWorkstation(p, ws_id);
        if (upd_st) *upd_st = updateState(ws.hlhsrUpdatePending());
        if (cur_mode) *cur_mode = ws.current().hlhsrMode;
        if (req_mode) *req_mode = ws.tables().hlhsrMode;
    });
}

void pset_view_tran_in_pri(Pint ws_id, Pint view_ind, Pint ref_view_ind, Prel_pri priority) {
    c::onOpenWorkstation(Pfn_set_view_tran_in_pri, ws_id, [&](Workstation& ws) {
        const int pri = c::raw(priority);
        if (pri != PPRI_HIGHER && pri != PPRI_LOWER)
            throw Error(PE_ENUM_TYPE_INVAL, "SET VIEW TRANSFORMATION INPUT PRIORITY");
        ws.setViewTransformationInputPriority(view_ind, ref_view_ind, pri == PPRI_HIGHER);
    });
}

void pinq_list_view_inds(Pint ws_id, Pint length, Pint start, Pint* err, Pint_list* inds, Pint* total) {
    if (!c::somewhereToAnswer(err, inds, total)) return;
    inquire(err, [&](Phigs& p) {
        c::answerList(c::inquiredWorkstation(p, ws_id).tables().views.inputPriority(), length, start, inds,
                      total);
    });
}

void pset_highl_filter(Pint ws_id, const Pfilter* filter) {
    c::onOpenWorkstation(Pfn_set_highl_filter, ws_id, [&](Workstation& ws) {
        ws.setHighlightingFilter(filterOf(filter, "SET HIGHLIGHTING FILTER"));
    });
}

void pset_invis_filter(Pint ws_id, const Pfilter* filter) {
    c::onOpenWorkstation(Pfn_set_invis_filter, ws_id, [&](Workstation& ws) {
        ws.setInvisibilityFilter(filterOf(filter, "SET INVISIBILITY FILTER"));
    });
}

void pinq_highl_filter(Pint ws_id, Pstore store, Pint* err, Pfilter** filter) {
    if (!c::somewhereToAnswer(err, filter)) return;
    inquire(err, [&](Phigs& p) {
        answerFilter(c::inquiredWorkstation(p, ws_id).filters().highlight, store, filter);
    });
}

void pinq_invis_filter(Pint ws_id, Pstore store, Pint* err, Pfilter** filter) {
    if (!c::somewhereToAnswer(err, filter)) return;
    inquire(err, [&](Phigs& p) {
        answerFilter(c::inquiredWorkstation(p, ws_id).filters().invisibility, store, filter);
    });
}

void pinq_wss_posted(Pint struct_id, Pint length, Pint start, Pint* err, Pint_list* ws_ids, Pint* total) {
    if (!c::somewhereToAnswer(err, ws_ids, total)) return;
    inquire(err, [&](Phigs& p) {
        c::answerList(p.workstationsPostedTo(struct_id), length, start, ws_ids, total);
    });
}

}  // extern "C"
