#include "Binding.h"

#include <map>

namespace phigs::c {

namespace {

const std::map<int, const char*>& names() {
    static const std::map<int, const char*> table = {
        {Pfn_open_phigs, "OPEN PHIGS"},
        {Pfn_close_phigs, "CLOSE PHIGS"},
        {Pfn_open_ws, "OPEN WORKSTATION"},
        {Pfn_close_ws, "CLOSE WORKSTATION"},
        {Pfn_redraw_all_structs, "REDRAW ALL STRUCTURES"},
        {Pfn_upd_ws, "UPDATE WORKSTATION"},
        {Pfn_set_view_rep3, "SET VIEW REPRESENTATION 3"},
        {Pfn_set_view_rep, "SET VIEW REPRESENTATION"},
        {Pfn_set_ws_win3, "SET WORKSTATION WINDOW 3"},
        {Pfn_set_ws_win, "SET WORKSTATION WINDOW"},
        {Pfn_set_ws_vp3, "SET WORKSTATION VIEWPORT 3"},
        {Pfn_set_ws_vp, "SET WORKSTATION VIEWPORT"},
        {Pfn_post_struct, "POST STRUCTURE"},
        {Pfn_unpost_struct, "UNPOST STRUCTURE"},
        {Pfn_unpost_all_structs, "UNPOST ALL STRUCTURES"},
        {Pfn_message, "MESSAGE"},
        {Pfn_polyline3, "POLYLINE 3"},
        {Pfn_polyline, "POLYLINE"},
        {Pfn_polymarker3, "POLYMARKER 3"},
        {Pfn_polymarker, "POLYMARKER"},
        {Pfn_text3, "TEXT 3"},
        {Pfn_text, "TEXT"},
        {Pfn_anno_text_rel3, "ANNOTATION TEXT RELATIVE 3"},
        {Pfn_anno_text_rel, "ANNOTATION TEXT RELATIVE"},
        {Pfn_fill_area3, "FILL AREA 3"},
        {Pfn_fill_area, "FILL AREA"},
        {Pfn_fill_area_set3, "FILL AREA SET 3"},
        {Pfn_fill_area_set, "FILL AREA SET"},
        {Pfn_cell_array3, "CELL ARRAY 3"},
        {Pfn_cell_array, "CELL ARRAY"},
        {Pfn_gdp3, "GENERALIZED DRAWING PRIMITIVE 3"},
        {Pfn_gdp, "GENERALIZED DRAWING PRIMITIVE"},
        {Pfn_set_line_ind, "SET POLYLINE INDEX"},
        {Pfn_set_marker_ind, "SET POLYMARKER INDEX"},
        {Pfn_set_text_ind, "SET TEXT INDEX"},
        {Pfn_set_int_ind, "SET INTERIOR INDEX"},
        {Pfn_set_edge_ind, "SET EDGE INDEX"},
        {Pfn_set_linetype, "SET LINETYPE"},
        {Pfn_set_linewidth, "SET LINEWIDTH SCALE FACTOR"},
        {Pfn_set_line_colr_ind, "SET POLYLINE COLOUR INDEX"},
        {Pfn_set_marker_type, "SET MARKER TYPE"},
        {Pfn_set_marker_size, "SET MARKER SIZE SCALE FACTOR"},
        {Pfn_set_marker_colr_ind, "SET POLYMARKER COLOUR INDEX"},
        {Pfn_set_text_font, "SET TEXT FONT"},
        {Pfn_set_text_prec, "SET TEXT PRECISION"},
        {Pfn_set_char_expan, "SET CHARACTER EXPANSION FACTOR"},
        {Pfn_set_char_space, "SET CHARACTER SPACING"},
        {Pfn_set_text_colr_ind, "SET TEXT COLOUR INDEX"},
        {Pfn_set_char_ht, "SET CHARACTER HEIGHT"},
        {Pfn_set_char_up_vec, "SET CHARACTER UP VECTOR"},
        {Pfn_set_text_path, "SET TEXT PATH"},
        {Pfn_set_text_align, "SET TEXT ALIGNMENT"},
        {Pfn_set_anno_char_ht, "SET ANNOTATION TEXT CHARACTER HEIGHT"},
        {Pfn_set_anno_char_up_vec, "SET ANNOTATION TEXT CHARACTER UP VECTOR"},
        {Pfn_set_anno_path, "SET ANNOTATION TEXT PATH"},
        {Pfn_set_anno_align, "SET ANNOTATION TEXT ALIGNMENT"},
        {Pfn_set_anno_style, "SET ANNOTATION STYLE"},
        {Pfn_set_int_style, "SET INTERIOR STYLE"},
        {Pfn_set_int_style_ind, "SET INTERIOR STYLE INDEX"},
        {Pfn_set_int_colr_ind, "SET INTERIOR COLOUR INDEX"},
        {Pfn_set_edge_flag, "SET EDGE FLAG"},
        {Pfn_set_edgetype, "SET EDGETYPE"},
        {Pfn_set_edgewidth, "SET EDGEWIDTH SCALE FACTOR"},
        {Pfn_set_edge_colr_ind, "SET EDGE COLOUR INDEX"},
        {Pfn_set_pat_size, "SET PATTERN SIZE"},
        {Pfn_set_pat_ref_point_vecs, "SET PATTERN REFERENCE POINT AND VECTORS"},
        {Pfn_set_pat_ref_point, "SET PATTERN REFERENCE POINT"},
        {Pfn_add_names_set, "ADD NAMES TO SET"},
        {Pfn_remove_names_set, "REMOVE NAMES FROM SET"},
        {Pfn_set_indiv_asf, "SET INDIVIDUAL ASF"},
        {Pfn_set_disp_upd_st, "SET DISPLAY UPDATE STATE"},
        {Pfn_set_line_rep, "SET POLYLINE REPRESENTATION"},
        {Pfn_set_marker_rep, "SET POLYMARKER REPRESENTATION"},
        {Pfn_set_text_rep, "SET TEXT REPRESENTATION"},
        {Pfn_set_int_rep, "SET INTERIOR REPRESENTATION"},
        {Pfn_set_edge_rep, "SET EDGE REPRESENTATION"},
        {Pfn_set_pat_rep, "SET PATTERN REPRESENTATION"},
        {Pfn_set_colr_rep, "SET COLOUR REPRESENTATION"},
        {Pfn_set_highl_filter, "SET HIGHLIGHTING FILTER"},
        {Pfn_set_invis_filter, "SET INVISIBILITY FILTER"},
        {Pfn_set_colr_model, "SET COLOUR MODEL"},
        {Pfn_set_hlhsr_mode, "SET HLHSR MODE"},
        {Pfn_set_view_tran_in_pri, "SET VIEW TRANSFORMATION INPUT PRIORITY"},
        {Pfn_set_hlhsr_id, "SET HLHSR IDENTIFIER"},
        {Pfn_set_local_tran3, "SET LOCAL TRANSFORMATION 3"},
        {Pfn_set_local_tran, "SET LOCAL TRANSFORMATION"},
        {Pfn_set_global_tran3, "SET GLOBAL TRANSFORMATION 3"},
        {Pfn_set_global_tran, "SET GLOBAL TRANSFORMATION"},
        {Pfn_set_model_clip_vol3, "SET MODELLING CLIPPING VOLUME 3"},
        {Pfn_set_model_clip_vol, "SET MODELLING CLIPPING VOLUME"},
        {Pfn_set_model_clip_ind, "SET MODELLING CLIPPING INDICATOR"},
        {Pfn_restore_model_clip_vol, "RESTORE MODELLING CLIPPING VOLUME"},
        {Pfn_set_view_ind, "SET VIEW INDEX"},
        {Pfn_open_struct, "OPEN STRUCTURE"},
        {Pfn_close_struct, "CLOSE STRUCTURE"},
        {Pfn_exec_struct, "EXECUTE STRUCTURE"},
        {Pfn_label, "LABEL"},
        {Pfn_appl_data, "APPLICATION DATA"},
        {Pfn_gse, "GENERALIZED STRUCTURE ELEMENT"},
        {Pfn_set_edit_mode, "SET EDIT MODE"},
        {Pfn_copy_all_elems_struct, "COPY ALL ELEMENTS FROM STRUCTURE"},
        {Pfn_set_elem_ptr, "SET ELEMENT POINTER"},
        {Pfn_offset_elem_ptr, "OFFSET ELEMENT POINTER"},
        {Pfn_set_elem_ptr_label, "SET ELEMENT POINTER AT LABEL"},
        {Pfn_del_elem, "DELETE ELEMENT"},
        {Pfn_del_elem_range, "DELETE ELEMENT RANGE"},
        {Pfn_del_elems_labels, "DELETE ELEMENTS BETWEEN LABELS"},
        {Pfn_empty_struct, "EMPTY STRUCTURE"},
        {Pfn_del_struct, "DELETE STRUCTURE"},
        {Pfn_del_struct_net, "DELETE STRUCTURE NETWORK"},
        {Pfn_del_all_structs, "DELETE ALL STRUCTURES"},
        {Pfn_change_struct_id, "CHANGE STRUCTURE IDENTIFIER"},
        {Pfn_change_struct_refs, "CHANGE STRUCTURE REFERENCES"},
        {Pfn_change_struct_id_refs, "CHANGE STRUCTURE IDENTIFIER AND REFERENCES"},
        {Pfn_open_ar_file, "OPEN ARCHIVE FILE"},
        {Pfn_close_ar_file, "CLOSE ARCHIVE FILE"},
        {Pfn_ar_structs, "ARCHIVE STRUCTURES"},
        {Pfn_ar_struct_nets, "ARCHIVE STRUCTURE NETWORKS"},
        {Pfn_ar_all_structs, "ARCHIVE ALL STRUCTURES"},
        {Pfn_set_conf_res, "SET CONFLICT RESOLUTION"},
        {Pfn_ret_struct_ids, "RETRIEVE STRUCTURE IDENTIFIERS"},
        {Pfn_ret_structs, "RETRIEVE STRUCTURES"},
        {Pfn_ret_struct_nets, "RETRIEVE STRUCTURE NETWORKS"},
        {Pfn_ret_all_structs, "RETRIEVE ALL STRUCTURES"},
        {Pfn_ret_paths_ances, "RETRIEVE PATHS TO ANCESTORS"},
        {Pfn_ret_paths_descs, "RETRIEVE PATHS TO DESCENDANTS"},
        {Pfn_del_structs_ar, "DELETE STRUCTURES FROM ARCHIVE"},
        {Pfn_del_struct_nets_ar, "DELETE STRUCTURE NETWORKS FROM ARCHIVE"},
        {Pfn_del_all_structs_ar, "DELETE ALL STRUCTURES FROM ARCHIVE"},
        {Pfn_set_pick_id, "SET PICK IDENTIFIER"},
        {Pfn_set_err_hand_mode, "SET ERROR HANDLING MODE"},
        {Pfn_escape, "ESCAPE"},
        {Pfn_line_colr, "SET POLYLINE COLOUR"},
        {Pfn_marker_colr, "SET POLYMARKER COLOUR"},
        {Pfn_text_colr, "SET TEXT COLOUR"},
        {Pfn_int_colr, "SET INTERIOR COLOUR"},
        {Pfn_edge_colr, "SET EDGE COLOUR"},
        {Pfn_write_item, "WRITE ITEM TO METAFILE"},
        {Pfn_get_item_type, "GET ITEM TYPE FROM METAFILE"},
        {Pfn_read_item, "READ ITEM FROM METAFILE"},
        {Pfn_interpret_item, "INTERPRET ITEM"},
        {Pfn_nuni_bsp_curv, "NON-UNIFORM B-SPLINE CURVE"},
        {Pfn_nuni_bsp_surf, "NON-UNIFORM B-SPLINE SURFACE"},
        {Pfn_set_line_shad_meth, "SET POLYLINE SHADING METHOD"},
        {Pfn_set_face_disting_mode, "SET FACE DISTINGUISHING MODE"},
        {Pfn_set_face_cull_mode, "SET FACE CULLING MODE"},
        {Pfn_set_int_shad_meth, "SET INTERIOR SHADING METHOD"},
        {Pfn_set_refl_props, "SET REFLECTANCE PROPERTIES"},
        {Pfn_set_refl_eqn, "SET REFLECTANCE EQUATION"},
        {Pfn_set_back_int_style, "SET BACK INTERIOR STYLE"},
        {Pfn_set_back_int_style_ind, "SET BACK INTERIOR STYLE INDEX"},
        {Pfn_set_back_int_colr, "SET BACK INTERIOR COLOUR"},
        {Pfn_set_back_int_shad_meth, "SET BACK INTERIOR SHADING METHOD"},
        {Pfn_set_back_refl_props, "SET BACK REFLECTANCE PROPERTIES"},
        {Pfn_set_back_refl_eqn, "SET BACK REFLECTANCE EQUATION"},
        {Pfn_set_light_src_state, "SET LIGHT SOURCE STATE"},
        {Pfn_set_curve_approx, "SET CURVE APPROXIMATION CRITERIA"},
        {Pfn_set_surf_approx, "SET SURFACE APPROXIMATION CRITERIA"},
        {Pfn_set_para_surf_characs, "SET PARAMETRIC SURFACE CHARACTERISTICS"},
        {Pfn_set_dcue_ind, "SET DEPTH CUE INDEX"},
        {Pfn_set_colr_map_ind, "SET COLOUR MAPPING INDEX"},
        {Pfn_set_line_rep_plus, "SET POLYLINE REPRESENTATION PLUS"},
        {Pfn_set_marker_rep_plus, "SET POLYMARKER REPRESENTATION PLUS"},
        {Pfn_set_text_rep_plus, "SET TEXT REPRESENTATION PLUS"},
        {Pfn_set_int_rep_plus, "SET INTERIOR REPRESENTATION PLUS"},
        {Pfn_set_edge_rep_plus, "SET EDGE REPRESENTATION PLUS"},
        {Pfn_set_pat_rep_plus, "SET PATTERN REPRESENTATION PLUS"},
        {Pfn_set_light_src_rep, "SET LIGHT SOURCE REPRESENTATION"},
        {Pfn_set_dcue_rep, "SET DEPTH CUE REPRESENTATION"},
        {Pfn_polyline_set3_data, "POLYLINE SET 3 WITH DATA"},
        {Pfn_cell_array3_plus, "CELL ARRAY 3 PLUS"},
        {Pfn_set_of_fill_area_set3_data, "SET OF FILL AREA SETS 3 WITH DATA"},
        {Pfn_set_rendering_colr_model, "SET RENDERING COLOUR MODEL"},
        {Pfn_set_colr_map_rep, "SET COLOUR MAPPING REPRESENTATION"},
    };
    return table;
}

}  // namespace

std::string functionName(int function) {
    auto it = names().find(function);
    if (it == names().end()) {
        if (const char* input = inputFunctionName(function)) return input;
    }
    return it != names().end() ? it->second : "function " + std::to_string(function);
}

Binding& Binding::instance() {
    static Binding binding;
    return binding;
}

void Binding::open(const char* errorFile) {
    if (phigs_) {
        report(errors::NotPhigsClosed, Pfn_open_phigs);
        return;
    }
    // The error file is (re)written from the start at OPEN PHIGS; without one, stderr.
    errorFile_ = errorFile ? errorFile : "";
    stream_ = errorFile ? std::fopen(errorFile, "w") : nullptr;
    mode_ = PERR_ON;  // each OPEN PHIGS starts with the error handling mode ON; the handler stays
    phigs_ = std::make_unique<Phigs>();
    ++openings_;
    registerOutputs(phigs_->outputs());
    phigs_->open();  // an error file that cannot be written leaves the lines on stderr
}

void Binding::close() {
    call(Pfn_close_phigs, [](Phigs& p) { p.close(); });
    if (phigs_ && phigs_->isOpen()) return;
    emergencyClose();
}

namespace {

/// Does `step`, whatever it throws: for closing down, where one failure must not stop the rest.
template <class Step>
void regardless(Step&& step) {
    try {
        step();
    } catch (...) {  // NOLINT(bugprone-empty-catch)
    }
}

}  // namespace

void Binding::emergencyClose() {
    // EMERGENCY CLOSE PHIGS (ISO 9592): the open structure is closed, then the archives (always
    // complete on disk), and each open workstation is updated and closed, so that as much of the
    // picture as can be is kept (a vector file written, a window's last picture shown). Nothing
    // here may fail: a workstation that cannot close does not keep the others open.
    if (phigs_) {
        Phigs& p = *phigs_;
        regardless([&] {
            if (p.store().isStructureOpen()) p.store().closeStructure();
        });
        for (int id : p.openArchiveIds()) regardless([&] { p.closeArchiveFile(id); });
        for (int id : p.openWorkstationIds()) regardless([&] { p.closeWorkstation(id); });
    }
    // Errors while PHIGS is closed go to the handler with no file name (so to stderr).
    phigs_.reset();
    specificTypes_.clear();
    if (stream_) std::fclose(stream_);
    stream_ = nullptr;
    errorFile_.clear();
}

void Binding::showChangesAtOnce(int function) {
    if (!phigs_ || !phigs_->isOpen() || !phigs_->anyWorkstationOpen()) return;
    const auto now = std::chrono::steady_clock::now();
    if (phigs_->store().isStructureOpen() && now - lastShown_ < kBuildingInterval) return;
    bool shown = false;
    for (int id : phigs_->openWorkstationIds()) {
        if (!phigs_) return;  // the handler of an error here closed PHIGS (EMERGENCY CLOSE)
        Workstation* ws = phigs_->findWorkstation(id);
        if (!ws || ws->type() != WorkstationType::Window || !ws->presentationBehind()) continue;
        shown = true;
        try {
            ws->present();  // a failure is not tried again until the picture changes
        } catch (const Error& e) {
            reportWith(e.number(), function, e.detail());
        } catch (const std::exception&) {  // NOLINT(bugprone-empty-catch): the next UPDATE reports it
        }
    }
    if (shown) lastShown_ = now;
}

Pint Binding::specificType(Pint id) {
    auto [entry, added] = specificTypes_.try_emplace(id, nextSpecificType_);
    if (added) ++nextSpecificType_;
    return entry->second;
}

Workstation* Binding::workstationOfSpecificType(Pint type) {
    for (const auto& [id, specific] : specificTypes_)
        if (specific == type) return phigs_ ? phigs_->findWorkstation(id) : nullptr;
    return nullptr;
}

void Binding::report(int number, int function) {
    if (mode_ == PERR_ON && handler_) handler_(number, function, errorFileName());
}

void Binding::reportWith(int number, int function, const std::string& why) {
    reporting_ = why;
    report(number, function);
    reporting_.clear();
}

void Binding::reportSince(int function, std::size_t before, int thrown, const std::string& why) {
    // A copy: a handler may call EMERGENCY CLOSE PHIGS, which takes the log with it.
    const std::vector<ErrorLog::Entry> entries =
        phigs_ ? phigs_->errorLog().entries() : std::vector<ErrorLog::Entry>{};
    bool thrownLogged = false;
    for (std::size_t i = before; i < entries.size(); ++i) {
        reportWith(entries[i].number, function, entries[i].detail);
        thrownLogged =
            thrownLogged || (thrown != 0 && entries[i].number == thrown && i + 1 == entries.size());
    }
    if (thrown != 0 && !thrownLogged) reportWith(thrown, function, why);
}

void Binding::log(int number, int function, const char* file) {
    const std::string message = errorMessage(number);
    const bool warning = message.starts_with("Warning");
    // The reason the core gave, where this is the error being reported now (a handler that logs it).
    const std::string line = std::string(warning ? "WARNING " : "ERROR ") + std::to_string(number) + " in " +
                             functionName(function) + " (function " + std::to_string(function) +
                             "): " + message + (reporting_.empty() ? "" : " (" + reporting_ + ")") + "\n";
    std::FILE* out = stream_;
    std::FILE* own = nullptr;
    // Another file than the open error file (or any file while PHIGS is closed) is appended to.
    if (file && (!stream_ || errorFile_ != file)) out = own = std::fopen(file, "a");
    if (!out) out = stderr;
    std::fputs(line.c_str(), out);
    std::fflush(out);
    if (own) std::fclose(own);
}

void Binding::message(int workstation, const char* text) {
    std::FILE* out = stream_ ? stream_ : stderr;
    std::fprintf(out, "MESSAGE %d: %s\n", workstation, text);
    std::fflush(out);
}

void Binding::setHandler(Handler handler, Handler* old) {
    if (old) *old = handler_;
    handler_ = handler ? handler : perr_hand;
}

}  // namespace phigs::c
