/* Pictures on the workstation types: a structure with a fill area and a polyline posted to the
 * headless offscreen type (lavapipe; the PNG its connection identifier names) and to the PDF
 * type; the PNG and the rasterised PDF (pdftoppm) have the drawn colours where the primitives
 * are and the background elsewhere, and the PDF holds no image (pdfimages -list); a blue square
 * added after the last UPDATE is in both files, which CLOSE WORKSTATION updates. With HLHSR on, a
 * line at NPC z = 0 (where 2D primitives lie) under a later coplanar fill area shows on both, as
 * lines on surfaces do. Links libpng
 * besides libphigs to read the PNG. argv[1]: a directory for the files. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include "picture.h"

/* Whether a pixel within `radius` of (x, y) (pixels, y down) is near the colour (r, g, b). */
static int has_colour_near(const Picture* p, int x, int y, int radius, int r, int g, int b) {
    for (int j = y - radius; j <= y + radius; ++j)
        for (int i = x - radius; i <= x + radius; ++i) {
            if (i < 0 || j < 0 || i >= p->width || j >= p->height) continue;
            const unsigned char* c = p->rgb + ((size_t)j * (size_t)p->width + (size_t)i) * 3;
            if (abs(c[0] - r) < 60 && abs(c[1] - g) < 60 && abs(c[2] - b) < 60) return 1;
        }
    return 0;
}

/* A red fill area over NPC [0.1, 0.4]^2 and a thick green polyline at x = 0.7 from y = 0.2 to 0.8. */
static void build_scene(void) {
    Ppoint3 square[4] = {{0.1f, 0.1f, 0}, {0.4f, 0.1f, 0}, {0.4f, 0.4f, 0}, {0.1f, 0.4f, 0}};
    Ppoint3 line[2] = {{0.7f, 0.2f, 0}, {0.7f, 0.8f, 0}};
    Ppoint_list3 area = {4, square}, polyline = {2, line};
    Pgcolr red = {PMODEL_RGB, {0}}, green = {PMODEL_RGB, {0}};
    red.val.general.x = 1;
    green.val.general.y = 1;
    popen_struct(1);
    pset_int_style(PSTYLE_SOLID);
    pset_int_colr(&red);
    pfill_area3(&area);
    pset_line_colr(&green);
    pset_linewidth(6);
    ppolyline3(&polyline);
    pclose_struct();
}

/* The scene's colours in `p`, whose display surface maps NPC [0, 1]^2 onto `side` pixels at
 * the lower left (the workstation transformation keeps the shape). */
static void check_picture(const Picture* p, double side, const char* what) {
    const int failed = failures;
#define AT(x, y) (int)((x)*side), (int)(p->height - (y)*side)
    CHECK(has_colour_near(p, AT(0.25, 0.25), 0, 255, 0, 0)); /* inside the fill area */
    CHECK(has_colour_near(p, AT(0.12, 0.38), 0, 255, 0, 0)); /* near its corner */
    CHECK(has_colour_near(p, AT(0.7, 0.5), 3, 0, 255, 0));   /* on the polyline */
    CHECK(has_colour_near(p, AT(0.7, 0.25), 3, 0, 255, 0));
    CHECK(!has_colour_near(p, AT(0.25, 0.7), 2, 255, 0, 0)); /* background above the area */
    CHECK(!has_colour_near(p, AT(0.5, 0.5), 2, 0, 255, 0));  /* background between */
    CHECK(!has_colour_near(p, AT(0.7, 0.9), 2, 0, 255, 0));  /* beyond the polyline's end */
#undef AT
    if (failures != failed) fprintf(stderr, "  in the %s picture (%d x %d)\n", what, p->width, p->height);
}

static int command_output_lines(const char* command) {
    char line[512];
    int lines = 0;
    FILE* pipe = popen(command, "r");
    if (!pipe) return -1;
    while (fgets(line, sizeof line, pipe)) ++lines;
    return pclose(pipe) == 0 ? lines : -1;
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char png[512], pdf[512], errors[512], command[2048], ppm[600];
    snprintf(png, sizeof png, "%s/ws_pictures.png", dir);
    snprintf(pdf, sizeof pdf, "%s/ws_pictures.pdf", dir);
    snprintf(errors, sizeof errors, "%s/ws_pictures_errors.txt", dir);
    remove(png);
    remove(pdf);
    open_with_handler(errors);
    build_scene();

    EXPECT_NO_ERROR(popen_ws(1, png, PWST_OFFSCREEN));
    EXPECT_NO_ERROR(popen_ws(2, pdf, PWST_PDF));
    EXPECT_NO_ERROR(ppost_struct(1, 1, 0.5f));
    EXPECT_NO_ERROR(ppost_struct(2, 1, 0.5f));
    EXPECT_NO_ERROR(pupd_ws(1, PFLAG_PERFORM));
    EXPECT_NO_ERROR(pupd_ws(2, PFLAG_PERFORM));

    Picture picture = {0};
    CHECK(read_png(png, &picture)); /* written by the update */
    if (picture.rgb) {
        CHECK(picture.width == 1024 && picture.height == 768);
        check_picture(&picture, 768, "offscreen PNG");
        free(picture.rgb);
        picture.rgb = NULL;
    }
    {
        /* Added after the last UPDATE: CLOSE WORKSTATION updates the picture it writes. */
        Ppoint3 square[4] = {{0.45f, 0.7f, 0}, {0.55f, 0.7f, 0}, {0.55f, 0.8f, 0}, {0.45f, 0.8f, 0}};
        Ppoint_list3 area = {4, square};
        Pgcolr blue = {PMODEL_RGB, {0}};
        blue.val.general.z = 1;
        popen_struct(1);
        pset_int_colr(&blue);
        pfill_area3(&area);
        pclose_struct();
    }
    EXPECT_NO_ERROR(pclose_ws(1));
    EXPECT_NO_ERROR(pclose_ws(2));
    pclose_phigs();
    CHECK(read_png(png, &picture));
    if (picture.rgb) {
        CHECK(has_colour_near(&picture, (int)(0.5 * 768), (int)(768 - 0.75 * 768), 0, 0, 0, 255));
        free(picture.rgb);
        picture.rgb = NULL;
    }

    /* HLHSR on: a white line at z = 0, then a yellow fill area over it at the same depth. */
    {
        char png2[512], pdf2[512], ppm2[600];
        snprintf(png2, sizeof png2, "%s/ws_pictures_coplanar.png", dir);
        snprintf(pdf2, sizeof pdf2, "%s/ws_pictures_coplanar.pdf", dir);
        Ppoint line_points[2] = {{0.1f, 0.3f}, {0.9f, 0.3f}};
        Ppoint square_points[4] = {{0.3f, 0.2f}, {0.6f, 0.2f}, {0.6f, 0.4f}, {0.3f, 0.4f}};
        Ppoint_list line = {2, line_points}, square = {4, square_points};
        Pgcolr white = {PMODEL_RGB, {0}}, yellow = {PMODEL_RGB, {0}};
        white.val.general.x = white.val.general.y = white.val.general.z = 1;
        yellow.val.general.x = yellow.val.general.y = 1;
        open_with_handler(errors);
        popen_struct(2);
        pset_line_colr(&white);
        pset_linewidth(3);
        ppolyline(&line);
        pset_int_style(PSTYLE_SOLID);
        pset_int_colr(&yellow);
        pfill_area(&square);
        pclose_struct();
        EXPECT_NO_ERROR(popen_ws(3, png2, PWST_OFFSCREEN));
        EXPECT_NO_ERROR(popen_ws(4, pdf2, PWST_PDF));
        for (Pint ws = 3; ws <= 4; ++ws) {
            EXPECT_NO_ERROR(pset_hlhsr_mode(ws, 1));
            EXPECT_NO_ERROR(ppost_struct(ws, 2, 0.5f));
        }
        EXPECT_NO_ERROR(pclose_ws(3));
        EXPECT_NO_ERROR(pclose_ws(4));
        pclose_phigs();
        CHECK(read_png(png2, &picture));
        if (picture.rgb) {
            CHECK(has_colour_near(&picture, (int)(0.45 * 768), (int)(768 - 0.3 * 768), 0, 255, 255, 255));
            CHECK(has_colour_near(&picture, (int)(0.45 * 768), (int)(768 - 0.35 * 768), 0, 255, 255, 0));
            free(picture.rgb);
            picture.rgb = NULL;
        }
        snprintf(command, sizeof command, "pdftoppm -r 72 -singlefile '%s' '%s/ws_pictures_coplanar'", pdf2,
                 dir);
        CHECK(system(command) == 0);
        snprintf(ppm2, sizeof ppm2, "%s/ws_pictures_coplanar.ppm", dir);
        CHECK(read_ppm(ppm2, &picture));
        if (picture.rgb) {
            const double side = 595.2756;
            CHECK(has_colour_near(&picture, (int)(0.45 * side), (int)(picture.height - 0.3 * side), 1, 255,
                                  255, 255));
            free(picture.rgb);
            picture.rgb = NULL;
        }
    }

    /* The PDF: vectors only, and its page at 72 dpi (one pixel per point) shows the scene. */
    snprintf(command, sizeof command, "pdfimages -list '%s'", pdf);
    CHECK(command_output_lines(command) == 2); /* the two heading lines, no image */
    snprintf(command, sizeof command, "pdftoppm -r 72 -singlefile '%s' '%s/ws_pictures_pdf'", pdf, dir);
    CHECK(system(command) == 0);
    snprintf(ppm, sizeof ppm, "%s/ws_pictures_pdf.ppm", dir);
    CHECK(read_ppm(ppm, &picture));
    if (picture.rgb) {
        CHECK(abs(picture.width - 842) <= 1 && abs(picture.height - 595) <= 1);
        check_picture(&picture, 595.2756, "PDF");
        CHECK(has_colour_near(&picture, (int)(0.5 * 595.2756), (int)(picture.height - 0.75 * 595.2756), 0, 0,
                              0, 255));
        free(picture.rgb);
    }
    return finish("test_ws_pictures");
}
