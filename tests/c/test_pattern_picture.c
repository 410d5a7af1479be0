/* Interior style PSTYLE_PAT and the transparency coefficient drawn on the headless offscreen
 * type (lavapipe): a square filled with a 2 x 2 pattern set by pset_pat_rep, placed by
 * pset_pat_size and pset_pat_ref_point, shows each cell's colour where the pattern box puts it;
 * a half transparent blue square over an opaque red one shows their mix. Links libpng besides
 * libphigs to read the PNG. argv[1]: a directory for the files. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include "picture.h"

/* Whether the pixel at NPC (x, y) (the display surface maps NPC [0, 1]^2 onto the picture's
 * height at the lower left) is within 8 of (r, g, b). */
static int shows(const Picture* p, double x, double y, int r, int g, int b) {
    const int i = (int)(x * p->height), j = (int)(p->height - y * p->height);
    const unsigned char* c = p->rgb + ((size_t)j * (size_t)p->width + (size_t)i) * 3;
    const int ok = abs(c[0] - r) <= 8 && abs(c[1] - g) <= 8 && abs(c[2] - b) <= 8;
    if (!ok)
        fprintf(stderr, "  at (%.3f, %.3f): %d %d %d, expected %d %d %d\n", x, y, c[0], c[1], c[2], r, g, b);
    return ok;
}

static void square(float x0, float y0, float x1, float y1) {
    Ppoint3 corners[4] = {{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}};
    Ppoint_list3 area = {4, corners};
    pfill_area3(&area);
}

/* The pattern square over NPC [0.05, 0.45]^2, its box 0.2 x 0.2 from (0.05, 0.05): cells 0.1
 * wide. An opaque red square over [0.55, 0.95] x [0.05, 0.45] and a blue one, transparency
 * coefficient 0.5, over [0.55, 0.95] x [0.25, 0.65] after it. */
static void build_scene(void) {
    Pfloat_size size = {0.2f, 0.2f};
    Ppoint reference = {0.05f, 0.05f};
    Pgcolr red = {PMODEL_RGB, {0}}, blue = {PMODEL_RGB, {0}};
    red.val.general.x = 1;
    blue.val.general.z = 1;
    Prefl_props see_through = {1, 1, 0, {PMODEL_RGB, {0}}, 1, 0.5f};
    popen_struct(1);
    pset_int_style(PSTYLE_PAT);
    pset_int_style_ind(3);
    pset_pat_size(&size);
    pset_pat_ref_point(&reference);
    square(0.05f, 0.05f, 0.45f, 0.45f);
    pset_int_style(PSTYLE_SOLID);
    pset_int_colr(&red);
    square(0.55f, 0.05f, 0.95f, 0.45f);
    pset_refl_props(&see_through);
    pset_int_colr(&blue);
    square(0.55f, 0.25f, 0.95f, 0.65f);
    pclose_struct();
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char png[512], errors[512];
    snprintf(png, sizeof png, "%s/pattern_picture.png", dir);
    snprintf(errors, sizeof errors, "%s/pattern_picture_errors.txt", dir);
    remove(png);
    open_with_handler(errors);
    build_scene();

    /* Cells row by row from the reference point: red, green / blue, a colour of our own. */
    Pint cells[4] = {2, 3, 4, 9};
    Ppat_rep pattern = {{2, 2}, cells};
    Pcolr_rep orange = {{1.0f, 0.5f, 0.0f}};
    EXPECT_NO_ERROR(popen_ws(1, png, PWST_OFFSCREEN));
    EXPECT_NO_ERROR(pset_colr_rep(1, 9, &orange));
    EXPECT_NO_ERROR(pset_pat_rep(1, 3, &pattern));
    EXPECT_NO_ERROR(ppost_struct(1, 1, 0.5f));
    EXPECT_NO_ERROR(pupd_ws(1, PFLAG_PERFORM));

    Picture picture = {0};
    CHECK(read_png(png, &picture));
    if (picture.rgb) {
        const int rgb[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 128, 0}};
        for (int row = 0; row < 4; ++row)
            for (int column = 0; column < 4; ++column) {
                const int* c = rgb[(row % 2) * 2 + column % 2];
                CHECK(shows(&picture, 0.1 + 0.1 * column, 0.1 + 0.1 * row, c[0], c[1], c[2]));
            }
        CHECK(shows(&picture, 0.75, 0.15, 255, 0, 0));   /* red alone */
        CHECK(shows(&picture, 0.75, 0.35, 128, 0, 128)); /* blue half over red */
        CHECK(shows(&picture, 0.75, 0.55, 0, 0, 128));   /* blue half over the black background */
        free(picture.rgb);
    }
    EXPECT_NO_ERROR(pclose_ws(1));
    pclose_phigs();
    return finish("test_pattern_picture");
}
