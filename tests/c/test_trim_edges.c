/* A trimming curve's visibility: a visible (PEDGE_ON) trim curve is drawn along the surface in the
 * edge colour while the edge flag is on, a hidden one is not, and neither is a visible one with the
 * edge flag off. Seeded random triangles in (u, v) trim a rational surface that maps (u, v)
 * affinely onto NPC [0.2, 0.8]^2 (interior EMPTY, one tessellation cell, so the facets' edges are
 * the square's sides), drawn on the offscreen type (lavapipe, validation layer on) and the PDF type
 * (rasterised by pdftoppm at 144 dpi); points along the triangle's sides, away from its corners and
 * the square, must show the green edge colour exactly when the curve is visible and the flag on.
 * argv[1]: a directory for the files. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include "picture.h"

static PictureFiles files;

/* Whether a pixel within one of NPC (x, y) (a 3 x 3 block) shows the edge colour (green). */
static int green_near(const Picture* p, double x, double y) {
    const int i0 = (int)(x * p->side), j0 = (int)(p->height - y * p->side);
    for (int j = j0 - 1; j <= j0 + 1; ++j)
        for (int i = i0 - 1; i <= i0 + 1; ++i) {
            const unsigned char* c = p->rgb + ((size_t)j * (size_t)p->width + (size_t)i) * 3;
            if (c[1] > 150 && c[0] < 100 && c[2] < 100) return 1;
        }
    return 0;
}

static void build(double tri[3][2], Pedge_flag visible, Pedge_flag edges) {
    /* Homogeneous points, weight 2: (2x, 2y, 0, 2); u fastest (3 along u, 2 along v). */
    Ppoint4 grid_points[6] = {{0.4f, 0.4f, 0, 2}, {1.0f, 0.4f, 0, 2}, {1.6f, 0.4f, 0, 2},
                              {0.4f, 1.6f, 0, 2}, {1.0f, 1.6f, 0, 2}, {1.6f, 1.6f, 0, 2}};
    Pfloat uk[6] = {0, 0, 0, 1, 1, 1}, vk[4] = {0, 0, 1, 1}, tk[6] = {0, 0, 1, 2, 3, 3};
    Pfloat_list uknots = {6, uk}, vknots = {4, vk};
    Ppoint_grid34 grid;
    Ppoint corners[4];
    Ptrimcurve trim;
    Ptrimcurve_list loop = {1, &trim};
    Pgcolr green = {PMODEL_RGB, {0}};
    grid.num_points.size_x = 3, grid.num_points.size_y = 2, grid.points.point4d = grid_points;
    for (int i = 0; i < 4; ++i) corners[i].x = (Pfloat)tri[i % 3][0], corners[i].y = (Pfloat)tri[i % 3][1];
    memset(&trim, 0, sizeof trim);
    trim.visible = visible, trim.rationality = PNON_RATIONAL, trim.order = 2;
    trim.approx_type = PCURV_WS_DEP;
    trim.knots.num_floats = 6, trim.knots.floats = tk;
    trim.cpts.point2d.num_points = 4, trim.cpts.point2d.points = corners;
    green.val.general.y = 1;
    pdel_struct(1);
    popen_struct(1);
    pset_int_style(PSTYLE_EMPTY);
    pset_edge_flag(edges);
    pset_edge_colr(&green);
    pset_surf_approx(PSURF_CONST_PARAM_SUBDIV_BETWEEN_KNOTS, 1, 1);
    EXPECT_NO_ERROR(pnuni_bsp_surf(3, 2, &uknots, &vknots, PRATIONAL, &grid, 1, &loop));
    pclose_struct();
}

/* Points along the triangle's sides (NPC), 10% to 90% of each side, at least `margin` from the
 * square's sides; how many of them show green in `p`. */
static int green_on_sides(const Picture* p, double tri[3][2], int* sampled) {
    int green = 0;
    *sampled = 0;
    for (int s = 0; s < 3; ++s)
        for (int k = 1; k <= 9; ++k) {
            const double t = k / 10.0;
            const double u = tri[s][0] + t * (tri[(s + 1) % 3][0] - tri[s][0]);
            const double v = tri[s][1] + t * (tri[(s + 1) % 3][1] - tri[s][1]);
            const double x = 0.2 + 0.6 * u, y = 0.2 + 0.6 * v, margin = 6.0 / p->side;
            if (x < 0.2 + margin || x > 0.8 - margin || y < 0.2 + margin || y > 0.8 - margin) continue;
            ++*sampled;
            green += green_near(p, x, y);
        }
    return green;
}

static void rounds(void) {
    for (int round = 0; round < 6; ++round) {
        double tri[3][2];
        /* Counter-clockwise corners in [0.1, 0.9]^2 around the cell's centre, which stays inside. */
        for (int i = 0; i < 3; ++i) {
            const double angle = (i + random_real(-0.2, 0.2)) * 2.0 * 3.14159265358979 / 3.0;
            const double radius = random_real(0.3, 0.4);
            tri[i][0] = 0.5 + radius * cos(angle), tri[i][1] = 0.5 + radius * sin(angle);
        }
        const Pedge_flag visible = round % 3 == 1 ? PEDGE_OFF : PEDGE_ON;
        const Pedge_flag edges = round % 3 == 2 ? PEDGE_OFF : PEDGE_ON;
        const int shown = visible == PEDGE_ON && edges == PEDGE_ON;
        Picture p[2];
        build(tri, visible, edges);
        CHECK(draw_offscreen_and_pdf(&files, p));
        for (int k = 0; k < 2; ++k) {
            if (p[k].rgb) {
                int sampled = 0;
                const int green = green_on_sides(&p[k], tri, &sampled);
                const double centre[2] = {0.2 + 0.6 * (tri[0][0] + tri[1][0] + tri[2][0]) / 3,
                                          0.2 + 0.6 * (tri[0][1] + tri[1][1] + tri[2][1]) / 3};
                if (shown ? green != sampled : green != 0)
                    fprintf(stderr, "  %s, round %d (visible %d, edges %d): %d of %d side points green\n",
                            p[k].name, round, (int)visible, (int)edges, green, sampled);
                CHECK(sampled >= 15);
                CHECK(shown ? green == sampled : green == 0);
                CHECK(!green_near(&p[k], centre[0], centre[1])); /* EMPTY: nothing inside */
                /* The facets' edges (the square's sides) follow the edge flag alone. */
                CHECK(green_near(&p[k], 0.5, 0.2) == (edges == PEDGE_ON));
            }
            free(p[k].rgb);
        }
    }
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    seed_random(0xbb67ae8584caa73bULL);
    files = picture_files(dir, "trim_edges");
    snprintf(errors, sizeof errors, "%s/trim_edges_errors.txt", dir);
    open_with_handler(errors);
    rounds();
    pclose_phigs();
    return finish("test_trim_edges");
}
