/* Representations: SET and INQUIRE of the polyline, polymarker, text, interior, edge, pattern
 * and colour tables with SET and REALIZED values under every deferral and modification mode,
 * the lists of defined indices, the colour model, and their errors (each refusal leaves the
 * table as it was). Opens only the SVG hardcopy type (no GPU). argv[1]: a directory. */
#include "check.h"

static char error_file[512], svg_file[512];

static void lines_under_every_mode(void) {
    Pint err = -1;
    for (int d = PDEFER_ASAP; d <= PDEFER_WAIT; ++d)
        for (int m = PMODE_NIVE; m <= PMODE_UQUM; ++m) {
            const Pline_bundle set = {1 + (d + m) % 4, 0.5f + (Pfloat)m, 2 + d};
            Pline_bundle got, realized;
            EXPECT_NO_ERROR(pset_disp_upd_st(1, (Pdefer_mode)d, (Pmod_mode)m));
            EXPECT_NO_ERROR(pset_line_rep(1, 6, &set));
            pinq_line_rep(1, 6, PINQ_SET, &err, &got);
            CHECK(err == 0 && got.type == set.type && near(got.width, set.width) &&
                  got.colr_ind == set.colr_ind);
            pinq_line_rep(1, 6, PINQ_REALIZED, &err, &realized);
            CHECK(err == 0 && realized.type == set.type && realized.colr_ind == set.colr_ind);
            CHECK(near(realized.width, set.width < 1.0f ? 1.0f : set.width)); /* at least 1 device unit */
        }
    EXPECT_NO_ERROR(pset_disp_upd_st(1, PDEFER_ASAP, PMODE_NIVE));
}

static void bundles(void) {
    Pint err = -1, total = 0, ids[40];
    Pint_list list = {0, ids};
    Pline_bundle line = {PLINE_DOT, 100.0f, 200}, line_got;
    Pmarker_bundle marker = {PMARKER_CIRCLE, 100.0f, 3}, marker_got;
    Ptext_bundle text = {4, PPREC_STRING, 2.0f, 0.5f, 5}, text_got;
    Pint_bundle interior = {PSTYLE_HATCH, 3, 6}, int_got;
    Pedge_bundle edge = {PEDGE_ON, PLINE_DASH, 2.0f, 7}, edge_got;
    EXPECT_NO_ERROR(pset_line_rep(1, 7, &line));
    EXPECT_NO_ERROR(pset_marker_rep(1, 7, &marker));
    EXPECT_NO_ERROR(pset_text_rep(1, 7, &text));
    EXPECT_NO_ERROR(pset_int_rep(1, 7, &interior));
    EXPECT_NO_ERROR(pset_edge_rep(1, 7, &edge));
    pinq_line_rep(1, 7, PINQ_REALIZED, &err, &line_got); /* width 100 clamped to 16, colour 200 -> 1 */
    CHECK(err == 0 && line_got.type == PLINE_DOT && near(line_got.width, 16.0f) && line_got.colr_ind == 1);
    pinq_marker_rep(1, 7, PINQ_SET, &err, &marker_got);
    CHECK(err == 0 && marker_got.type == PMARKER_CIRCLE && near(marker_got.size, 100.0f));
    pinq_marker_rep(1, 7, PINQ_REALIZED, &err, &marker_got); /* 700 device units -> 64: scale 64 / 7 */
    CHECK(err == 0 && near(marker_got.size, 64.0f / 7.0f) && marker_got.colr_ind == 3);
    pinq_text_rep(1, 7, PINQ_SET, &err, &text_got);
    CHECK(err == 0 && text_got.font == 4 && text_got.prec == PPREC_STRING && near(text_got.char_expan, 2.0f));
    pinq_text_rep(1, 7, PINQ_REALIZED, &err, &text_got);
    CHECK(err == 0 && text_got.prec == PPREC_STROKE && near(text_got.char_space, 0.5f) &&
          text_got.colr_ind == 5);
    pinq_int_rep(1, 7, PINQ_SET, &err, &int_got);
    CHECK(err == 0 && int_got.style == PSTYLE_HATCH && int_got.style_ind == 3 && int_got.colr_ind == 6);
    pinq_edge_rep(1, 7, PINQ_SET, &err, &edge_got);
    CHECK(err == 0 && edge_got.flag == PEDGE_ON && edge_got.type == PLINE_DASH && near(edge_got.width, 2.0f));
    /* An undefined index: 101 for SET, bundle 1 for REALIZED. */
    pinq_edge_rep(1, 20, PINQ_SET, &err, &edge_got);
    CHECK(err == 101);
    pinq_edge_rep(1, 20, PINQ_REALIZED, &err, &edge_got);
    CHECK(err == 0 && edge_got.flag == PEDGE_OFF && edge_got.type == PLINE_SOLID);
    pinq_int_rep(1, 20, PINQ_REALIZED, &err, &int_got);
    CHECK(err == 0 && int_got.style == PSTYLE_HOLLOW);
    pinq_line_rep(1, 0, PINQ_SET, &err, &line_got);
    CHECK(err == 100);
    pinq_line_rep(1, 1, (Pinq_type)7, &err, &line_got);
    CHECK(err == PE_ENUM_TYPE_INVAL);
    pinq_line_rep(3, 1, PINQ_SET, &err, &line_got);
    CHECK(err == 54);
    /* Predefined 1..5 (edges 1..3) and the ones set. */
    pinq_list_line_inds(1, 40, 0, &err, &list, &total);
    CHECK(err == 0 && total == 7 && ids[0] == 1 && ids[5] == 6 && ids[6] == 7);
    pinq_list_marker_inds(1, 40, 0, &err, &list, &total);
    CHECK(err == 0 && total == 6 && ids[5] == 7);
    pinq_list_text_inds(1, 2, 4, &err, &list, &total);
    CHECK(err == 0 && total == 6 && list.num_ints == 2 && ids[0] == 5 && ids[1] == 7);
    pinq_list_int_inds(1, 40, 0, &err, &list, &total);
    CHECK(err == 0 && total == 6);
    pinq_list_edge_inds(1, 40, 0, &err, &list, &total);
    CHECK(err == 0 && total == 4 && ids[3] == 7);
    pinq_list_edge_inds(1, -1, 0, &err, &list, &total);
    CHECK(err == PE_LIST_LENGTH_LT_ZERO);
}

/* Each refused SET leaves entry 7 as it was. */
static void bundle_errors(void) {
    Pint err = -1;
    Pline_bundle line = {PLINE_SOLID, 1.0f, 1}, got;
    Pmarker_bundle marker = {9, 1.0f, 1};
    Ptext_bundle text = {5, PPREC_STROKE, 1.0f, 0.0f, 1};
    Pint_bundle interior = {(Pint_style)7, 1, 1};
    Pint_bundle pattern_zero = {PSTYLE_PAT, 0, 1};
    Pedge_bundle edge = {PEDGE_ON, 9, 1.0f, 1};
    EXPECT_ERROR(pset_line_rep(1, 0, &line), 100, Pfn_set_line_rep);
    line.colr_ind = -1;
    EXPECT_ERROR(pset_line_rep(1, 7, &line), 113, Pfn_set_line_rep);
    line.colr_ind = 1;
    line.type = 9;
    EXPECT_ERROR(pset_line_rep(1, 7, &line), 104, Pfn_set_line_rep);
    EXPECT_ERROR(pset_line_rep(1, 7, NULL), -204, Pfn_set_line_rep);
    pinq_line_rep(1, 7, PINQ_SET, &err, &got);
    CHECK(err == 0 && got.type == PLINE_DOT && got.colr_ind == 200);
    EXPECT_ERROR(pset_marker_rep(1, 7, &marker), 105, Pfn_set_marker_rep);
    EXPECT_ERROR(pset_text_rep(1, 7, &text), 106, Pfn_set_text_rep);
    text.font = 1;
    text.prec = (Ptext_prec)5;
    EXPECT_ERROR(pset_text_rep(1, 7, &text), PE_ENUM_TYPE_INVAL, Pfn_set_text_rep);
    EXPECT_ERROR(pset_int_rep(1, 7, &interior), PE_ENUM_TYPE_INVAL, Pfn_set_int_rep);
    EXPECT_ERROR(pset_int_rep(1, 7, &pattern_zero), 112, Pfn_set_int_rep);
    EXPECT_ERROR(pset_edge_rep(1, 7, &edge), 107, Pfn_set_edge_rep);
    EXPECT_ERROR(pset_edge_rep(4, 7, &edge), 54, Pfn_set_edge_rep);
    /* The table holds 32 polyline bundles: a 33rd index is refused. */
    line.type = PLINE_SOLID;
    for (Pint i = 8; i <= 32; ++i) pset_line_rep(1, i, &line);
    EXPECT_ERROR(pset_line_rep(1, 40, &line), 103, Pfn_set_line_rep);
    EXPECT_NO_ERROR(pset_line_rep(1, 32, &line)); /* redefining an entry is no new entry */
}

static void patterns_and_colours(void) {
    Pint err = -1, total = 0, ids[300];
    Pint_list list = {0, ids};
    Pint cells[6] = {0, 1, 2, 3, 4, 250};
    Ppat_rep pat = {{3, 2}, cells}, *got = NULL;
    Pstore store = NULL;
    Pcolr_rep colour, colour_got;
    pcreate_store(&err, &store);
    EXPECT_NO_ERROR(pset_pat_rep(1, 3, &pat));
    pinq_pat_rep(1, 3, PINQ_SET, store, &err, &got);
    CHECK(err == 0 && got && got->dims.size_x == 3 && got->dims.size_y == 2 && got->colr_array[5] == 250);
    pinq_pat_rep(1, 3, PINQ_REALIZED, store, &err, &got); /* colour 250 is not defined: 1 */
    CHECK(err == 0 && got->colr_array[4] == 4 && got->colr_array[5] == 1);
    pinq_pat_rep(1, 9, PINQ_SET, store, &err, &got);
    CHECK(err == 101);
    pinq_pat_rep(1, 9, PINQ_REALIZED, store, &err, &got); /* pattern 1: 2 x 2 */
    CHECK(err == 0 && got->dims.size_x == 2 && got->dims.size_y == 2);
    pinq_pat_rep(1, 0, PINQ_SET, store, &err, &got);
    CHECK(err == 112);
    EXPECT_ERROR(pset_pat_rep(1, 0, &pat), 112, Pfn_set_pat_rep);
    pat.dims.size_x = 0;
    EXPECT_ERROR(pset_pat_rep(1, 3, &pat), 116, Pfn_set_pat_rep);
    pat.dims.size_x = 3;
    cells[0] = -1;
    EXPECT_ERROR(pset_pat_rep(1, 3, &pat), 113, Pfn_set_pat_rep);
    pinq_pat_rep(1, 3, PINQ_SET, store, &err, &got);
    CHECK(err == 0 && got->colr_array[0] == 0); /* unchanged */
    pinq_list_pat_inds(1, 10, 0, &err, &list, &total);
    CHECK(err == 0 && total == 3 && ids[2] == 3);

    colour.rgb = (Prgb){0.25f, 0.5f, 0.75f};
    EXPECT_NO_ERROR(pset_colr_rep(1, 12, &colour));
    pinq_colr_rep(1, 12, PINQ_SET, &err, &colour_got);
    CHECK(err == 0 && near(colour_got.rgb.red, 0.25f) && near(colour_got.rgb.blue, 0.75f));
    pinq_colr_rep(1, 200, PINQ_SET, &err, &colour_got);
    CHECK(err == 101);
    pinq_colr_rep(1, 200, PINQ_REALIZED, &err, &colour_got);
    CHECK(err == 0 && near(colour_got.rgb.green, 1.0f)); /* colour 1: white */
    pinq_colr_rep(1, -1, PINQ_SET, &err, &colour_got);
    CHECK(err == 113);
    EXPECT_ERROR(pset_colr_rep(1, -1, &colour), 113, Pfn_set_colr_rep);
    EXPECT_ERROR(pset_colr_rep(1, 300, &colour), 103, Pfn_set_colr_rep);
    colour.rgb.green = 1.5f;
    EXPECT_ERROR(pset_colr_rep(1, 12, &colour), 118, Pfn_set_colr_rep);
    pinq_colr_rep(1, 12, PINQ_SET, &err, &colour_got);
    CHECK(err == 0 && near(colour_got.rgb.green, 0.5f));
    pinq_list_colr_inds(1, 300, 0, &err, &list, &total);
    CHECK(err == 0 && total == 9 && ids[0] == 0 && ids[8] == 12);
    pdel_store(store);
}

static void colour_model(void) {
    Pint err = -1, model = 0;
    pinq_colr_model(1, &err, &model);
    CHECK(err == 0 && model == PMODEL_RGB);
    EXPECT_ERROR(pset_colr_model(1, PMODEL_HLS + 1), 110, Pfn_set_colr_model);
    EXPECT_NO_ERROR(pset_colr_model(1, PMODEL_RGB));
    pinq_colr_model(1, &err, &model);
    CHECK(err == 0 && model == PMODEL_RGB);
    pinq_colr_model(2, &err, &model);
    CHECK(err == 54);
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    Pint err = -1;
    Pline_bundle line = {1, 1.0f, 1};
    snprintf(error_file, sizeof error_file, "%s/ws_reps_errors.txt", dir);
    snprintf(svg_file, sizeof svg_file, "%s/ws_reps.svg", dir);
    open_with_handler(error_file);
    EXPECT_ERROR(pset_line_rep(1, 1, &line), 3, Pfn_set_line_rep);
    pinq_line_rep(1, 1, PINQ_SET, &err, &line);
    CHECK(err == 3);
    EXPECT_NO_ERROR(popen_ws(1, svg_file, PWST_SVG));
    lines_under_every_mode();
    bundles();
    bundle_errors();
    patterns_and_colours();
    colour_model();
    EXPECT_NO_ERROR(pclose_ws(1));
    pclose_phigs();
    return finish("test_ws_reps");
}
