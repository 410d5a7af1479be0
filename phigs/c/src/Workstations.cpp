// Workstations: open and close on the types of phigs.h (PWST_*), posting, update and redraw,
// workstation window and viewport, view representations, and their inquiries.

#include "Binding.h"
#include "Conversions.h"
#include "Input.h"
#include "Inquiry.h"
#include "StoreBuffer.h"
#include "WorkstationAccess.h"
#include "phigs.h"

#include <algorithm>
#include <exception>

using phigs::c::Binding;

namespace {

using namespace phigs;

Pint cType(WorkstationType type) {
    return static_cast<Pint>(type) + PWST_OFFSCREEN;
}

/// INQUIRE GDP (3): the polyline attributes for a GDP the type draws, else error 64.
void answerGdpAttributes(const std::vector<int>& available, Pint gdp, Pint* count, Pattrs attrs[5]) {
    if (std::find(available.begin(), available.end(), gdp) == available.end())
        throw Error(errors::GdpNotAvailable, "inquiry", "GDP " + std::to_string(gdp));
    if (count) *count = 1;
    if (attrs) attrs[0] = PATTR_LINE;
}

/// Shows the workstation's picture on its target; a target that fails (a file that cannot be
/// written, a lost device) is error 903 naming the reason.
void show(Workstation& ws, const char* function) {
    try {
        ws.present();
    } catch (const Error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(errors::WriteError, function, "workstation " + std::to_string(ws.id()) + ": " + e.what());
    }
}

glm::dvec3 low(const Plimit3& l) {
    return {l.x_min, l.y_min, l.z_min};
}
glm::dvec3 high(const Plimit3& l) {
    return {l.x_max, l.y_max, l.z_max};
}

bool clips(const Pclip_ind& indicator, const char* function) {
    const int v = c::raw(indicator);
    if (v != PIND_NO_CLIP && v != PIND_CLIP) throw Error(PE_ENUM_TYPE_INVAL, function);
    return v == PIND_CLIP;
}

}  // namespace

extern "C" {

void popen_ws(Pint ws_id, const void* conn_id, Pint ws_type) {
    Binding::instance().call(Pfn_open_ws, [&](Phigs& p) {
        OutputConnection connection;
        // The binding's connection identifier is untyped; every type here takes a string.
        if (conn_id) connection.identifier = static_cast<const char*>(conn_id);
        // Error 52 names the type the program gave (a specific type opens as its generic type).
        p.openWorkstation(ws_id, c::workstationTypeOf(ws_type, "OPEN WORKSTATION"), connection);
        Binding::instance().specificType(ws_id);
    });
}

void pclose_ws(Pint ws_id) {
    Binding::instance().call(Pfn_close_ws, [&](Phigs& p) { p.closeWorkstation(ws_id); });
    // Its input script and device records go with it (also when its last picture failed).
    if (Phigs* p = Binding::instance().system(); p && !p->findWorkstation(ws_id)) {
        c::forgetInput(ws_id);
        Binding::instance().forgetSpecificType(ws_id);
    }
}

void ppost_struct(Pint ws_id, Pint struct_id, Pfloat priority) {
    c::onOpenWorkstation(Pfn_post_struct, ws_id,
                         [&](Workstation& ws) { ws.postStructure(struct_id, priority); });
}

void punpost_struct(Pint ws_id, Pint struct_id) {
    c::onOpenWorkstation(Pfn_unpost_struct, ws_id, [&](Workstation& ws) { ws.unpostStructure(struct_id); });
}

void punpost_all_structs(Pint ws_id) {
    c::onOpenWorkstation(Pfn_unpost_all_structs, ws_id, [&](Workstation& ws) { ws.unpostAllStructures(); });
}

void predraw_all_structs(Pint ws_id, Pctrl_flag ctrl_flag) {
    c::onOpenWorkstation(Pfn_redraw_all_structs, ws_id, [&](Workstation& ws) {
        const int flag = c::raw(ctrl_flag);
        if (flag != PFLAG_COND && flag != PFLAG_ALWAYS)
            throw Error(PE_ENUM_TYPE_INVAL, "REDRAW ALL STRUCTURES");
        ws.redrawAllStructures();
        show(ws, "REDRAW ALL STRUCTURES");
    });
}

void pupd_ws(Pint ws_id, Pregen_flag regen_flag) {
    c::onOpenWorkstation(Pfn_upd_ws, ws_id, [&](Workstation& ws) {
        const int flag = c::raw(regen_flag);
        if (flag != PFLAG_POSTPONE && flag != PFLAG_PERFORM)
            throw Error(PE_ENUM_TYPE_INVAL, "UPDATE WORKSTATION");
        if (flag == PFLAG_POSTPONE) return;
        ws.update(Regeneration::Perform);
        show(ws, "UPDATE WORKSTATION");
    });
}

void pset_ws_win3(Pint ws_id, const Plimit3* lim) {
    c::onOpenWorkstation(Pfn_set_ws_win3, ws_id, [&](Workstation& ws) {
        c::require(lim, "SET WORKSTATION WINDOW 3");
        ws.setWorkstationWindow(low(*lim), high(*lim));
    });
}

void pset_ws_win(Pint ws_id, const Plimit* lim) {
    c::onOpenWorkstation(Pfn_set_ws_win, ws_id, [&](Workstation& ws) {
        c::require(lim, "SET WORKSTATION WINDOW");
        const WorkstationTables& t = ws.tables();
        ws.setWorkstationWindow({lim->x_min, lim->y_min, t.windowMin.z},
                                {lim->x_max, lim->y_max, t.windowMax.z});
    });
}

void pset_ws_vp3(Pint ws_id, const Plimit3* lim) {
    c::onOpenWorkstation(Pfn_set_ws_vp3, ws_id, [&](Workstation& ws) {
        c::require(lim, "SET WORKSTATION VIEWPORT 3");
        ws.setWorkstationViewport(low(*lim), high(*lim));
    });
}

void pset_ws_vp(Pint ws_id, const Plimit* lim) {
    c::onOpenWorkstation(Pfn_set_ws_vp, ws_id, [&](Workstation& ws) {
        c::require(lim, "SET WORKSTATION VIEWPORT");
        const WorkstationTables& t = ws.tables();
        ws.setWorkstationViewport({lim->x_min, lim->y_min, t.viewportMin.z},
                                  {lim->x_max, lim->y_max, t.viewportMax.z});
    });
}

void pset_view_rep3(Pint ws_id, Pint view_ind, const Pview_rep3* rep) {
    c::onOpenWorkstation(Pfn_set_view_rep3, ws_id, [&](Workstation& ws) {
        const char* function = "SET VIEW REPRESENTATION 3";
        c::require(rep, function);
        ViewRepresentation view;
        Pview_rep3 copy = *rep;
        view.orientation = c::toGlm(copy.ori_matrix);
        view.mapping = c::toGlm(copy.map_matrix);
        view.clipMin = low(rep->clip_limit);
        view.clipMax = high(rep->clip_limit);
        view.clipXY = clips(rep->xy_clip, function);
        view.clipBack = clips(rep->back_clip, function);
        view.clipFront = clips(rep->front_clip, function);
        ws.setViewRepresentation(view_ind, view);
    });
}

void pset_view_rep(Pint ws_id, Pint view_ind, const Pview_rep* rep) {
    c::onOpenWorkstation(Pfn_set_view_rep, ws_id, [&](Workstation& ws) {
        const char* function = "SET VIEW REPRESENTATION";
        c::require(rep, function);
        ViewRepresentation view;
        Pview_rep copy = *rep;
        view.orientation = c::lift(c::toGlm(copy.ori_matrix));
        view.mapping = c::lift(c::toGlm(copy.map_matrix));
        view.clipMin = {rep->clip_limit.x_min, rep->clip_limit.y_min, 0.0};
        view.clipMax = {rep->clip_limit.x_max, rep->clip_limit.y_max, 1.0};
        view.clipXY = clips(rep->xy_clip, function);
        view.clipBack = view.clipFront = false;
        ws.setViewRepresentation(view_ind, view);
    });
}

void pinq_ws_st(Pws_st* ws_state) {
    if (!ws_state) return;
    Phigs* p = Binding::instance().system();
    *ws_state = p && p->anyWorkstationOpen() ? PWS_ST_WSOP : PWS_ST_WSCL;
}

void pinq_open_wss(Pint appl, Pint start, Pint* err, Pint_list* ids, Pint* total) {
    if (!c::somewhereToAnswer(err, ids, total)) return;
    c::inquire(err, [&](Phigs& p) { c::answerList(p.openWorkstationIds(), appl, start, ids, total); });
}

void pinq_ws_conn_type(Pint ws_id, Pstore store, Pint* err, void** conn_id, Pint* ws_type) {
    if (!c::somewhereToAnswer(err, conn_id, ws_type)) return;
    c::inquire(err, [&](Phigs& p) {
        Workstation& ws = c::inquiredWorkstation(p, ws_id);
        Phigs_store& s = c::storeOf(store);
        s.clear();
        s.text = ws.connectionIdentifier();
        if (conn_id) *conn_id = s.text.empty() ? nullptr : s.text.data();
        // The specific type: its description is this workstation's as it is now.
        if (ws_type) *ws_type = Binding::instance().specificType(ws_id);
    });
}

void pinq_posted_structs(Pint ws_id, Pint appl, Pint start, Pint* err, Pposted_struct_list* out,
                         Pint* total) {
    if (!c::somewhereToAnswer(err, out, total)) return;
    c::inquire(err, [&](Phigs& p) {
        const std::vector<PostedStructure> posted = c::inquiredWorkstation(p, ws_id).postedStructures();
        std::vector<int> order(posted.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
        // The simple list rules (2201, 2200, lengths) on the positions, then the postings copied.
        Pint_list positions{0, nullptr};
        std::vector<Pint> room(static_cast<std::size_t>(std::max<Pint>(appl, 0)));
        positions.ints = room.data();
        c::answerList(order, appl, start, out ? &positions : nullptr, total);
        if (!out) return;
        if (positions.num_ints > 0) c::require(out->postings, "INQUIRE POSTED STRUCTURES");
        for (Pint i = 0; i < positions.num_ints; ++i) {
            const PostedStructure& ps = posted[static_cast<std::size_t>(positions.ints[i])];
            out->postings[i] = {ps.structureId, static_cast<Pfloat>(ps.priority)};
        }
        out->num_postings = positions.num_ints;
    });
}

void pinq_list_avail_ws_types(Pint appl, Pint start, Pint* err, Pint_list* types, Pint* total) {
    if (!c::somewhereToAnswer(err, types, total)) return;
    c::inquire(err, [&](Phigs& p) {
        std::vector<int> available;
        for (WorkstationType type : p.outputs().types()) available.push_back(cType(type));
        c::answerList(available, appl, start, types, total);
    });
}

void pinq_list_avail_gdp3(Pint ws_type, Pint appl, Pint start, Pint* err, Pint_list* gdps, Pint* total) {
    if (!c::somewhereToAnswer(err, gdps, total)) return;
    c::inquire(err, [&](Phigs&) {
        const auto d = c::describedType(ws_type, "INQUIRE LIST OF AVAILABLE GDP 3");
        c::answerList(d.gdps3, appl, start, gdps, total);
    });
}

void pinq_list_avail_gdp(Pint ws_type, Pint appl, Pint start, Pint* err, Pint_list* gdps, Pint* total) {
    if (!c::somewhereToAnswer(err, gdps, total)) return;
    c::inquire(err, [&](Phigs&) {
        const auto d = c::describedType(ws_type, "INQUIRE LIST OF AVAILABLE GDP");
        c::answerList(d.gdps, appl, start, gdps, total);
    });
}

void pinq_gdp3(Pint ws_type, Pint gdp, Pint* err, Pint* num_attrs, Pattrs attrs[5]) {
    if (!c::somewhereToAnswer(err, num_attrs, attrs)) return;
    c::inquire(err, [&](Phigs&) {
        answerGdpAttributes(c::describedType(ws_type, "INQUIRE GDP 3").gdps3, gdp, num_attrs, attrs);
    });
}

void pinq_gdp(Pint ws_type, Pint gdp, Pint* err, Pint* num_attrs, Pattrs attrs[5]) {
    if (!c::somewhereToAnswer(err, num_attrs, attrs)) return;
    c::inquire(err, [&](Phigs&) {
        answerGdpAttributes(c::describedType(ws_type, "INQUIRE GDP").gdps, gdp, num_attrs, attrs);
    });
}

void pinq_list_avail_gse(Pint ws_type, Pint appl, Pint start, Pint* err, Pint_list* gses, Pint* total) {
    if (!c::somewhereToAnswer(err, gses, total)) return;
    c::inquire(err, [&](Phigs&) {
        const auto d = c::describedType(ws_type, "INQUIRE LIST OF AVAILABLE GSE");
        c::answerList(d.gses, appl, start, gses, total);
    });
}

void pinq_gse_facs(Pint ws_type, Pint appl, Pint start, Pint* err, Pgse_id_dep_list* gses, Pint* total) {
    if (!c::somewhereToAnswer(err, gses, total)) return;
    c::inquire(err, [&](Phigs&) {
        const auto d = c::describedType(ws_type, "INQUIRE GSE FACILITIES");
        std::vector<Pint> buffer(std::min(d.gses.size(), static_cast<std::size_t>(std::max<Pint>(appl, 0))));
        Pint_list ids{0, buffer.data()};
        c::answerList(d.gses, appl, start, gses ? &ids : nullptr, total);
        if (!gses) return;
        if (ids.num_ints > 0) c::require(gses->id_facs, "inquiry");
        for (Pint i = 0; i < ids.num_ints; ++i) gses->id_facs[i] = {ids.ints[i], PWS_INDEP};
        gses->num_id_facs = ids.num_ints;
    });
}

void pinq_ws_cat(Pint ws_type, Pint* err, Pws_cat* ws_cat) {
    if (!c::somewhereToAnswer(err, ws_cat)) return;
    c::inquire(err, [&](Phigs&) {
        const WorkstationDescription d = c::describedType(ws_type, "INQUIRE WORKSTATION CATEGORY");
        if (ws_cat) *ws_cat = d.category == WorkstationCategory::OutIn ? PCAT_OUTIN : PCAT_OUT;
    });
}

}  // extern "C"
