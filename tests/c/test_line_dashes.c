/* Dashed polylines with vertex colours keep one dash pattern along the whole polyline: a polyline
 * set with data of random vertices along a horizontal line, random vertex colours, polyline
 * shading PSD_NONE or PSD_COLOUR and a random line type, drawn on the offscreen type (lavapipe,
 * validation layer on) and the PDF type (rasterised by pdftoppm at 144 dpi), is on and off in the
 * same columns as a plain polyline of the same line type and ends drawn beside it (within a
 * pixel of a dash end). argv[1]: a directory for the files. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include "picture.h"

/* Whether anything is drawn at pixel column i near NPC height y (a pixel above or below too). */
static int drawn(const Picture* p, int i, double y) {
    const int j0 = (int)(p->height - y * p->side);
    for (int j = j0 - 1; j <= j0 + 1; ++j) {
        const unsigned char* c = p->rgb + ((size_t)j * (size_t)p->width + (size_t)i) * 3;
        if (c[0] + c[1] + c[2] > 150) return 1;
    }
    return 0;
}

static char png[512], pdf[512], ppm_root[512];

/* Draws structure 1 on a fresh offscreen and PDF workstation and reads both pictures (p[0], p[1]). */
static int draw(Picture p[2]) {
    char command[2048], ppm[600];
    remove(png), remove(pdf);
    EXPECT_NO_ERROR(popen_ws(1, png, PWST_OFFSCREEN));
    EXPECT_NO_ERROR(popen_ws(2, pdf, PWST_PDF));
    for (Pint ws = 1; ws <= 2; ++ws) {
        EXPECT_NO_ERROR(ppost_struct(ws, 1, 0.5f));
        EXPECT_NO_ERROR(pupd_ws(ws, PFLAG_PERFORM));
        EXPECT_NO_ERROR(pclose_ws(ws));
    }
    p[0].rgb = p[1].rgb = NULL;
    p[0].side = 768, p[0].name = "offscreen";
    p[1].side = 595.2756 * 2, p[1].name = "PDF";
    snprintf(command, sizeof command, "pdftoppm -r 144 -singlefile '%s' '%s'", pdf, ppm_root);
    snprintf(ppm, sizeof ppm, "%s.ppm", ppm_root);
    return read_png(png, &p[0]) && system(command) == 0 && read_ppm(ppm, &p[1]);
}

/* The columns between x0 and x1 where the coloured line (at y) and the plain one (at y_plain)
 * differ, leaving out those within a pixel of a change of the plain one. */
static int differing_columns(const Picture* p, double x0, double x1, double y, double y_plain) {
    const int first = (int)(x0 * p->side) + 3, last = (int)(x1 * p->side) - 3;
    int differ = 0;
    for (int i = first; i <= last; ++i) {
        const int plain = drawn(p, i, y_plain);
        if (plain != drawn(p, i - 1, y_plain) || plain != drawn(p, i + 1, y_plain)) continue;
        if (drawn(p, i, y) != plain) ++differ;
    }
    return differ;
}

static void dashes(void) {
    for (int round = 0; round < 8; ++round) {
        enum { kMax = 12 };
        Pptco3 vertices[kMax];
        Ppoint3 ends[2];
        Ppoint_list3 plain = {2, ends};
        Pline_vdata_list3 line;
        Picture p[2];
        const int n = 3 + (int)(next_random() % (kMax - 2));
        const Pint type = PLINE_DASH + (Pint)(next_random() % 3);
        const int shaded = round % 2;
        const double y = 0.3 + 0.4 * (next_random() % 1000) / 1000.0, y_plain = y - 0.1;
        for (int i = 0; i < n; ++i) {
            /* increasing x from 0.1 to 0.9 at random steps */
            vertices[i].point.x =
                (Pfloat)(i == 0       ? 0.1
                         : i == n - 1 ? 0.9
                                      : 0.1 + 0.8 * (i + (next_random() % 800) / 1000.0 - 0.4) / (n - 1));
            vertices[i].point.y = (Pfloat)y, vertices[i].point.z = 0;
            /* bright colours: every one shows against the black background */
            vertices[i].colr.direct.x = (Pfloat)(0.5 + (next_random() % 128) / 255.0);
            vertices[i].colr.direct.y = (Pfloat)(0.5 + (next_random() % 128) / 255.0);
            vertices[i].colr.direct.z = (Pfloat)(0.5 + (next_random() % 128) / 255.0);
        }
        ends[0] = vertices[0].point, ends[1] = vertices[n - 1].point;
        ends[0].y = ends[1].y = (Pfloat)y_plain;
        line.num_vertices = n, line.vertex_data.ptcolrs = vertices;
        pdel_struct(1);
        popen_struct(1);
        pset_linewidth(3);
        pset_linetype(type);
        pset_line_shad_meth(shaded ? PSD_COLOUR : PSD_NONE);
        ppolyline_set3_data(PVERT_COORD_COLOUR, PMODEL_RGB, 1, &line);
        pset_line_colr_ind(1);
        ppolyline3(&plain);
        pclose_struct();
        CHECK(draw(p));
        for (int k = 0; k < 2; ++k) {
            if (p[k].rgb) {
                const int differ = differing_columns(&p[k], 0.1, 0.9, y, y_plain);
                if (differ > 2)
                    fprintf(stderr, "  %s, line type %d, %d vertices, %s: %d columns differ\n", p[k].name,
                            (int)type, n, shaded ? "PSD_COLOUR" : "PSD_NONE", differ);
                CHECK(differ <= 2);
            }
            free(p[k].rgb);
        }
    }
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    seed_random(0x6a09e667f3bcc908ULL);
    snprintf(png, sizeof png, "%s/line_dashes.png", dir);
    snprintf(pdf, sizeof pdf, "%s/line_dashes.pdf", dir);
    snprintf(ppm_root, sizeof ppm_root, "%s/line_dashes_pdf", dir);
    snprintf(errors, sizeof errors, "%s/line_dashes_errors.txt", dir);
    open_with_handler(errors);
    dashes();
    pclose_phigs();
    return finish("test_line_dashes");
}
