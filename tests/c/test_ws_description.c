/* The workstation description tables of every workstation type, found by inquiry without
 * opening one: class, display space, table lengths, dynamics, the facilities of each
 * representation, predefined representations, and their errors (2, 52, 100, 102, 112, 113,
 * 114, 2200); a workstation opened starts with the predefined representations; the specific
 * type of an open workstation. Opens only the
 * SVG hardcopy type (no GPU). argv[1]: a directory for the files. */
#include "check.h"

static char error_file[512], svg_file[512];

static const Pint types[6] = {PWST_OFFSCREEN, PWST_WINDOW, PWST_PNG, PWST_PDF, PWST_SVG, PWST_EPS};

static int is_vector(Pint t) {
    return t == PWST_PDF || t == PWST_SVG || t == PWST_EPS;
}

static void tables_of(Pint t) {
    Pint err = -1, n = -1, total = -1, ints[16];
    Pint_list list = {0, ints};
    Pws_class cls;
    Pdisp_space_size3 size3;
    Pdisp_space_size size;
    Pws_tables lengths;
    Pdyns_ws_attrs dyn;
    Pdyns_structs dyn_structs;
    pinq_ws_class(t, &err, &cls);
    CHECK(err == 0 && cls == (is_vector(t) ? PCLASS_VEC : PCLASS_RASTER));
    pinq_disp_space_size3(t, &err, &size3);
    CHECK(err == 0 && size3.dc_units == PDC_OTHER && size3.size_dc.size_x > size3.size_dc.size_y);
    CHECK(size3.size_raster.size_x > 0 && size3.size_dc.size_z == 1.0f);
    pinq_disp_space_size(t, &err, &size);
    CHECK(err == 0 && near(size.size_dc.size_x, size3.size_dc.size_x) &&
          size.size_raster.size_y == size3.size_raster.size_y);
    if (is_vector(t)) CHECK(near(size3.size_dc.size_x, 841.8898f)); /* A4 landscape in points */
    pinq_ws_st_table(t, &err, &lengths);
    CHECK(err == 0 && lengths.line_bundles == 32 && lengths.edge_bundles == 32 && lengths.pat_reps == 32);
    CHECK(lengths.colr_reps == 256 && lengths.view_reps == 32);
    pinq_num_disp_pris(t, &err, &n);
    CHECK(err == 0 && n == 0); /* continuous */
    pinq_dyns_ws_attrs(t, &err, &dyn);
    CHECK(err == 0 && dyn.line_bundle == PDYN_IRG && dyn.view_rep == PDYN_IRG && dyn.hlhsr_mode == PDYN_IRG);
    pinq_dyns_structs(t, &err, &dyn_structs);
    CHECK(err == 0 && dyn_structs.content == PDYN_IRG && dyn_structs.ref == PDYN_IRG);
    pinq_hlhsr_mode_facs(t, 16, 0, &err, &list, &total);
    CHECK(err == 0 && total == 2 && ints[0] == 0 && ints[1] == 1);
    pinq_hlhsr_id_facs(t, 16, 0, &err, &list, &total);
    CHECK(err == 0 && total == 2);
    pinq_view_facs(t, &err, &n);
    CHECK(err == 0 && n == 1);
    {
        Pdefer_mode d;
        Pmod_mode m;
        pinq_def_disp_upd_st(t, &err, &d, &m);
        CHECK(err == 0 && d == PDEFER_ASAP && m == PMODE_NIVE);
    }
}

static void facilities_of(Pint t) {
    Pint err = -1, total = -1, ints[16], n = -1, def = 0;
    Ptext_font_prec pairs[16];
    Pline_facs line = {{0, ints}, 0, 0, 0, 0, 0};
    Pmarker_facs marker = {{0, ints}, 0, 0, 0, 0, 0};
    Ptext_facs text;
    Pint_facs interior;
    Pedge_facs edge = {{0, ints}, 0, 0, 0, 0, 0};
    Pcolr_facs colour;
    Pint_list list = {0, ints};
    Pfloat lo = 0, hi = 0;
    pinq_line_facs(t, 16, 0, &err, &line, &total);
    CHECK(err == 0 && total == 4 && line.types.num_ints == 4 && ints[3] == PLINE_DASH_DOT);
    CHECK(line.num_widths == 0 && near(line.nom_width, 1.0f) && near(line.max_width, 16.0f) &&
          line.num_pred_inds == 5);
    pinq_marker_facs(t, 2, 3, &err, &marker, &total);
    CHECK(err == 0 && total == 5 && marker.types.num_ints == 2 && ints[0] == PMARKER_CIRCLE);
    CHECK(near(marker.nom_size, 7.0f) && marker.num_pred_inds == 5);
    text.font_precs = pairs;
    pinq_text_facs(t, 2, 10, &err, &text, &total); /* the last two of 4 fonts x 3 precisions */
    CHECK(err == 0 && total == 12 && text.num_font_precs == 2);
    CHECK(pairs[0].font == 4 && pairs[0].prec == PPREC_CHAR && pairs[1].prec == PPREC_STROKE);
    CHECK(text.num_char_hts == 0 && text.num_pred_inds == 5);
    interior.hatch_styles.ints = ints;
    pinq_int_facs(t, 16, 0, &err, &interior, &total);
    CHECK(err == 0 && interior.num_int_styles == 5 && interior.int_styles[4] == PSTYLE_EMPTY);
    CHECK(total == 6 && interior.hatch_styles.num_ints == total && interior.num_pred_inds == 5);
    pinq_edge_facs(t, 16, 0, &err, &edge, &total);
    CHECK(err == 0 && total == 4 && edge.num_pred_inds == 3);
    pinq_pat_facs(t, &err, &n);
    CHECK(err == 0 && n == 2);
    pinq_colr_facs(t, &err, &colour);
    CHECK(err == 0 && colour.colr_avail == PAVAIL_COLR && colour.num_pred_inds == 8);
    pinq_colr_model_facs(t, 16, 0, &err, &list, &total, &def);
    CHECK(err == 0 && total == 4 && ints[0] == PMODEL_RGB && ints[1] == PMODEL_CIELUV &&
          ints[2] == PMODEL_HSV && ints[3] == PMODEL_HLS && def == PMODEL_RGB);
    pinq_anno_facs(t, 16, 0, &err, &list, &total, &n, &lo, &hi);
    CHECK(err == 0 && total == 2 && ints[1] == PANNO_STYLE_LEAD_LINE && n == 0 && lo < hi);
    pinq_line_facs(t, 1, 4, &err, &line, &total);
    CHECK(err == PE_START_IND_INVAL);
}

static void predefined_of(Pint t) {
    Pint err = -1;
    Pline_bundle line;
    Pmarker_bundle marker;
    Ptext_bundle text;
    Pint_bundle interior;
    Pedge_bundle edge;
    Pcolr_rep colour;
    Pview_rep3 view;
    Ppat_rep* pat = NULL;
    Pstore store = NULL;
    pinq_pred_line_rep(t, 2, &err, &line);
    CHECK(err == 0 && line.type == PLINE_DASH && line.colr_ind == 1);
    pinq_pred_line_rep(t, 0, &err, &line);
    CHECK(err == 100);
    pinq_pred_line_rep(t, 6, &err, &line);
    CHECK(err == 102);
    pinq_pred_marker_rep(t, 4, &err, &marker);
    CHECK(err == 0 && marker.type == PMARKER_CIRCLE);
    pinq_pred_text_rep(t, 2, &err, &text);
    CHECK(err == 0 && text.font == 1 && text.prec == PPREC_STRING);
    pinq_pred_int_rep(t, 2, &err, &interior);
    CHECK(err == 0 && interior.style == PSTYLE_SOLID);
    pinq_pred_edge_rep(t, 2, &err, &edge);
    CHECK(err == 0 && edge.flag == PEDGE_ON);
    pinq_pred_edge_rep(t, 4, &err, &edge);
    CHECK(err == 102);
    pinq_pred_colr_rep(t, 2, &err, &colour);
    CHECK(err == 0 && near(colour.rgb.red, 1.0f) && near(colour.rgb.green, 0.0f));
    pinq_pred_colr_rep(t, -1, &err, &colour);
    CHECK(err == 113);
    pinq_pred_colr_rep(t, 8, &err, &colour);
    CHECK(err == 102);
    pinq_pred_view_rep(t, 0, &err, &view);
    CHECK(err == 0 && near(view.map_matrix[0][0], 1.0f) && near(view.ori_matrix[0][3], 0.0f));
    pinq_pred_view_rep(t, -1, &err, &view);
    CHECK(err == 114);
    pinq_pred_view_rep(t, 1, &err, &view);
    CHECK(err == 102);
    pcreate_store(&err, &store);
    pinq_pred_pat_rep(t, 1, store, &err, &pat);
    CHECK(err == 0 && pat && pat->dims.size_x == 2 && pat->dims.size_y == 2 && pat->colr_array[1] == 1);
    pinq_pred_pat_rep(t, 0, store, &err, &pat);
    CHECK(err == 112);
    pinq_pred_pat_rep(t, 3, store, &err, &pat);
    CHECK(err == 102);
    pdel_store(store);
}

static void unknown_type(void) {
    Pint err = -1, n = 0, total = 0;
    Pws_class cls;
    Pline_bundle line;
    Pline_facs facs;
    pinq_ws_class(77, &err, &cls);
    CHECK(err == 52);
    pinq_num_disp_pris(0, &err, &n);
    CHECK(err == 52);
    pinq_pred_line_rep(77, 1, &err, &line);
    CHECK(err == 52);
    pinq_line_facs(-3, 1, 0, &err, &facs, &total);
    CHECK(err == 52);
}

/* The specific type of an open workstation: its own number, answered by pinq_ws_conn_type,
 * describes it as its generic type does here (hardcopy keeps its size), opens its generic type,
 * and names nothing once the workstation is closed; a closed one reopened gets a new one. */
static void specific_types(void) {
    Pint err = -1, s1 = 0, s2 = 0, s3 = 0, again = 0, n = -1;
    Pws_class cls;
    Pws_cat cat;
    Pdisp_space_size3 generic, specific;
    Pline_bundle pred, pred_specific;
    void* conn = NULL;
    Pstore store = NULL;
    char second[600];
    snprintf(second, sizeof second, "%s.second.svg", svg_file);
    pcreate_store(&err, &store);
    EXPECT_NO_ERROR(popen_ws(1, svg_file, PWST_SVG));
    EXPECT_NO_ERROR(popen_ws(2, second, PWST_SVG));
    pinq_ws_conn_type(1, store, &err, &conn, &s1);
    CHECK(err == 0 && s1 >= PWST_SPECIFIC_BASE);
    pinq_ws_conn_type(2, store, &err, &conn, &s2);
    CHECK(err == 0 && s2 >= PWST_SPECIFIC_BASE && s2 != s1);
    pinq_ws_conn_type(1, store, &err, &conn, &again);
    CHECK(err == 0 && again == s1);
    pinq_ws_class(s1, &err, &cls);
    CHECK(err == 0 && cls == PCLASS_VEC);
    pinq_ws_cat(s2, &err, &cat);
    CHECK(err == 0 && cat == PCAT_OUT);
    pinq_disp_space_size3(PWST_SVG, &err, &generic);
    pinq_disp_space_size3(s1, &err, &specific);
    CHECK(err == 0 && near(specific.size_dc.size_x, generic.size_dc.size_x) &&
          near(specific.size_dc.size_y, generic.size_dc.size_y));
    pinq_pred_line_rep(s1, 2, &err, &pred_specific);
    pinq_pred_line_rep(PWST_SVG, 2, &err, &pred);
    CHECK(err == 0 && pred.type == pred_specific.type && pred.colr_ind == pred_specific.colr_ind);
    EXPECT_NO_ERROR(popen_ws(3, second, s2)); /* the generic type of s2 */
    pinq_ws_conn_type(3, store, &err, &conn, &s3);
    CHECK(err == 0 && s3 != s1 && s3 != s2);
    EXPECT_NO_ERROR(pclose_ws(3));
    EXPECT_NO_ERROR(pclose_ws(1));
    pinq_disp_space_size3(s1, &err, &specific);
    CHECK(err == 52);
    pinq_num_disp_pris(s3, &err, &n);
    CHECK(err == 52);
    EXPECT_ERROR(popen_ws(4, second, s1), 52, Pfn_open_ws);
    EXPECT_NO_ERROR(popen_ws(1, svg_file, PWST_SVG));
    pinq_ws_conn_type(1, store, &err, &conn, &again);
    CHECK(err == 0 && again != s1 && again != s2 && again != s3);
    pinq_ws_class(PWST_SPECIFIC_BASE + 100000, &err, &cls);
    CHECK(err == 52);
    EXPECT_NO_ERROR(pclose_ws(1));
    EXPECT_NO_ERROR(pclose_ws(2));
    pdel_store(store);
}

/* A workstation starts with its type's predefined representations. */
static void opened_starts_predefined(void) {
    Pint err = -1, total = 0, ints[8], planes = 0;
    Pint_list ops = {0, ints};
    Pline_bundle pred, rep;
    Ptext_bundle text;
    EXPECT_NO_ERROR(popen_ws(1, svg_file, PWST_SVG));
    for (Pint i = 1; i <= 5; ++i) {
        pinq_pred_line_rep(PWST_SVG, i, &err, &pred);
        pinq_line_rep(1, i, PINQ_SET, &err, &rep);
        CHECK(err == 0 && rep.type == pred.type && near(rep.width, pred.width) &&
              rep.colr_ind == pred.colr_ind);
    }
    pinq_text_rep(1, 5, PINQ_SET, &err, &text);
    CHECK(err == 0 && text.font == 3 && text.colr_ind == 2);
    EXPECT_NO_ERROR(pclose_ws(1));
    pinq_model_clip_facs(8, 0, &err, &planes, &ops, &total);
    CHECK(err == 0 && planes == 64 && total == 2 && ints[0] == PMC_REPLACE && ints[1] == PMC_INTERSECT);
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    Pint err = -1;
    Pws_class cls;
    snprintf(error_file, sizeof error_file, "%s/ws_description_errors.txt", dir);
    snprintf(svg_file, sizeof svg_file, "%s/ws_description.svg", dir);
    pinq_ws_class(PWST_SVG, &err, &cls);
    CHECK(err == 2); /* PHIGS closed */
    open_with_handler(error_file);
    const int lines = file_line_count(error_file);
    for (int i = 0; i < 6; ++i) {
        tables_of(types[i]);
        facilities_of(types[i]);
        predefined_of(types[i]);
    }
    unknown_type();
    CHECK(file_line_count(error_file) == lines); /* inquiries answer, never log */
    opened_starts_predefined();
    specific_types();
    pclose_phigs();
    return finish("test_ws_description");
}
