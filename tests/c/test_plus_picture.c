/* A PHIGS PLUS NURBS surface drawn on the headless offscreen type (lavapipe) and compared with a
 * reference image computed from its geometry: a rational quadratic-by-linear surface whose
 * control points are evenly spaced, so it maps (u, v) affinely onto NPC [0.2, 0.8]^2, trimmed
 * to a triangle in (u, v) by a trim curve whose range [tmin, tmax] leaves out a detour at each
 * end of its control polygon (the whole curve would trim away a different region). Every pixel more than six
 * pixels (a tessellation cell's diagonal and a pixel: the core keeps or drops whole cells) from the
 * triangle's edges must have the reference's colour (the surface's red inside, the background outside); the
 * reference is written beside the picture. Links libpng besides libphigs. argv[1]: a directory for the files.
 */
#include "check.h"

#include <png.h>

#define SIDE 768 /* NPC [0, 1]^2 onto the lower-left 768 x 768 pixels of the 1024 x 768 display */

static const double tri[3][2] = {{0.1, 0.1}, {0.9, 0.1}, {0.5, 0.9}}; /* the trim loop in (u, v) */

static void npc_of(const double uv[2], double out[2]) {
    out[0] = 0.2 + 0.6 * uv[0];
    out[1] = 0.2 + 0.6 * uv[1];
}

/* Signed distance (NPC) from p to the triangle's edge a-b, positive on the inside. */
static double edge_distance(const double a[2], const double b[2], const double p[2]) {
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    return ((p[1] - a[1]) * ex - (p[0] - a[0]) * ey) / sqrt(ex * ex + ey * ey);
}

/* 1 inside, 0 outside, -1 within `margin` of an edge. */
static int classify(const double p[2], double margin) {
    double v[3][2], least = 1e9;
    for (int i = 0; i < 3; ++i) npc_of(tri[i], v[i]);
    for (int i = 0; i < 3; ++i) {
        const double d = edge_distance(v[i], v[(i + 1) % 3], p);
        if (d < least) least = d;
    }
    if (least > margin) return 1;
    if (least < -margin) return 0;
    return -1;
}

static void build_surface(void) {
    /* Homogeneous points, weight 2: (2x, 2y, 0, 2); u fastest (3 along u, 2 along v). */
    Ppoint4 grid_points[6] = {{0.4f, 0.4f, 0, 2}, {1.0f, 0.4f, 0, 2}, {1.6f, 0.4f, 0, 2},
                              {0.4f, 1.6f, 0, 2}, {1.0f, 1.6f, 0, 2}, {1.6f, 1.6f, 0, 2}};
    Pfloat uk[6] = {0, 0, 0, 1, 1, 1}, vk[4] = {0, 0, 1, 1}, tk[8] = {0, 0, 1, 2, 3, 4, 5, 5};
    Pfloat_list uknots = {6, uk}, vknots = {4, vk};
    Ppoint_grid34 grid;
    /* Linear: t = 1 .. 4 runs round the triangle; t in [0, 1] and [4, 5] are the detours. */
    Ppoint loop_points[6] = {{0.95f, 0.95f}, {0, 0}, {0, 0}, {0, 0}, {0, 0}, {0.05f, 0.95f}};
    Ptrimcurve trim;
    Ptrimcurve_list loop = {1, &trim};
    Pgcolr red = {PMODEL_RGB, {0}};
    grid.num_points.size_x = 3, grid.num_points.size_y = 2, grid.points.point4d = grid_points;
    for (int i = 0; i < 4; ++i)
        loop_points[i + 1].x = (Pfloat)tri[i % 3][0], loop_points[i + 1].y = (Pfloat)tri[i % 3][1];
    memset(&trim, 0, sizeof trim);
    trim.visible = PEDGE_OFF, trim.rationality = PNON_RATIONAL, trim.order = 2;
    trim.knots.num_floats = 8, trim.knots.floats = tk, trim.tmin = 1, trim.tmax = 4;
    trim.cpts.point2d.num_points = 6, trim.cpts.point2d.points = loop_points;
    red.val.general.x = 1;
    popen_struct(1);
    pset_int_style(PSTYLE_SOLID);
    pset_int_colr(&red);
    /* The core trims whole tessellation cells: 128 cells per knot span keeps them small. */
    pset_surf_approx(PSURF_CONST_PARAM_SUBDIV_BETWEEN_KNOTS, 128, 128);
    pnuni_bsp_surf(3, 2, &uknots, &vknots, PRATIONAL, &grid, 1, &loop);
    pclose_struct();
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char png[512], reference[512], errors[512];
    png_image image;
    unsigned char *rgb = NULL, *expected = NULL;
    int mismatches = 0, inside = 0;
    snprintf(png, sizeof png, "%s/plus_picture.png", dir);
    snprintf(reference, sizeof reference, "%s/plus_picture_reference.png", dir);
    snprintf(errors, sizeof errors, "%s/plus_picture_errors.txt", dir);
    remove(png);
    open_with_handler(errors);
    build_surface();
    EXPECT_NO_ERROR(popen_ws(1, png, PWST_OFFSCREEN));
    EXPECT_NO_ERROR(ppost_struct(1, 1, 0.5f));
    EXPECT_NO_ERROR(pupd_ws(1, PFLAG_PERFORM));
    EXPECT_NO_ERROR(pclose_ws(1));
    pclose_phigs();

    memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    CHECK(png_image_begin_read_from_file(&image, png));
    image.format = PNG_FORMAT_RGB;
    CHECK(image.width == 1024 && image.height == 768);
    if (failures) return finish("test_plus_picture");
    rgb = malloc(PNG_IMAGE_SIZE(image));
    expected = calloc(PNG_IMAGE_SIZE(image), 1);
    CHECK(rgb && expected && png_image_finish_read(&image, NULL, rgb, 0, NULL));
    for (int j = 0; rgb && expected && j < (int)image.height; ++j)
        for (int i = 0; i < (int)image.width; ++i) {
            const double p[2] = {(i + 0.5) / SIDE, (image.height - j - 0.5) / SIDE};
            const int want = classify(p, 6.0 / SIDE);
            unsigned char* c = rgb + ((size_t)j * image.width + (size_t)i) * 3;
            unsigned char* e = expected + ((size_t)j * image.width + (size_t)i) * 3;
            const int red = c[0] > 200 && c[1] < 60 && c[2] < 60, dark = c[0] < 60 && c[1] < 60 && c[2] < 60;
            if (classify(p, 0) == 1) e[0] = 255;
            if (want == 1) inside += red, mismatches += !red;
            if (want == 0) mismatches += !dark;
        }
    CHECK(mismatches == 0);
    CHECK(inside > 20000); /* the triangle covers about 0.115 of NPC: some 68,000 pixels */
    if (mismatches) fprintf(stderr, "  %d pixels differ from the reference\n", mismatches);
    image.format = PNG_FORMAT_RGB;
    if (expected) CHECK(png_image_write_to_file(&image, reference, 0, expected, 0, NULL));
    free(rgb);
    free(expected);
    return finish("test_plus_picture");
}
