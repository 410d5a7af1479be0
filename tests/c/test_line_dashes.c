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

static PictureFiles files;

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

/* Whether the plain line at y shows dashes between x0 and x1: many drawn and many blank columns
 * (without them the comparison above would pass on an empty picture). */
static int dashed(const Picture* p, double x0, double x1, double y) {
    const int first = (int)(x0 * p->side) + 3, last = (int)(x1 * p->side) - 3;
    int on = 0;
    for (int i = first; i <= last; ++i) on += drawn(p, i, y);
    return on > (last - first) / 10 && last - first + 1 - on > (last - first) / 10;
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
            vertices[i].colr.direct.rgb.red = (Pfloat)(0.5 + (next_random() % 128) / 255.0);
            vertices[i].colr.direct.rgb.green = (Pfloat)(0.5 + (next_random() % 128) / 255.0);
            vertices[i].colr.direct.rgb.blue = (Pfloat)(0.5 + (next_random() % 128) / 255.0);
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
        CHECK(draw_offscreen_and_pdf(&files, p));
        for (int k = 0; k < 2; ++k) {
            if (p[k].rgb) {
                const int differ = differing_columns(&p[k], 0.1, 0.9, y, y_plain);
                if (differ > 2)
                    fprintf(stderr, "  %s, line type %d, %d vertices, %s: %d columns differ\n", p[k].name,
                            (int)type, n, shaded ? "PSD_COLOUR" : "PSD_NONE", differ);
                CHECK(differ <= 2);
                CHECK(dashed(&p[k], 0.1, 0.9, y_plain));
            }
            free(p[k].rgb);
        }
    }
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    seed_random(0x6a09e667f3bcc908ULL);
    files = picture_files(dir, "line_dashes");
    snprintf(errors, sizeof errors, "%s/line_dashes_errors.txt", dir);
    open_with_handler(errors);
    dashes();
    pclose_phigs();
    return finish("test_line_dashes");
}
