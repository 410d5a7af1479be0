/* Workstations: the types found by inquiry, OPEN / CLOSE WORKSTATION and their errors, posting,
 * update, window and viewport, view representations, and the workstation inquiries. Opens only
 * vector hardcopy types (cairo, no GPU). argv[1]: a directory for the files. */
#include "check.h"

static char error_file[512], pdf_file[512], svg_file[512];

static void types_by_inquiry(void) {
    Pint err = -1, total = 0, types[8];
    Pint_list list = {0, types};
    Pws_cat cat = PCAT_MI;
    pinq_list_avail_ws_types(8, 0, &err, &list, &total);
    CHECK(err == 0 && total >= 5 && list.num_ints == total);
    int offscreen = 0, pdf = 0, svg = 0, eps = 0;
    for (Pint i = 0; i < list.num_ints; ++i) {
        offscreen += types[i] == PWST_OFFSCREEN;
        pdf += types[i] == PWST_PDF;
        svg += types[i] == PWST_SVG;
        eps += types[i] == PWST_EPS;
    }
    CHECK(offscreen == 1 && pdf == 1 && svg == 1 && eps == 1);
    pinq_ws_cat(PWST_OFFSCREEN, &err, &cat);
    CHECK(err == 0 && cat == PCAT_OUTIN);
    pinq_ws_cat(PWST_WINDOW, &err, &cat);
    CHECK(err == 0 && cat == PCAT_OUTIN);
    pinq_ws_cat(PWST_PDF, &err, &cat);
    CHECK(err == 0 && cat == PCAT_OUT);
    pinq_ws_cat(PWST_PNG, &err, &cat);
    CHECK(err == 0 && cat == PCAT_OUT);
    pinq_ws_cat(77, &err, &cat);
    CHECK(err == 52);
}

/* GDPs and GSEs by workstation type: the two registered GDPs, each with the polyline
 * attributes; error 64 for another identifier; no GSE. Inquiries log nothing. */
static void gdps_and_gses(void) {
    const Pint ws_types[3] = {PWST_OFFSCREEN, PWST_PDF, PWST_WINDOW};
    for (int t = 0; t < 3; ++t) {
        Pint err = -1, total = -1, ids[4] = {0, 0, 0, 0}, count = -1;
        Pint_list list = {0, ids};
        Pattrs attrs[5];
        Pgse_id_dep facs[2];
        Pgse_id_dep_list gse_list = {-1, facs};
        pinq_list_avail_gdp3(ws_types[t], 4, 0, &err, &list, &total);
        CHECK(err == 0 && total == 2 && list.num_ints == 2);
        CHECK((ids[0] == PGDP_CIRCLE && ids[1] == PGDP_ARC) || (ids[0] == PGDP_ARC && ids[1] == PGDP_CIRCLE));
        const Pint second = ids[1];
        pinq_list_avail_gdp(ws_types[t], 1, 1, &err, &list, &total); /* the second only */
        CHECK(err == 0 && total == 2 && list.num_ints == 1 && ids[0] == second);
        pinq_list_avail_gdp(ws_types[t], 1, 5, &err, &list, &total);
        CHECK(err == PE_START_IND_INVAL);
        pinq_gdp3(ws_types[t], PGDP_CIRCLE, &err, &count, attrs);
        CHECK(err == 0 && count == 1 && attrs[0] == PATTR_LINE);
        pinq_gdp(ws_types[t], PGDP_ARC, &err, &count, attrs);
        CHECK(err == 0 && count == 1 && attrs[0] == PATTR_LINE);
        pinq_gdp3(ws_types[t], 4711, &err, &count, attrs);
        CHECK(err == 64);
        pinq_list_avail_gse(ws_types[t], 4, 0, &err, &list, &total);
        CHECK(err == 0 && total == 0 && list.num_ints == 0);
        pinq_gse_facs(ws_types[t], 2, 0, &err, &gse_list, &total);
        CHECK(err == 0 && total == 0 && gse_list.num_id_facs == 0);
    }
    {
        Pint err = -1, total = 0, count = 0;
        Pattrs attrs[5];
        pinq_list_avail_gdp3(77, 0, 0, &err, NULL, &total);
        CHECK(err == 52);
        pinq_gdp(77, PGDP_CIRCLE, &err, &count, attrs);
        CHECK(err == 52);
        pinq_list_avail_gse(PWST_PDF, -1, 0, &err, NULL, &total);
        CHECK(err == PE_LIST_LENGTH_LT_ZERO);
    }
}

static void open_and_close_errors(void) {
    Pws_st st = PWS_ST_WSOP;
    pinq_ws_st(&st);
    CHECK(st == PWS_ST_WSCL);
    EXPECT_ERROR(ppost_struct(1, 1, 0.5f), 3, Pfn_post_struct); /* none open */
    EXPECT_ERROR(popen_ws(1, pdf_file, 77), 52, Pfn_open_ws);
    EXPECT_ERROR(popen_ws(1, pdf_file, 0), 52, Pfn_open_ws);
    EXPECT_ERROR(popen_ws(1, NULL, PWST_PDF), 50, Pfn_open_ws);
    EXPECT_ERROR(popen_ws(1, "", PWST_SVG), 50, Pfn_open_ws);
    EXPECT_ERROR(popen_ws(1, NULL, PWST_PNG), 50, Pfn_open_ws);
    pinq_ws_st(&st);
    CHECK(st == PWS_ST_WSCL);
    EXPECT_NO_ERROR(popen_ws(1, pdf_file, PWST_PDF));
    pinq_ws_st(&st);
    CHECK(st == PWS_ST_WSOP);
    EXPECT_ERROR(popen_ws(1, svg_file, PWST_SVG), 53, Pfn_open_ws);
    EXPECT_ERROR(ppost_struct(2, 1, 0.5f), 54, Pfn_post_struct);
    EXPECT_ERROR(pupd_ws(2, PFLAG_PERFORM), 54, Pfn_upd_ws);
    EXPECT_ERROR(pclose_ws(2), 54, Pfn_close_ws);
    EXPECT_ERROR(ppost_struct(1, 1, 1.5f), 208, Pfn_post_struct);
    EXPECT_ERROR(pupd_ws(1, (Pregen_flag)9), PE_ENUM_TYPE_INVAL, Pfn_upd_ws);
    EXPECT_ERROR(pclose_phigs(), 4, Pfn_close_phigs);
    /* The error file names the function and the standard's message. */
    CHECK(file_has_line(error_file,
                        "ERROR 50 in OPEN WORKSTATION (function 2): Ignoring function, connection "
                        "identifier not recognized by the implementation"));
    CHECK(file_has_line(error_file,
                        "ERROR 53 in OPEN WORKSTATION (function 2): Ignoring function, workstation "
                        "identifier already is in use"));
    CHECK(file_has_line(error_file,
                        "ERROR 52 in OPEN WORKSTATION (function 2): Ignoring function, workstation type "
                        "not recognized by the implementation (workstation type 77)"));
    EXPECT_NO_ERROR(pclose_ws(1));
    EXPECT_ERROR(pclose_ws(1), 3, Pfn_close_ws);
}

/* A file type whose file cannot be written: 903 at UPDATE WORKSTATION, and again at CLOSE
   WORKSTATION, which writes the last picture first; the workstation is closed all the same. */
static void unwritable_files(void) {
    const Pint types[] = {PWST_PDF, PWST_SVG, PWST_EPS, PWST_PNG};
    char path[600];
    snprintf(path, sizeof path, "%s/under_a_file.out", error_file); /* the error file is no folder */
    for (int i = 0; i < 4; ++i) {
        Pws_st st = PWS_ST_WSOP;
        EXPECT_NO_ERROR(popen_ws(4, path, types[i]));
        EXPECT_ERROR(pupd_ws(4, PFLAG_PERFORM), 903, Pfn_upd_ws);
        EXPECT_ERROR(pclose_ws(4), 903, Pfn_close_ws);
        pinq_ws_st(&st);
        CHECK(st == PWS_ST_WSCL);
    }
}

static void posting_and_inquiries(void) {
    Pint err = -1, total = 0, ids[4], type = 0;
    Pint_list open = {0, ids};
    Pposted_struct postings[4];
    Pposted_struct_list posted = {0, postings};
    void* conn = NULL;
    Pstore store = NULL;
    pcreate_store(&err, &store);
    CHECK(err == 0);

    EXPECT_NO_ERROR(popen_ws(3, svg_file, PWST_SVG));
    EXPECT_NO_ERROR(popen_ws(1, pdf_file, PWST_PDF));
    pinq_open_wss(4, 0, &err, &open, &total);
    CHECK(err == 0 && total == 2 && open.num_ints == 2 && ids[0] == 1 && ids[1] == 3);
    pinq_ws_conn_type(3, store, &err, &conn, &type);
    CHECK(err == 0 && type >= PWST_SPECIFIC_BASE && conn && strcmp((const char*)conn, svg_file) == 0);
    pinq_ws_conn_type(2, store, &err, &conn, &type);
    CHECK(err == 54);

    EXPECT_NO_ERROR(ppost_struct(1, 10, 0.7f));
    EXPECT_NO_ERROR(ppost_struct(1, 11, 0.2f));
    EXPECT_NO_ERROR(ppost_struct(1, 12, 0.7f));
    pinq_posted_structs(1, 4, 0, &err, &posted, &total);
    CHECK(err == 0 && total == 3 && posted.num_postings == 3);
    CHECK(postings[0].id == 11 && postings[1].id == 10 && postings[2].id == 12);
    CHECK(fabsf(postings[0].disp_pri - 0.2f) < 1e-6f);
    pinq_posted_structs(1, 1, 2, &err, &posted, &total); /* from the third on */
    CHECK(err == 0 && total == 3 && posted.num_postings == 1 && postings[0].id == 12);
    pinq_posted_structs(1, 1, 3, &err, &posted, &total);
    CHECK(err == PE_START_IND_INVAL);
    pinq_posted_structs(9, 1, 0, &err, &posted, &total);
    CHECK(err == 54);
    EXPECT_NO_ERROR(punpost_struct(1, 10));
    pinq_posted_structs(1, 4, 0, &err, &posted, &total);
    CHECK(err == 0 && total == 2);
    EXPECT_NO_ERROR(punpost_all_structs(1));
    pinq_posted_structs(1, 4, 0, &err, &posted, &total);
    CHECK(err == 0 && total == 0);

    /* Window and viewport: the core's checks. */
    Plimit3 window = {0, 1, 0, 1, 0, 1}, bad = {0.5f, 0.2f, 0, 1, 0, 1}, outside = {0, 2, 0, 1, 0, 1};
    Plimit viewport = {0, 500, 0, 500};
    EXPECT_NO_ERROR(pset_ws_win3(1, &window));
    EXPECT_ERROR(pset_ws_win3(1, &bad), 151, Pfn_set_ws_win3);
    EXPECT_ERROR(pset_ws_win3(1, &outside), 156, Pfn_set_ws_win3);
    EXPECT_ERROR(pset_ws_win3(1, NULL), -204, Pfn_set_ws_win3);
    EXPECT_NO_ERROR(pset_ws_vp(1, &viewport));
    viewport.x_max = 5000;
    EXPECT_ERROR(pset_ws_vp(1, &viewport), 157, Pfn_set_ws_vp);

    Pview_rep3 view;
    memset(&view, 0, sizeof view);
    for (int i = 0; i < 4; ++i) view.ori_matrix[i][i] = view.map_matrix[i][i] = 1;
    view.clip_limit = window;
    view.xy_clip = view.back_clip = view.front_clip = PIND_CLIP;
    EXPECT_NO_ERROR(pset_view_rep3(1, 1, &view));
    EXPECT_ERROR(pset_view_rep3(1, 0, &view), 115, Pfn_set_view_rep3);
    view.xy_clip = (Pclip_ind)5;
    EXPECT_ERROR(pset_view_rep3(1, 2, &view), PE_ENUM_TYPE_INVAL, Pfn_set_view_rep3);

    EXPECT_NO_ERROR(pclose_ws(3));
    EXPECT_NO_ERROR(pclose_ws(1));
    pdel_store(store);
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    snprintf(error_file, sizeof error_file, "%s/workstations_errors.txt", dir);
    snprintf(pdf_file, sizeof pdf_file, "%s/workstations.pdf", dir);
    snprintf(svg_file, sizeof svg_file, "%s/workstations.svg", dir);
    void (*old)(Pint, Pint, const char*) = NULL;
    pset_err_hand(recording_handler, &old);
    EXPECT_ERROR(popen_ws(1, pdf_file, PWST_PDF), 2, Pfn_open_ws); /* PHIGS closed */
    open_with_handler(error_file);
    types_by_inquiry();
    {
        const int lines = file_line_count(error_file);
        gdps_and_gses();
        CHECK(file_line_count(error_file) == lines); /* inquiries answer, never log */
    }
    open_and_close_errors();
    unwritable_files();
    posting_and_inquiries();
    pclose_phigs();
    /* The closed hardcopies are complete files. */
    FILE* f = fopen(pdf_file, "rb");
    char magic[5] = {0};
    CHECK(f && fread(magic, 1, 4, f) == 4 && strcmp(magic, "%PDF") == 0);
    if (f) fclose(f);
    f = fopen(svg_file, "rb");
    CHECK(f != NULL);
    if (f) fclose(f);
    return finish("test_workstations");
}
