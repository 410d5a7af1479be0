/* PHIGS PLUS bundle and pattern representations: random extended bundles (general colours,
 * shading, reflectance, approximation, back faces) set and inquired with SET and REALIZED
 * values under every deferral and modification mode, the plain and PLUS views of one table
 * cross-checked both ways, the predefined PLUS representations, facilities, table lengths and
 * dynamics of every workstation type, the errors (each refusal leaves the entry as it was), and
 * the colours the SVG picture draws from them. Opens only the SVG hardcopy type (no GPU).
 * argv[1]: a directory for the files. */
#include "check.h"

static char error_file[512], svg_file[512];

static const Pint types[6] = {PWST_OFFSCREEN, PWST_WINDOW, PWST_PNG, PWST_PDF, PWST_SVG, PWST_EPS};

static int random_int(int lo, int hi) {
    return lo + (int)(next_random() % (unsigned)(hi - lo + 1));
}

/* An index (0 .. 20: 0 .. 7 are defined) or a direct RGB colour. */
static Pgcolr random_colour(void) {
    Pgcolr c;
    memset(&c, 0, sizeof c);
    if (next_random() % 2) {
        c.type = PINDIRECT;
        c.val.ind = random_int(0, 20);
    } else {
        c.type = PMODEL_RGB;
        c.val.general.x = random_real(0, 1), c.val.general.y = random_real(0, 1),
        c.val.general.z = random_real(0, 1);
    }
    return c;
}

static int same_colour(Pgcolr a, Pgcolr b) {
    if (a.type != b.type) return 0;
    if (a.type == PINDIRECT) return a.val.ind == b.val.ind;
    return near(a.val.general.x, b.val.general.x) && near(a.val.general.y, b.val.general.y) &&
           near(a.val.general.z, b.val.general.z);
}

/* What is drawn: an index the colour table does not define as index 1. */
static Pgcolr realized_colour(Pgcolr c) {
    if (c.type == PINDIRECT && c.val.ind > 7) c.val.ind = 1;
    return c;
}

static Pfloat clampf(Pfloat v, Pfloat lo, Pfloat hi) {
    return v < lo ? lo : v > hi ? hi : v;
}

static Prefl_props random_props(void) {
    Prefl_props p;
    p.ambient_coef = random_real(0, 1), p.diffuse_coef = random_real(0, 1),
    p.specular_coef = random_real(0, 1);
    p.specular_colr = random_colour();
    p.specular_exp = random_real(1, 100), p.transpar_coef = random_real(0, 1);
    return p;
}

static int same_props(Prefl_props a, Prefl_props b, int realize) {
    return near(a.ambient_coef, b.ambient_coef) && near(a.diffuse_coef, b.diffuse_coef) &&
           near(a.specular_coef, b.specular_coef) && near(a.specular_exp, b.specular_exp) &&
           near(a.transpar_coef, b.transpar_coef) &&
           same_colour(realize ? realized_colour(a.specular_colr) : a.specular_colr, b.specular_colr);
}

static Pint_bundle_plus random_interior(void) {
    Pint_bundle_plus b;
    b.style = (Pint_style)random_int(PSTYLE_HOLLOW, PSTYLE_EMPTY), b.style_ind = random_int(1, 6);
    b.colr = random_colour(), b.refl_eqn = random_int(PREFL_NONE, PREFL_AMB_DIFF_SPEC);
    b.shad_meth = random_int(PSD_NONE, PSD_NORMAL), b.refl_props = random_props();
    b.back_style = (Pint_style)random_int(PSTYLE_HOLLOW, PSTYLE_EMPTY), b.back_style_ind = random_int(1, 6);
    b.back_colr = random_colour(), b.back_refl_eqn = random_int(PREFL_NONE, PREFL_AMB_DIFF_SPEC);
    b.back_shad_meth = random_int(PSD_NONE, PSD_NORMAL), b.back_refl_props = random_props();
    b.approx_type = random_int(0, 2) == 0 ? PSURF_WS_DEP
                    : random_int(0, 1)    ? PSURF_CONST_PARAM_SUBDIV_BETWEEN_KNOTS
                                          : PSURF_CHORDAL_DEVIATION_WC;
    b.approx_val[0] = random_real(0.001, 16), b.approx_val[1] = random_real(0.001, 16);
    return b;
}

static int same_interior(const Pint_bundle_plus* a, const Pint_bundle_plus* b, int realize) {
    Pgcolr colr = realize ? realized_colour(a->colr) : a->colr;
    Pgcolr back = realize ? realized_colour(a->back_colr) : a->back_colr;
    return a->style == b->style && a->style_ind == b->style_ind && same_colour(colr, b->colr) &&
           a->refl_eqn == b->refl_eqn && a->shad_meth == b->shad_meth &&
           same_props(a->refl_props, b->refl_props, realize) && a->back_style == b->back_style &&
           a->back_style_ind == b->back_style_ind && same_colour(back, b->back_colr) &&
           a->back_refl_eqn == b->back_refl_eqn && a->back_shad_meth == b->back_shad_meth &&
           same_props(a->back_refl_props, b->back_refl_props, realize) && a->approx_type == b->approx_type &&
           near(a->approx_val[0], b->approx_val[0]) && near(a->approx_val[1], b->approx_val[1]);
}

/* The visual state after a change in mode (d, m): correct at once (ASAP, BNIG, BNIL), simulated
 * (UQUM) or deferred until UPDATE WORKSTATION. */
static void check_visual_state(Pdefer_mode d, Pmod_mode m) {
    Pint err = -1;
    Pvisual_st vis;
    const int at_once = d == PDEFER_ASAP || d == PDEFER_BNIG || d == PDEFER_BNIL;
    pinq_disp_upd_st(1, &err, NULL, NULL, NULL, &vis);
    CHECK(err == 0 && vis == (at_once           ? PVISUAL_ST_CORRECT
                              : m == PMODE_UQUM ? PVISUAL_ST_SIMULATED
                                                : PVISUAL_ST_DEFER));
    EXPECT_NO_ERROR(pupd_ws(1, PFLAG_PERFORM));
    pinq_disp_upd_st(1, &err, NULL, NULL, NULL, &vis);
    CHECK(err == 0 && vis == PVISUAL_ST_CORRECT);
}

/* A random polyline bundle: SET and REALIZED (width within 1 .. 16 device units) through the PLUS
 * inquiry, and the plain view (134 for a direct colour). */
static void one_line(Pint index) {
    Pint err = -1;
    Pline_bundle_plus set, got;
    Pline_bundle plain;
    set.type = random_int(PLINE_SOLID, PLINE_DASH_DOT), set.width = random_real(0.1, 30);
    set.colr = random_colour(), set.shad_meth = random_int(PSD_NONE, PSD_COLOUR);
    set.approx_type = random_int(0, 1) ? PCURV_CONST_PARAM_SUBDIV_BETWEEN_KNOTS : PCURV_CHORDAL_DEVIATION_WC;
    set.approx_val = random_real(0.01, 20);
    EXPECT_NO_ERROR(pset_line_rep_plus(1, index, &set));
    pinq_line_rep_plus(1, index, PINQ_SET, &err, &got);
    CHECK(err == 0 && got.type == set.type && near(got.width, set.width) && same_colour(got.colr, set.colr));
    CHECK(got.shad_meth == set.shad_meth && got.approx_type == set.approx_type &&
          near(got.approx_val, set.approx_val));
    pinq_line_rep_plus(1, index, PINQ_REALIZED, &err, &got);
    CHECK(err == 0 && near(got.width, clampf(set.width, 1, 16)) &&
          same_colour(got.colr, realized_colour(set.colr)) && got.shad_meth == set.shad_meth);
    pinq_line_rep(1, index, PINQ_SET, &err, &plain);
    if (set.colr.type == PINDIRECT)
        CHECK(err == 0 && plain.type == set.type && near(plain.width, set.width) &&
              plain.colr_ind == set.colr.val.ind);
    else
        CHECK(err == 134);
}

static void one_marker_text_edge(Pint index) {
    Pint err = -1;
    Pmarker_bundle_plus marker = {random_int(PMARKER_DOT, PMARKER_CROSS), random_real(0.05, 20),
                                  random_colour()},
                        marker_got;
    Ptext_bundle_plus text = {random_int(1, 4), (Ptext_prec)random_int(PPREC_STRING, PPREC_STROKE),
                              random_real(0.001, 200), random_real(-1, 1), random_colour()},
                      text_got;
    Pedge_bundle_plus edge = {(Pedge_flag)random_int(PEDGE_OFF, PEDGE_ON),
                              random_int(PLINE_SOLID, PLINE_DASH_DOT), random_real(0.1, 30), random_colour()},
                      edge_got;
    Pmarker_bundle marker_plain;
    Ptext_bundle text_plain;
    Pedge_bundle edge_plain;
    EXPECT_NO_ERROR(pset_marker_rep_plus(1, index, &marker));
    EXPECT_NO_ERROR(pset_text_rep_plus(1, index, &text));
    EXPECT_NO_ERROR(pset_edge_rep_plus(1, index, &edge));
    pinq_marker_rep_plus(1, index, PINQ_SET, &err, &marker_got);
    CHECK(err == 0 && marker_got.type == marker.type && near(marker_got.size, marker.size) &&
          same_colour(marker_got.colr, marker.colr));
    pinq_marker_rep_plus(1, index, PINQ_REALIZED, &err, &marker_got); /* 1 .. 64 device units of 8 */
    CHECK(err == 0 && near(marker_got.size, clampf(marker.size * 7, 1, 64) / 7) &&
          same_colour(marker_got.colr, realized_colour(marker.colr)));
    pinq_text_rep_plus(1, index, PINQ_SET, &err, &text_got);
    CHECK(err == 0 && text_got.font == text.font && text_got.prec == text.prec &&
          near(text_got.char_expan, text.char_expan) && near(text_got.char_space, text.char_space) &&
          same_colour(text_got.colr, text.colr));
    pinq_text_rep_plus(1, index, PINQ_REALIZED, &err, &text_got); /* stroke fonts, expansion 0.01 .. 100 */
    CHECK(err == 0 && text_got.prec == PPREC_STROKE &&
          near(text_got.char_expan, clampf(text.char_expan, 0.01f, 100)) &&
          same_colour(text_got.colr, realized_colour(text.colr)));
    pinq_edge_rep_plus(1, index, PINQ_SET, &err, &edge_got);
    CHECK(err == 0 && edge_got.flag == edge.flag && edge_got.type == edge.type &&
          near(edge_got.width, edge.width) && same_colour(edge_got.colr, edge.colr));
    pinq_edge_rep_plus(1, index, PINQ_REALIZED, &err, &edge_got);
    CHECK(err == 0 && near(edge_got.width, clampf(edge.width, 1, 16)) &&
          same_colour(edge_got.colr, realized_colour(edge.colr)));
    pinq_marker_rep(1, index, PINQ_SET, &err, &marker_plain);
    CHECK(marker.colr.type == PINDIRECT ? err == 0 && marker_plain.colr_ind == marker.colr.val.ind
                                        : err == 134);
    pinq_text_rep(1, index, PINQ_SET, &err, &text_plain);
    CHECK(text.colr.type == PINDIRECT ? err == 0 && text_plain.font == text.font : err == 134);
    pinq_edge_rep(1, index, PINQ_SET, &err, &edge_plain);
    CHECK(edge.colr.type == PINDIRECT ? err == 0 && edge_plain.flag == edge.flag : err == 134);
}

static void one_interior(Pint index) {
    Pint err = -1;
    Pint_bundle_plus set = random_interior(), got;
    Pint_bundle plain;
    EXPECT_NO_ERROR(pset_int_rep_plus(1, index, &set));
    pinq_int_rep_plus(1, index, PINQ_SET, &err, &got);
    CHECK(err == 0 && same_interior(&set, &got, 0));
    pinq_int_rep_plus(1, index, PINQ_REALIZED, &err, &got);
    CHECK(err == 0 && same_interior(&set, &got, 1));
    pinq_int_rep(1, index, PINQ_SET, &err, &plain);
    if (set.colr.type == PINDIRECT)
        CHECK(err == 0 && plain.style == set.style && plain.style_ind == set.style_ind &&
              plain.colr_ind == set.colr.val.ind);
    else
        CHECK(err == 134);
}

/* A random pattern of one colour type: PLUS SET and REALIZED, and the plain view. */
static void one_pattern(Pint index, Pstore store) {
    Pint err = -1;
    Pcoval cells[16];
    Ppat_rep_plus set = {{random_int(1, 4), random_int(1, 4)},
                         next_random() % 2 ? PINDIRECT : PMODEL_RGB,
                         cells},
                  *got = NULL;
    Ppat_rep* plain = NULL;
    const int n = set.dims.size_x * set.dims.size_y;
    for (int i = 0; i < n; ++i) {
        if (set.type == PINDIRECT)
            cells[i].ind = random_int(0, 12);
        else
            cells[i].direct.rgb.red = random_real(0, 1), cells[i].direct.rgb.green = random_real(0, 1),
            cells[i].direct.rgb.blue = random_real(0, 1);
    }
    EXPECT_NO_ERROR(pset_pat_rep_plus(1, index, &set));
    for (int realize = 0; realize <= 1; ++realize) {
        pinq_pat_rep_plus(1, index, realize ? PINQ_REALIZED : PINQ_SET, store, &err, &got);
        CHECK(err == 0 && got && got->dims.size_x == set.dims.size_x && got->dims.size_y == set.dims.size_y &&
              got->type == set.type);
        for (int i = 0; err == 0 && i < n; ++i) {
            if (set.type == PINDIRECT)
                CHECK(got->colr_array[i].ind == (realize && cells[i].ind > 7 ? 1 : cells[i].ind));
            else
                CHECK(near(got->colr_array[i].direct.rgb.red, cells[i].direct.rgb.red) &&
                      near(got->colr_array[i].direct.rgb.blue, cells[i].direct.rgb.blue));
        }
    }
    pinq_pat_rep(1, index, PINQ_SET, store, &err, &plain);
    if (set.type == PINDIRECT)
        CHECK(err == 0 && plain->dims.size_x == set.dims.size_x &&
              plain->colr_array[n - 1] == cells[n - 1].ind);
    else
        CHECK(err == 134);
}

/* Random PLUS entries under every deferral and modification mode; each change shows as the mode
 * says until UPDATE WORKSTATION. */
static void plus_under_every_mode(Pstore store) {
    for (int d = PDEFER_ASAP; d <= PDEFER_WAIT; ++d)
        for (int m = PMODE_NIVE; m <= PMODE_UQUM; ++m)
            for (int round = 0; round < 4; ++round) {
                const Pint index = random_int(6, 20);
                EXPECT_NO_ERROR(pset_disp_upd_st(1, (Pdefer_mode)d, (Pmod_mode)m));
                one_line(index);
                check_visual_state((Pdefer_mode)d, (Pmod_mode)m);
                one_marker_text_edge(index);
                one_interior(index);
                check_visual_state((Pdefer_mode)d, (Pmod_mode)m);
                one_pattern(random_int(3, 12), store);
                check_visual_state((Pdefer_mode)d, (Pmod_mode)m);
            }
    EXPECT_NO_ERROR(pset_disp_upd_st(1, PDEFER_ASAP, PMODE_NIVE));
}

/* A plain SET over a PLUS entry: the PLUS view answers the index as PINDIRECT and the PHIGS PLUS
 * fields at their defaults (the back face as the front). */
static void plain_over_plus(Pstore store) {
    Pint err = -1, cells[2] = {4, 30};
    for (int round = 0; round < 20; ++round) {
        const Pint index = random_int(21, 30);
        Pline_bundle line = {random_int(1, 4), random_real(0.5, 4), random_int(0, 40)};
        Pline_bundle_plus line_plus;
        Pint_bundle interior = {(Pint_style)random_int(0, 4), random_int(1, 5), random_int(0, 40)};
        Pint_bundle_plus int_plus = random_interior();
        Ppat_rep pattern = {{2, 1}, cells};
        Ppat_rep_plus* pattern_plus = NULL;
        EXPECT_NO_ERROR(pset_int_rep_plus(1, index, &int_plus));
        EXPECT_NO_ERROR(pset_line_rep(1, index, &line));
        EXPECT_NO_ERROR(pset_int_rep(1, index, &interior));
        pinq_line_rep_plus(1, index, PINQ_SET, &err, &line_plus);
        CHECK(err == 0 && line_plus.type == line.type && near(line_plus.width, line.width) &&
              line_plus.colr.type == PINDIRECT && line_plus.colr.val.ind == line.colr_ind);
        CHECK(line_plus.shad_meth == PSD_NONE && line_plus.approx_type == PCURV_WS_DEP &&
              near(line_plus.approx_val, 1));
        pinq_int_rep_plus(1, index, PINQ_SET, &err, &int_plus);
        CHECK(err == 0 && int_plus.style == interior.style && int_plus.back_style == interior.style &&
              int_plus.style_ind == interior.style_ind && int_plus.back_style_ind == interior.style_ind);
        CHECK(int_plus.colr.type == PINDIRECT && int_plus.colr.val.ind == interior.colr_ind &&
              same_colour(int_plus.back_colr, int_plus.colr));
        CHECK(int_plus.refl_eqn == PREFL_NONE && int_plus.shad_meth == PSD_NONE &&
              int_plus.back_shad_meth == PSD_NONE && int_plus.approx_type == PSURF_WS_DEP);
        CHECK(near(int_plus.refl_props.ambient_coef, 0.3f) && near(int_plus.refl_props.diffuse_coef, 0.7f) &&
              int_plus.refl_props.specular_colr.type == PMODEL_RGB);
        EXPECT_NO_ERROR(pset_pat_rep(1, 2, &pattern));
        pinq_pat_rep_plus(1, 2, PINQ_REALIZED, store, &err, &pattern_plus); /* colour 30 is not defined */
        CHECK(err == 0 && pattern_plus->type == PINDIRECT && pattern_plus->colr_array[0].ind == 4 &&
              pattern_plus->colr_array[1].ind == 1);
    }
}

/* The predefined PLUS representations of every type: the plain ones with an indexed colour and
 * the PHIGS PLUS defaults, as many as the facilities say, and what a new workstation holds. */
static void predefined(Pstore store) {
    for (int k = 0; k < 6; ++k) {
        const Pint t = types[k];
        Pint err = -1, total = 0, ints[8], count = 0;
        Pline_facs line_facs = {{0, ints}, 0, 0, 0, 0, 0};
        pinq_line_facs(t, 8, 0, &err, &line_facs, &total);
        CHECK(err == 0 && line_facs.num_pred_inds == 5);
        for (Pint i = 1; i <= line_facs.num_pred_inds; ++i) {
            Pline_bundle plain;
            Pline_bundle_plus plus, on_ws;
            Pint_bundle int_plain;
            Pint_bundle_plus int_plus;
            Pmarker_bundle_plus marker;
            Ptext_bundle_plus text;
            pinq_pred_line_rep(t, i, &err, &plain);
            pinq_pred_line_rep_plus(t, i, &err, &plus);
            CHECK(err == 0 && plus.type == plain.type && near(plus.width, plain.width) &&
                  plus.colr.type == PINDIRECT && plus.colr.val.ind == plain.colr_ind &&
                  plus.shad_meth == PSD_NONE);
            pinq_line_rep_plus(1, i, PINQ_SET, &err, &on_ws);
            if (t == PWST_SVG)
                CHECK(err == 0 && on_ws.type == plus.type && same_colour(on_ws.colr, plus.colr));
            pinq_pred_int_rep(t, i, &err, &int_plain);
            pinq_pred_int_rep_plus(t, i, &err, &int_plus);
            CHECK(err == 0 && int_plus.style == int_plain.style && int_plus.back_style == int_plain.style &&
                  int_plus.colr.val.ind == int_plain.colr_ind && int_plus.refl_eqn == PREFL_NONE);
            pinq_pred_marker_rep_plus(t, i, &err, &marker);
            CHECK(err == 0 && marker.colr.type == PINDIRECT);
            pinq_pred_text_rep_plus(t, i, &err, &text);
            CHECK(err == 0 && text.font >= 1 && text.colr.type == PINDIRECT);
            ++count;
        }
        CHECK(count == 5);
        {
            Pedge_bundle edge;
            Pedge_bundle_plus edge_plus;
            Ppat_rep* pattern = NULL;
            Ppat_rep_plus* pattern_plus = NULL;
            Pline_bundle_plus plus;
            pinq_pred_edge_rep(t, 3, &err, &edge);
            pinq_pred_edge_rep_plus(t, 3, &err, &edge_plus);
            CHECK(err == 0 && edge_plus.flag == edge.flag && edge_plus.type == edge.type);
            pinq_pred_edge_rep_plus(t, 4, &err, &edge_plus);
            CHECK(err == 102);
            pinq_pred_pat_rep(t, 2, store, &err, &pattern);
            CHECK(err == 0);
            const Pint cell = pattern->colr_array[2];
            pinq_pred_pat_rep_plus(t, 2, store, &err, &pattern_plus);
            CHECK(err == 0 && pattern_plus->type == PINDIRECT && pattern_plus->dims.size_x == 4 &&
                  pattern_plus->colr_array[2].ind == cell);
            pinq_pred_pat_rep_plus(t, 0, store, &err, &pattern_plus);
            CHECK(err == 112);
            pinq_pred_pat_rep_plus(t, 3, store, &err, &pattern_plus);
            CHECK(err == 102);
            pinq_pred_pat_rep_plus(t, 1, NULL, &err, &pattern_plus);
            CHECK(err == PE_ALLOC_STORE);
            pinq_pred_line_rep_plus(t, 0, &err, &plus);
            CHECK(err == 100);
            pinq_pred_line_rep_plus(t, 6, &err, &plus);
            CHECK(err == 102);
        }
    }
    {
        Pint err = -1;
        Pline_bundle_plus plus;
        pinq_pred_line_rep_plus(77, 1, &err, &plus);
        CHECK(err == 52);
    }
}

/* Facilities, table lengths and dynamics of every type; the light and depth cue tables hold as
 * many entries as the lengths say. */
static void facilities(void) {
    for (int k = 0; k < 6; ++k) {
        const Pint t = types[k];
        Pint err = -1, total = 0, ints[8], lt = 0, sm = 0, tis = 0, ths = 0, tre = 0, tsh = 0;
        Pint plus_ints[8], shads[8], hatches[8], plain_hatches[8], refl[8], int_shads[8];
        Pint_style styles[8];
        Pline_facs line = {{0, ints}, 0, 0, 0, 0, 0};
        Pline_facs_plus plus = {{0, plus_ints}, 0, 0, 0, 0, 0, {0, shads}};
        Pint_facs int_plain = {0, {PSTYLE_HOLLOW}, {0, plain_hatches}, 0};
        Pint_facs_plus int_plus = {0, styles, {0, hatches}, 0, {0, refl}, {0, int_shads}};
        Pws_tables lengths;
        Pws_tables_plus lengths_plus;
        Pdyns_ws_attrs dyns;
        Pdyns_ws_attrs_plus dyns_plus;
        pinq_line_facs(t, 8, 0, &err, &line, &total);
        pinq_line_facs_plus(t, 8, 0, 8, 0, &err, &lt, &sm, &plus);
        CHECK(err == 0 && lt == total && plus.types.num_ints == line.types.num_ints &&
              plus.types.ints[3] == ints[3]);
        CHECK(sm == 2 && plus.shads.num_ints == 2 && shads[0] == PSD_NONE && shads[1] == PSD_COLOUR);
        CHECK(near(plus.max_width, line.max_width) && plus.num_pred_inds == line.num_pred_inds);
        pinq_line_facs_plus(t, 0, 0, 1, 1, &err, &lt, &sm, &plus);
        CHECK(err == 0 && plus.types.num_ints == 0 && plus.shads.num_ints == 1 && shads[0] == PSD_COLOUR);
        pinq_line_facs_plus(t, 1, 0, 1, 2, &err, &lt, &sm, &plus);
        CHECK(err == PE_START_IND_INVAL);
        pinq_line_facs_plus(t, -1, 0, 1, 0, &err, &lt, &sm, &plus);
        CHECK(err == PE_LIST_LENGTH_LT_ZERO);
        pinq_int_facs(t, 8, 0, &err, &int_plain, &total);
        pinq_int_facs_plus(t, 8, 0, 8, 0, 8, 0, 8, 0, &err, &int_plus, &tis, &ths, &tre, &tsh);
        CHECK(err == 0 && tis == 5 && int_plus.num_int_styles == 5 && styles[4] == PSTYLE_EMPTY);
        CHECK(ths == total && int_plus.hatch_styles.num_ints == int_plain.hatch_styles.num_ints);
        /* Every type draws hatch styles 1-6 (raster shader and vector painter alike). */
        CHECK(total == 6 && plain_hatches[0] == 1 && plain_hatches[5] == 6 && hatches[5] == 6);
        CHECK(tre == 4 && refl[0] == PREFL_NONE && refl[3] == PREFL_AMB_DIFF_SPEC && tsh == 4 &&
              int_shads[3] == PSD_NORMAL);
        CHECK(int_plus.num_pred_inds == int_plain.num_pred_inds);
        pinq_int_facs_plus(t, 2, 3, 0, 0, 1, 2, 0, 0, &err, &int_plus, &tis, &ths, &tre, &tsh);
        CHECK(err == 0 && int_plus.num_int_styles == 2 && styles[0] == PSTYLE_HATCH &&
              int_plus.refl_eqns.num_ints == 1 && refl[0] == PREFL_AMB_DIFF);
        pinq_int_facs_plus(t, 1, 0, 1, 0, 1, 9, 1, 0, &err, &int_plus, &tis, &ths, &tre, &tsh);
        CHECK(err == PE_START_IND_INVAL);
        pinq_ws_st_table(t, &err, &lengths);
        pinq_ws_st_table_plus(t, &err, &lengths_plus);
        CHECK(err == 0 && lengths_plus.line_bundles == lengths.line_bundles &&
              lengths_plus.pat_reps == lengths.pat_reps && lengths_plus.colr_reps == lengths.colr_reps &&
              lengths_plus.view_reps == lengths.view_reps);
        CHECK(lengths_plus.dcue_rep >= 1 && lengths_plus.light_src_rep >= 1 &&
              lengths_plus.colr_map_rep == 20);
        pinq_dyns_ws_attrs(t, &err, &dyns);
        pinq_dyns_ws_attrs_plus(t, &err, &dyns_plus);
        CHECK(err == 0 && dyns_plus.light_src_rep == dyns.line_bundle && dyns_plus.dcue_rep == PDYN_IRG &&
              dyns_plus.colr_map_rep == PDYN_IRG);
    }
    {
        Pint err = -1, lt, sm;
        Pws_tables_plus lengths;
        Pdyns_ws_attrs_plus dyns;
        Pline_facs_plus plus;
        pinq_ws_st_table_plus(-3, &err, &lengths);
        CHECK(err == 52);
        pinq_dyns_ws_attrs_plus(99, &err, &dyns);
        CHECK(err == 52);
        pinq_line_facs_plus(PWST_SVG, 0, 0, 0, 0, &err, NULL, &sm, &plus);
        CHECK(err == -204);
        pinq_line_facs_plus(PWST_SVG, 0, 0, 0, 0, &err, &lt, &sm, &plus);
        CHECK(err == 0 && lt == 4 && sm == 2);
    }
}

/* The light source and depth cue tables of the open SVG workstation hold what the lengths say. */
static void table_lengths_hold(void) {
    Pint err = -1;
    Pws_tables_plus lengths;
    Plight_src_bundle light;
    Pdcue_bundle cue;
    memset(&light, 0, sizeof light);
    memset(&cue, 0, sizeof cue);
    light.type = PLIGHT_AMBIENT;
    light.rec.ambient.colr.type = PMODEL_RGB;
    cue.mode = PALLOWED;
    cue.ref_planes[1] = 1.0f;
    cue.colr.type = PMODEL_RGB;
    pinq_ws_st_table_plus(PWST_SVG, &err, &lengths);
    CHECK(err == 0);
    for (Pint i = 1; i <= lengths.light_src_rep; ++i) EXPECT_NO_ERROR(pset_light_src_rep(1, i, &light));
    EXPECT_ERROR(pset_light_src_rep(1, lengths.light_src_rep + 1, &light), 103, Pfn_set_light_src_rep);
    for (Pint i = 1; i < lengths.dcue_rep; ++i)
        EXPECT_NO_ERROR(pset_dcue_rep(1, i, &cue)); /* 0 is predefined */
    EXPECT_ERROR(pset_dcue_rep(1, lengths.dcue_rep, &cue), 103, Pfn_set_dcue_rep);
}

/* Each refused SET ... PLUS leaves entry 5 as it was; the inquiries' errors. */
static void errors(Pstore store) {
    Pint err = -1;
    Pline_bundle_plus line = {PLINE_DASH, 2.0f, {PINDIRECT, {3}}, PSD_COLOUR, PCURV_WS_DEP, 1.0f}, line_got;
    Pmarker_bundle_plus marker = {9, 1.0f, {PINDIRECT, {1}}};
    Ptext_bundle_plus text = {7, PPREC_STROKE, 1.0f, 0.0f, {PINDIRECT, {1}}};
    Pedge_bundle_plus edge = {PEDGE_ON, 8, 1.0f, {PINDIRECT, {1}}};
    Pint_bundle_plus interior = random_interior(), int_got;
    Pedge_bundle_plus edge_got;
    Pcoval cells[4];
    Ppat_rep_plus pattern = {{2, 2}, PINDIRECT, cells}, *pattern_got = NULL;
    EXPECT_NO_ERROR(pset_line_rep_plus(1, 5, &line));
    EXPECT_ERROR(pset_line_rep_plus(1, 0, &line), 100, Pfn_set_line_rep_plus);
    line.type = 9;
    EXPECT_ERROR(pset_line_rep_plus(1, 5, &line), 104, Pfn_set_line_rep_plus);
    line.type = PLINE_SOLID;
    line.shad_meth = PSD_DOT_PRODUCT;
    EXPECT_ERROR(pset_line_rep_plus(1, 5, &line), 122, Pfn_set_line_rep_plus);
    CHECK(
        file_has_line(error_file,
                      "ERROR 122 in SET POLYLINE REPRESENTATION PLUS (function 334): Ignoring function, the "
                      "specified polyline shading method is not available on the workstation"));
    line.shad_meth = PSD_NONE;
    line.colr.type = PMODEL_HLS + 1; /* no colour model */
    EXPECT_ERROR(pset_line_rep_plus(1, 5, &line), 110, Pfn_set_line_rep_plus);
    line.colr.type = PINDIRECT;
    line.colr.val.ind = -1;
    EXPECT_ERROR(pset_line_rep_plus(1, 5, &line), 113, Pfn_set_line_rep_plus);
    line.colr.type = PMODEL_RGB;
    line.colr.val.general.x = 1.5f;
    EXPECT_ERROR(pset_line_rep_plus(1, 5, &line), 136, Pfn_set_line_rep_plus);
    EXPECT_ERROR(pset_line_rep_plus(1, 5, NULL), -204, Pfn_set_line_rep_plus);
    EXPECT_ERROR(pset_line_rep_plus(4, 5, &line), 54, Pfn_set_line_rep_plus);
    pinq_line_rep_plus(1, 5, PINQ_SET, &err, &line_got);
    CHECK(err == 0 && line_got.type == PLINE_DASH && line_got.colr.val.ind == 3 &&
          line_got.shad_meth == PSD_COLOUR);
    EXPECT_ERROR(pset_marker_rep_plus(1, 5, &marker), 105, Pfn_set_marker_rep_plus);
    EXPECT_ERROR(pset_text_rep_plus(1, 5, &text), 106, Pfn_set_text_rep_plus);
    text.font = 1;
    text.prec = (Ptext_prec)9;
    EXPECT_ERROR(pset_text_rep_plus(1, 5, &text), PE_ENUM_TYPE_INVAL, Pfn_set_text_rep_plus);
    EXPECT_ERROR(pset_edge_rep_plus(1, 5, &edge), 107, Pfn_set_edge_rep_plus);
    edge.type = PLINE_SOLID;
    edge.flag = (Pedge_flag)4;
    EXPECT_ERROR(pset_edge_rep_plus(1, 5, &edge), PE_ENUM_TYPE_INVAL, Pfn_set_edge_rep_plus);

    /* Interior: every colour, both faces' shading and reflectance, style and pattern index. */
    interior.colr.type = interior.back_colr.type = PINDIRECT;
    interior.colr.val.ind = interior.back_colr.val.ind = 2;
    interior.refl_props.specular_colr = interior.back_refl_props.specular_colr = interior.colr;
    EXPECT_NO_ERROR(pset_int_rep_plus(1, 5, &interior));
    {
        Pint_bundle_plus bad = interior;
        bad.back_colr.val.ind = -2;
        EXPECT_ERROR(pset_int_rep_plus(1, 5, &bad), 113, Pfn_set_int_rep_plus);
        bad = interior;
        bad.back_refl_props.specular_colr.type = PMODEL_RGB;
        bad.back_refl_props.specular_colr.val.general.y = -0.5f;
        EXPECT_ERROR(pset_int_rep_plus(1, 5, &bad), 136, Pfn_set_int_rep_plus);
        bad = interior;
        bad.refl_props.specular_colr.type = 7;
        EXPECT_ERROR(pset_int_rep_plus(1, 5, &bad), 110, Pfn_set_int_rep_plus);
        bad = interior;
        bad.back_shad_meth = 5;
        EXPECT_ERROR(pset_int_rep_plus(1, 5, &bad), 123, Pfn_set_int_rep_plus);
        bad = interior;
        bad.refl_eqn = 0;
        EXPECT_ERROR(pset_int_rep_plus(1, 5, &bad), 124, Pfn_set_int_rep_plus);
        bad = interior;
        bad.back_style = (Pint_style)6;
        EXPECT_ERROR(pset_int_rep_plus(1, 5, &bad), PE_ENUM_TYPE_INVAL, Pfn_set_int_rep_plus);
        bad = interior;
        bad.back_style = PSTYLE_PAT;
        bad.back_style_ind = 0;
        EXPECT_ERROR(pset_int_rep_plus(1, 5, &bad), 112, Pfn_set_int_rep_plus);
        pinq_int_rep_plus(1, 5, PINQ_SET, &err, &int_got);
        CHECK(err == 0 && same_interior(&interior, &int_got, 0));
    }

    /* Patterns. */
    for (int i = 0; i < 4; ++i) cells[i].ind = i;
    EXPECT_NO_ERROR(pset_pat_rep_plus(1, 4, &pattern));
    EXPECT_ERROR(pset_pat_rep_plus(1, 0, &pattern), 112, Pfn_set_pat_rep_plus);
    pattern.type = -1;
    EXPECT_ERROR(pset_pat_rep_plus(1, 4, &pattern), 110, Pfn_set_pat_rep_plus);
    pattern.type = PINDIRECT;
    pattern.dims.size_y = 0;
    EXPECT_ERROR(pset_pat_rep_plus(1, 4, &pattern), 116, Pfn_set_pat_rep_plus);
    pattern.dims.size_y = 2;
    cells[3].ind = -1;
    EXPECT_ERROR(pset_pat_rep_plus(1, 4, &pattern), 113, Pfn_set_pat_rep_plus);
    pattern.type = PMODEL_RGB;
    for (int i = 0; i < 4; ++i) cells[i].direct.rgb.red = cells[i].direct.rgb.green = cells[i].direct.rgb.blue = 0.5f;
    cells[2].direct.rgb.blue = 2.0f;
    EXPECT_ERROR(pset_pat_rep_plus(1, 4, &pattern), 136, Pfn_set_pat_rep_plus);
    pattern.colr_array = NULL;
    EXPECT_ERROR(pset_pat_rep_plus(1, 4, &pattern), -204, Pfn_set_pat_rep_plus);
    pinq_pat_rep_plus(1, 4, PINQ_SET, store, &err, &pattern_got);
    CHECK(err == 0 && pattern_got->type == PINDIRECT && pattern_got->colr_array[3].ind == 3);

    /* The table holds 32 bundles: a new index past them is refused, a defined one is not. */
    line.colr.type = PINDIRECT;
    line.colr.val.ind = 1;
    for (Pint i = 1; i <= 32; ++i) pset_line_rep_plus(1, i, &line);
    EXPECT_ERROR(pset_line_rep_plus(1, 33, &line), 103, Pfn_set_line_rep_plus);
    EXPECT_NO_ERROR(pset_line_rep_plus(1, 32, &line));

    /* Inquiries: 2202, 100, 101 (SET of an undefined index; REALIZED answers entry 1), 54, 112, 2203. */
    pinq_line_rep_plus(1, 5, (Pinq_type)3, &err, &line_got);
    CHECK(err == PE_ENUM_TYPE_INVAL);
    pinq_int_rep_plus(1, 0, PINQ_SET, &err, &int_got);
    CHECK(err == 100);
    pinq_int_rep_plus(1, 31, PINQ_SET, &err, &int_got);
    CHECK(err == 101);
    pinq_int_rep_plus(1, 31, PINQ_REALIZED, &err, &int_got);
    CHECK(err == 0 && int_got.style == PSTYLE_HOLLOW && int_got.colr.type == PINDIRECT &&
          int_got.colr.val.ind == 1);
    pinq_edge_rep_plus(2, 1, PINQ_SET, &err, &edge_got);
    CHECK(err == 54);
    pinq_edge_rep_plus(2, 1, PINQ_SET, &err, NULL); /* the binding checks before the core */
    CHECK(err == -204);
    pinq_pat_rep_plus(1, 0, PINQ_SET, store, &err, &pattern_got);
    CHECK(err == 112);
    pinq_pat_rep_plus(1, 30, PINQ_SET, store, &err, &pattern_got);
    CHECK(err == 101);
    pinq_pat_rep_plus(1, 30, PINQ_REALIZED, store, &err, &pattern_got); /* pattern 1: 2 x 2 */
    CHECK(err == 0 && pattern_got->dims.size_x == 2 && pattern_got->dims.size_y == 2);
    pinq_pat_rep_plus(1, 4, PINQ_SET, NULL, &err, &pattern_got);
    CHECK(err == PE_ALLOC_STORE);
}

/* Whether the file holds `text`. */
static int file_contains(const char* path, const char* text) {
    static char content[1 << 20];
    FILE* f = fopen(path, "rb");
    size_t n = 0;
    if (!f) return 0;
    n = fread(content, 1, sizeof content - 1, f);
    fclose(f);
    content[n] = '\0';
    return strstr(content, text) != NULL;
}

/* Whether the SVG paints the colour with percentages r, g, b (cairo writes "rgb(R%, G%, B%)",
 * with or without the spaces). */
static int svg_has_colour(int r, int g, int b) {
    char spaced[64], tight[64];
    snprintf(spaced, sizeof spaced, "rgb(%d%%, %d%%, %d%%)", r, g, b);
    snprintf(tight, sizeof tight, "rgb(%d%%,%d%%,%d%%)", r, g, b);
    return file_contains(svg_file, spaced) || file_contains(svg_file, tight);
}

/* The picture draws bundled colours from the PLUS entries: a direct green polyline and a direct
 * blue fill area; a plain SET of the polyline entry then draws index 2 (red). */
static void drawn_from_plus_bundles(void) {
    Ppoint3 square[4] = {{0.1f, 0.1f, 0}, {0.4f, 0.1f, 0}, {0.4f, 0.4f, 0}, {0.1f, 0.4f, 0}};
    Ppoint3 segment[2] = {{0.7f, 0.2f, 0}, {0.7f, 0.8f, 0}};
    Ppoint_list3 area = {4, square}, polyline = {2, segment};
    Pline_bundle_plus line = {PLINE_SOLID, 4.0f, {PMODEL_RGB, {0}}, PSD_NONE, PCURV_WS_DEP, 1.0f};
    Pint_bundle_plus interior = random_interior();
    Pline_bundle red = {PLINE_SOLID, 4.0f, 2};
    line.colr.val.general.y = 1.0f;
    interior.style = PSTYLE_SOLID;
    interior.colr.type = PMODEL_RGB;
    interior.colr.val.general.x = interior.colr.val.general.y = 0.0f, interior.colr.val.general.z = 1.0f;
    interior.refl_eqn = PREFL_NONE;
    popen_struct(1);
    pset_line_ind(3);
    pset_indiv_asf(PASPECT_LINE_COLR_IND, PASF_BUNDLED);
    ppolyline3(&polyline);
    pset_int_ind(3);
    pset_indiv_asf(PASPECT_INT_STYLE, PASF_BUNDLED);
    pset_indiv_asf(PASPECT_INT_COLR_IND, PASF_BUNDLED);
    pfill_area3(&area);
    pclose_struct();
    EXPECT_NO_ERROR(ppost_struct(1, 1, 1.0f));
    EXPECT_NO_ERROR(pset_line_rep_plus(1, 3, &line));
    EXPECT_NO_ERROR(pset_int_rep_plus(1, 3, &interior));
    EXPECT_NO_ERROR(pupd_ws(1, PFLAG_PERFORM));
    CHECK(svg_has_colour(0, 100, 0) && svg_has_colour(0, 0, 100) && !svg_has_colour(100, 0, 0));
    EXPECT_NO_ERROR(pset_line_rep(1, 3, &red));
    EXPECT_NO_ERROR(pupd_ws(1, PFLAG_PERFORM));
    CHECK(svg_has_colour(100, 0, 0) && !svg_has_colour(0, 100, 0) && svg_has_colour(0, 0, 100));
    /* The PHIGS PLUS aspects are bundled too: the entry's reflectance equation AMBIENT, taken from
     * the bundle after the fill area's set, sums over no active light: no blue is drawn. */
    interior.refl_eqn = PREFL_AMBIENT;
    EXPECT_NO_ERROR(pset_int_rep_plus(1, 3, &interior));
    popen_struct(1);
    pset_elem_ptr(6);
    pset_indiv_asf(PASPECT_INT_REFL_EQN, PASF_BUNDLED);
    pclose_struct();
    EXPECT_NO_ERROR(pupd_ws(1, PFLAG_PERFORM));
    CHECK(svg_has_colour(100, 0, 0) && !svg_has_colour(0, 0, 100));
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    Pint err = -1;
    Pstore store = NULL;
    seed_random(0x9e3779b97f4a7c15ULL);
    Pline_bundle_plus line = {1, 1.0f, {PINDIRECT, {1}}, PSD_NONE, PCURV_WS_DEP, 1.0f};
    snprintf(error_file, sizeof error_file, "%s/plus_reps_errors.txt", dir);
    snprintf(svg_file, sizeof svg_file, "%s/plus_reps.svg", dir);
    pinq_pred_line_rep_plus(PWST_SVG, 1, &err, &line);
    CHECK(err == 2);
    open_with_handler(error_file);
    EXPECT_ERROR(pset_line_rep_plus(1, 1, &line), 3, Pfn_set_line_rep_plus);
    pinq_line_rep_plus(1, 1, PINQ_SET, &err, &line);
    CHECK(err == 3);
    pcreate_store(&err, &store);
    EXPECT_NO_ERROR(popen_ws(1, svg_file, PWST_SVG));
    predefined(store);
    facilities();
    table_lengths_hold();
    plus_under_every_mode(store);
    plain_over_plus(store);
    errors(store);
    drawn_from_plus_bundles();
    EXPECT_NO_ERROR(pclose_ws(1));
    pdel_store(store);
    pclose_phigs();
    return finish("test_plus_reps");
}
