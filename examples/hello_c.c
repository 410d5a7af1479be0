/* Example 7, the C binding: example 1 through phigs.h alone. A yellow zigzag and white text in
 * structure 1, posted on an offscreen workstation (lavapipe, no display needed) whose
 * connection identifier names the PNG it writes at every update and at close.
 *
 *     hello_c [FILE.png]      the picture (default: hello_c.png)
 */
#include <phigs.h>
#include <stdio.h>

int main(int argc, char** argv) {
    const char* file = argc > 1 ? argv[1] : "hello_c.png";
    Ppoint3 zigzag[5] = {{0.1f, 0.2f, 0}, {0.3f, 0.5f, 0}, {0.5f, 0.2f, 0}, {0.7f, 0.5f, 0}, {0.9f, 0.2f, 0}};
    Ppoint_list3 line = {5, zigzag};
    Ppoint3 text_position = {0.1f, 0.7f, 0};
    Pvec3 text_directions[2] = {{1, 0, 0}, {0, 1, 0}};
    Pgcolr yellow, white;
    Pint err = 0, posted = 0;
    Pws_st ws_state = PWS_ST_WSCL;

    yellow.type = PMODEL_RGB;
    yellow.val.general.x = 1, yellow.val.general.y = 1, yellow.val.general.z = 0;
    white.type = PMODEL_RGB;
    white.val.general.x = 1, white.val.general.y = 1, white.val.general.z = 1;

    popen_phigs(NULL, PDEF_MEM_SIZE); /* errors, if any, are written to stderr */
    popen_struct(1);
    pset_line_colr(&yellow);
    pset_linewidth(3);
    ppolyline3(&line);
    pset_text_colr(&white);
    pset_char_ht(0.08f);
    ptext3(&text_position, text_directions, "Hello, PHIGS");
    pclose_struct();

    /* OPEN WORKSTATION on the offscreen type, POST STRUCTURE, UPDATE WORKSTATION: the picture. */
    popen_ws(1, file, PWST_OFFSCREEN);
    pinq_ws_st(&ws_state);
    ppost_struct(1, 1, 0.5f);
    pupd_ws(1, PFLAG_PERFORM);
    {
        Pint ids[4];
        Pint_list list = {0, ids};
        pinq_open_wss(4, 0, &err, &list, &posted);
    }
    printf("workstation %s, %d open, picture in %s\n", ws_state == PWS_ST_WSOP ? "open" : "closed",
           (int)posted, file);
    pclose_ws(1);
    pclose_phigs();
    return err == 0 && ws_state == PWS_ST_WSOP ? 0 : 1;
}
