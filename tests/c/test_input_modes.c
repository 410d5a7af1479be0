/* Input: every device class in REQUEST, SAMPLE and EVENT mode on the headless OUTIN type,
 * fed by input scripts attached with ESCAPE PUESC_INPUT_SCRIPT; AWAIT EVENT, GET, simultaneous
 * events, FLUSH DEVICE EVENTS and the input queue's overflow. argv[1]: a directory for files.
 *
 * The picture: structure 1 holds a solid square of NPC [0.4, 0.6]^2 with name 1 and pick id 7. The
 * workstation window [0,1]^2 maps onto the 768 x 768 square at the left of the 1024 x 768
 * display, so NPC (x, y) is pixel (768 x, 768 (1 - y)) from the top left. */
#include "check.h"

#define WS 1

static void attach(const char* script) {
    Pescape_in_data in;
    Pescape_out_data* out = NULL;
    in.escape_in_u11.ws_id = WS;
    in.escape_in_u11.script = script;
    in.escape_in_u11.file = NULL;
    EXPECT_NO_ERROR(pescape(PUESC_INPUT_SCRIPT, &in, NULL, &out));
    CHECK(out == NULL);
}

static void build_picture(void) {
    Ppoint square[4] = {{0.4f, 0.4f}, {0.6f, 0.4f}, {0.6f, 0.6f}, {0.4f, 0.6f}};
    Ppoint_list area = {4, square};
    Pint one = 1;
    Pint_list names = {1, &one};
    popen_struct(1);
    pset_int_style(PSTYLE_SOLID); /* element 1: a hollow area is picked on its edges only */
    padd_names_set(&names);       /* element 2 */
    pset_pick_id(7);              /* element 3 */
    pfill_area(&area);            /* element 4 */
    pclose_struct();
    EXPECT_NO_ERROR(popen_ws(WS, NULL, PWST_OFFSCREEN));
    EXPECT_NO_ERROR(ppost_struct(WS, 1, 0.5f));
}

/* ISO 9592: a pick device's filter starts with empty inclusion and exclusion sets, so nothing is
 * pickable until SET PICK FILTER includes a name; the exclusion set wins over the inclusion set. */
static void pick_filter_starts_empty(void) {
    Pint one = 1, err = -1;
    Pop_mode mode;
    Pecho_switch echo;
    Pfilter* filter_back = NULL;
    Pin_status status = PIN_STATUS_NONE;
    Ppick_path* init_path = NULL;
    Pint pet = 0;
    Plimit area;
    Ppick_data* data = NULL;
    Ppath_order order;
    Pstore store = NULL;
    EXPECT_NO_ERROR(pcreate_store(&err, &store));
    pinq_pick_st(WS, 1, PINQ_SET, store, &err, &mode, &echo, &filter_back, &status, &init_path, &pet, &area,
                 &data, &order);
    CHECK(err == 0 && filter_back->incl_set.num_ints == 0 && filter_back->excl_set.num_ints == 0);
    pdel_store(store);

    attach("pick 384 384\npick 384 384\npick 384 384\n");
    Ppick_path_elem items[2];
    Ppick_path path = {0, items};
    EXPECT_NO_ERROR(preq_pick(WS, 1, 2, &status, &path));
    CHECK(status == PIN_STATUS_NO_IN && path.depth == 0); /* named, under the cursor, filtered out */
    Pfilter both = {{1, &one}, {1, &one}};
    EXPECT_NO_ERROR(pset_pick_filter(WS, 1, &both));
    EXPECT_NO_ERROR(preq_pick(WS, 1, 2, &status, &path));
    CHECK(status == PIN_STATUS_NO_IN && path.depth == 0);
    Pfilter filter = {{1, &one}, {0, NULL}};
    EXPECT_NO_ERROR(pset_pick_filter(WS, 1, &filter));
    EXPECT_NO_ERROR(preq_pick(WS, 1, 2, &status, &path));
    CHECK(status == PIN_STATUS_OK && path.depth == 1 && items[0].pick_id == 7);
}

/* The SI's REQUEST PICK: path->depth is the path's real depth and only the first `depth` items are
 * written, so an application can tell that its path was cut. */
static void pick_path_depth_is_real(void) {
    popen_struct(2);
    pexec_struct(1); /* element 1 */
    pclose_struct();
    EXPECT_NO_ERROR(punpost_struct(WS, 1));
    EXPECT_NO_ERROR(ppost_struct(WS, 2, 0.5f));
    attach("pick 384 384\npick 384 384\n");
    Ppick_path_elem items[3] = {{-1, -1, -1}, {-1, -1, -1}, {-1, -1, -1}};
    Ppick_path path = {0, items};
    Pin_status status = PIN_STATUS_NONE;
    EXPECT_NO_ERROR(preq_pick(WS, 1, 1, &status, &path));
    CHECK(status == PIN_STATUS_OK && path.depth == 2);
    CHECK(items[0].struct_id == 2 && items[0].elem_pos == 1 && items[1].struct_id == -1);
    EXPECT_NO_ERROR(preq_pick(WS, 1, 3, &status, &path));
    CHECK(status == PIN_STATUS_OK && path.depth == 2);
    CHECK(items[1].struct_id == 1 && items[1].elem_pos == 4 && items[1].pick_id == 7 &&
          items[2].struct_id == -1);
    EXPECT_NO_ERROR(punpost_struct(WS, 2));
    EXPECT_NO_ERROR(ppost_struct(WS, 1, 0.5f));
}

static void request_each_class(void) {
    attach(
        "locator 192 192\nlocator 384 384\nstroke 0 768 384 384\nvaluator 1 0.75\nchoice 3\n"
        "choice 0\npick 384 384\npick 700 100\nstring hello world\nbreak\n");
    Pin_status status = PIN_STATUS_NONE;
    Pint view = -1, choice = -1;
    Ppoint3 at3 = {9, 9, 9};
    Ppoint at = {9, 9};
    EXPECT_NO_ERROR(preq_loc3(WS, 1, &status, &view, &at3));
    CHECK(status == PIN_STATUS_OK && view == 0 && near(at3.x, 0.25) && near(at3.y, 0.75) && near(at3.z, 0));
    EXPECT_NO_ERROR(preq_loc(WS, 1, &status, &view, &at));
    CHECK(status == PIN_STATUS_OK && near(at.x, 0.5) && near(at.y, 0.5));

    Ppoint3 points[256];
    Ppoint_list3 stroke = {0, points};
    EXPECT_NO_ERROR(preq_stroke3(WS, 1, &status, &view, &stroke));
    CHECK(status == PIN_STATUS_OK && stroke.num_points == 2);
    CHECK(near(points[0].x, 0) && near(points[0].y, 0) && near(points[1].x, 0.5) && near(points[1].y, 0.5));

    Pfloat value = -1;
    EXPECT_NO_ERROR(preq_val(WS, 1, &status, &value));
    CHECK(status == PIN_STATUS_OK && near(value, 0.75));
    EXPECT_NO_ERROR(preq_choice(WS, 1, &status, &choice));
    CHECK(status == PIN_STATUS_OK && choice == 3);
    EXPECT_NO_ERROR(preq_choice(WS, 1, &status, &choice));
    CHECK(status == PIN_STATUS_NO_IN);

    Ppick_path_elem items[4];
    Ppick_path path = {0, items};
    EXPECT_NO_ERROR(preq_pick(WS, 1, 4, &status, &path));
    CHECK(status == PIN_STATUS_OK && path.depth == 1);
    CHECK(items[0].struct_id == 1 && items[0].pick_id == 7 && items[0].elem_pos == 4);
    EXPECT_NO_ERROR(preq_pick(WS, 1, 4, &status, &path));
    CHECK(status == PIN_STATUS_NO_IN && path.depth == 0);

    char text[300];
    EXPECT_NO_ERROR(preq_string(WS, 1, &status, text));
    CHECK(status == PIN_STATUS_OK && strcmp(text, "hello world") == 0);
    value = 42;
    EXPECT_NO_ERROR(preq_val(WS, 1, &status, &value)); /* the operator breaks it */
    CHECK(status == PIN_STATUS_NONE && value == 42);
    /* The script has ended: a request can never be satisfied. */
    EXPECT_ERROR(preq_val(WS, 1, &status, &value), PE_INPUT_SCRIPT_ENDED, Pfn_req_val);
}

static void sample_each_class(void) {
    Pint view = -1, choice = -1;
    Pin_status status = PIN_STATUS_NONE;
    EXPECT_NO_ERROR(pset_loc_mode(WS, 1, POP_SAMPLE, PSWITCH_NO_ECHO));
    EXPECT_NO_ERROR(pset_stroke_mode(WS, 1, POP_SAMPLE, PSWITCH_ECHO));
    EXPECT_NO_ERROR(pset_val_mode(WS, 2, POP_SAMPLE, PSWITCH_ECHO));
    EXPECT_NO_ERROR(pset_choice_mode(WS, 2, POP_SAMPLE, PSWITCH_ECHO));
    EXPECT_NO_ERROR(pset_pick_mode(WS, 1, POP_SAMPLE, PSWITCH_ECHO));
    EXPECT_NO_ERROR(pset_string_mode(WS, 1, POP_SAMPLE, PSWITCH_ECHO));
    /* Each sample delivers one line first. */
    attach(
        "move 384 0\nstroke 0 0 768 0 768 768\nvaluator 2 0.25\nvaluator 2 0.5\nchoice 4 device 2\n"
        "pick 400 350\nstring abc\n");
    Ppoint at = {9, 9};
    EXPECT_NO_ERROR(psample_loc(WS, 1, &view, &at));
    CHECK(view == 0 && near(at.x, 0.5) && near(at.y, 1.0));
    Ppoint points[256];
    Ppoint_list stroke = {0, points};
    EXPECT_NO_ERROR(psample_stroke(WS, 1, &view, &stroke));
    CHECK(stroke.num_points == 3 && near(points[2].x, 1) && near(points[2].y, 0));
    Pfloat value = -1;
    EXPECT_NO_ERROR(psample_val(WS, 2, &value));
    CHECK(near(value, 0.25));
    EXPECT_NO_ERROR(psample_val(WS, 2, &value));
    CHECK(near(value, 0.5));
    EXPECT_NO_ERROR(psample_choice(WS, 2, &status, &choice));
    CHECK(status == PIN_STATUS_OK && choice == 4);
    Ppick_path_elem items[2];
    Ppick_path path = {0, items};
    EXPECT_NO_ERROR(psample_pick(WS, 1, 2, &status, &path));
    CHECK(status == PIN_STATUS_OK && path.depth == 1 && items[0].struct_id == 1);
    char text[300];
    EXPECT_NO_ERROR(psample_string(WS, 1, text));
    CHECK(strcmp(text, "abc") == 0);
    /* The script has ended: samples keep the last measures (the press moved the locator). */
    EXPECT_NO_ERROR(psample_val(WS, 2, &value));
    CHECK(near(value, 0.5));
    Ppoint3 at3;
    EXPECT_NO_ERROR(psample_loc3(WS, 1, &view, &at3));
    CHECK(near(at3.x, 400.0 / 768) && near(at3.y, 1 - 350.0 / 768));
    Ppoint3 points3[256];
    Ppoint_list3 stroke3 = {0, points3};
    EXPECT_NO_ERROR(psample_stroke3(WS, 1, &view, &stroke3));
    CHECK(stroke3.num_points == 3);
    /* REQUEST needs REQUEST mode. */
    EXPECT_ERROR(preq_loc(WS, 1, &status, &view, &at), 251, Pfn_req_loc);
}

static void events(void) {
    Pint ws = -1, number = -1, choice = -1, view = -1;
    Pin_class in_class = PIN_NONE;
    Pin_status status = PIN_STATUS_NONE;
    Pmore_simult_events more = PSIMULT_MORE;
    Pint err = -1;
    EXPECT_NO_ERROR(pset_loc_mode(WS, 1, POP_EVENT, PSWITCH_ECHO));
    EXPECT_NO_ERROR(pset_pick_mode(WS, 1, POP_EVENT, PSWITCH_ECHO));
    EXPECT_NO_ERROR(pset_choice_mode(WS, 1, POP_EVENT, PSWITCH_ECHO));
    EXPECT_NO_ERROR(pset_stroke_mode(WS, 1, POP_EVENT, PSWITCH_ECHO));
    EXPECT_NO_ERROR(pset_val_mode(WS, 3, POP_EVENT, PSWITCH_ECHO));
    EXPECT_NO_ERROR(pset_string_mode(WS, 1, POP_EVENT, PSWITCH_ECHO));
    attach("choice 2\npick 384 384\nwait\npick 384 384\nvaluator 3 0.125\nstroke 0 0 10 10\nstring ev\n");
    EXPECT_NO_ERROR(pawait_event(0, &ws, &in_class, &number));
    CHECK(ws == WS && in_class == PIN_CHOICE && number == 1);
    EXPECT_NO_ERROR(pget_choice(&status, &choice));
    CHECK(status == PIN_STATUS_OK && choice == 2);
    pinq_more_simult_events(&err, &more);
    CHECK(err == 0 && more == PSIMULT_NO_MORE);
    /* A press triggers the pick and the locator: two simultaneous events. */
    EXPECT_NO_ERROR(pawait_event(0, &ws, &in_class, &number));
    CHECK(in_class == PIN_PICK && number == 1);
    pinq_more_simult_events(&err, &more);
    CHECK(err == 0 && more == PSIMULT_MORE);
    Ppick_path_elem items[2];
    Ppick_path path = {0, items};
    EXPECT_NO_ERROR(pget_pick(2, &status, &path));
    CHECK(status == PIN_STATUS_OK && path.depth == 1 && items[0].pick_id == 7);
    Ppoint at;
    EXPECT_ERROR(pget_loc(&view, &at), 259, Pfn_get_loc); /* the current report is the pick */
    EXPECT_NO_ERROR(pawait_event(0, &ws, &in_class, &number));
    CHECK(in_class == PIN_LOC);
    EXPECT_NO_ERROR(pget_loc(&view, &at));
    CHECK(near(at.x, 0.5) && near(at.y, 0.5));
    pinq_more_simult_events(&err, &more);
    CHECK(err == 0 && more == PSIMULT_NO_MORE);
    /* "wait": no event in time. */
    EXPECT_NO_ERROR(pawait_event(0.5f, &ws, &in_class, &number));
    CHECK(in_class == PIN_NONE);
    EXPECT_ERROR(pget_choice(&status, &choice), 259, Pfn_get_choice);
    /* The second press's locator event is flushed before it is awaited. */
    EXPECT_NO_ERROR(pawait_event(0, &ws, &in_class, &number));
    CHECK(in_class == PIN_PICK);
    EXPECT_NO_ERROR(pflush_events(WS, PIN_LOC, 1));
    EXPECT_NO_ERROR(pawait_event(0, &ws, &in_class, &number));
    CHECK(in_class == PIN_VAL && number == 3);
    Pfloat value = 0;
    EXPECT_NO_ERROR(pget_val(&value));
    CHECK(near(value, 0.125));
    EXPECT_NO_ERROR(pawait_event(0, &ws, &in_class, &number));
    CHECK(in_class == PIN_STROKE);
    Ppoint3 points3[256];
    Ppoint_list3 stroke3 = {0, points3};
    EXPECT_NO_ERROR(pget_stroke3(&view, &stroke3));
    CHECK(stroke3.num_points == 2);
    EXPECT_NO_ERROR(pawait_event(0, &ws, &in_class, &number));
    CHECK(in_class == PIN_STRING);
    char text[300];
    EXPECT_NO_ERROR(pget_string(text));
    CHECK(strcmp(text, "ev") == 0);
    /* The end of the script is a timeout. */
    EXPECT_NO_ERROR(pawait_event(1, &ws, &in_class, &number));
    CHECK(in_class == PIN_NONE);
}

/* 70 valuator events queued without AWAIT EVENT (each SAMPLE delivers one line): the queue
 * holds 64, then overflows (warning 256, once: it takes nothing more until AWAIT EVENT finds it
 * empty) and INQUIRE INPUT QUEUE OVERFLOW names the device, also after another script is
 * attached (only closing the workstation removes its events). */
static void overflow(void) {
    static char script[70 * 20 + 1];
    script[0] = '\0';
    for (int i = 0; i < 70; ++i) strcat(script, "valuator 4 0.5\n");
    EXPECT_NO_ERROR(pset_val_mode(WS, 4, POP_EVENT, PSWITCH_ECHO));
    attach(script);
    Pfloat value = 0;
    int warnings = 0;
    for (int i = 0; i < 70; ++i) {
        error_count = 0;
        psample_val(WS, 2, &value);
        warnings += error_count == 1 && error_numbers[0] == 256 && error_functions[0] == Pfn_sample_val;
    }
    CHECK(warnings == 1);
    /* Another script on the open workstation keeps its queued events and the overflow. */
    attach("wait\n");
    Pint err = -1, ws = -1, number = -1;
    Pin_class in_class = PIN_NONE;
    pinq_in_overf(&err, &ws, &in_class, &number);
    CHECK(err == 0 && ws == WS && in_class == PIN_VAL && number == 4);
    pinq_in_overf(&err, &ws, &in_class, &number);
    CHECK(err == 257);
    EXPECT_NO_ERROR(pawait_event(0, &ws, &in_class, &number));
    CHECK(in_class == PIN_VAL && number == 4);
    EXPECT_NO_ERROR(pflush_events(WS, PIN_VAL, 4));
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    snprintf(errors, sizeof errors, "%s/input_modes_errors.txt", dir);
    open_with_handler(errors);
    build_picture();
    pick_filter_starts_empty();
    pick_path_depth_is_real();
    request_each_class();
    sample_each_class();
    events();
    overflow();
    EXPECT_NO_ERROR(pclose_ws(WS));
    pclose_phigs();
    return finish("test_input_modes");
}
