/* Control and error handling: OPEN / CLOSE / EMERGENCY CLOSE PHIGS (which updates and closes the
 * open workstations, also from an error handler), the system state, the
 * error handler, its mode, ERROR LOGGING's lines in the error file, and that inquiries never
 * call the handler. argv[1]: a directory for the error file. */
#include "check.h"

static void handler_and_mode(const char* file) {
    void (*old)(Pint, Pint, const char*) = NULL;
    Pint err = -1;
    Perr_mode mode = PERR_OFF;

    pset_err_hand(recording_handler, &old);
    CHECK(old == recording_handler); /* open_with_handler installed it */
    pinq_err_hand_mode(&err, &mode);
    CHECK(err == 0 && mode == PERR_ON);

    EXPECT_ERROR(popen_phigs(file, PDEF_MEM_SIZE), 1, Pfn_open_phigs);
    EXPECT_REFUSED(pdel_elem(), 5, Pfn_del_elem);
    pset_err_hand_mode(PERR_OFF);
    EXPECT_NO_ERROR(pdel_elem()); /* still refused, but the handler is not called */
    pinq_err_hand_mode(&err, &mode);
    CHECK(err == 0 && mode == PERR_OFF);
    pset_err_hand_mode(PERR_ON);
    EXPECT_ERROR(pset_err_hand_mode((Perr_mode)7), PE_ENUM_TYPE_INVAL, Pfn_set_err_hand_mode);
    pinq_err_hand_mode(&err, &mode);
    CHECK(mode == PERR_ON);

    /* Inquiries answer an error indicator only. */
    error_count = 0;
    pinq_elem_ptr(&err, &(Pint){0});
    CHECK(err == 5);
    pinq_elem_type_size(99, 1, &err, &(Pelem_type){PELEM_ALL}, &(size_t){0});
    CHECK(err == 201);
    CHECK(error_count == 0);
}

static void message_and_facilities(void) {
    Pint err = -1, ws = 0, ar = 0, names = 0, normal = 0, inverse = 0, total = -1, sets[4];
    Pint_list char_sets = {-1, sets};
    EXPECT_REFUSED(pmessage(1, "hello"), 3, Pfn_message); /* no workstation open */
    pinq_phigs_facs(4, 0, &err, &ws, &ar, &names, &char_sets, &total, &normal, &inverse);
    CHECK(err == 0 && ws == 2147483647 && ar == 2147483647 && names == 2147483647);
    CHECK(normal == 2147483647 && inverse == 2147483647 && total == 0 && char_sets.num_ints == 0);
    pinq_phigs_facs(-1, 0, &err, &ws, &ar, &names, &char_sets, &total, &normal, &inverse);
    CHECK(err == PE_LIST_LENGTH_LT_ZERO);
}

/* No escape is registered: any identifier is warning 350 and a NULL output record. */
static void escapes(const char* file) {
    Pstore store = NULL;
    Pescape_out_data* out = (Pescape_out_data*)&store; /* not NULL, so the reset shows */
    Pint err = -1;
    pcreate_store(&err, &store);
    EXPECT_REFUSED(pescape(-1, NULL, store, &out), 350, Pfn_escape);
    CHECK(out == NULL);
    CHECK(file_has_line(
        file,
        "WARNING 350 in ESCAPE (function 180): Warning, the specified escape is not available on "
        "one or more workstations in this implementation"));
    pdel_store(store);
}

/* ERROR LOGGING writes the reason the core gave after the standard's message. */
static void reasons(const char* file) {
    Pview_rep3 current, requested;
    Pupd_st state = PUPD_NOT_PEND;
    Pint err = -1;
    popen_ws(7, NULL, PWST_OFFSCREEN);
    pinq_view_rep(7, 0, &err, &state, &current, &requested);
    CHECK(err == 0);
    EXPECT_REFUSED(pset_view_rep3(7, 40, &current), 150, Pfn_set_view_rep3);
    CHECK(
        file_has_line(file,
                      "ERROR 150 in SET VIEW REPRESENTATION 3 (function 83): Ignoring function, setting this "
                      "view table entry would exceed the maximum number of entries allowed in the "
                      "workstation's view table (view index 40)"));
    pclose_ws(7);
}

static void close_needs_everything_closed(void) {
    Psys_st st = PSYS_ST_PHCL;
    popen_struct(1);
    EXPECT_ERROR(pclose_phigs(), 4, Pfn_close_phigs);
    pinq_sys_st(&st);
    CHECK(st == PSYS_ST_PHOP);
    pclose_struct();
}

/* The whole text of `path` (to be freed), or NULL when it cannot be read. */
static char* file_text(const char* path) {
    FILE* f = fopen(path, "rb");
    if (!f) return NULL;
    char* text = calloc(1 << 20, 1);
    if (text) fread(text, 1, (1 << 20) - 1, f);
    fclose(f);
    return text;
}

static int closing_handler_calls = 0;
/* An old program's handler: a fatal error closes PHIGS down at once. */
static void closing_handler(Pint err, Pint fn, const char* file) {
    ++closing_handler_calls;
    perr_hand(err, fn, file);
    pemergency_close_phigs();
}

/* EMERGENCY CLOSE PHIGS updates and closes the open workstations (ISO 9592): a vector file holds
 * the picture changed since the last update, also when an error handler closes down. */
static void emergency_close_keeps_pictures(const char* dir, const char* errors) {
    char svg[512], archive[512];
    Psys_st st = PSYS_ST_PHOP;
    for (int through_handler = 0; through_handler < 2; ++through_handler) {
        snprintf(svg, sizeof svg, "%s/emergency_%d.svg", dir, through_handler);
        snprintf(archive, sizeof archive, "%s/emergency_%d.phar", dir, through_handler);
        remove(svg), remove(archive);
        open_with_handler(errors);
        EXPECT_NO_ERROR(popen_ws(1, svg, PWST_SVG));
        EXPECT_NO_ERROR(popen_ar_file(1, archive));
        Ppoint3 line[2] = {{0.2f, 0.2f, 0}, {0.8f, 0.7f, 0}};
        Ppoint_list3 points = {2, line};
        Pgcolr magenta = {PMODEL_RGB, {0}};
        magenta.val.general.x = magenta.val.general.z = 1;
        EXPECT_NO_ERROR(popen_struct(1));
        EXPECT_NO_ERROR(pset_line_colr(&magenta));
        EXPECT_NO_ERROR(ppolyline3(&points));
        EXPECT_NO_ERROR(ppost_struct(1, 1, 0.5f));
        EXPECT_NO_ERROR(pset_line_colr(&magenta)); /* the structure stays open */
        if (through_handler) {
            pset_err_hand(closing_handler, NULL);
            closing_handler_calls = 0;
            popen_ws(1, svg, PWST_SVG); /* error 53: the handler closes PHIGS */
            CHECK(closing_handler_calls == 1);
            pset_err_hand(recording_handler, NULL);
        } else {
            pemergency_close_phigs();
        }
        pinq_sys_st(&st);
        CHECK(st == PSYS_ST_PHCL);
        char* text = file_text(svg);
        CHECK(text != NULL);
        if (text) CHECK(strstr(text, "<path") != NULL && strstr(text, "stroke:rgb(100%,0%,100%)") != NULL);
        free(text);
        open_with_handler(errors); /* the archive closed complete: it opens again */
        EXPECT_NO_ERROR(popen_ar_file(1, archive));
        EXPECT_NO_ERROR(pclose_ar_file(1));
        EXPECT_NO_ERROR(pclose_phigs());
    }
}

int main(int argc, char** argv) {
    char file[512];
    Psys_st st = PSYS_ST_PHOP;
    Pint err = -1, total = -1;
    Pstruct_status status = PSTRUCT_STATUS_NON_EXIST;
    snprintf(file, sizeof file, "%s/control_errors.txt", argc > 1 ? argv[1] : ".");

    pinq_sys_st(&st);
    CHECK(st == PSYS_ST_PHCL);
    pset_err_hand(recording_handler, NULL);
    EXPECT_ERROR(popen_struct(1), 6, Pfn_open_struct); /* PHIGS closed: its state error, on stderr */
    pinq_struct_status(1, &err, &status);
    CHECK(err == 2);

    open_with_handler(file);
    pinq_sys_st(&st);
    CHECK(st == PSYS_ST_PHOP);
    handler_and_mode(file);
    message_and_facilities();
    escapes(file);
    reasons(file);
    close_needs_everything_closed();
    EXPECT_NO_ERROR(pclose_phigs());
    pinq_sys_st(&st);
    CHECK(st == PSYS_ST_PHCL);

    /* ERROR LOGGING's lines, in the order they were raised; the PERR_OFF error is not there. */
    CHECK(file_line_count(file) == 7);
    CHECK(file_has_line(file,
                        "ERROR 1 in OPEN PHIGS (function 0): Ignoring function, function requires state "
                        "(PHCL, WSCL, STCL, ARCL)"));
    CHECK(file_has_line(file,
                        "ERROR 5 in DELETE ELEMENT (function 101): Ignoring function, function requires "
                        "state (PHOP, *, STOP, *)"));
    CHECK(file_has_line(
        file, "ERROR 2202 in SET ERROR HANDLING MODE (function 179): Enumeration type out of range"));
    CHECK(file_has_line(file,
                        "ERROR 4 in CLOSE PHIGS (function 1): Ignoring function, function requires state "
                        "(PHOP, WSCL, STCL, ARCL)"));
    perr_log(201, Pfn_empty_struct, file); /* ERROR LOGGING called directly, PHIGS closed */
    CHECK(file_has_line(file,
                        "ERROR 201 in EMPTY STRUCTURE (function 104): Ignoring function, the specified "
                        "structure does not exist"));

    /* EMERGENCY CLOSE PHIGS closes whatever is open; the next OPEN PHIGS starts afresh. */
    open_with_handler(file);
    CHECK(file_line_count(file) == 0); /* the error file starts again */
    popen_struct(3);
    pemergency_close_phigs();
    pinq_sys_st(&st);
    CHECK(st == PSYS_ST_PHCL);
    pemergency_close_phigs(); /* nothing open: nothing happens */
    open_with_handler(file);
    pset_err_hand_mode(PERR_OFF);
    pemergency_close_phigs();
    open_with_handler(file);
    {
        Perr_mode mode = PERR_OFF;
        pinq_err_hand_mode(&err, &mode);
        CHECK(err == 0 && mode == PERR_ON); /* OPEN PHIGS starts with the mode ON */
    }
    pinq_struct_ids(0, 0, &err, NULL, &total);
    CHECK(err == 0 && total == 0);
    EXPECT_NO_ERROR(pclose_phigs());
    emergency_close_keeps_pictures(argc > 1 ? argv[1] : ".", file);
    return finish("test_control");
}
