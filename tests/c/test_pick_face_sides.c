/* Picking by the side shown, on the headless offscreen type (lavapipe, validation layer on) with a
 * script-fed pick device: seeded random squares wound either way (front or back facing) under
 * random front and back interior styles, face distinguishing, culling and edge flags are picked
 * at their centre exactly when the side shown is filled (SOLID, HATCH, PATTERN: the back's style
 * with distinguishing on) and not culled, and on an edge exactly when that holds, the side shown
 * is HOLLOW (not culled), or edges are on. argv[1]: a directory for files.
 *
 * The workstation window [0,1]^2 maps onto the 768 x 768 square at the left of the 1024 x 768
 * display, so NPC (x, y) is pixel (768 x, 768 (1 - y)) from the top left. */
#include "check.h"

#define WS 1

/* Whether REQUEST PICK at NPC (x, y) finds the square (pick id 7). */
static int picked_at(double x, double y) {
    char script[64];
    Pescape_in_data in;
    Pescape_out_data* out = NULL;
    Ppick_path_elem items[2];
    Ppick_path path = {0, items};
    Pin_status status = PIN_STATUS_NONE;
    snprintf(script, sizeof script, "pick %d %d\n", (int)lround(768 * x), (int)lround(768 * (1 - y)));
    in.escape_in_u11.ws_id = WS;
    in.escape_in_u11.script = script;
    in.escape_in_u11.file = NULL;
    EXPECT_NO_ERROR(pescape(PUESC_INPUT_SCRIPT, &in, NULL, &out));
    EXPECT_NO_ERROR(preq_pick(WS, 1, 2, &status, &path));
    CHECK(status == PIN_STATUS_NO_IN ||
          (status == PIN_STATUS_OK && path.depth == 1 && items[0].pick_id == 7));
    return status == PIN_STATUS_OK;
}

static int filled(Pint_style s) {
    return s == PSTYLE_SOLID || s == PSTYLE_HATCH || s == PSTYLE_PAT;
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    Pint one = 1;
    Pint_list names = {1, &one};
    Pfilter filter = {{1, &one}, {0, NULL}};
    int backHits = 0, backOutlines = 0, frontMisses = 0;
    seed_random(0x9e3779b97f4a7c15ULL);
    snprintf(errors, sizeof errors, "%s/pick_face_sides_errors.txt", dir);
    open_with_handler(errors);
    EXPECT_NO_ERROR(popen_ws(WS, NULL, PWST_OFFSCREEN));
    EXPECT_NO_ERROR(pset_pick_filter(WS, 1, &filter));
    for (int round = 0; round < 48; ++round) {
        const Pint_style styles[5] = {PSTYLE_HOLLOW, PSTYLE_SOLID, PSTYLE_PAT, PSTYLE_HATCH, PSTYLE_EMPTY};
        /* Every sixth round a HOLLOW back shown under a filled front. */
        const int hollowBack = round % 6 == 1;
        const Pint_style frontStyle = hollowBack ? styles[1 + next_random() % 3] : styles[next_random() % 5];
        const Pint_style backStyle = hollowBack ? PSTYLE_HOLLOW : styles[next_random() % 5];
        const int backFacing = hollowBack || (int)(next_random() % 2);
        const int distinguish = hollowBack || (int)(next_random() % 4 != 0);
        const Pcull_mode cull =
            (Pcull_mode)(!hollowBack && next_random() % 5 == 0 ? 1 + next_random() % 2 : PCULL_NONE);
        const int edges = next_random() % 5 == 0;
        double x0, y0, side;
        Ppoint3 corners[4];
        Ppoint_list3 square = {4, corners};
        random_square(corners, backFacing, &x0, &y0, &side);
        EXPECT_NO_ERROR(pdel_struct(1));
        EXPECT_NO_ERROR(popen_struct(1));
        padd_names_set(&names);
        pset_pick_id(7);
        pset_int_style(frontStyle);
        pset_back_int_style(backStyle);
        pset_face_disting_mode(distinguish ? PDISTING_YES : PDISTING_NO);
        pset_face_cull_mode(cull);
        pset_edge_flag(edges ? PEDGE_ON : PEDGE_OFF);
        pfill_area3(&square);
        EXPECT_NO_ERROR(pclose_struct());
        EXPECT_NO_ERROR(ppost_struct(WS, 1, 0.5f));
        {
            const int culled =
                (backFacing && cull == PCULL_BACKFACE) || (!backFacing && cull == PCULL_FRONTFACE);
            const Pint_style shown = backFacing && distinguish ? backStyle : frontStyle;
            const int inside = !culled && filled(shown);
            const int outline = inside || (!culled && shown == PSTYLE_HOLLOW) || edges;
            const int centre = picked_at(x0 + side / 2, y0 + side / 2), edge = picked_at(x0 + side / 2, y0);
            if (centre != inside || edge != outline)
                fprintf(stderr,
                        "  square %s, styles %d / %d, distinguishing %d, cull %d, edges %d: picked %d %d\n",
                        backFacing ? "back" : "front", (int)frontStyle, (int)backStyle, distinguish,
                        (int)cull, edges, centre, edge);
            CHECK(centre == inside);
            CHECK(edge == outline);
            backHits += backFacing && inside && shown != frontStyle;
            backOutlines += backFacing && !inside && outline && !edges && shown != frontStyle;
            frontMisses += !backFacing && !inside && filled(backStyle) && distinguish;
        }
    }
    /* The sequence reaches the cases a front-only rule gets wrong. */
    CHECK(backHits >= 2);
    CHECK(backOutlines >= 2);
    CHECK(frontMisses >= 2);
    EXPECT_NO_ERROR(pclose_ws(WS));
    pclose_phigs();
    return finish("test_pick_face_sides");
}
