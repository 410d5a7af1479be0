/* Back faces and polyline shading drawn on the offscreen type (lavapipe, validation layer on)
 * and the PDF type (rasterised by pdftoppm at 144 dpi):
 * seeded random triangles, front or back facing, under every face distinguishing mode, face
 * culling mode and front and back interior style, show at their centre the front colour, the back colour
 * or the background exactly as the rules say; and a polyline set with data whose two vertex
 * colours are random shows at its midpoint their mean with polyline shading PSD_COLOUR, its first
 * vertex's colour with PSD_NONE. argv[1]: a directory for the files. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include "picture.h"

static double random_real(double lo, double hi) {
    return lo + (hi - lo) * (next_random() % 100001u) / 100000.0;
}

static const unsigned char* pixel(const Picture* p, double x, double y) {
    const int i = (int)(x * p->side), j = (int)(p->height - y * p->side);
    return p->rgb + ((size_t)j * (size_t)p->width + (size_t)i) * 3;
}

/* Whether the pixel at NPC (x, y) is `rgb` (NULL: the background, the pixel at NPC (0.02, 0.02)),
 * within 2/255. */
static int pixel_is(const Picture* p, double x, double y, const double* rgb, const char* what) {
    const unsigned char* c = pixel(p, x, y);
    const unsigned char* background = pixel(p, 0.02, 0.02);
    double expected[3];
    int ok = 1;
    for (int k = 0; k < 3; ++k) expected[k] = rgb ? 255 * rgb[k] : background[k];
    for (int k = 0; k < 3; ++k) ok = ok && fabs(c[k] - expected[k]) <= 2.5;
    if (!ok)
        fprintf(stderr, "  %s, %s: pixel at NPC (%.3f, %.3f) is %d %d %d, expected %.1f %.1f %.1f\n", p->name,
                what, x, y, c[0], c[1], c[2], expected[0], expected[1], expected[2]);
    return ok;
}

static Pgcolr direct(const double c[3]) {
    Pgcolr g;
    g.type = PMODEL_RGB;
    g.val.direct.x = (Pfloat)c[0], g.val.direct.y = (Pfloat)c[1], g.val.direct.z = (Pfloat)c[2];
    return g;
}

static void random_rgb(double c[3]) {
    /* Multiples of 1/255: what the picture can hold exactly. */
    for (int k = 0; k < 3; ++k) c[k] = (double)(next_random() % 256u) / 255.0;
}

static PictureFiles files;

static void back_faces(void) {
    int filledBackUnderOpenFront = 0;
    for (int round = 0; round < 32; ++round) {
        double front[3], back[3];
        /* Every fourth round a filled back under an open (HOLLOW or EMPTY) front, shown. */
        const int openFront = round % 4 == 0;
        const int backFacing = openFront || (int)(next_random() % 2),
                  distinguish = openFront || (int)(next_random() % 2);
        const Pcull_mode cull = (Pcull_mode)(next_random() % 3);
        const Pint_style frontStyle = (Pint_style)(next_random() % 3 == 0                ? PSTYLE_EMPTY
                                                   : next_random() % 2 == 0 || openFront ? PSTYLE_HOLLOW
                                                                                         : PSTYLE_SOLID);
        const Pint_style backStyle = (Pint_style)(openFront || next_random() % 3 != 0 ? PSTYLE_SOLID
                                                  : next_random() % 2 == 0            ? PSTYLE_HOLLOW
                                                                                      : PSTYLE_EMPTY);
        const double cx = random_real(0.3, 0.7), cy = random_real(0.3, 0.7), r = random_real(0.1, 0.2);
        Ppoint3 corners[3];
        Ppoint_list3 triangle = {3, corners};
        Pgcolr f, b;
        Picture p[2];
        const double* expected;
        random_rgb(front), random_rgb(back);
        f = direct(front), b = direct(back);
        for (int k = 0; k < 3; ++k) {
            /* Counter-clockwise seen from +z (front facing) or clockwise. */
            const double a = (backFacing ? -1 : 1) * k * 2.0943951 + 0.3;
            corners[k].x = (Pfloat)(cx + r * cos(a)), corners[k].y = (Pfloat)(cy + r * sin(a)),
            corners[k].z = 0;
        }
        pdel_struct(1);
        popen_struct(1);
        pset_int_style(frontStyle);
        pset_int_colr(&f);
        pset_back_int_colr(&b);
        pset_back_int_style(backStyle);
        pset_face_disting_mode(distinguish ? PDISTING_YES : PDISTING_NO);
        pset_face_cull_mode(cull);
        pfill_area3(&triangle);
        pclose_struct();
        /* Each side by its own style: a SOLID back shows under a HOLLOW or EMPTY front too; a
         * HOLLOW side shows its outline only, away from the centre. */
        if ((backFacing && cull == PCULL_BACKFACE) || (!backFacing && cull == PCULL_FRONTFACE))
            expected = NULL; /* the background */
        else if (!backFacing || !distinguish)
            expected = frontStyle == PSTYLE_SOLID ? front : NULL;
        else
            expected = backStyle == PSTYLE_SOLID ? back : NULL;
        if (expected == back && frontStyle != PSTYLE_SOLID) ++filledBackUnderOpenFront;
        CHECK(draw_offscreen_and_pdf(&files, p));
        for (int i = 0; i < 2; ++i) {
            char what[160];
            snprintf(what, sizeof what, "triangle %s, distinguishing %d, cull %d, styles %d / %d",
                     backFacing ? "back" : "front", distinguish, (int)cull, (int)frontStyle, (int)backStyle);
            if (p[i].rgb) CHECK(pixel_is(&p[i], cx, cy, expected, what));
            free(p[i].rgb);
        }
    }
    CHECK(filledBackUnderOpenFront >= 2); /* the sequence reaches the case */
}

static void line_shading(void) {
    for (int round = 0; round < 12; ++round) {
        double c0[3], c1[3], mid[3];
        const int shaded = round % 2;
        const double y = random_real(0.2, 0.8);
        Pptco3 vertices[2];
        Pline_vdata_list3 line;
        Picture p[2];
        random_rgb(c0), random_rgb(c1);
        for (int k = 0; k < 3; ++k) mid[k] = (c0[k] + c1[k]) / 2;
        vertices[0].point.x = 0.1f, vertices[1].point.x = 0.9f;
        vertices[0].point.y = vertices[1].point.y = (Pfloat)y;
        vertices[0].point.z = vertices[1].point.z = 0;
        vertices[0].colr.direct.x = (Pfloat)c0[0], vertices[0].colr.direct.y = (Pfloat)c0[1],
        vertices[0].colr.direct.z = (Pfloat)c0[2];
        vertices[1].colr.direct.x = (Pfloat)c1[0], vertices[1].colr.direct.y = (Pfloat)c1[1],
        vertices[1].colr.direct.z = (Pfloat)c1[2];
        line.num_vertices = 2, line.vertex_data.ptcolrs = vertices;
        pdel_struct(1);
        popen_struct(1);
        pset_linewidth(6);
        pset_line_shad_meth(shaded ? PSD_COLOUR : PSD_NONE);
        ppolyline_set3_data(PVERT_COORD_COLOUR, PMODEL_RGB, 1, &line);
        pclose_struct();
        CHECK(draw_offscreen_and_pdf(&files, p));
        for (int i = 0; i < 2; ++i) {
            if (p[i].rgb) {
                CHECK(
                    pixel_is(&p[i], 0.5, y, shaded ? mid : c0, shaded ? "shaded midpoint" : "flat midpoint"));
                CHECK(pixel_is(&p[i], 0.102, y, c0, "first end"));
                if (shaded) CHECK(pixel_is(&p[i], 0.898, y, c1, "last end"));
            }
            free(p[i].rgb);
        }
    }
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    seed_random(0x853c49e6748fea9bULL);
    files = picture_files(dir, "plus_shading");
    snprintf(errors, sizeof errors, "%s/plus_shading_errors.txt", dir);
    open_with_handler(errors);
    back_faces();
    line_shading();
    pclose_phigs();
    return finish("test_plus_shading");
}
