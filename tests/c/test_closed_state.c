/* While PHIGS is closed each function reports the state error ISO 9592 lists for it: 2 for
 * (PHOP, *, *, *), 3 where it needs a workstation open, 5 a structure open, 6 a structure closed,
 * 7 an archive open. The same call with PHIGS open and nothing open reports the same error (the
 * class property). Errors while closed reach the handler with no file name. argv[1]: a directory. */
#include "check.h"

#include <string.h>

static const char* handed_file = "unset";
static void naming_handler(Pint err, Pint fn, const char* file) {
    handed_file = file;
    recording_handler(err, fn, file);
}

static Ppoint points[2] = {{0, 0}, {1, 1}};
static Ppoint_list line = {2, points};
static Pline_bundle bundle = {1, 1.0, 1};

static void c_set_elem_ptr(void) {
    pset_elem_ptr(1);
}
static void c_label(void) {
    plabel(1);
}
static void c_del_elem_range(void) {
    pdel_elem_range(1, 2);
}
static void c_close_struct(void) {
    pclose_struct();
}
static void c_copy_all(void) {
    pcopy_all_elems_struct(1);
}
static void c_polyline(void) {
    ppolyline(&line);
}
static void c_linetype(void) {
    pset_linetype(1);
}
static void c_exec(void) {
    pexec_struct(2);
}
static void c_ret_all(void) {
    pret_all_structs(1);
}
static void c_close_ar(void) {
    pclose_ar_file(1);
}
static void c_upd_ws(void) {
    pupd_ws(1, PFLAG_PERFORM);
}
static void c_post(void) {
    ppost_struct(1, 1, 0.5);
}
static void c_line_rep(void) {
    pset_line_rep(1, 1, &bundle);
}
static void c_message(void) {
    pmessage(1, "hello");
}

typedef struct {
    void (*call)(void);
    Pint error, function;
} Stated;

static const Stated stated[] = {
    {c_set_elem_ptr, 5, Pfn_set_elem_ptr},
    {c_label, 5, Pfn_label},
    {c_del_elem_range, 5, Pfn_del_elem_range},
    {c_close_struct, 5, Pfn_close_struct},
    {c_copy_all, 5, Pfn_copy_all_elems_struct},
    {c_polyline, 5, Pfn_polyline},
    {c_linetype, 5, Pfn_set_linetype},
    {c_exec, 5, Pfn_exec_struct},
    {c_ret_all, 7, Pfn_ret_all_structs},
    {c_close_ar, 7, Pfn_close_ar_file},
    {c_upd_ws, 3, Pfn_upd_ws},
    {c_post, 3, Pfn_post_struct},
    {c_line_rep, 3, Pfn_set_line_rep},
    {c_message, 3, Pfn_message},
};
enum { STATED = sizeof stated / sizeof stated[0] };

/* The inquiries' state errors, with PHIGS closed or open with nothing open. */
static void inquiries(int closed) {
    Pint err = -1, ptr = 0, total = 0, ids[4], type = 0;
    Pint_list list = {0, ids};
    Pelem_type elem = PELEM_ALL;
    size_t size = 0;
    void* conn = NULL;
    Pdefer_mode defer;
    Pmod_mode mod;
    Pdisp_surf_empty empty;
    Pvisual_st visual;
    pinq_elem_ptr(&err, &ptr);
    CHECK(err == 5);
    pinq_cur_elem_type_size(&err, &elem, &size);
    CHECK(err == 5);
    pinq_all_conf_structs(1, 4, 0, &err, &list, &total);
    CHECK(err == 7);
    pinq_disp_upd_st(1, &err, &defer, &mod, &empty, &visual);
    CHECK(err == 3);
    pinq_ws_conn_type(1, NULL, &err, &conn, &type);
    CHECK(err == 3);
    pinq_struct_ids(4, 0, &err, &list, &total);
    CHECK(err == (closed ? 2 : 0));
}

int main(int argc, char** argv) {
    char file[512];
    snprintf(file, sizeof file, "%s/closed_state_errors.txt", argc > 1 ? argv[1] : ".");
    pset_err_hand(naming_handler, NULL);

    for (int i = 0; i < STATED; ++i) EXPECT_ERROR(stated[i].call(), stated[i].error, stated[i].function);
    EXPECT_ERROR(popen_struct(1), 6, Pfn_open_struct);
    EXPECT_ERROR(pdel_struct(1), 2, Pfn_del_struct);
    EXPECT_ERROR(popen_ar_file(1, "never.phar"), 2, Pfn_open_ar_file);
    EXPECT_ERROR(pclose_phigs(), 4, Pfn_close_phigs); /* the one error ISO lists for it */
    inquiries(1);

    /* Open with nothing open: the same errors. */
    popen_phigs(file, PDEF_MEM_SIZE);
    for (int i = 0; i < STATED; ++i) EXPECT_ERROR(stated[i].call(), stated[i].error, stated[i].function);
    inquiries(0);
    popen_struct(1);
    EXPECT_ERROR(popen_struct(2), 6, Pfn_open_struct);
    pclose_struct();
    const int lines = file_line_count(file);
    pclose_phigs();

    /* Closed again: the handler gets no file name, and the old error file no line. */
    EXPECT_ERROR(pdel_struct(1), 2, Pfn_del_struct);
    CHECK(handed_file == NULL);
    EXPECT_ERROR(pset_elem_ptr(1), 5, Pfn_set_elem_ptr);
    CHECK(file_line_count(file) == lines);
    return finish("test_closed_state");
}
