/* Example 8, the C binding's input: a structure network posted on the headless OUTIN
 * workstation (PWST_OFFSCREEN: lavapipe, no display), drawn, then picked by the pick device
 * in REQUEST mode, fed by an input script (ESCAPE PUESC_INPUT_SCRIPT) instead of an operator.
 *
 *     pick_c [SCRIPT [FILE.png]]   the script file (default: a press on the square, one beside
 *                                  it, then "break"), the picture (default: none written)
 *
 * Structure 1 adds name 1 to the name set, sets pick id 3 and executes structure 2, which sets
 * pick id 4 and fills a solid square over NPC [0.4, 0.6]^2. The workstation window [0, 1]^2
 * maps onto the 768 x 768 square at the left of the 1024 x 768 display, so the square's centre
 * is pixel (384, 384) from the top left. Each pick device starts with empty filter sets, so
 * SET PICK FILTER includes name 1 first. */
#include <phigs.h>
#include <stdio.h>

static const char* default_script =
    "# a press on the square, then one beside it\n"
    "pick 384 384\n"
    "pick 700 100\n"
    "break\n";

static void build_network(void) {
    Ppoint square[4] = {{0.4f, 0.4f}, {0.6f, 0.4f}, {0.6f, 0.6f}, {0.4f, 0.6f}};
    Ppoint_list area = {4, square};
    Pint name = 1;
    Pint_list names = {1, &name};
    popen_struct(2);
    pset_int_style(PSTYLE_SOLID); /* element 1 */
    pset_pick_id(4);              /* element 2 */
    pfill_area(&area);            /* element 3 */
    pclose_struct();
    popen_struct(1);
    padd_names_set(&names); /* element 1 */
    pset_pick_id(3);        /* element 2 */
    pexec_struct(2);        /* element 3 */
    pclose_struct();
}

/* REQUEST PICK: the path, root first, as (structure, element, pick id) triples. */
static int request_pick(int press) {
    Ppick_path_elem items[8];
    Ppick_path path = {0, items};
    Pin_status status = PIN_STATUS_NONE;
    preq_pick(1, 1, 8, &status, &path);
    if (status == PIN_STATUS_NONE) return 0; /* broken, or refused (the error is on stderr) */
    printf("press %d: ", press);
    if (status == PIN_STATUS_NO_IN) {
        printf("nothing picked\n");
        return 1;
    }
    printf("pick path (structure, element, pick id):");
    for (Pint i = 0; i < path.depth && i < 8; ++i) /* depth is the path's own: it can be more */
        printf(" (%d, %d, %d)", (int)items[i].struct_id, (int)items[i].elem_pos, (int)items[i].pick_id);
    printf("\n");
    return 1;
}

int main(int argc, char** argv) {
    Pint included = 1, picks = 0;
    Pws_st state = PWS_ST_WSCL;
    Pfilter filter = {{1, &included}, {0, NULL}};
    Pescape_in_data script;
    Pescape_out_data* out = NULL;

    popen_phigs(NULL, PDEF_MEM_SIZE);
    build_network();
    popen_ws(1, argc > 2 ? argv[2] : NULL, PWST_OFFSCREEN);
    pinq_ws_st(&state);
    if (state != PWS_ST_WSOP) {
        fprintf(stderr, "pick_c: the offscreen workstation could not be opened\n");
        pclose_phigs();
        return 1;
    }
    ppost_struct(1, 1, 0.5f);
    pupd_ws(1, PFLAG_PERFORM); /* draws the picture (and writes FILE.png when given) */
    pset_pick_filter(1, 1, &filter);

    script.escape_in_u11.ws_id = 1;
    script.escape_in_u11.script = argc > 1 ? NULL : default_script;
    script.escape_in_u11.file = argc > 1 ? argv[1] : NULL;
    pescape(PUESC_INPUT_SCRIPT, &script, NULL, &out);

    /* One request per press, until the operator (the script's "break") breaks one. */
    while (request_pick(picks + 1)) ++picks;
    printf("%d picks\n", (int)picks);
    pclose_ws(1);
    pclose_phigs();
    return picks > 0 ? 0 : 1;
}
