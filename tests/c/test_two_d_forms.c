/* The 2D forms of the input, view and utility functions against their 3D forms, over random
 * members (seeded): INITIALIZE of each class with an echo area and the 2D device-state and
 * default-data inquiries (the 2D answer is the 3D one without z; an echo area is the echo
 * volume with z in [0, 1]; a 2D locator position has z = 0); REQUEST STROKE, GET STROKE and
 * GET LOCATOR 3 fed by input scripts; SET VIEW REPRESENTATION, SET WORKSTATION WINDOW and
 * VIEWPORT (3); SCALE and COMPOSE TRANSFORMATION MATRIX. A refused 2D call reports its own
 * function and changes nothing. argv[1]: a directory for files. */
#include "check.h"

#define WS 1 /* PWST_OFFSCREEN: OUTIN, 1024 x 768 */
#define ROUNDS 24

static Pstore store;

/* A random echo area within the 1024 x 768 display, of positive size. */
static Plimit random_area(void) {
    Plimit a;
    a.x_min = (Pfloat)random_real(0, 500), a.x_max = a.x_min + (Pfloat)random_real(1, 500);
    a.y_min = (Pfloat)random_real(0, 380), a.y_max = a.y_min + (Pfloat)random_real(1, 380);
    return a;
}

static int same_area(Plimit a, Plimit b) {
    return a.x_min == b.x_min && a.x_max == b.x_max && a.y_min == b.y_min && a.y_max == b.y_max;
}

/* The echo volume the 3D inquiry answers for a 2D echo area. */
static int is_lifted(Plimit3 v, Plimit a) {
    return v.x_min == a.x_min && v.x_max == a.x_max && v.y_min == a.y_min && v.y_max == a.y_max &&
           v.z_min == 0 && v.z_max == 1;
}

static void locator(void) {
    const Plimit area = random_area();
    const Ppoint at = {(Pfloat)random_real(0, 1), (Pfloat)random_real(0, 1)};
    const Pint pet = 1 + (Pint)(next_random() % 3);
    EXPECT_NO_ERROR(pinit_loc(WS, 1, 0, &at, pet, &area, NULL));
    for (int t = 0; t < 2; ++t) {
        Pint err = -1, view = -1, pet_back = -1;
        Pop_mode mode;
        Pecho_switch echo;
        Ppoint back = {9, 9};
        Plimit area_back;
        Ploc_data* data = NULL;
        pinq_loc_st(WS, 1, t ? PINQ_REALIZED : PINQ_SET, store, &err, &mode, &echo, &view, &back, &pet_back,
                    &area_back, &data);
        CHECK(err == 0 && mode == POP_REQ && view == 0 && pet_back == pet && data != NULL);
        CHECK(back.x == at.x && back.y == at.y && same_area(area_back, area));
    }
    Pint err = -1, view = -1, pet_back = -1;
    Pop_mode mode;
    Pecho_switch echo;
    Ppoint3 back3 = {9, 9, 9};
    Plimit3 volume;
    Ploc_data3* data3 = NULL;
    pinq_loc_st3(WS, 1, PINQ_SET, store, &err, &mode, &echo, &view, &back3, &pet_back, &volume, &data3);
    CHECK(err == 0 && back3.x == at.x && back3.y == at.y && back3.z == 0 && is_lifted(volume, area));
}

static void stroke(void) {
    Ppoint points[5];
    const Pint n = 1 + (Pint)(next_random() % 5);
    for (Pint i = 0; i < n; ++i)
        points[i].x = (Pfloat)random_real(0, 1), points[i].y = (Pfloat)random_real(0, 1);
    Ppoint_list initial = {n, points};
    const Pstroke_data data = {n + (Pint)(next_random() % 8), 1 + (Pint)(next_random() % (unsigned)(n + 1)),
                               (Pfloat)random_real(0, 0.1),   (Pfloat)random_real(0, 0.1),
                               (Pfloat)random_real(0, 2),     {{0}}};
    const Plimit area = random_area();
    EXPECT_NO_ERROR(pinit_stroke(WS, 1, 0, &initial, PSTROKE_DIGIT, &area, &data));
    Pint err = -1, view = -1, pet = -1;
    Pop_mode mode;
    Pecho_switch echo;
    Ppoint_list* back = NULL;
    Plimit area_back;
    Pstroke_data* record = NULL;
    pinq_stroke_st(WS, 1, PINQ_SET, store, &err, &mode, &echo, &view, &back, &pet, &area_back, &record);
    CHECK(err == 0 && pet == PSTROKE_DIGIT && back && back->num_points == n && same_area(area_back, area));
    for (Pint i = 0; err == 0 && i < n; ++i)
        CHECK(back->points[i].x == points[i].x && back->points[i].y == points[i].y);
    CHECK(record && record->buffer_size == data.buffer_size && record->init_pos == data.init_pos);
    CHECK(record->x_interval == data.x_interval && record->y_interval == data.y_interval);
    CHECK(record->time_interval == data.time_interval);
    Ppoint_list3* back3 = NULL;
    Plimit3 volume;
    Pstroke_data3* record3 = NULL;
    pinq_stroke_st3(WS, 1, PINQ_SET, store, &err, &mode, &echo, &view, &back3, &pet, &volume, &record3);
    CHECK(err == 0 && back3->num_points == n && back3->points[n - 1].z == 0 && is_lifted(volume, area));
    CHECK(record3->z_interval == 0 && record3->time_interval == data.time_interval);
}

static void valuator(void) {
    const Pint device = 1 + (Pint)(next_random() % 12);
    const Pfloat low = (Pfloat)random_real(-10, 10), high = low + (Pfloat)random_real(0.5, 10);
    const Pfloat value = (Pfloat)random_real(low, high);
    const Pval_data range = {low, high, {{0}}};
    const Plimit area = random_area();
    EXPECT_NO_ERROR(pinit_val(WS, device, value, PVAL_GRAPH, &area, &range));
    Pint err = -1, pet = -1;
    Pop_mode mode;
    Pecho_switch echo;
    Pfloat back = 0;
    Plimit area_back;
    Pval_data* record = NULL;
    pinq_val_st(WS, device, store, &err, &mode, &echo, &back, &pet, &area_back, &record);
    CHECK(err == 0 && back == value && pet == PVAL_GRAPH && same_area(area_back, area));
    CHECK(record && record->low == low && record->high == high);
    Plimit3 volume;
    pinq_val_st3(WS, device, store, &err, &mode, &echo, &back, &pet, &volume, &record);
    CHECK(err == 0 && is_lifted(volume, area));
}

static void pick(void) {
    Ppick_path_elem items[2] = {{1 + (Pint)(next_random() % 9), (Pint)(next_random() % 20), 1},
                                {1 + (Pint)(next_random() % 9), (Pint)(next_random() % 20), 2}};
    Ppick_path path = {(Pint)(next_random() % 3), items};
    const Pin_status status = path.depth ? PIN_STATUS_OK : PIN_STATUS_NO_IN;
    const Ppath_order order = next_random() % 2 ? PORDER_TOP_FIRST : PORDER_BOTTOM_FIRST;
    const Plimit area = random_area();
    EXPECT_NO_ERROR(pinit_pick(WS, 1, status, &path, PPICK_GROUP_HIGHL, &area, NULL, order));
    Pint err = -1, pet = -1;
    Pop_mode mode;
    Pecho_switch echo;
    Pfilter* filter = NULL;
    Pin_status status_back = PIN_STATUS_NONE;
    Ppick_path* back = NULL;
    Plimit area_back;
    Ppick_data* data = NULL;
    Ppath_order order_back;
    pinq_pick_st(WS, 1, PINQ_SET, store, &err, &mode, &echo, &filter, &status_back, &back, &pet, &area_back,
                 &data, &order_back);
    CHECK(err == 0 && status_back == status && pet == PPICK_GROUP_HIGHL && order_back == order);
    CHECK(same_area(area_back, area) && back && back->depth == (status == PIN_STATUS_OK ? path.depth : 0));
    for (Pint i = 0; err == 0 && back && i < back->depth; ++i)
        CHECK(back->path_list[i].struct_id == items[i].struct_id &&
              back->path_list[i].elem_pos == items[i].elem_pos);
}

static void string(void) {
    char text[12];
    const Pint n = (Pint)(next_random() % 11);
    for (Pint i = 0; i < n; ++i) text[i] = (char)('a' + next_random() % 26);
    text[n] = '\0';
    const Pstring_data data = {
        n + 1 + (Pint)(next_random() % 8), 1 + (Pint)(next_random() % (unsigned)(n + 1)), {{0}}};
    const Plimit area = random_area();
    EXPECT_NO_ERROR(pinit_string(WS, 1, text, PSTRING_DEF, &area, &data));
    Pint err = -1, pet = -1;
    Pop_mode mode;
    Pecho_switch echo;
    char* back = NULL;
    Plimit area_back;
    Pstring_data* record = NULL;
    pinq_string_st(WS, 1, store, &err, &mode, &echo, &back, &pet, &area_back, &record);
    CHECK(err == 0 && back && strcmp(back, text) == 0 && same_area(area_back, area));
    CHECK(record && record->buffer_size == data.buffer_size && record->init_pos == data.init_pos);
}

/* The 2D default data are the 3D ones without z. */
static void default_data(void) {
    Pint err = -1, err3 = -1, max = 0, max3 = 0;
    Pint_list *pets = NULL, *pets3 = NULL;
    Plimit area;
    Plimit3 volume;
    Ppoint at = {9, 9};
    Ppoint3 at3;
    Ploc_data *loc = NULL, *loc3 = NULL;
    Pstore store3 = NULL;
    pcreate_store(&err, &store3);
    pinq_def_loc_data(PWST_OFFSCREEN, 1, store, &err, &at, &pets, &area, &loc);
    pinq_def_loc_data3(PWST_OFFSCREEN, 1, store3, &err3, &at3, &pets3, &volume, &loc3);
    CHECK(err == 0 && err3 == 0 && at.x == at3.x && at.y == at3.y && is_lifted(volume, area) && loc);
    CHECK(pets->num_ints == pets3->num_ints &&
          pets->ints[pets->num_ints - 1] == pets3->ints[pets3->num_ints - 1]);
    Pstroke_data* stroke = NULL;
    Pstroke_data3* stroke3 = NULL;
    pinq_def_stroke_data(PWST_OFFSCREEN, 1, store, &err, &max, &pets, &area, &stroke);
    pinq_def_stroke_data3(PWST_OFFSCREEN, 1, store3, &err3, &max3, &pets3, &volume, &stroke3);
    CHECK(err == 0 && err3 == 0 && max == max3 && pets->num_ints == pets3->num_ints &&
          is_lifted(volume, area));
    CHECK(stroke->buffer_size == stroke3->buffer_size && stroke->init_pos == stroke3->init_pos);
    Pchoice_data *choice = NULL, *choice3 = NULL;
    pinq_def_choice_data(PWST_OFFSCREEN, 4, store, &err, &max, &pets, &area, &choice);
    pinq_def_choice_data3(PWST_OFFSCREEN, 4, store3, &err3, &max3, &pets3, &volume, &choice3);
    CHECK(err == 0 && err3 == 0 && max == max3 && max == 64 && pets->num_ints == pets3->num_ints && choice);
    CHECK(is_lifted(volume, area));
    Ppick_data *pick_data = NULL, *pick3 = NULL;
    pinq_def_pick_data(PWST_OFFSCREEN, 1, store, &err, &pets, &area, &pick_data);
    pinq_def_pick_data3(PWST_OFFSCREEN, 1, store3, &err3, &pets3, &volume, &pick3);
    CHECK(err == 0 && err3 == 0 && pets->num_ints == pets3->num_ints && is_lifted(volume, area) && pick_data);
    pinq_def_pick_data(PWST_OFFSCREEN, 2, store, &err, &pets, &area, &pick_data);
    CHECK(err == 250);
    pinq_def_loc_data(77, 1, store, &err, &at, &pets, &area, &loc);
    CHECK(err == 52);
    pdel_store(store3);
}

static void attach(const char* script) {
    Pescape_in_data in;
    Pescape_out_data* out = NULL;
    in.escape_in_u11.ws_id = WS;
    in.escape_in_u11.script = script;
    in.escape_in_u11.file = NULL;
    EXPECT_NO_ERROR(pescape(PUESC_INPUT_SCRIPT, &in, NULL, &out));
}

/* REQUEST STROKE (2D), then GET STROKE (2D) and GET LOCATOR 3 of events. The display's 768 x 768
 * square at the left shows NPC [0, 1]^2: pixel (i, j) from the top left is NPC (i, 768 - j) / 768. */
static void scripted(void) {
    Ppoint points[64];
    Ppoint_list stroke_back = {0, points};
    Pstroke_data data = {64, 1, 0, 0, 0, {{0}}};
    const Plimit whole = {0, 1024, 0, 768};
    Ppoint_list none = {0, NULL};
    EXPECT_NO_ERROR(pinit_stroke(WS, 1, 0, &none, PSTROKE_DEF, &whole, &data));
    attach("stroke 0 768 384 384 768 0\n");
    Pin_status status = PIN_STATUS_NONE;
    Pint view = -1;
    EXPECT_NO_ERROR(preq_stroke(WS, 1, &status, &view, &stroke_back));
    CHECK(status == PIN_STATUS_OK && view == 0 && stroke_back.num_points == 3);
    CHECK(near(points[0].x, 0) && near(points[0].y, 0) && near(points[1].x, 0.5) && near(points[2].y, 1));

    EXPECT_NO_ERROR(pset_stroke_mode(WS, 1, POP_EVENT, PSWITCH_ECHO));
    EXPECT_NO_ERROR(pset_loc_mode(WS, 1, POP_EVENT, PSWITCH_ECHO));
    attach("stroke 192 576 576 192\nlocator 192 192\n");
    Pint ws = -1, number = -1;
    Pin_class in_class = PIN_NONE;
    EXPECT_NO_ERROR(pawait_event(0, &ws, &in_class, &number));
    CHECK(ws == WS && in_class == PIN_STROKE && number == 1);
    Ppoint3 at3 = {9, 9, 9};
    EXPECT_ERROR(pget_loc3(&view, &at3), 259, Pfn_get_loc3); /* the current report is the stroke */
    stroke_back.num_points = 0;
    EXPECT_NO_ERROR(pget_stroke(&view, &stroke_back));
    CHECK(stroke_back.num_points == 2 && near(points[0].x, 0.25) && near(points[1].y, 0.75));
    EXPECT_NO_ERROR(pawait_event(0, &ws, &in_class, &number));
    CHECK(in_class == PIN_LOC && number == 1);
    EXPECT_NO_ERROR(pget_loc3(&view, &at3));
    CHECK(view == 0 && near(at3.x, 0.25) && near(at3.y, 0.75) && at3.z == 0);
    EXPECT_ERROR(pget_stroke(&view, &stroke_back), 259, Pfn_get_stroke);
    EXPECT_NO_ERROR(pset_stroke_mode(WS, 1, POP_REQ, PSWITCH_ECHO));
    EXPECT_NO_ERROR(pset_loc_mode(WS, 1, POP_REQ, PSWITCH_ECHO));
}

/* Each refused 2D initialisation names its own function and leaves the device as it was. */
static void refusals(void) {
    const Plimit area = {10, 200, 20, 300}, empty = {10, 10, 20, 300}, outside = {10, 2000, 20, 300};
    const Ppoint at = {0.5f, 0.5f};
    EXPECT_NO_ERROR(pinit_loc(WS, 1, 0, &at, 1, &area, NULL));
    EXPECT_ERROR(pinit_loc(WS, 1, -1, &at, 1, &area, NULL), 114, Pfn_init_loc);
    EXPECT_ERROR(pinit_loc(WS, 1, 0, &at, 1, &empty, NULL), 254, Pfn_init_loc);
    EXPECT_ERROR(pinit_loc(WS, 2, 0, &at, 1, &area, NULL), 250, Pfn_init_loc);
    Pint err = -1, view = -1, pet = -1;
    Pop_mode mode;
    Pecho_switch echo;
    Ppoint back;
    Plimit area_back;
    Ploc_data* loc = NULL;
    pinq_loc_st(WS, 1, PINQ_SET, store, &err, &mode, &echo, &view, &back, &pet, &area_back, &loc);
    CHECK(err == 0 && same_area(area_back, area) && back.x == 0.5f);
    const Pval_data reversed = {1, 0, {{0}}}, range = {0, 1, {{0}}};
    EXPECT_NO_ERROR(pinit_val(WS, 3, 0.25f, 1, &area, &range));
    EXPECT_ERROR(pinit_val(WS, 3, 0.5f, 1, &area, &reversed), 260, Pfn_init_val);
    EXPECT_ERROR(pinit_val(WS, 3, 0.5f, 1, &outside, &range), 255, Pfn_init_val);
    Pfloat value = 0;
    Pval_data* val = NULL;
    pinq_val_st(WS, 3, store, &err, &mode, &echo, &value, &pet, &area_back, &val);
    CHECK(err == 0 && value == 0.25f && same_area(area_back, area));
    const Pstring_data small = {3, 1, {{0}}};
    EXPECT_ERROR(pinit_string(WS, 1, "abcdef", 1, &area, &small), 263, Pfn_init_string);
    Ppoint points[3] = {{0, 0}, {1, 0}, {1, 1}};
    Ppoint_list three = {3, points};
    const Pstroke_data two = {2, 1, 0, 0, 0, {{0}}};
    EXPECT_ERROR(pinit_stroke(WS, 1, 0, &three, 1, &area, &two), 262, Pfn_init_stroke);
    Ppick_path none = {0, NULL};
    EXPECT_ERROR(pinit_pick(WS, 1, PIN_STATUS_NO_IN, &none, 1, &empty, NULL, PORDER_TOP_FIRST), 254,
                 Pfn_init_pick);
}

static void identity(Pmatrix m) {
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m[r][c] = r == c ? 1.0f : 0.0f;
}

/* The 3D matrix of a 2D one: z passes through. */
static int lifts(Pmatrix3 m3, Pmatrix m) {
    static const int at[4] = {0, 1, -1, 2};
    int ok = 1;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            const double want = at[r] < 0 || at[c] < 0 ? (r == c ? 1.0 : 0.0) : m[at[r]][at[c]];
            ok = ok && near(m3[r][c], want);
        }
    return ok;
}

static void views_and_utilities(void) {
    Pview_rep rep;
    identity(rep.ori_matrix), identity(rep.map_matrix);
    rep.ori_matrix[0][2] = (Pfloat)random_real(-1, 1), rep.ori_matrix[1][0] = (Pfloat)random_real(-1, 1);
    rep.map_matrix[0][0] = (Pfloat)random_real(0.5, 2), rep.map_matrix[1][2] = (Pfloat)random_real(-1, 1);
    rep.clip_limit.x_min = (Pfloat)random_real(0, 0.4), rep.clip_limit.x_max = (Pfloat)random_real(0.6, 1);
    rep.clip_limit.y_min = (Pfloat)random_real(0, 0.4), rep.clip_limit.y_max = (Pfloat)random_real(0.6, 1);
    rep.xy_clip = next_random() % 2 ? PIND_CLIP : PIND_NO_CLIP;
    const Pint index = 1 + (Pint)(next_random() % 31);
    EXPECT_NO_ERROR(pset_view_rep(WS, index, &rep));
    Pint err = -1;
    Pupd_st upd;
    Pview_rep3 cur, req;
    pinq_view_rep(WS, index, &err, &upd, &cur, &req);
    CHECK(err == 0 && lifts(req.ori_matrix, rep.ori_matrix) && lifts(req.map_matrix, rep.map_matrix));
    CHECK(req.clip_limit.x_min == rep.clip_limit.x_min && req.clip_limit.y_max == rep.clip_limit.y_max);
    CHECK(req.clip_limit.z_min == 0 && req.clip_limit.z_max == 1 && req.xy_clip == rep.xy_clip);
    CHECK(req.back_clip == PIND_NO_CLIP && req.front_clip == PIND_NO_CLIP);
    EXPECT_ERROR(pset_view_rep(WS, 0, &rep), 115, Pfn_set_view_rep);

    /* The window keeps its z limits; the 3D viewport sets them. */
    const Plimit3 vp3 = {(Pfloat)random_real(0, 100), (Pfloat)random_real(500, 768),
                         (Pfloat)random_real(0, 100), (Pfloat)random_real(500, 768),
                         (Pfloat)random_real(0, 0.4), (Pfloat)random_real(0.6, 1)};
    const Plimit win = {(Pfloat)random_real(0, 0.4), (Pfloat)random_real(0.6, 1), (Pfloat)random_real(0, 0.4),
                        (Pfloat)random_real(0.6, 1)};
    Plimit3 req_win, cur_win, req_vp, cur_vp;
    pinq_ws_tran3(WS, &err, &upd, &req_win, &cur_win, &req_vp, &cur_vp);
    const Plimit3 old_win = req_win, old_vp = req_vp;
    const Pfloat z_min = req_win.z_min, z_max = req_win.z_max;
    EXPECT_NO_ERROR(pset_ws_win(WS, &win));
    EXPECT_NO_ERROR(pset_ws_vp3(WS, &vp3));
    pinq_ws_tran3(WS, &err, &upd, &req_win, &cur_win, &req_vp, &cur_vp);
    CHECK(err == 0 && req_win.x_min == win.x_min && req_win.y_max == win.y_max);
    CHECK(req_win.z_min == z_min && req_win.z_max == z_max);
    CHECK(req_vp.x_max == vp3.x_max && req_vp.y_min == vp3.y_min && req_vp.z_min == vp3.z_min &&
          req_vp.z_max == vp3.z_max);
    const Plimit3 beyond = {0, 2000, 0, 768, 0, 1};
    EXPECT_ERROR(pset_ws_vp3(WS, &beyond), 157, Pfn_set_ws_vp3);
    const Plimit reversed = {0.6f, 0.4f, 0, 1};
    EXPECT_ERROR(pset_ws_win(WS, &reversed), 151, Pfn_set_ws_win);
    EXPECT_NO_ERROR(pset_ws_win3(WS, &old_win));
    EXPECT_NO_ERROR(pset_ws_vp3(WS, &old_vp));

    /* SCALE is SCALE 3 without z; COMPOSE TRANSFORMATION MATRIX is BUILD's matrix times the given one. */
    const Pvec s = {(Pfloat)random_real(-3, 3), (Pfloat)random_real(-3, 3)};
    const Pvec3 s3 = {s.delta_x, s.delta_y, 1};
    Pmatrix m, given, built, product;
    Pmatrix3 m3;
    pscale(&s, &err, m);
    CHECK(err == 0);
    pscale3(&s3, &err, m3);
    CHECK(err == 0 && lifts(m3, m));
    identity(given);
    given[0][1] = (Pfloat)random_real(-1, 1), given[1][2] = (Pfloat)random_real(-1, 1);
    const Ppoint fixed = {(Pfloat)random_real(-1, 1), (Pfloat)random_real(-1, 1)};
    const Pvec shift = {(Pfloat)random_real(-1, 1), (Pfloat)random_real(-1, 1)};
    const Pfloat angle = (Pfloat)random_real(-3, 3);
    pbuild_tran_matrix(&fixed, &shift, angle, &s, &err, built);
    pcompose_matrix(built, given, &err, product);
    pcompose_tran_matrix(given, &fixed, &shift, angle, &s, &err, m);
    CHECK(err == 0);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) CHECK(fabs(m[r][c] - product[r][c]) <= 1e-4 * (1 + fabs(product[r][c])));
    pcompose_tran_matrix(NULL, &fixed, &shift, angle, &s, &err, m);
    CHECK(err == -204);
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors_file[512];
    Pint err = -1;
    snprintf(errors_file, sizeof errors_file, "%s/two_d_forms_errors.txt", dir);
    seed_random(19);
    open_with_handler(errors_file);
    pcreate_store(&err, &store);
    CHECK(err == 0);
    EXPECT_NO_ERROR(popen_ws(WS, NULL, PWST_OFFSCREEN));
    for (int round = 0; round < ROUNDS; ++round) {
        locator();
        stroke();
        valuator();
        pick();
        string();
        views_and_utilities();
    }
    default_data();
    scripted();
    refusals();
    EXPECT_NO_ERROR(pclose_ws(WS));
    pdel_store(store);
    pclose_phigs();
    return finish("test_two_d_forms");
}
