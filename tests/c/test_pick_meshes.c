/* Picking meshes by the side each facet shows, on the headless offscreen type (lavapipe,
 * validation layer on) with a script-fed pick device: seeded random quadrilateral meshes (planar
 * facets on a height field z = g(x) + h(y)) and triangle strips in space, under random parallel
 * and perspective views, front and back interior styles, face distinguishing, culling and edge
 * flags, are picked at random points, facet centres and points near facet edges exactly when a
 * brute-force test of every facet says so: a facet counts by the side it shows (the back's style
 * with distinguishing on; a culled side not at all), inside and within the aperture when that side
 * is SOLID or HATCH, near its own edges (no diagonals) when it is HOLLOW or the edges are on, not
 * at all when it is EMPTY. Points within the rounding of the aperture's edge are left out.
 * argv[1]: a directory for files.
 *
 * The workstation window [0,1]^2 maps onto the 768 x 768 square at the left of the 1024 x 768
 * display, so NPC (x, y) is pixel (768 x, 768 (1 - y)) from the top left. */
#include "check.h"

#define WS 1
#define APERTURE 0.01 /* the pick device's aperture half-size in NPC */

/* Whether REQUEST PICK at pixel (px, py) finds the mesh (pick id 7). */
static int picked_at(long px, long py) {
    char script[64];
    Pescape_in_data in;
    Pescape_out_data* out = NULL;
    Ppick_path_elem items[2];
    Ppick_path path = {0, items};
    Pin_status status = PIN_STATUS_NONE;
    snprintf(script, sizeof script, "pick %ld %ld\n", px, py);
    in.escape_in_u11.ws_id = WS;
    in.escape_in_u11.script = script;
    in.escape_in_u11.file = NULL;
    EXPECT_NO_ERROR(pescape(PUESC_INPUT_SCRIPT, &in, NULL, &out));
    EXPECT_NO_ERROR(preq_pick(WS, 1, 2, &status, &path));
    CHECK(status == PIN_STATUS_NO_IN ||
          (status == PIN_STATUS_OK && path.depth == 1 && items[0].pick_id == 7));
    return status == PIN_STATUS_OK;
}

/* A facet: 3 or 4 vertex indices around it, in the order that makes its front. */
typedef struct {
    int count, v[4];
} Facet;

static double npc[16][2]; /* the vertices in NPC x, y */

static double segment_distance(const double* p, const double* a, const double* b) {
    const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2 : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

/* Twice the signed area of a facet in NPC (> 0: its front shows). */
static double facet_area(const Facet* f) {
    double area = 0;
    for (int i = 0; i < f->count; ++i) {
        const double* a = npc[f->v[i]];
        const double* b = npc[f->v[(i + 1) % f->count]];
        area += a[0] * b[1] - b[0] * a[1];
    }
    return area;
}

/* Distance from p to the facet's edges, and whether p lies inside it (convex in NPC). */
static double edge_distance(const Facet* f, const double* p, int* inside) {
    double best = 1e9;
    int positive = 0, negative = 0;
    for (int i = 0; i < f->count; ++i) {
        const double* a = npc[f->v[i]];
        const double* b = npc[f->v[(i + 1) % f->count]];
        const double cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        positive += cross > 0, negative += cross < 0;
        best = fmin(best, segment_distance(p, a, b));
    }
    *inside = positive == 0 || negative == 0;
    return best;
}

typedef struct {
    Pint_style front, back;
    int distinguish, edges;
    Pcull_mode cull;
} Style;

/* 1 hit, 0 missed, -1 too close to the aperture's edge (or an edge-on facet) to say. */
static int expected_pick(const Facet* facets, int count, const Style* s, const double* p, int* outlineOnly) {
    int unsure = 0;
    *outlineOnly = 1;
    for (int k = 0; k < count; ++k) {
        const double area = facet_area(&facets[k]);
        int inside;
        const double d = edge_distance(&facets[k], p, &inside);
        if (fabs(area) < 1e-4) { /* seen (nearly) edge on: its side is a matter of rounding */
            unsure = unsure || d < 1.6 * APERTURE || inside;
            continue;
        }
        const int side = area > 0 ? 1 : -1;
        const int culled =
            (side > 0 && s->cull == PCULL_FRONTFACE) || (side < 0 && s->cull == PCULL_BACKFACE);
        const Pint_style style = side < 0 && s->distinguish ? s->back : s->front;
        const int filled = !culled && (style == PSTYLE_SOLID || style == PSTYLE_HATCH);
        const int outlined = s->edges || (!culled && style == PSTYLE_HOLLOW);
        double r = 1e9;
        if (filled) r = inside ? 0 : d;
        if (outlined) r = fmin(r, d);
        if (r < 0.85 * APERTURE) {
            *outlineOnly = *outlineOnly && !(filled && inside);
            return 1;
        }
        unsure = unsure || r <= 1.6 * APERTURE;
    }
    return unsure ? -1 : 0;
}

static double viewMatrix[4][4]; /* the view's mapping times orientation, as the workstation has it */

/* A random view 1 (parallel in even rounds, perspective in odd ones) looking at (0.5, 0.5, 0). */
static void random_view(int round) {
    Ppoint3 vrp = {0.5f, 0.5f, 0.0f};
    Pvec3 vpn, vup;
    Pview_map3 map;
    Pview_rep3 view;
    Pint err = 0;
    double a, b, dot;
    do {
        vpn.delta_x = (Pfloat)random_real(-1, 1), vpn.delta_y = (Pfloat)random_real(-1, 1);
        vpn.delta_z = (Pfloat)random_real(-1, 1);
        vup.delta_x = (Pfloat)random_real(-1, 1), vup.delta_y = (Pfloat)random_real(-1, 1);
        vup.delta_z = (Pfloat)random_real(-1, 1);
        a = sqrt(vpn.delta_x * vpn.delta_x + vpn.delta_y * vpn.delta_y + vpn.delta_z * vpn.delta_z);
        b = sqrt(vup.delta_x * vup.delta_x + vup.delta_y * vup.delta_y + vup.delta_z * vup.delta_z);
        dot = vpn.delta_x * vup.delta_x + vpn.delta_y * vup.delta_y + vpn.delta_z * vup.delta_z;
    } while (a < 0.3 || b < 0.3 || fabs(dot) > 0.8 * a * b);
    peval_view_ori_matrix3(&vrp, &vpn, &vup, &err, view.ori_matrix);
    CHECK(err == 0);
    map.win.x_min = map.win.y_min = -0.7f, map.win.x_max = map.win.y_max = 0.7f;
    map.proj_vp.x_min = map.proj_vp.y_min = map.proj_vp.z_min = 0;
    map.proj_vp.x_max = map.proj_vp.y_max = map.proj_vp.z_max = 1;
    map.proj_type = round % 2 ? PTYPE_PERSPECT : PTYPE_PARAL;
    map.proj_ref_point.x = (Pfloat)random_real(-0.2, 0.2),
    map.proj_ref_point.y = (Pfloat)random_real(-0.2, 0.2);
    map.proj_ref_point.z = (Pfloat)random_real(2.5, 4);
    map.view_plane = 0, map.back_plane = -1.5f, map.front_plane = 1.5f;
    peval_view_map_matrix3(&map, &err, view.map_matrix);
    CHECK(err == 0);
    view.clip_limit.x_min = view.clip_limit.y_min = view.clip_limit.z_min = 0;
    view.clip_limit.x_max = view.clip_limit.y_max = view.clip_limit.z_max = 1;
    view.xy_clip = view.back_clip = view.front_clip = PIND_NO_CLIP;
    EXPECT_NO_ERROR(pset_view_rep3(WS, 1, &view));
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            viewMatrix[i][j] = 0;
            for (int k = 0; k < 4; ++k)
                viewMatrix[i][j] += (double)view.map_matrix[i][k] * view.ori_matrix[k][j];
        }
}

/* npc[i]: the points through the view. */
static void project(const Ppoint3* points, int count) {
    for (int i = 0; i < count; ++i) {
        const double p[4] = {points[i].x, points[i].y, points[i].z, 1};
        double h[4] = {0, 0, 0, 0};
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k) h[r] += viewMatrix[r][k] * p[k];
        npc[i][0] = h[0] / h[3], npc[i][1] = h[1] / h[3];
    }
}

static Style random_style(void) {
    const Pint_style styles[4] = {PSTYLE_HOLLOW, PSTYLE_SOLID, PSTYLE_EMPTY, PSTYLE_HATCH};
    Style s;
    s.front = styles[next_random() % 4];
    s.back = styles[next_random() % 4];
    s.distinguish = next_random() % 4 != 0;
    s.cull = (Pcull_mode)(next_random() % 4 == 0 ? 1 + next_random() % 2 : PCULL_NONE);
    s.edges = next_random() % 5 == 0;
    return s;
}

/* A random mesh in structure 1 and its facets: a quadrilateral mesh of planar facets (even
 * rounds) or a triangle strip. Gives back the facet count. */
static int random_mesh(int round, const Style* s, Ppoint3* points, Facet* facets) {
    Pint one = 1;
    Pint_list names = {1, &one};
    Pfacet_data_arr3 fdata;
    Pfacet_vdata_arr3 vdata;
    int count = 0;
    fdata.norms = NULL;
    vdata.points = points;
    EXPECT_NO_ERROR(pdel_struct(1));
    EXPECT_NO_ERROR(popen_struct(1));
    padd_names_set(&names);
    pset_pick_id(7);
    pset_view_ind(1);
    pset_int_style(s->front);
    pset_back_int_style(s->back);
    pset_face_disting_mode(s->distinguish ? PDISTING_YES : PDISTING_NO);
    pset_face_cull_mode(s->cull);
    pset_edge_flag(s->edges ? PEDGE_ON : PEDGE_OFF);
    if (round % 2 == 0) {
        const int nx = 3 + (int)(next_random() % 2), ny = 3 + (int)(next_random() % 2);
        double xs[4], ys[4], g[4], h[4];
        Pint_size dim;
        for (int i = 0; i < 4; ++i)
            xs[i] = 0.2 + 0.6 * i / (nx - 1) + random_real(-0.04, 0.04),
            ys[i] = 0.2 + 0.6 * i / (ny - 1) + random_real(-0.04, 0.04), g[i] = random_real(-0.3, 0.3),
            h[i] = random_real(-0.3, 0.3);
        /* z = g(x) + h(y) on the grid: every quadrilateral is planar. */
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                points[j * nx + i].x = (Pfloat)xs[i], points[j * nx + i].y = (Pfloat)ys[j],
                                points[j * nx + i].z = (Pfloat)(g[i] + h[j]);
        for (int j = 0; j + 1 < ny; ++j)
            for (int i = 0; i + 1 < nx; ++i, ++count) {
                facets[count].count = 4;
                facets[count].v[0] = j * nx + i, facets[count].v[1] = j * nx + i + 1;
                facets[count].v[2] = (j + 1) * nx + i + 1, facets[count].v[3] = (j + 1) * nx + i;
            }
        dim.size_x = nx, dim.size_y = ny;
        pquad_mesh3_data(PFACET_NONE, PVERT_COORD, PMODEL_RGB, &dim, &fdata, &vdata);
        project(points, nx * ny);
    } else {
        const int n = 4 + (int)(next_random() % 4);
        for (int k = 0; k < n; ++k)
            points[k].x = (Pfloat)(0.2 + 0.6 * k / (n - 1) + random_real(-0.03, 0.03)),
            points[k].y = (Pfloat)(k % 2 ? random_real(0.6, 0.8) : random_real(0.2, 0.4)),
            points[k].z = (Pfloat)random_real(-0.3, 0.3);
        /* Triangle k is k, k + 1, k + 2, every other one turned so that all wind alike. */
        for (int k = 0; k + 2 < n; ++k, ++count) {
            facets[count].count = 3;
            facets[count].v[0] = k % 2 ? k + 1 : k, facets[count].v[1] = k % 2 ? k : k + 1;
            facets[count].v[2] = k + 2;
        }
        ptri_strip3_data(PFACET_NONE, PVERT_COORD, PMODEL_RGB, n, &fdata, &vdata);
        project(points, n);
    }
    EXPECT_NO_ERROR(pclose_struct());
    return count;
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    Pint one = 1;
    Pfilter filter = {{1, &one}, {0, NULL}};
    int picks = 0, outlineHits = 0, hollowMisses = 0, backHits = 0, unsure = 0;
    seed_random(0x5851f42d4c957f2dULL);
    snprintf(errors, sizeof errors, "%s/pick_meshes_errors.txt", dir);
    open_with_handler(errors);
    EXPECT_NO_ERROR(popen_ws(WS, NULL, PWST_OFFSCREEN));
    EXPECT_NO_ERROR(pset_pick_filter(WS, 1, &filter));
    for (int round = 0; round < 40; ++round) {
        Ppoint3 points[16];
        Facet facets[9];
        const Style s = random_style();
        random_view(round);
        const int count = random_mesh(round, &s, points, facets);
        EXPECT_NO_ERROR(ppost_struct(WS, 1, 0.5f));
        for (int k = 0; k < 30; ++k) {
            double p[2];
            const Facet* f = &facets[next_random() % (unsigned)count];
            if (k % 3 == 0) {
                /* Anywhere around the mesh. */
                p[0] = random_real(0.05, 0.95), p[1] = random_real(0.05, 0.95);
            } else if (k % 3 == 1) {
                /* A facet's centre. */
                p[0] = p[1] = 0;
                for (int i = 0; i < f->count; ++i)
                    p[0] += npc[f->v[i]][0] / f->count, p[1] += npc[f->v[i]][1] / f->count;
            } else {
                /* Near one of its edges, inside or out. */
                const int e = (int)(next_random() % (unsigned)f->count);
                const double* a = npc[f->v[e]];
                const double* b = npc[f->v[(e + 1) % f->count]];
                const double t = random_real(0.2, 0.8);
                p[0] = a[0] + t * (b[0] - a[0]) + random_real(-0.5, 0.5) * APERTURE;
                p[1] = a[1] + t * (b[1] - a[1]) + random_real(-0.5, 0.5) * APERTURE;
            }
            {
                const long px = lround(768 * p[0]), py = lround(768 * (1 - p[1]));
                const double q[2] = {px / 768.0, 1 - py / 768.0};
                int outlineOnly = 0;
                int expected;
                if (px < 0 || px > 767 || py < 0 || py > 767) continue;
                expected = expected_pick(facets, count, &s, q, &outlineOnly);
                if (expected < 0) {
                    ++unsure;
                    continue;
                }
                ++picks;
                {
                    const int picked = picked_at(px, py);
                    if (picked != expected)
                        fprintf(
                            stderr,
                            "  round %d (%s), styles %d / %d, distinguishing %d, cull %d, edges %d: pick at "
                            "NPC (%.4f, %.4f) %s\n",
                            round, round % 2 ? "strip" : "quadrilaterals", (int)s.front, (int)s.back,
                            s.distinguish, (int)s.cull, s.edges, q[0], q[1],
                            picked ? "hit, expected none" : "missed");
                    CHECK(picked == expected);
                }
                outlineHits += expected && outlineOnly && !s.edges;
                hollowMisses += !expected && k % 3 == 1;
                backHits += expected && !outlineOnly && s.distinguish && s.back != s.front &&
                            (s.back == PSTYLE_SOLID || s.back == PSTYLE_HATCH);
            }
        }
    }
    /* The sequence reaches the cases, and few points are left out. */
    CHECK(picks >= 800);
    CHECK(unsure < picks / 4);
    CHECK(outlineHits >= 20);
    CHECK(hollowMisses >= 20);
    CHECK(backHits >= 20);
    printf("test_pick_meshes: %d picks (%d left out), %d on outlines, %d centres missed, %d back hits\n",
           picks, unsure, outlineHits, hollowMisses, backHits);
    EXPECT_NO_ERROR(pclose_ws(WS));
    pclose_phigs();
    return finish("test_pick_meshes");
}
