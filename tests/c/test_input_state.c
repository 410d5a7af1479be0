/* Input: the device-state and default-data inquiries, INITIALIZE of each class as they answer
 * it, and the errors of the input functions, each leaving the device's state as it was.
 * argv[1]: a directory for files. */
#include "check.h"

#define WS 1  /* PWST_OFFSCREEN: OUTIN, 1024 x 768 */
#define PDF 2 /* PWST_PDF: OUTPUT */

static Pstore store;

static int same_limit(Plimit3 a, Plimit3 b) {
    return a.x_min == b.x_min && a.x_max == b.x_max && a.y_min == b.y_min && a.y_max == b.y_max &&
           a.z_min == b.z_min && a.z_max == b.z_max;
}

/* The default data of the OUTIN type, and the type errors. */
static void default_data(void) {
    Pint err = -1, max = 0;
    Pint_list* pets = NULL;
    Plimit3 volume;
    const Plimit3 whole = {0, 1024, 0, 768, 0, 1};
    Ppoint3 at = {9, 9, 9};
    Ploc_data3* loc = NULL;
    pinq_def_loc_data3(PWST_OFFSCREEN, 1, store, &err, &at, &pets, &volume, &loc);
    CHECK(err == 0 && at.x == 0 && pets && pets->num_ints == 3 && pets->ints[2] == PLOC_TRACK_CROSS);
    CHECK(same_limit(volume, whole) && loc != NULL);
    Pstroke_data3* stroke = NULL;
    pinq_def_stroke_data3(PWST_OFFSCREEN, 1, store, &err, &max, &pets, &volume, &stroke);
    CHECK(err == 0 && max == 4096 && pets->num_ints == 2 && stroke->buffer_size == 256 &&
          stroke->init_pos == 1);
    Pfloat value = -1;
    Pval_data* val = NULL;
    Plimit area;
    pinq_def_val_data(PWST_OFFSCREEN, 12, store, &err, &value, &pets, &area, &val);
    CHECK(err == 0 && value == 0 && val->low == 0 && val->high == 1 && area.x_max == 1024 &&
          area.y_max == 768);
    Pchoice_data3* choice = NULL;
    pinq_def_choice_data3(PWST_OFFSCREEN, 4, store, &err, &max, &pets, &volume, &choice);
    CHECK(err == 0 && max == 64 && pets->num_ints == 3 && choice != NULL);
    Ppick_data3* pick = NULL;
    pinq_def_pick_data3(PWST_OFFSCREEN, 1, store, &err, &pets, &volume, &pick);
    CHECK(err == 0 && pets->num_ints == 2 && pets->ints[1] == PPICK_GROUP_HIGHL);
    Pstring_data* string = NULL;
    pinq_def_string_data(PWST_OFFSCREEN, 1, store, &err, &max, &pets, &area, &string);
    CHECK(err == 0 && max == 4096 && pets->num_ints == 1 && string->buffer_size == 256);
    pinq_def_val_data3(PWST_OFFSCREEN, 13, store, &err, &value, &pets, &volume, &val);
    CHECK(err == 250);
    pinq_def_pick_data3(PWST_PDF, 1, store, &err, &pets, &volume, &pick);
    CHECK(err == 61);
    pinq_def_loc_data3(77, 1, store, &err, &at, &pets, &volume, &loc);
    CHECK(err == 52);
    pinq_def_string_data3(PWST_OFFSCREEN, 1, NULL, &err, &max, &pets, &volume, NULL);
    CHECK(err == PE_ALLOC_STORE);
    Pnum_in n = {0, 0, 0, 0, 0, 0};
    pinq_num_avail_in(PWST_OFFSCREEN, &err, &n);
    CHECK(err == 0 && n.loc == 1 && n.stroke == 1 && n.val == 12 && n.choice == 4 && n.pick == 1 &&
          n.string == 1);
    pinq_num_avail_in(PWST_SVG, &err, &n);
    CHECK(err == 61);
}

/* Each class initialised and inquired back (echo areas in device coordinates, y up). */
static void initialise_and_inquire(void) {
    Pint err = -1, view = -1, pet = -1;
    Pop_mode mode = POP_EVENT;
    Pecho_switch echo = PSWITCH_NO_ECHO;
    Plimit3 volume;
    const Plimit3 box = {10, 200, 20, 300, 0, 1};
    Ppoint3 at = {0.25f, 0.5f, 0.75f};
    EXPECT_NO_ERROR(pinit_loc3(WS, 1, 3, &at, PLOC_CROSS_HAIR, &box, NULL));
    Ploc_data3* loc = NULL;
    Ppoint3 back;
    pinq_loc_st3(WS, 1, PINQ_REALIZED, store, &err, &mode, &echo, &view, &back, &pet, &volume, &loc);
    CHECK(err == 0 && mode == POP_REQ && echo == PSWITCH_ECHO && view == 3 && pet == PLOC_CROSS_HAIR);
    CHECK(back.x == 0.25f && back.y == 0.5f && back.z == 0.75f && same_limit(volume, box) && loc != NULL);

    Ppoint line[2] = {{0.1f, 0.2f}, {0.3f, 0.4f}};
    Ppoint_list initial = {2, line};
    Pstroke_data data = {8, 3, 0.5f, 0.25f, 1.0f, {{0}}};
    const Plimit area = {0, 512, 0, 384};
    EXPECT_NO_ERROR(pinit_stroke(WS, 1, 0, &initial, PSTROKE_DIGIT, &area, &data));
    Ppoint_list3* stroke3 = NULL;
    Pstroke_data3* record3 = NULL;
    pinq_stroke_st3(WS, 1, PINQ_SET, store, &err, &mode, &echo, &view, &stroke3, &pet, &volume, &record3);
    CHECK(err == 0 && pet == PSTROKE_DIGIT && stroke3->num_points == 2 && stroke3->points[1].y == 0.4f);
    CHECK(record3->buffer_size == 8 && record3->init_pos == 3 && record3->x_interval == 0.5f);
    CHECK(record3->time_interval == 1.0f && volume.x_max == 512 && volume.y_max == 384);

    Pval_data3 range = {-5, 5, {{0}}};
    EXPECT_NO_ERROR(pinit_val3(WS, 7, 2.5f, PVAL_GRAPH, &box, &range));
    Pfloat value = 0;
    Pval_data3* val = NULL;
    pinq_val_st3(WS, 7, store, &err, &mode, &echo, &value, &pet, &volume, &val);
    CHECK(err == 0 && value == 2.5f && pet == PVAL_GRAPH && val->low == -5 && val->high == 5);

    char* names[3] = {"wing", "fuselage", "tail"};
    Pchoice_data3 menu;
    menu.pets.pet_r3.num_strings = 3;
    menu.pets.pet_r3.strings = names;
    EXPECT_NO_ERROR(pinit_choice3(WS, 2, PIN_STATUS_OK, 2, PCHOICE_STRING_PR, &box, &menu));
    Pin_status status = PIN_STATUS_NONE;
    Pint choice = 0;
    Pchoice_data3* answer = NULL;
    pinq_choice_st3(WS, 2, store, &err, &mode, &echo, &status, &choice, &pet, &volume, &answer);
    CHECK(err == 0 && status == PIN_STATUS_OK && choice == 2 && pet == PCHOICE_STRING_PR);
    CHECK(answer->pets.pet_r3.num_strings == 3 && strcmp(answer->pets.pet_r3.strings[1], "fuselage") == 0);
    Ppr_switch prompts[2] = {PPR_ON, PPR_OFF};
    Pchoice_data lights;
    lights.pets.pet_r2.num_prompts = 2;
    lights.pets.pet_r2.prompts = prompts;
    EXPECT_NO_ERROR(pinit_choice(WS, 3, PIN_STATUS_NO_IN, 0, PCHOICE_PR_ECHO, &area, &lights));
    Pchoice_data* answer2 = NULL;
    Plimit area_back;
    pinq_choice_st(WS, 3, store, &err, &mode, &echo, &status, &choice, &pet, &area_back, &answer2);
    CHECK(err == 0 && status == PIN_STATUS_NO_IN && pet == PCHOICE_PR_ECHO && area_back.x_max == 512);
    CHECK(answer2->pets.pet_r2.num_prompts == 2 && answer2->pets.pet_r2.prompts[0] == PPR_ON);

    Ppick_path_elem items[2] = {{1, 5, 2}, {4, 6, 9}};
    Ppick_path path = {2, items};
    EXPECT_NO_ERROR(pinit_pick3(WS, 1, PIN_STATUS_OK, &path, PPICK_DEF, &box, NULL, PORDER_BOTTOM_FIRST));
    Pint in[2] = {3, 1}, out[1] = {8};
    Pfilter filter = {{2, in}, {1, out}};
    EXPECT_NO_ERROR(pset_pick_filter(WS, 1, &filter));
    Pfilter* filter_back = NULL;
    Ppick_path* path_back = NULL;
    Ppick_data3* pick = NULL;
    Ppath_order order = PORDER_TOP_FIRST;
    pinq_pick_st3(WS, 1, PINQ_SET, store, &err, &mode, &echo, &filter_back, &status, &path_back, &pet,
                  &volume, &pick, &order);
    CHECK(err == 0 && status == PIN_STATUS_OK && order == PORDER_BOTTOM_FIRST && path_back->depth == 2);
    CHECK(path_back->path_list[1].struct_id == 4 && path_back->path_list[1].pick_id == 6);
    CHECK(path_back->path_list[1].elem_pos == 9 && filter_back->incl_set.num_ints == 2);
    CHECK(filter_back->incl_set.ints[0] == 1 && filter_back->excl_set.ints[0] == 8);

    Pstring_data3 buffer = {16, 4, {{0}}};
    EXPECT_NO_ERROR(pinit_string3(WS, 1, "abc", PSTRING_DEF, &box, &buffer));
    char* text = NULL;
    Pstring_data3* string = NULL;
    pinq_string_st3(WS, 1, store, &err, &mode, &echo, &text, &pet, &volume, &string);
    CHECK(err == 0 && strcmp(text, "abc") == 0 && string->buffer_size == 16 && string->init_pos == 4);

    /* SET MODE shows in the state; a device never initialised answers the whole display. */
    EXPECT_NO_ERROR(pset_val_mode(WS, 9, POP_SAMPLE, PSWITCH_NO_ECHO));
    pinq_val_st3(WS, 9, store, &err, &mode, &echo, &value, &pet, &volume, &val);
    CHECK(err == 0 && mode == POP_SAMPLE && echo == PSWITCH_NO_ECHO && volume.x_max == 1024);
    EXPECT_NO_ERROR(pset_val_mode(WS, 9, POP_REQ, PSWITCH_ECHO));
}

/* A valuator's state, to show that a refused call changed nothing. */
typedef struct {
    Pint err, pet;
    Pop_mode mode;
    Pecho_switch echo;
    Pfloat value, low, high;
    Plimit3 volume;
} ValState;

static ValState val_state(Pint dev) {
    ValState s;
    Pval_data3* record = NULL;
    memset(&s, 0, sizeof s);
    pinq_val_st3(WS, dev, store, &s.err, &s.mode, &s.echo, &s.value, &s.pet, &s.volume, &record);
    if (s.err == 0) s.low = record->low, s.high = record->high;
    return s;
}

static int same_val(ValState a, ValState b) {
    return a.err == 0 && b.err == 0 && a.pet == b.pet && a.mode == b.mode && a.echo == b.echo &&
           a.value == b.value && a.low == b.low && a.high == b.high && same_limit(a.volume, b.volume);
}

/* The call reports `num` of `fn` and valuator 7 keeps its state. */
#define EXPECT_VAL_REFUSED(call, num, fn)       \
    do {                                        \
        const ValState before_ = val_state(7);  \
        EXPECT_ERROR(call, num, fn);            \
        CHECK(same_val(before_, val_state(7))); \
    } while (0)

static void errors(void) {
    const Plimit3 box = {10, 200, 20, 300, 0, 1}, empty = {10, 10, 20, 300, 0, 1};
    const Plimit3 outside = {10, 2000, 20, 300, 0, 1}, deep = {10, 200, 20, 300, 0.5f, 0.25f};
    Pval_data3 range = {0, 1, {{0}}}, reversed = {1, 0, {{0}}};
    EXPECT_VAL_REFUSED(pinit_val3(3, 7, 0.5f, 1, &box, &range), 54, Pfn_init_val3);
    EXPECT_VAL_REFUSED(pinit_val3(PDF, 7, 0.5f, 1, &box, &range), 61, Pfn_init_val3);
    EXPECT_VAL_REFUSED(pinit_val3(WS, 13, 0.5f, 1, &box, &range), 250, Pfn_init_val3);
    EXPECT_VAL_REFUSED(pinit_val3(WS, 7, 0.5f, 1, &empty, &range), 254, Pfn_init_val3);
    EXPECT_VAL_REFUSED(pinit_val3(WS, 7, 0.5f, 1, &deep, &range), 254, Pfn_init_val3);
    EXPECT_VAL_REFUSED(pinit_val3(WS, 7, 0.5f, 1, &outside, &range), 255, Pfn_init_val3);
    EXPECT_VAL_REFUSED(pinit_val3(WS, 7, 0.5f, 1, &box, &reversed), 260, Pfn_init_val3);
    EXPECT_VAL_REFUSED(pinit_val3(WS, 7, 1.5f, 1, &box, &range), 261, Pfn_init_val3);
    EXPECT_VAL_REFUSED(pset_val_mode(WS, 7, (Pop_mode)7, PSWITCH_ECHO), PE_ENUM_TYPE_INVAL, Pfn_set_val_mode);
    EXPECT_VAL_REFUSED(pset_val_mode(WS, 13, POP_SAMPLE, PSWITCH_ECHO), 250, Pfn_set_val_mode);
    EXPECT_NO_ERROR(pset_val_mode(WS, 7, POP_EVENT, PSWITCH_ECHO));
    EXPECT_VAL_REFUSED(pinit_val3(WS, 7, 0.5f, 1, &box, &range), 251, Pfn_init_val3);
    Pfloat value = 0;
    EXPECT_VAL_REFUSED(psample_val(WS, 7, &value), 252, Pfn_sample_val);
    EXPECT_NO_ERROR(pset_val_mode(WS, 7, POP_REQ, PSWITCH_ECHO));
    /* An unknown prompt/echo type: warning 253, then type 1 with the default record. */
    EXPECT_ERROR(pinit_val3(WS, 7, 0.5f, 9, &box, &reversed), 253, Pfn_init_val3);
    const ValState after = val_state(7);
    CHECK(after.pet == 1 && after.low == 0 && after.high == 1 && after.value == 0.5f);

    /* The data records and initial values of the other classes. */
    Ppoint3 at = {0, 0, 0};
    EXPECT_ERROR(pinit_loc3(WS, 1, -1, &at, 1, &box, NULL), 114, Pfn_init_loc3);
    Ppoint3 points[3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    Ppoint_list3 three = {3, points};
    Pstroke_data3 two = {2, 1, 0, 0, 0, 0, {{0}}}, none = {0, 1, 0, 0, 0, 0, {{0}}};
    Pstroke_data3 late = {8, 5, 0, 0, 0, 0, {{0}}}, backwards = {8, 1, -1, 0, 0, 0, {{0}}};
    EXPECT_ERROR(pinit_stroke3(WS, 1, 0, &three, 1, &box, &two), 262, Pfn_init_stroke3);
    EXPECT_ERROR(pinit_stroke3(WS, 1, 0, &three, 1, &box, &none), 260, Pfn_init_stroke3);
    EXPECT_ERROR(pinit_stroke3(WS, 1, 0, &three, 1, &box, &late), 260, Pfn_init_stroke3);
    EXPECT_ERROR(pinit_stroke3(WS, 1, 0, &three, 1, &box, &backwards), 260, Pfn_init_stroke3);
    Pstring_data3 small = {3, 1, {{0}}};
    EXPECT_ERROR(pinit_string3(WS, 1, "abcdef", 1, &box, &small), 263, Pfn_init_string3);
    Pchoice_data3 nothing;
    nothing.pets.pet_r3.num_strings = 0;
    nothing.pets.pet_r3.strings = NULL;
    EXPECT_ERROR(pinit_choice3(WS, 1, PIN_STATUS_OK, 1, 3, &box, &nothing), 260, Pfn_init_choice3);
    EXPECT_ERROR(pinit_choice3(WS, 1, PIN_STATUS_OK, 0, 1, &box, NULL), 261, Pfn_init_choice3);
    EXPECT_ERROR(pinit_pick3(PDF, 1, PIN_STATUS_NO_IN, NULL, 1, &box, NULL, PORDER_TOP_FIRST), 60,
                 Pfn_init_pick3);
    Pfilter filter = {{0, NULL}, {0, NULL}};
    EXPECT_ERROR(pset_pick_filter(WS, 2, &filter), 250, Pfn_set_pick_filter);
    /* The refused stroke, string and choice initialisations left those devices as they were. */
    Pint err = -1, view = -1, pet = -1, choice = -1;
    Pop_mode mode;
    Pecho_switch echo;
    Plimit3 volume;
    Ppoint_list3* stroke = NULL;
    Pstroke_data3* stroke_data = NULL;
    pinq_stroke_st3(WS, 1, PINQ_SET, store, &err, &mode, &echo, &view, &stroke, &pet, &volume, &stroke_data);
    CHECK(err == 0 && stroke->num_points == 2 && stroke_data->buffer_size == 8 && stroke_data->init_pos == 3);
    char* text = NULL;
    Pstring_data3* string_data = NULL;
    pinq_string_st3(WS, 1, store, &err, &mode, &echo, &text, &pet, &volume, &string_data);
    CHECK(err == 0 && strcmp(text, "abc") == 0 && string_data->buffer_size == 16);
    Pin_status init_status = PIN_STATUS_NONE;
    Pchoice_data3* choice_data = NULL;
    pinq_choice_st3(WS, 1, store, &err, &mode, &echo, &init_status, &choice, &pet, &volume, &choice_data);
    CHECK(err == 0 && pet == 1 && init_status == PIN_STATUS_OK && choice == 1);

    /* REQUEST without a script, GET without an event, the escape's errors. */
    Pin_status status;
    EXPECT_ERROR(preq_val(WS, 7, &status, &value), 250, Pfn_req_val);
    EXPECT_ERROR(pget_val(&value), 259, Pfn_get_val);
    EXPECT_ERROR(pflush_events(WS, PIN_NONE, 1), PE_ENUM_TYPE_INVAL, Pfn_flush_events);
    Pescape_in_data in;
    Pescape_out_data* out = NULL;
    in.escape_in_u11.ws_id = WS;
    in.escape_in_u11.script = "frobnicate 1 2\n";
    in.escape_in_u11.file = NULL;
    EXPECT_ERROR(pescape(PUESC_INPUT_SCRIPT, &in, NULL, &out), 351, Pfn_escape);
    in.escape_in_u11.script = NULL;
    in.escape_in_u11.file = "/nonexistent/script.txt";
    EXPECT_ERROR(pescape(PUESC_INPUT_SCRIPT, &in, NULL, &out), 351, Pfn_escape);
    in.escape_in_u11.ws_id = PDF;
    in.escape_in_u11.script = "break\n";
    EXPECT_ERROR(pescape(PUESC_INPUT_SCRIPT, &in, NULL, &out), 61, Pfn_escape);
    in.escape_in_u11.ws_id = 9;
    EXPECT_ERROR(pescape(PUESC_INPUT_SCRIPT, &in, NULL, &out), 54, Pfn_escape);

    /* Inquiries answer errors in err_ind only. */
    Pin_class in_class;
    Pint ws, dev;
    error_count = 0;
    pinq_in_overf(&err, &ws, &in_class, &dev);
    CHECK(err == 257);
    CHECK(val_state(13).err == 250);
    Pfilter* filter_back;
    Ppick_path* path;
    Ppick_data3* data;
    Ppath_order order;
    pinq_pick_st3(PDF, 1, PINQ_SET, store, &err, &mode, &echo, &filter_back, &init_status, &path, &pet,
                  &volume, &data, &order);
    CHECK(err == 60);
    pinq_pick_st3(WS, 1, (Pinq_type)5, store, &err, &mode, &echo, &filter_back, &init_status, &path, &pet,
                  &volume, &data, &order);
    CHECK(err == PE_ENUM_TYPE_INVAL);
    CHECK(error_count == 0);
}

/* CLOSE WORKSTATION drops its script and device records: reopened, it starts afresh. */
static void reopen(void) {
    Pescape_in_data in;
    Pescape_out_data* out = NULL;
    in.escape_in_u11.ws_id = WS;
    in.escape_in_u11.script = "valuator 7 0.5\n";
    in.escape_in_u11.file = NULL;
    EXPECT_NO_ERROR(pescape(PUESC_INPUT_SCRIPT, &in, NULL, &out));
    EXPECT_NO_ERROR(pclose_ws(WS));
    EXPECT_NO_ERROR(popen_ws(WS, NULL, PWST_OFFSCREEN));
    Pin_status status;
    Pfloat value;
    EXPECT_ERROR(preq_val(WS, 7, &status, &value), 250, Pfn_req_val);
    const ValState fresh = val_state(7);
    const Plimit3 whole = {0, 1024, 0, 768, 0, 1};
    CHECK(fresh.err == 0 && fresh.pet == 1 && fresh.value == 0 && same_limit(fresh.volume, whole));
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors_file[512], pdf[512];
    Pint err = -1;
    snprintf(errors_file, sizeof errors_file, "%s/input_state_errors.txt", dir);
    snprintf(pdf, sizeof pdf, "%s/input_state.pdf", dir);
    open_with_handler(errors_file);
    pcreate_store(&err, &store);
    CHECK(err == 0);
    Pfloat value;
    EXPECT_ERROR(psample_val(WS, 1, &value), 3, Pfn_sample_val); /* no workstation open */
    EXPECT_NO_ERROR(popen_ws(WS, NULL, PWST_OFFSCREEN));
    EXPECT_NO_ERROR(popen_ws(PDF, pdf, PWST_PDF));
    default_data();
    initialise_and_inquire();
    errors();
    reopen();
    EXPECT_NO_ERROR(pclose_ws(PDF));
    EXPECT_NO_ERROR(pclose_ws(WS));
    pdel_store(store);
    pclose_phigs();
    return finish("test_input_state");
}
