/* The window workstation type from C, under an Xvfb of its own (label window): opened on
 * $DISPLAY (NULL) and by display name, drawn at update, its connection identifier inquired; a
 * second display while a window is open is error 50, a display with no server 55. Its devices
 * read the window (AWAIT EVENT times out with no operator) or, once given, an input script.
 * argv[1]: a directory for the error file. */
#include "check.h"

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    snprintf(errors, sizeof errors, "%s/window_ws_errors.txt", dir);
    const char* display = getenv("DISPLAY");
    CHECK(display != NULL);
    if (!display) return finish("window_ws");
    open_with_handler(errors);
    Ppoint3 points[2] = {{0.1f, 0.1f, 0}, {0.9f, 0.9f, 0}};
    Ppoint_list3 line = {2, points};
    popen_struct(1);
    ppolyline3(&line);
    pclose_struct();

    Pint err = -1, type = 0;
    void* conn = NULL;
    Pstore store = NULL;
    pcreate_store(&err, &store);
    EXPECT_NO_ERROR(popen_ws(1, NULL, PWST_WINDOW));
    EXPECT_NO_ERROR(ppost_struct(1, 1, 0.5f));
    EXPECT_NO_ERROR(pupd_ws(1, PFLAG_PERFORM));
    EXPECT_NO_ERROR(popen_ws(2, display, PWST_WINDOW)); /* the same display by name */
    pinq_ws_conn_type(2, store, &err, &conn, &type);
    CHECK(err == 0 && type >= PWST_SPECIFIC_BASE && conn && strcmp((const char*)conn, display) == 0);
    pinq_ws_conn_type(1, store, &err, &conn, &type);
    CHECK(err == 0 && type >= PWST_SPECIFIC_BASE && conn == NULL);
    {
        /* The window's own size: the type's display size, as it was opened with no other. */
        Pdisp_space_size3 generic, specific;
        Pws_cat cat;
        pinq_disp_space_size3(PWST_WINDOW, &err, &generic);
        pinq_disp_space_size3(type, &err, &specific);
        CHECK(err == 0 && specific.size_raster.size_x == generic.size_raster.size_x &&
              specific.size_raster.size_y == generic.size_raster.size_y);
        pinq_ws_cat(type, &err, &cat);
        CHECK(err == 0 && cat == PCAT_OUTIN);
    }
    EXPECT_NO_ERROR(predraw_all_structs(2, PFLAG_ALWAYS));
    Pint ws = -1, number = -1;
    Pin_class in_class = PIN_LOC;
    EXPECT_NO_ERROR(pset_choice_mode(1, 1, POP_EVENT, PSWITCH_ECHO));
    EXPECT_NO_ERROR(pawait_event(0.05f, &ws, &in_class, &number));
    CHECK(in_class == PIN_NONE);
    Pescape_in_data in;
    Pescape_out_data* out = NULL;
    in.escape_in_u11.ws_id = 2;
    in.escape_in_u11.script = "valuator 1 0.5\n";
    in.escape_in_u11.file = NULL;
    EXPECT_NO_ERROR(pescape(PUESC_INPUT_SCRIPT, &in, NULL, &out));
    Pin_status status = PIN_STATUS_NONE;
    Pfloat value = 0;
    EXPECT_NO_ERROR(preq_val(2, 1, &status, &value));
    CHECK(status == PIN_STATUS_OK && value == 0.5f);
    EXPECT_ERROR(popen_ws(3, ":4711", PWST_WINDOW), 50, Pfn_open_ws); /* one display per process */
    EXPECT_NO_ERROR(pclose_ws(1));
    EXPECT_NO_ERROR(pclose_ws(2));
    EXPECT_ERROR(popen_ws(3, ":4711", PWST_WINDOW), 55, Pfn_open_ws); /* no server there */
    EXPECT_NO_ERROR(popen_ws(3, NULL, PWST_WINDOW));                  /* $DISPLAY is as it was */
    EXPECT_NO_ERROR(pclose_ws(3));
    pdel_store(store);
    pclose_phigs();
    return finish("window_ws");
}
