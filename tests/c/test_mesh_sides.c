/* Meshes drawn by the side each facet shows, on the offscreen type (lavapipe, validation layer on)
 * and the PDF type (rasterised by pdftoppm at 144 dpi): seeded random quadrilateral meshes and
 * triangle strips in z = 0.5 (inside the view volume), their facets turned either way by random facet
 * normals, under random front and back interior styles (SOLID over HOLLOW and HOLLOW over SOLID mostly), face
 * distinguishing and culling, seen from the front or (turned or mirrored about x = 0.5) from the
 * back. Each facet fills by the style of the side it shows; a HOLLOW side draws the facet's own
 * edges in that side's colour and nothing inside (no quadrilateral diagonals); an EMPTY or culled
 * side draws nothing; an edge-on facet (in a plane through the view direction) shows its front.
 * argv[1]: a directory for the files. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include "picture.h"

static PictureFiles files;

/* How one facet shows: filled or outlined, in which colour. */
typedef struct {
    int filled, outlined;
    const double* colour;
} Shown;

typedef struct {
    Pint_style front, back;
    int distinguish, flip;
    Pcull_mode cull;
    double frontColour[3], backColour[3];
} Sides;

static Shown shown_side(const Sides* s, int facetSide) {
    const int side = s->flip ? -facetSide : facetSide;
    const int culled = (side > 0 && s->cull == PCULL_FRONTFACE) || (side < 0 && s->cull == PCULL_BACKFACE);
    const int useBack = side < 0 && s->distinguish;
    const Pint_style style = useBack ? s->back : s->front;
    Shown out;
    out.filled = !culled && style == PSTYLE_SOLID;
    out.outlined = !culled && style == PSTYLE_HOLLOW;
    out.colour = useBack ? s->backColour : s->frontColour;
    return out;
}

/* NPC x of world x as drawn: the back views map x to 1 - x. */
static double npc_x(const Sides* s, double x) {
    return s->flip ? 1 - x : x;
}

/* The largest channel difference (in 1/255) between `rgb` (NULL: the background) and the pixel
 * nearest it among those within 3 pixels of NPC (x, y) along (dx, dy) (a unit direction). */
static double nearest_along(const Picture* p, double x, double y, double dx, double dy, const double* rgb) {
    const unsigned char* background = picture_pixel(p, 0.02, 0.02);
    double best = 1e9;
    for (int d = -3; d <= 3; ++d) {
        const unsigned char* c = picture_pixel(p, x + d * dx / p->side, y + d * dy / p->side);
        double worst = 0;
        for (int k = 0; k < 3; ++k) worst = fmax(worst, fabs(c[k] - (rgb ? 255 * rgb[k] : background[k])));
        best = fmin(best, worst);
    }
    return best;
}

/* nearest_along for a line crossed along (dx, dy): besides single pixels, the sum of two
 * neighbours over the background, since an anti-aliased hairline of the PDF raster that falls
 * between two pixel rows lights each in part, neither in its full colour. */
static double line_along(const Picture* p, double x, double y, double dx, double dy, const double* rgb) {
    const unsigned char* background = picture_pixel(p, 0.02, 0.02);
    double best = nearest_along(p, x, y, dx, dy, rgb);
    for (int d = -3; d < 3; ++d) {
        const unsigned char* c = picture_pixel(p, x + d * dx / p->side, y + d * dy / p->side);
        const unsigned char* e = picture_pixel(p, x + (d + 1) * dx / p->side, y + (d + 1) * dy / p->side);
        double worst = 0;
        for (int k = 0; k < 3; ++k) worst = fmax(worst, fabs(c[k] + e[k] - background[k] - 255 * rgb[k]));
        best = fmin(best, worst);
    }
    return best;
}

/* The worst channel difference from the background among those pixels. */
static double farthest_from_background(const Picture* p, double x, double y, double dx, double dy) {
    const unsigned char* background = picture_pixel(p, 0.02, 0.02);
    double worst = 0;
    for (int d = -3; d <= 3; ++d) {
        const unsigned char* c = picture_pixel(p, x + d * dx / p->side, y + d * dy / p->side);
        for (int k = 0; k < 3; ++k) worst = fmax(worst, abs(c[k] - background[k]));
    }
    return worst;
}

/* A point inside a facet: its fill colour when filled, else the background. */
static void check_inside(const Picture* p, double x, double y, const Shown* s, const char* what) {
    const double miss = nearest_along(p, x, y, 0, 0, s->filled ? s->colour : NULL);
    if (miss > 2.5) {
        fprintf(stderr, "  %s: %s at NPC (%.3f, %.3f): %s expected (off by %.0f)\n", p->name, what, x, y,
                s->filled ? "the fill" : "the background", miss);
        CHECK(0);
    }
}

/* An edge at NPC (x, y) crossed along (dx, dy), of facets a and b (b NULL: a border edge): drawn
 * in an outlining facet's colour, nothing when neither outlines; not checked where one fills. */
static void check_edge(const Picture* p, double x, double y, double dx, double dy, const Shown* a,
                       const Shown* b) {
    int ok = 1;
    if (a->filled || (b && b->filled)) return;
    if (!a->outlined && !(b && b->outlined))
        ok = farthest_from_background(p, x, y, dx, dy) <= 24;
    else if (a->outlined && b && b->outlined)
        ok = line_along(p, x, y, dx, dy, a->colour) <= 24 || line_along(p, x, y, dx, dy, b->colour) <= 24;
    else
        ok = line_along(p, x, y, dx, dy, a->outlined ? a->colour : b->colour) <= 24;
    if (!ok) {
        fprintf(stderr, "  %s: edge at NPC (%.3f, %.3f): %s\n", p->name, x, y,
                a->outlined || (b && b->outlined) ? "outline missing" : "a line drawn");
        CHECK(0);
    }
}

/* Structure 1 anew: the styles of `s`, then the mesh `add` puts. */
static void open_mesh_structure(const Sides* s) {
    Pgcolr f, b;
    f.type = b.type = PMODEL_RGB;
    f.val.general.x = (Pfloat)s->frontColour[0], f.val.general.y = (Pfloat)s->frontColour[1],
    f.val.general.z = (Pfloat)s->frontColour[2];
    b.val.general.x = (Pfloat)s->backColour[0], b.val.general.y = (Pfloat)s->backColour[1],
    b.val.general.z = (Pfloat)s->backColour[2];
    pdel_struct(1);
    popen_struct(1);
    if (s->flip) {
        /* Turned half way about the vertical line x = 0.5, or mirrored in it: x to 1 - x either way. */
        const Ppoint3 centre = {0.5f, 0.5f, 0.5f};
        const Pvec3 none = {0, 0, 0}, unit = {1, 1, 1}, mirror = {-1, 1, 1};
        Pmatrix3 m;
        Pint err = 0;
        if (s->flip == 1)
            pbuild_tran_matrix3(&centre, &none, 0, (Pfloat)3.14159265358979, 0, &unit, &err, m);
        else
            pbuild_tran_matrix3(&centre, &none, 0, 0, 0, &mirror, &err, m);
        CHECK(err == 0);
        pset_global_tran3(m);
    }
    pset_int_style(s->front);
    pset_back_int_style(s->back);
    pset_int_colr(&f);
    pset_back_int_colr(&b);
    pset_face_disting_mode(s->distinguish ? PDISTING_YES : PDISTING_NO);
    pset_face_cull_mode(s->cull);
}

static void random_sides(Sides* s, int round) {
    const Pint_style styles[3] = {PSTYLE_HOLLOW, PSTYLE_SOLID, PSTYLE_EMPTY};
    /* Most rounds one SOLID and one HOLLOW side, either way round. */
    if (round % 4 != 3) {
        const int hollowFront = (int)(next_random() % 2);
        s->front = hollowFront ? PSTYLE_HOLLOW : PSTYLE_SOLID;
        s->back = hollowFront ? PSTYLE_SOLID : PSTYLE_HOLLOW;
    } else {
        s->front = styles[next_random() % 3];
        s->back = styles[next_random() % 3];
    }
    s->distinguish = round % 4 != 3 || next_random() % 2 == 0;
    s->cull = (Pcull_mode)(next_random() % 5 == 0 ? 1 + next_random() % 2 : PCULL_NONE);
    s->flip = (int)(next_random() % 3); /* 0 front, 1 turned, 2 mirrored */
    do {
        for (int k = 0; k < 3; ++k)
            s->frontColour[k] = (double)(128 + next_random() % 128u) / 255.0,
            s->backColour[k] = (double)(next_random() % 256u) / 255.0;
    } while (fabs(s->frontColour[0] - s->backColour[0]) + fabs(s->frontColour[1] - s->backColour[1]) +
                     fabs(s->frontColour[2] - s->backColour[2]) <
                 0.6 ||
             s->backColour[0] + s->backColour[1] + s->backColour[2] < 0.8);
}

/* Random grid lines: `count` values from `start`, steps in [0.12, 0.2]. */
static void grid_lines(double* v, int count, double start) {
    v[0] = start;
    for (int i = 1; i < count; ++i) v[i] = v[i - 1] + random_real(0.12, 0.2);
}

static int hollowQuads = 0, filledQuadsBesideHollow = 0, turnedFacets = 0;

static void quad_meshes(void) {
    for (int round = 0; round < 16; ++round) {
        Sides s;
        double xs[4], ys[4];
        const int nx = 2 + (int)(next_random() % 3), ny = 2 + (int)(next_random() % 3);
        const int normals = round % 2 == 0;
        Ppoint3 points[16];
        Pvec3 norms[9];
        int facetSide[9];
        Shown shown[9];
        Pint_size dim;
        Pfacet_data_arr3 fdata;
        Pfacet_vdata_arr3 vdata;
        Picture p[2];
        random_sides(&s, round);
        grid_lines(xs, nx, random_real(0.15, 0.2));
        grid_lines(ys, ny, random_real(0.15, 0.2));
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                points[j * nx + i].x = (Pfloat)xs[i], points[j * nx + i].y = (Pfloat)ys[j],
                                points[j * nx + i].z = 0.5f;
        for (int q = 0; q < (nx - 1) * (ny - 1); ++q) {
            facetSide[q] = normals && next_random() % 2 == 0 ? -1 : 1;
            norms[q].delta_x = norms[q].delta_y = 0, norms[q].delta_z = (Pfloat)facetSide[q];
            shown[q] = shown_side(&s, facetSide[q]);
            turnedFacets += facetSide[q] < 0;
        }
        open_mesh_structure(&s);
        dim.size_x = nx, dim.size_y = ny;
        fdata.norms = norms;
        vdata.points = points;
        pquad_mesh3_data(normals ? PFACET_NORMAL : PFACET_NONE, PVERT_COORD, PMODEL_RGB, &dim, &fdata,
                         &vdata);
        pclose_struct();
        CHECK(draw_offscreen_and_pdf(&files, p));
        for (int i = 0; i < 2; ++i) {
            if (!p[i].rgb) continue;
            for (int r = 0; r + 1 < ny; ++r)
                for (int c = 0; c + 1 < nx; ++c) {
                    const int q = r * (nx - 1) + c;
                    const Shown* a = &shown[q];
                    const double x0 = xs[c], x1 = xs[c + 1], y0 = ys[r], y1 = ys[r + 1];
                    const double xm = (x0 + x1) / 2, ym = (y0 + y1) / 2;
                    hollowQuads += i == 0 && a->outlined;
                    filledQuadsBesideHollow += i == 0 && a->filled && q > 0 && shown[q - 1].outlined;
                    check_inside(&p[i], npc_x(&s, xm), ym, a, "quadrilateral centre");
                    /* Along both diagonals, a quarter from each end: no diagonal inside a HOLLOW side. */
                    for (int k = 0; k < 2; ++k) {
                        const double t = k ? 0.75 : 0.25;
                        check_inside(&p[i], npc_x(&s, x0 + t * (x1 - x0)), y0 + t * (y1 - y0), a, "diagonal");
                        check_inside(&p[i], npc_x(&s, x1 - t * (x1 - x0)), y0 + t * (y1 - y0), a, "diagonal");
                    }
                    /* Its bottom and left edges (with the facet beyond, if any), and the border's top
                     * and right ones. */
                    check_edge(&p[i], npc_x(&s, xm), y0, 0, 1, a, r > 0 ? &shown[q - (nx - 1)] : NULL);
                    check_edge(&p[i], npc_x(&s, x0), ym, 1, 0, a, c > 0 ? &shown[q - 1] : NULL);
                    if (r + 2 == ny) check_edge(&p[i], npc_x(&s, xm), y1, 0, 1, a, NULL);
                    if (c + 2 == nx) check_edge(&p[i], npc_x(&s, x1), ym, 1, 0, a, NULL);
                }
        }
        for (int i = 0; i < 2; ++i) free(p[i].rgb);
    }
}

static void triangle_strips(void) {
    for (int round = 0; round < 12; ++round) {
        Sides s;
        const int n = 4 + (int)(next_random() % 4), normals = round % 2 == 1;
        const int upFirst = (int)(next_random() % 2); /* the strip's own winding: front or back */
        const double x0 = random_real(0.15, 0.2), d = random_real(0.06, 0.09);
        const double y0 = random_real(0.2, 0.3), h = random_real(0.2, 0.35);
        Ppoint3 points[7];
        Pvec3 norms[5];
        Shown shown[5];
        Pfacet_data_arr3 fdata;
        Pfacet_vdata_arr3 vdata;
        Picture p[2];
        random_sides(&s, round);
        for (int k = 0; k < n; ++k)
            points[k].x = (Pfloat)(x0 + k * d), points[k].y = (Pfloat)((k % 2 == 0) != upFirst ? y0 : y0 + h),
            points[k].z = 0.5f;
        for (int k = 0; k + 2 < n; ++k) {
            /* Triangle k is k, k + 1, k + 2 wound as the first: counter-clockwise when it starts up. */
            const int wound = upFirst ? 1 : -1;
            const int side = normals ? (next_random() % 2 == 0 ? -1 : 1) : wound;
            norms[k].delta_x = norms[k].delta_y = 0, norms[k].delta_z = (Pfloat)side;
            shown[k] = shown_side(&s, side);
            turnedFacets += normals && side != wound;
        }
        open_mesh_structure(&s);
        fdata.norms = norms;
        vdata.points = points;
        ptri_strip3_data(normals ? PFACET_NORMAL : PFACET_NONE, PVERT_COORD, PMODEL_RGB, n, &fdata, &vdata);
        pclose_struct();
        CHECK(draw_offscreen_and_pdf(&files, p));
        for (int i = 0; i < 2; ++i) {
            if (!p[i].rgb) continue;
            for (int k = 0; k + 2 < n; ++k) {
                const double cx = (points[k].x + points[k + 1].x + points[k + 2].x) / 3.0;
                const double cy = (points[k].y + points[k + 1].y + points[k + 2].y) / 3.0;
                check_inside(&p[i], npc_x(&s, cx), cy, &shown[k], "triangle centre");
                /* Its border edge (k to k + 2), and the edge k + 1 to k + 2 it shares with the next. */
                check_edge(&p[i], npc_x(&s, x0 + (k + 1) * d), points[k].y, 0, 1, &shown[k], NULL);
                if (k + 3 < n)
                    check_edge(&p[i], npc_x(&s, x0 + (k + 1.5) * d), y0 + h / 2, 1, 0, &shown[k],
                               &shown[k + 1]);
            }
        }
        for (int i = 0; i < 2; ++i) free(p[i].rgb);
    }
}

static int edgeOnOutlined = 0, edgeOnBlank = 0;

/* Quadrilateral meshes in a plane x = c through the view direction: every facet edge-on (its
 * projected winding exactly zero) shows its front, whichever way its vertices or its facet normal
 * turn it: a HOLLOW front draws the facets' edges as one vertical line in the front colour, any
 * other front (SOLID fills no area) or a culled front nothing. */
static void edge_on(void) {
    for (int round = 0; round < 10; ++round) {
        Sides s;
        double ys[4], zs[3];
        const int ny = 2 + (int)(next_random() % 3), nz = 2 + (int)(next_random() % 2);
        const int normals = round % 2 == 0, reversed = (int)(next_random() % 2);
        const double c = random_real(0.3, 0.7);
        Ppoint3 points[12];
        Pvec3 norms[6];
        Pint_size dim;
        Pfacet_data_arr3 fdata;
        Pfacet_vdata_arr3 vdata;
        Picture p[2];
        random_sides(&s, round);
        s.flip = 0;
        if (round % 3 != 2) { /* HOLLOW over SOLID, either way round: the side shown decides */
            s.front = round % 3 == 0 ? PSTYLE_HOLLOW : PSTYLE_SOLID;
            s.back = round % 3 == 0 ? PSTYLE_SOLID : PSTYLE_HOLLOW;
            s.distinguish = 1;
        }
        grid_lines(ys, ny, random_real(0.15, 0.2));
        grid_lines(zs, nz, random_real(0.3, 0.4));
        /* u runs along y (or against it, reversing the winding), v along z. */
        for (int j = 0; j < nz; ++j)
            for (int i = 0; i < ny; ++i)
                points[j * ny + i].x = (Pfloat)c,
                                points[j * ny + i].y = (Pfloat)ys[reversed ? ny - 1 - i : i],
                                points[j * ny + i].z = (Pfloat)zs[j];
        for (int q = 0; q < (ny - 1) * (nz - 1); ++q)
            norms[q].delta_x = next_random() % 2 ? 1.0f : -1.0f, norms[q].delta_y = norms[q].delta_z = 0;
        const Shown front = shown_side(&s, 1);
        open_mesh_structure(&s);
        dim.size_x = ny, dim.size_y = nz;
        fdata.norms = norms;
        vdata.points = points;
        pquad_mesh3_data(normals ? PFACET_NORMAL : PFACET_NONE, PVERT_COORD, PMODEL_RGB, &dim, &fdata,
                         &vdata);
        pclose_struct();
        CHECK(draw_offscreen_and_pdf(&files, p));
        edgeOnOutlined += front.outlined, edgeOnBlank += !front.outlined;
        for (int i = 0; i < 2; ++i) {
            if (!p[i].rgb) continue;
            for (int k = 1; k < 8; ++k) {
                const double y = ys[0] + (ys[ny - 1] - ys[0]) * k / 8.0;
                const int ok = front.outlined ? line_along(&p[i], c, y, 1, 0, front.colour) <= 24
                                              : farthest_from_background(&p[i], c, y, 1, 0) <= 24;
                if (!ok)
                    fprintf(stderr, "  %s: edge-on mesh at NPC (%.3f, %.3f): %s (round %d)\n", p[i].name, c,
                            y, front.outlined ? "front outline missing" : "something drawn", round);
                CHECK(ok);
            }
        }
        for (int i = 0; i < 2; ++i) free(p[i].rgb);
    }
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    seed_random(0x2545f4914f6cdd1dULL);
    files = picture_files(dir, "mesh_sides");
    snprintf(errors, sizeof errors, "%s/mesh_sides_errors.txt", dir);
    open_with_handler(errors);
    quad_meshes();
    triangle_strips();
    edge_on();
    /* The sequence reaches the cases: HOLLOW quadrilaterals, filled ones beside them, facets turned. */
    CHECK(hollowQuads >= 8);
    CHECK(filledQuadsBesideHollow >= 2);
    CHECK(turnedFacets >= 8);
    CHECK(edgeOnOutlined >= 3 && edgeOnBlank >= 2);
    pclose_phigs();
    return finish("test_mesh_sides");
}
