/* Every inquiry given NULL for all its result pointers has nowhere to answer: it answers -204, and
 * 2 while PHIGS is closed (the state check comes first). Any one of several results may be NULL
 * (test_ws_state, test_inquiries); this covers the rest, one call per inquiry of phigs.h. */
#include "check.h"

static Pint expected = 0;
static int asked = 0;

#define ASK(call)                                                                                   \
    do {                                                                                            \
        err = 12345;                                                                                \
        call;                                                                                       \
        ++asked;                                                                                    \
        if (err != expected) {                                                                      \
            fprintf(stderr, "%s:%d: %s answered %d, not %d\n", __FILE__, __LINE__, #call, (int)err, \
                    (int)expected);                                                                 \
            ++failures;                                                                             \
        }                                                                                           \
    } while (0)

/* Each inquiry once, every result pointer NULL, the other arguments valid where they can be. */
static void ask_every_inquiry(Pstore store) {
    Pint err = 0;
    ASK(pinq_phigs_facs(1, 1, &err, NULL, NULL, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_err_hand_mode(&err, NULL));
    ASK(pinq_open_struct(&err, NULL, NULL));
    ASK(pinq_elem_ptr(&err, NULL));
    ASK(pinq_edit_mode(&err, NULL));
    ASK(pinq_cur_elem_type_size(&err, NULL, NULL));
    ASK(pinq_cur_elem_content(store, &err, NULL));
    ASK(pinq_elem_type_size(1, 1, &err, NULL, NULL));
    ASK(pinq_elem_content(1, 1, store, &err, NULL));
    ASK(pinq_struct_status(1, &err, NULL));
    ASK(pinq_struct_ids(1, 1, &err, NULL, NULL));
    ASK(pinq_paths_ances(1, (Ppath_order)0, 1, store, &err, NULL));
    ASK(pinq_paths_descs(1, (Ppath_order)0, 1, store, &err, NULL));
    ASK(pinq_ar_files(store, &err, NULL));
    ASK(pinq_conf_res(&err, NULL, NULL));
    ASK(pinq_all_conf_structs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_conf_structs_net(1, 1, (Pstruct_net_source)0, 1, 1, &err, NULL, NULL));
    ASK(pinq_open_wss(1, 1, &err, NULL, NULL));
    ASK(pinq_ws_conn_type(1, store, &err, NULL, NULL));
    ASK(pinq_posted_structs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_list_avail_ws_types(1, 1, &err, NULL, NULL));
    ASK(pinq_ws_cat(1, &err, NULL));
    ASK(pinq_list_avail_gdp3(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_list_avail_gdp(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_gdp3(1, 1, &err, NULL, NULL));
    ASK(pinq_gdp(1, 1, &err, NULL, NULL));
    ASK(pinq_list_avail_gse(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_gse_facs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_disp_upd_st(1, &err, NULL, NULL, NULL, NULL));
    ASK(pinq_def_disp_upd_st(1, &err, NULL, NULL));
    ASK(pinq_view_rep(1, 1, &err, NULL, NULL, NULL));
    ASK(pinq_ws_tran3(1, &err, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_ws_tran(1, &err, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_hlhsr_mode(1, &err, NULL, NULL, NULL));
    ASK(pinq_list_view_inds(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_highl_filter(1, store, &err, NULL));
    ASK(pinq_invis_filter(1, store, &err, NULL));
    ASK(pinq_wss_posted(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_line_rep(1, 1, (Pinq_type)0, &err, NULL));
    ASK(pinq_marker_rep(1, 1, (Pinq_type)0, &err, NULL));
    ASK(pinq_text_rep(1, 1, (Pinq_type)0, &err, NULL));
    ASK(pinq_int_rep(1, 1, (Pinq_type)0, &err, NULL));
    ASK(pinq_edge_rep(1, 1, (Pinq_type)0, &err, NULL));
    ASK(pinq_pat_rep(1, 1, (Pinq_type)0, store, &err, NULL));
    ASK(pinq_colr_rep(1, 1, (Pinq_type)0, &err, NULL));
    ASK(pinq_colr_model(1, &err, NULL));
    ASK(pinq_list_line_inds(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_list_marker_inds(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_list_text_inds(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_list_int_inds(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_list_edge_inds(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_list_pat_inds(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_list_colr_inds(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_ws_class(1, &err, NULL));
    ASK(pinq_disp_space_size3(1, &err, NULL));
    ASK(pinq_disp_space_size(1, &err, NULL));
    ASK(pinq_ws_st_table(1, &err, NULL));
    ASK(pinq_num_disp_pris(1, &err, NULL));
    ASK(pinq_dyns_ws_attrs(1, &err, NULL));
    ASK(pinq_dyns_structs(1, &err, NULL));
    ASK(pinq_line_facs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_marker_facs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_text_facs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_int_facs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_edge_facs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_pat_facs(1, &err, NULL));
    ASK(pinq_colr_facs(1, &err, NULL));
    ASK(pinq_colr_model_facs(1, 1, 1, &err, NULL, NULL, NULL));
    ASK(pinq_view_facs(1, &err, NULL));
    ASK(pinq_hlhsr_id_facs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_hlhsr_mode_facs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_anno_facs(1, 1, 1, &err, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_model_clip_facs(1, 1, &err, NULL, NULL, NULL));
    ASK(pinq_pred_line_rep(1, 1, &err, NULL));
    ASK(pinq_pred_marker_rep(1, 1, &err, NULL));
    ASK(pinq_pred_text_rep(1, 1, &err, NULL));
    ASK(pinq_pred_int_rep(1, 1, &err, NULL));
    ASK(pinq_pred_edge_rep(1, 1, &err, NULL));
    ASK(pinq_pred_pat_rep(1, 1, store, &err, NULL));
    ASK(pinq_pred_colr_rep(1, 1, &err, NULL));
    ASK(pinq_pred_view_rep(1, 1, &err, NULL));
    ASK(pinq_loc_st3(1, 1, (Pinq_type)0, store, &err, NULL, NULL, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_loc_st(1, 1, (Pinq_type)0, store, &err, NULL, NULL, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_stroke_st3(1, 1, (Pinq_type)0, store, &err, NULL, NULL, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_stroke_st(1, 1, (Pinq_type)0, store, &err, NULL, NULL, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_val_st3(1, 1, store, &err, NULL, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_val_st(1, 1, store, &err, NULL, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_choice_st3(1, 1, store, &err, NULL, NULL, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_choice_st(1, 1, store, &err, NULL, NULL, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_pick_st3(1, 1, (Pinq_type)0, store, &err, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_pick_st(1, 1, (Pinq_type)0, store, &err, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_string_st3(1, 1, store, &err, NULL, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_string_st(1, 1, store, &err, NULL, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_def_loc_data3(1, 1, store, &err, NULL, NULL, NULL, NULL));
    ASK(pinq_def_loc_data(1, 1, store, &err, NULL, NULL, NULL, NULL));
    ASK(pinq_def_stroke_data3(1, 1, store, &err, NULL, NULL, NULL, NULL));
    ASK(pinq_def_stroke_data(1, 1, store, &err, NULL, NULL, NULL, NULL));
    ASK(pinq_def_val_data3(1, 1, store, &err, NULL, NULL, NULL, NULL));
    ASK(pinq_def_val_data(1, 1, store, &err, NULL, NULL, NULL, NULL));
    ASK(pinq_def_choice_data3(1, 1, store, &err, NULL, NULL, NULL, NULL));
    ASK(pinq_def_choice_data(1, 1, store, &err, NULL, NULL, NULL, NULL));
    ASK(pinq_def_pick_data3(1, 1, store, &err, NULL, NULL, NULL));
    ASK(pinq_def_pick_data(1, 1, store, &err, NULL, NULL, NULL));
    ASK(pinq_def_string_data3(1, 1, store, &err, NULL, NULL, NULL, NULL));
    ASK(pinq_def_string_data(1, 1, store, &err, NULL, NULL, NULL, NULL));
    ASK(pinq_num_avail_in(1, &err, NULL));
    ASK(pinq_in_overf(&err, NULL, NULL, NULL));
    ASK(pinq_more_simult_events(&err, NULL));
    ASK(pinq_text_extent(1, 1, 0, 0, 0, (Ptext_path)0, (Phor_text_align)0, (Pvert_text_align)0, NULL, &err,
                         NULL, NULL));
    ASK(pinq_light_src_rep(1, 1, (Pinq_type)0, &err, NULL));
    ASK(pinq_list_light_src_inds(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_pred_light_src_rep(1, 1, &err, NULL));
    ASK(pinq_pred_dcue_rep(1, 1, &err, NULL));
    ASK(pinq_light_src_facs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_dcue_facs(1, &err, NULL));
    ASK(pinq_direct_colr_model_facs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_rendering_colr_model_facs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_curv_surf_facs(1, 1, 1, 1, 1, 1, 1, 1, 1, &err, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_dcue_rep(1, 1, (Pinq_type)0, &err, NULL));
    ASK(pinq_list_dcue_inds(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_colr_map_rep(1, 1, (Pinq_type)0, store, &err, NULL, NULL));
    ASK(pinq_pred_colr_map_rep(1, 1, store, &err, NULL, NULL));
    ASK(pinq_list_colr_map_inds(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_colr_map_st(1, 1, &err, NULL));
    ASK(pinq_colr_map_facs(1, 1, 1, &err, NULL, NULL));
    ASK(pinq_colr_map_method_facs(1, 1, &err, NULL));
    ASK(pinq_line_rep_plus(1, 1, (Pinq_type)0, &err, NULL));
    ASK(pinq_marker_rep_plus(1, 1, (Pinq_type)0, &err, NULL));
    ASK(pinq_text_rep_plus(1, 1, (Pinq_type)0, &err, NULL));
    ASK(pinq_int_rep_plus(1, 1, (Pinq_type)0, &err, NULL));
    ASK(pinq_edge_rep_plus(1, 1, (Pinq_type)0, &err, NULL));
    ASK(pinq_pat_rep_plus(1, 1, (Pinq_type)0, store, &err, NULL));
    ASK(pinq_pred_line_rep_plus(1, 1, &err, NULL));
    ASK(pinq_pred_marker_rep_plus(1, 1, &err, NULL));
    ASK(pinq_pred_text_rep_plus(1, 1, &err, NULL));
    ASK(pinq_pred_int_rep_plus(1, 1, &err, NULL));
    ASK(pinq_pred_edge_rep_plus(1, 1, &err, NULL));
    ASK(pinq_pred_pat_rep_plus(1, 1, store, &err, NULL));
    ASK(pinq_line_facs_plus(1, 1, 1, 1, 1, &err, NULL, NULL, NULL));
    ASK(pinq_int_facs_plus(1, 1, 1, 1, 1, 1, 1, 1, 1, &err, NULL, NULL, NULL, NULL, NULL));
    ASK(pinq_ws_st_table_plus(1, &err, NULL));
    ASK(pinq_dyns_ws_attrs_plus(1, &err, NULL));
}

int main(int argc, char** argv) {
    (void)argc, (void)argv;
    Pint err = 0;
    Pstore store = NULL;
    expected = 2; /* PHIGS closed */
    ask_every_inquiry(store);
    const int inquiries = asked;
    CHECK(inquiries > 140);
    popen_phigs(NULL, PDEF_MEM_SIZE);
    pcreate_store(&err, &store);
    CHECK(err == 0);
    popen_struct(1);
    plabel(1);
    pclose_struct();
    expected = -204;
    ask_every_inquiry(store);
    CHECK(asked == 2 * inquiries);
    pdel_store(store);
    pclose_phigs();
    return failures == 0 ? 0 : 1;
}
