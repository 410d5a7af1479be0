/* Workstation state: SET DISPLAY UPDATE STATE under every deferral and modification mode, the
 * requested and current view representation, workstation transformation and HLHSR mode with
 * their update states, UPDATE WORKSTATION with POSTPONE and PERFORM, the visual state, view
 * input priority, the highlighting and invisibility filters and their errors. Opens only the
 * SVG hardcopy type (cairo, no GPU). argv[1]: a directory for the files. */
#include "check.h"

static char error_file[512], svg_file[512], svg_file2[512];

static void identity(Pmatrix3 m) {
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[r][c] = r == c ? 1.0f : 0.0f;
}

/* A view that scales x by `s` and clips to [0, 0.5] in x. */
static Pview_rep3 view_scaled(Pfloat s) {
    Pview_rep3 v;
    identity(v.ori_matrix);
    identity(v.map_matrix);
    v.map_matrix[0][0] = s;
    v.clip_limit = (Plimit3){0.0f, 0.5f, 0.0f, 1.0f, 0.0f, 1.0f};
    v.xy_clip = v.back_clip = v.front_clip = PIND_CLIP;
    return v;
}

static int at_once(Pdefer_mode d) {
    return d == PDEFER_ASAP || d == PDEFER_BNIG || d == PDEFER_BNIL;
}

/* One deferral and modification mode: a change of view 1, the workstation window and the HLHSR
 * mode takes effect at once (ASAP, BNIG, BNIL), simulated at once (UQUM) or pends until
 * UPDATE WORKSTATION (PERFORM); POSTPONE changes nothing. */
static void one_mode(Pdefer_mode d, Pmod_mode m, int round) {
    const Pint ws = 1;
    Pint err = -1, cur_mode = -1, req_mode = -1;
    Pupd_st upd = PUPD_PEND;
    Pdefer_mode dm;
    Pmod_mode mm;
    Pdisp_surf_empty empty;
    Pvisual_st vis;
    Pview_rep3 cur, req;
    Plimit3 req_win, cur_win, req_vp, cur_vp;
    EXPECT_NO_ERROR(pset_disp_upd_st(ws, d, m));
    pinq_disp_upd_st(ws, &err, &dm, &mm, &empty, &vis);
    CHECK(err == 0 && dm == d && mm == m && vis == PVISUAL_ST_CORRECT);

    const Pfloat s = 0.5f + 0.01f * (Pfloat)round;
    const Pview_rep3 v = view_scaled(s);
    const Plimit3 win = {0.0f, s, 0.0f, s, 0.0f, 1.0f};
    const Pint mode = round % 2 ? 1 : 0;
    EXPECT_NO_ERROR(pset_view_rep3(ws, 1, &v));
    EXPECT_NO_ERROR(pset_ws_win3(ws, &win));
    EXPECT_NO_ERROR(pset_hlhsr_mode(ws, mode));

    const int immediate = at_once(d), simulated = !immediate && m == PMODE_UQUM;
    const int effective = immediate || simulated;
    pinq_view_rep(ws, 1, &err, &upd, &cur, &req);
    CHECK(err == 0 && near(req.map_matrix[0][0], s));
    CHECK(upd == (effective ? PUPD_NOT_PEND : PUPD_PEND));
    CHECK(effective ? near(cur.map_matrix[0][0], s) : !near(cur.map_matrix[0][0], s));
    pinq_ws_tran3(ws, &err, &upd, &req_win, &cur_win, &req_vp, &cur_vp);
    CHECK(err == 0 && near(req_win.x_max, s) && upd == (effective ? PUPD_NOT_PEND : PUPD_PEND));
    CHECK(effective ? near(cur_win.x_max, s) : !near(cur_win.x_max, s));
    pinq_hlhsr_mode(ws, &err, &upd, &cur_mode, &req_mode);
    CHECK(err == 0 && req_mode == mode && (effective ? cur_mode == mode : cur_mode != mode));
    CHECK(upd == (effective ? PUPD_NOT_PEND : PUPD_PEND));
    pinq_disp_upd_st(ws, &err, &dm, &mm, &empty, &vis);
    CHECK(err == 0 && empty == PSURF_NOT_EMPTY);
    CHECK(vis == (immediate ? PVISUAL_ST_CORRECT : simulated ? PVISUAL_ST_SIMULATED : PVISUAL_ST_DEFER));

    EXPECT_NO_ERROR(pupd_ws(ws, PFLAG_POSTPONE)); /* no regeneration: still pending */
    pinq_ws_tran3(ws, &err, &upd, &req_win, &cur_win, &req_vp, &cur_vp);
    CHECK(err == 0 && upd == (effective ? PUPD_NOT_PEND : PUPD_PEND));
    EXPECT_NO_ERROR(pupd_ws(ws, PFLAG_PERFORM));
    pinq_view_rep(ws, 1, &err, &upd, &cur, &req);
    CHECK(err == 0 && upd == PUPD_NOT_PEND && near(cur.map_matrix[0][0], s));
    pinq_ws_tran(ws, &err, &upd, NULL, NULL, NULL, NULL);
    CHECK(err == 0 && upd == PUPD_NOT_PEND);
    pinq_hlhsr_mode(ws, &err, &upd, &cur_mode, &req_mode);
    CHECK(err == 0 && upd == PUPD_NOT_PEND && cur_mode == mode);
    pinq_disp_upd_st(ws, &err, &dm, &mm, &empty, &vis);
    CHECK(err == 0 && vis == PVISUAL_ST_CORRECT);
}

/* Switching from WAIT to ASAP performs what was deferred. */
static void deferred_then_asap(void) {
    Pint err = -1, cur_mode = -1, req_mode = -1;
    Pupd_st upd;
    Pvisual_st vis;
    EXPECT_NO_ERROR(pset_disp_upd_st(1, PDEFER_WAIT, PMODE_NIVE));
    pinq_hlhsr_mode(1, &err, &upd, &cur_mode, &req_mode);
    CHECK(err == 0 && req_mode == 1 && cur_mode == 1 && upd == PUPD_NOT_PEND);
    EXPECT_NO_ERROR(pset_hlhsr_mode(1, 0));
    pinq_hlhsr_mode(1, &err, &upd, &cur_mode, &req_mode);
    CHECK(err == 0 && req_mode == 0 && cur_mode == 1 && upd == PUPD_PEND);
    EXPECT_NO_ERROR(pset_disp_upd_st(1, PDEFER_ASAP, PMODE_NIVE));
    pinq_hlhsr_mode(1, &err, &upd, &cur_mode, &req_mode);
    CHECK(err == 0 && cur_mode == 0 && upd == PUPD_NOT_PEND);
    pinq_disp_upd_st(1, &err, NULL, NULL, NULL, &vis);
    CHECK(err == 0 && vis == PVISUAL_ST_CORRECT);
}

static void errors_leave_state(void) {
    Pint err = -1, cur_mode = -1, req_mode = -1;
    Pupd_st upd;
    Pdefer_mode dm;
    Pmod_mode mm;
    Pview_rep3 cur, req;
    EXPECT_ERROR(pset_disp_upd_st(1, (Pdefer_mode)9, PMODE_NIVE), PE_ENUM_TYPE_INVAL, Pfn_set_disp_upd_st);
    EXPECT_ERROR(pset_disp_upd_st(1, PDEFER_WAIT, (Pmod_mode)-1), PE_ENUM_TYPE_INVAL, Pfn_set_disp_upd_st);
    EXPECT_ERROR(pset_disp_upd_st(7, PDEFER_WAIT, PMODE_NIVE), 54, Pfn_set_disp_upd_st);
    pinq_disp_upd_st(1, &err, &dm, &mm, NULL, NULL);
    CHECK(err == 0 && dm == PDEFER_ASAP && mm == PMODE_NIVE); /* unchanged by the refusals */
    EXPECT_ERROR(pset_hlhsr_mode(1, 5), 111, Pfn_set_hlhsr_mode);
    pinq_hlhsr_mode(1, &err, &upd, &cur_mode, &req_mode);
    CHECK(err == 0 && req_mode == 0 && cur_mode == 0);
    pinq_hlhsr_mode(7, &err, &upd, &cur_mode, &req_mode);
    CHECK(err == 54);
    pinq_view_rep(1, -1, &err, &upd, &cur, &req);
    CHECK(err == 114);
    pinq_view_rep(1, 30, &err, &upd, &cur, &req);
    CHECK(err == 101);
    pinq_view_rep(1, 0, &err, &upd, &cur, &req); /* view 0: the identity, always defined */
    CHECK(err == 0 && upd == PUPD_NOT_PEND && near(req.map_matrix[0][0], 1.0f) && req.xy_clip == PIND_CLIP);
    pinq_def_disp_upd_st(PWST_SVG, &err, &dm, &mm);
    CHECK(err == 0 && dm == PDEFER_ASAP && mm == PMODE_NIVE);
    pinq_def_disp_upd_st(77, &err, &dm, &mm);
    CHECK(err == 52);
}

static void input_priority(void) {
    Pint err = -1, total = 0, ids[8];
    Pint_list list = {0, ids};
    const Pview_rep3 v = view_scaled(0.25f);
    EXPECT_NO_ERROR(pset_view_rep3(1, 3, &v));
    pinq_list_view_inds(1, 8, 0, &err, &list, &total);
    CHECK(err == 0 && total == 3 && ids[0] == 0 && ids[1] == 1 && ids[2] == 3);
    EXPECT_NO_ERROR(pset_view_tran_in_pri(1, 3, 0, PPRI_HIGHER));
    pinq_list_view_inds(1, 8, 0, &err, &list, &total);
    CHECK(err == 0 && total == 3 && ids[0] == 3 && ids[1] == 0 && ids[2] == 1);
    EXPECT_ERROR(pset_view_tran_in_pri(1, -1, 0, PPRI_LOWER), 114, Pfn_set_view_tran_in_pri);
    EXPECT_ERROR(pset_view_tran_in_pri(1, 5, 0, PPRI_LOWER), 101, Pfn_set_view_tran_in_pri);
    EXPECT_ERROR(pset_view_tran_in_pri(1, 1, 0, (Prel_pri)4), PE_ENUM_TYPE_INVAL, Pfn_set_view_tran_in_pri);
    pinq_list_view_inds(1, 1, 1, &err, &list, &total); /* the second only */
    CHECK(err == 0 && total == 3 && list.num_ints == 1 && ids[0] == 0);
    pinq_list_view_inds(1, 1, 5, &err, &list, &total);
    CHECK(err == PE_START_IND_INVAL);
}

static void filters(void) {
    Pint err = -1, in[3] = {5, 2, 9}, ex[1] = {2};
    Pfilter f = {{3, in}, {1, ex}}, *answer = NULL;
    Pstore store = NULL;
    pcreate_store(&err, &store);
    pinq_highl_filter(1, store, &err, &answer);
    CHECK(err == 0 && answer && answer->incl_set.num_ints == 0 && answer->excl_set.num_ints == 0);
    EXPECT_NO_ERROR(pset_highl_filter(1, &f));
    pinq_highl_filter(1, store, &err, &answer);
    CHECK(err == 0 && answer->incl_set.num_ints == 3 && answer->excl_set.num_ints == 1);
    CHECK(answer->incl_set.ints[0] == 2 && answer->incl_set.ints[1] == 5 && answer->incl_set.ints[2] == 9);
    CHECK(answer->excl_set.ints[0] == 2);
    f.excl_set.num_ints = 0;
    EXPECT_NO_ERROR(pset_invis_filter(1, &f));
    pinq_invis_filter(1, store, &err, &answer);
    CHECK(err == 0 && answer->incl_set.num_ints == 3 && answer->excl_set.num_ints == 0);
    f.incl_set.num_ints = -1;
    EXPECT_ERROR(pset_invis_filter(1, &f), -204, Pfn_set_invis_filter);
    EXPECT_ERROR(pset_highl_filter(1, NULL), -204, Pfn_set_highl_filter);
    EXPECT_ERROR(pset_highl_filter(9, NULL), 54, Pfn_set_highl_filter);
    pinq_invis_filter(1, store, &err, &answer);
    CHECK(err == 0 && answer->incl_set.num_ints == 3); /* unchanged by the refusal */
    pinq_highl_filter(1, NULL, &err, &answer);
    CHECK(err == PE_ALLOC_STORE);
    pdel_store(store);
}

static void posted_to(void) {
    Pint err = -1, total = 0, ids[4];
    Pint_list list = {0, ids};
    Pdisp_surf_empty empty;
    EXPECT_NO_ERROR(popen_ws(2, svg_file2, PWST_SVG));
    pinq_disp_upd_st(2, &err, NULL, NULL, &empty, NULL);
    CHECK(err == 0 && empty == PSURF_EMPTY);
    EXPECT_NO_ERROR(ppost_struct(2, 10, 0.5f));
    pinq_wss_posted(10, 4, 0, &err, &list, &total);
    CHECK(err == 0 && total == 2 && ids[0] == 1 && ids[1] == 2);
    pinq_wss_posted(11, 4, 0, &err, &list, &total);
    CHECK(err == 201);
    EXPECT_NO_ERROR(pclose_ws(2));
    pinq_wss_posted(10, 4, 0, &err, &list, &total);
    CHECK(err == 0 && total == 1 && ids[0] == 1);
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    Pint err = -1;
    Pdefer_mode dm;
    snprintf(error_file, sizeof error_file, "%s/ws_state_errors.txt", dir);
    snprintf(svg_file, sizeof svg_file, "%s/ws_state.svg", dir);
    snprintf(svg_file2, sizeof svg_file2, "%s/ws_state2.svg", dir);
    open_with_handler(error_file);
    pinq_disp_upd_st(1, &err, &dm, NULL, NULL, NULL);
    CHECK(err == 3);
    EXPECT_ERROR(pset_disp_upd_st(1, PDEFER_WAIT, PMODE_NIVE), 3, Pfn_set_disp_upd_st);
    EXPECT_NO_ERROR(popen_ws(1, svg_file, PWST_SVG));
    popen_struct(10);
    {
        Ppoint3 pts[2] = {{0.1f, 0.1f, 0.0f}, {0.9f, 0.9f, 0.0f}};
        Ppoint_list3 line = {2, pts};
        ppolyline3(&line);
    }
    pclose_struct();
    EXPECT_NO_ERROR(ppost_struct(1, 10, 0.5f));
    int round = 0;
    for (int d = PDEFER_ASAP; d <= PDEFER_WAIT; ++d)
        for (int m = PMODE_NIVE; m <= PMODE_UQUM; ++m) one_mode((Pdefer_mode)d, (Pmod_mode)m, ++round);
    deferred_then_asap();
    errors_leave_state();
    input_priority();
    filters();
    posted_to();
    EXPECT_NO_ERROR(pclose_ws(1));
    pclose_phigs();
    return finish("test_ws_state");
}
