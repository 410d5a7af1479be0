#include "Binding.h"

namespace phigs::c {

// ISO 9592 lists one state error for each function: the one whose required operating state it
// names. While PHIGS is closed every requirement fails, and a function reports its own.
int closedStateError(int function) {
    switch (function) {
        case Pfn_close_phigs:
            return errors::NotAllClosed;  // (PHOP, WSCL, STCL, ARCL)
        case Pfn_open_struct:
            return errors::NotStructureClosed;  // (PHOP, *, STCL, *)
        case Pfn_close_struct:
        case Pfn_exec_struct:
        case Pfn_label:
        case Pfn_appl_data:
        case Pfn_gse:
        case Pfn_copy_all_elems_struct:
        case Pfn_set_elem_ptr:
        case Pfn_offset_elem_ptr:
        case Pfn_set_elem_ptr_label:
        case Pfn_del_elem:
        case Pfn_del_elem_range:
        case Pfn_del_elems_labels:
        case Pfn_set_pick_id:
            return errors::NotStructureOpen;  // (PHOP, *, STOP, *)
        case Pfn_close_ar_file:
        case Pfn_ar_structs:
        case Pfn_ar_struct_nets:
        case Pfn_ar_all_structs:
        case Pfn_ret_struct_ids:
        case Pfn_ret_structs:
        case Pfn_ret_struct_nets:
        case Pfn_ret_all_structs:
        case Pfn_ret_paths_ances:
        case Pfn_ret_paths_descs:
        case Pfn_del_structs_ar:
        case Pfn_del_struct_nets_ar:
        case Pfn_del_all_structs_ar:
            return errors::NoArchiveOpen;  // (PHOP, *, *, AROP)
        case Pfn_close_ws:
        case Pfn_redraw_all_structs:
        case Pfn_upd_ws:
        case Pfn_set_disp_upd_st:
        case Pfn_message:
        case Pfn_set_view_rep3:
        case Pfn_set_view_rep:
        case Pfn_set_view_tran_in_pri:
        case Pfn_set_ws_win3:
        case Pfn_set_ws_win:
        case Pfn_set_ws_vp3:
        case Pfn_set_ws_vp:
        case Pfn_post_struct:
        case Pfn_unpost_struct:
        case Pfn_unpost_all_structs:
        case Pfn_set_hlhsr_mode:
        case Pfn_set_light_src_rep:
        case Pfn_set_dcue_rep:
        case Pfn_set_colr_map_rep:
        case Pfn_write_item:
        case Pfn_get_item_type:
        case Pfn_read_item:
            return errors::NoWorkstationOpen;  // (PHOP, WSOP, *, *)
        default:
            break;
    }
    // The workstation tables, filters and input (SET ... REPRESENTATION [PLUS], SET ... FILTER,
    // SET COLOUR MODEL, INITIALIZE, SET MODE, REQUEST, SAMPLE, AWAIT EVENT, FLUSH, GET): WSOP.
    if ((function >= Pfn_set_line_rep && function <= Pfn_set_colr_model) ||
        (function >= Pfn_set_pick_filter && function <= Pfn_get_string) ||
        (function >= Pfn_set_line_rep_plus && function <= Pfn_set_pat_rep_plus))
        return errors::NoWorkstationOpen;
    // Output primitives and attributes, PHIGS's (POLYLINE 3 to SET INDIVIDUAL ASF, SET HLHSR
    // IDENTIFIER to SET VIEW INDEX) and PHIGS PLUS's (301 on, but for the representations above):
    // elements of the open structure.
    if ((function >= Pfn_polyline3 && function <= Pfn_set_indiv_asf) ||
        (function >= Pfn_set_hlhsr_id && function <= Pfn_set_view_ind && function != Pfn_set_hlhsr_mode) ||
        (function >= Pfn_polyline_set3_data && function <= Pfn_set_colr_map_ind))
        return errors::NotStructureOpen;
    return errors::NotPhigsOpen;  // (PHOP, *, *, *)
}

Phigs& closedStateProbe() {
    static Phigs* probe = [] {
        auto* p = new Phigs;  // never freed: it may be asked during static destruction
        p->open();
        return p;
    }();
    probe->errorLog().clear();
    return *probe;
}

}  // namespace phigs::c
