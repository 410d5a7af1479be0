/* SET RENDERING COLOUR MODEL drawn on the offscreen type (lavapipe, validation layer on) and the
 * PDF type (rasterised by pdftoppm at 144 dpi): seeded random triangles whose corners have random,
 * clearly saturated colours, unlit and Gouraud lit (ambient, coefficient 1), under each model,
 * show at a pixel near their centre the corners' colours interpolated in that model (offscreen:
 * with the pixel centre's barycentric weights; PDF, which paints each triangle of the area flat
 * in the raster's colour at its centroid, a lone triangle uncut: their mean), computed here
 * on the CPU with conversions of its own (Foley, van Dam, Feiner, Hughes, "Computer Graphics:
 * Principles and Practice", 2nd ed., 1990, 13.3); a SOLID triangle depth cued with a constant
 * scale shows its colour and the cue colour mixed in the model; RGB and HSV give mid colours
 * apart; the facilities list every model. argv[1]: a directory for the files. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include "picture.h"

/* ---- The colour models, as ISO 9592 and the binding's pset_colr_model give them. */

static void hsv_to_rgb(const double c[3], double out[3]) {
    const double h = 6.0 * (c[0] - floor(c[0])), s = c[1], v = c[2];
    const int sector = (int)floor(h) % 6;
    const double f = h - floor(h), p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    const double table[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
    for (int k = 0; k < 3; ++k) out[k] = table[sector][k];
}

static double hue(const double c[3], double hi, double lo) {
    const double d = hi - lo;
    double h = hi == c[0] ? (c[1] - c[2]) / d : hi == c[1] ? 2 + (c[2] - c[0]) / d : 4 + (c[0] - c[1]) / d;
    h /= 6;
    if (h < 0) h += 1;
    return h >= 1 ? 0 : h;
}

static double hls_value(double n1, double n2, double h) {
    h = h - floor(h);
    if (h < 1.0 / 6) return n1 + (n2 - n1) * h * 6;
    if (h < 0.5) return n2;
    if (h < 2.0 / 3) return n1 + (n2 - n1) * (2.0 / 3 - h) * 6;
    return n1;
}

/* RGB (IEC 61966-2-1 primaries, white D65) to CIE XYZ. */
static const double to_xyz[3][3] = {
    {0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};

static void solve3(const double m[3][3], const double b[3], double x[3]) {
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    for (int k = 0; k < 3; ++k) {
        double a[3][3];
        memcpy(a, m, sizeof a);
        for (int r = 0; r < 3; ++r) a[r][k] = b[r];
        x[k] = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])) /
               det;
    }
}

/* The components in rendering colour model `m` of an RGB colour in [0, 1]. */
static void from_rgb(Pint m, const double c[3], double out[3]) {
    const double hi = fmax(c[0], fmax(c[1], c[2])), lo = fmin(c[0], fmin(c[1], c[2]));
    if (m == PRCM_CIE) {
        double xyz[3] = {0, 0, 0};
        for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) xyz[r] += to_xyz[r][k] * c[k];
        const double d = xyz[0] + 15 * xyz[1] + 3 * xyz[2];
        out[0] = 4 * xyz[0] / d, out[1] = 9 * xyz[1] / d, out[2] = xyz[1];
    } else if (m == PRCM_HSV) {
        out[0] = hue(c, hi, lo), out[1] = (hi - lo) / hi, out[2] = hi;
    } else if (m == PRCM_HLS) {
        const double l = (hi + lo) / 2;
        out[0] = hue(c, hi, lo), out[1] = l,
        out[2] = l <= 0.5 ? (hi - lo) / (hi + lo) : (hi - lo) / (2 - hi - lo);
    } else {
        memcpy(out, c, 3 * sizeof(double));
    }
}

/* The RGB colour, clamped to [0, 1], of components in rendering colour model `m`. */
static void to_rgb(Pint m, const double c[3], double out[3]) {
    if (m == PRCM_CIE) {
        const double y = c[2],
                     xyz[3] = {y * 9 * c[0] / (4 * c[1]), y, y * (12 - 3 * c[0] - 20 * c[1]) / (4 * c[1])};
        solve3(to_xyz, xyz, out);
    } else if (m == PRCM_HSV) {
        hsv_to_rgb(c, out);
    } else if (m == PRCM_HLS) {
        const double l = c[1], s = c[2], n2 = l <= 0.5 ? l * (1 + s) : l + s - l * s, n1 = 2 * l - n2;
        out[0] = hls_value(n1, n2, c[0] + 1.0 / 3), out[1] = hls_value(n1, n2, c[0]),
        out[2] = hls_value(n1, n2, c[0] - 1.0 / 3);
    } else {
        memcpy(out, c, 3 * sizeof(double));
    }
    for (int k = 0; k < 3; ++k) out[k] = fmin(1, fmax(0, out[k]));
}

/* The colours `c` weighted by `w` (summing to 1), in model `m`, as RGB. */
static void interpolate(Pint m, double c[][3], const double* w, int n, double out[3]) {
    double sum[3] = {0, 0, 0};
    for (int i = 0; i < n; ++i) {
        double in[3];
        from_rgb(m, c[i], in);
        for (int k = 0; k < 3; ++k) sum[k] += w[i] * in[k];
    }
    to_rgb(m, sum, out);
}

/* ---- Drawing */

static PictureFiles files;

/* Structure 1 drawn on fresh offscreen (1) and PDF (2) workstations as draw_offscreen_and_pdf
 * does, with depth cue entry 1 set to a constant scale `cue_scale` toward `cue` when cue is given. */
static int draw(Picture p[2], const double* cue, double cue_scale) {
    char command[2048], ppm[600];
    remove(files.png), remove(files.pdf);
    EXPECT_NO_ERROR(popen_ws(1, files.png, PWST_OFFSCREEN));
    EXPECT_NO_ERROR(popen_ws(2, files.pdf, PWST_PDF));
    for (Pint ws = 1; ws <= 2; ++ws) {
        if (cue) {
            Pdcue_bundle d;
            d.mode = PALLOWED;
            d.ref_planes[0] = 1, d.ref_planes[1] = 0;
            d.scaling[0] = d.scaling[1] = (Pfloat)cue_scale;
            d.colr.type = PMODEL_RGB;
            d.colr.val.general.x = (Pfloat)cue[0], d.colr.val.general.y = (Pfloat)cue[1],
            d.colr.val.general.z = (Pfloat)cue[2];
            EXPECT_NO_ERROR(pset_dcue_rep(ws, 1, &d));
        }
        EXPECT_NO_ERROR(ppost_struct(ws, 1, 0.5f));
        EXPECT_NO_ERROR(pupd_ws(ws, PFLAG_PERFORM));
        EXPECT_NO_ERROR(pclose_ws(ws));
    }
    p[0].rgb = p[1].rgb = NULL;
    p[0].side = 768, p[0].name = "offscreen";
    p[1].side = 595.2756 * 2, p[1].name = "PDF";
    snprintf(command, sizeof command, "pdftoppm -r 144 -singlefile '%s' '%s'", files.pdf, files.ppm_root);
    snprintf(ppm, sizeof ppm, "%s.ppm", files.ppm_root);
    return read_png(files.png, &p[0]) && system(command) == 0 && read_ppm(ppm, &p[1]);
}

/* Whether the pixel at NPC (x, y) is `rgb` within `tolerance` (in 1/255). */
static int pixel_is(const Picture* p, double x, double y, const double rgb[3], double tolerance,
                    const char* what) {
    const unsigned char* c = picture_pixel(p, x, y);
    int ok = 1;
    for (int k = 0; k < 3; ++k) ok = ok && fabs(c[k] - 255 * rgb[k]) <= tolerance;
    if (!ok)
        fprintf(stderr, "  %s, %s: pixel at NPC (%.4f, %.4f) is %d %d %d, expected %.1f %.1f %.1f\n", p->name,
                what, x, y, c[0], c[1], c[2], 255 * rgb[0], 255 * rgb[1], 255 * rgb[2]);
    return ok;
}

/* A random colour, a multiple of 1/255 in each component, whose largest and smallest components
 * differ by at least 0.4 (a well defined hue). */
static void saturated_rgb(double c[3]) {
    do
        for (int k = 0; k < 3; ++k) c[k] = (double)(next_random() % 256u) / 255.0;
    while (fmax(c[0], fmax(c[1], c[2])) - fmin(c[0], fmin(c[1], c[2])) < 0.4);
}

static const Pint models[5] = {PRCM_WS_DEP, PRCM_RGB, PRCM_CIE, PRCM_HSV, PRCM_HLS};

/* Structure 1 anew: a triangle with vertex colours (and normals (0, 0, 1)) in rendering colour
 * model `model`, unlit or Gouraud lit by the predefined white ambient light 1. */
static void coloured_triangle(Pint model, double corners[3][2], double colours[3][3], int lit) {
    Pptconorm3 v[3];
    Pfacet_vdata_list3 vdata;
    Pint on = 1;
    Pint_list activate = {1, &on}, none = {0, NULL};
    Prefl_props props;
    memset(&props, 0, sizeof props);
    props.ambient_coef = 1;
    props.specular_colr.type = PMODEL_RGB;
    for (int i = 0; i < 3; ++i) {
        v[i].point.x = (Pfloat)corners[i][0], v[i].point.y = (Pfloat)corners[i][1], v[i].point.z = 0;
        v[i].colr.direct.rgb.red = (Pfloat)colours[i][0], v[i].colr.direct.rgb.green = (Pfloat)colours[i][1],
        v[i].colr.direct.rgb.blue = (Pfloat)colours[i][2];
        v[i].norm.delta_x = 0, v[i].norm.delta_y = 0, v[i].norm.delta_z = 1;
    }
    vdata.num_vertices = 3, vdata.vertex_data.ptconorms = v;
    pdel_struct(1);
    popen_struct(1);
    pset_int_style(PSTYLE_SOLID);
    pset_rendering_colr_model(model);
    pset_int_shad_meth(PSD_COLOUR);
    if (lit) {
        pset_refl_eqn(PREFL_AMBIENT);
        pset_refl_props(&props);
        pset_light_src_state(&activate, &none);
    }
    EXPECT_NO_ERROR(pfill_area_set3_data(PFACET_NONE, PEDGE_NONE, PVERT_COORD_COLOUR_NORMAL, PMODEL_RGB, NULL,
                                         1, NULL, &vdata));
    pclose_struct();
}

/* The barycentric weights of (x, y) in the triangle. */
static void barycentric(double t[3][2], double x, double y, double w[3]) {
    const double d = (t[1][1] - t[2][1]) * (t[0][0] - t[2][0]) + (t[2][0] - t[1][0]) * (t[0][1] - t[2][1]);
    w[0] = ((t[1][1] - t[2][1]) * (x - t[2][0]) + (t[2][0] - t[1][0]) * (y - t[2][1])) / d;
    w[1] = ((t[2][1] - t[0][1]) * (x - t[2][0]) + (t[0][0] - t[2][0]) * (y - t[2][1])) / d;
    w[2] = 1 - w[0] - w[1];
}

static void interpolated_triangles(void) {
    double farthest = 0; /* the largest RGB / HSV mid colour difference met */
    for (int round = 0; round < 20; ++round) {
        const Pint model = models[round % 5];
        const int lit = (round / 5) % 2;
        const double cx = random_real(0.35, 0.65), cy = random_real(0.35, 0.65), r = random_real(0.15, 0.25);
        double corners[3][2], colours[3][3], centre[2], w[3], third[3] = {1.0 / 3, 1.0 / 3, 1.0 / 3};
        double expected[2][3], rgbMean[3], hsvMean[3];
        Picture p[2];
        for (int k = 0; k < 3; ++k) {
            const double a = k * 2.0943951 + random_real(0, 1);
            corners[k][0] = (double)(Pfloat)(cx + r * cos(a)),
            corners[k][1] = (double)(Pfloat)(cy + r * sin(a));
            saturated_rgb(colours[k]);
        }
        /* The pixel centre nearest the centroid (x, y in pixel units + 1/2). */
        for (int k = 0; k < 2; ++k)
            centre[k] = (floor((corners[0][k] + corners[1][k] + corners[2][k]) / 3 * 768) + 0.5) / 768;
        barycentric(corners, centre[0], centre[1], w);
        interpolate(model, colours, w, 3, expected[0]);     /* per pixel */
        interpolate(model, colours, third, 3, expected[1]); /* per facet */
        interpolate(PRCM_RGB, colours, third, 3, rgbMean);
        interpolate(PRCM_HSV, colours, third, 3, hsvMean);
        for (int k = 0; k < 3; ++k) farthest = fmax(farthest, fabs(rgbMean[k] - hsvMean[k]));
        coloured_triangle(model, corners, colours, lit);
        CHECK(draw(p, NULL, 0));
        for (int i = 0; i < 2; ++i) {
            char what[120];
            snprintf(what, sizeof what, "model %d, %s", (int)model, lit ? "Gouraud lit" : "unlit");
            if (p[i].rgb) CHECK(pixel_is(&p[i], centre[0], centre[1], expected[i], 3.0, what));
            free(p[i].rgb);
        }
    }
    CHECK(farthest > 0.3); /* the models' mid colours are far apart: the test tells them apart */
}

static void depth_cued_triangles(void) {
    for (int round = 0; round < 5; ++round) {
        const Pint model = models[round];
        const double s = random_real(0.3, 0.7), weights[2] = {s, 1 - s};
        double colours[2][3], expected[3];
        Ppoint3 corners[3];
        Ppoint_list3 triangle = {3, corners};
        Pgcolr g;
        Picture p[2];
        saturated_rgb(colours[0]), saturated_rgb(colours[1]);
        for (int k = 0; k < 3; ++k) {
            const double a = k * 2.0943951 + 0.3;
            corners[k].x = (Pfloat)(0.5 + 0.3 * cos(a)), corners[k].y = (Pfloat)(0.5 + 0.3 * sin(a)),
            corners[k].z = 0;
        }
        interpolate(model, colours, weights, 2, expected);
        g.type = PMODEL_RGB;
        g.val.general.x = (Pfloat)colours[0][0], g.val.general.y = (Pfloat)colours[0][1],
        g.val.general.z = (Pfloat)colours[0][2];
        pdel_struct(1);
        popen_struct(1);
        pset_int_style(PSTYLE_SOLID);
        pset_int_colr(&g);
        pset_rendering_colr_model(model);
        pset_dcue_ind(1);
        pfill_area3(&triangle);
        pclose_struct();
        CHECK(draw(p, colours[1], s));
        for (int i = 0; i < 2; ++i) {
            char what[120];
            snprintf(what, sizeof what, "model %d, depth cued at scale %.3f", (int)model, s);
            if (p[i].rgb) CHECK(pixel_is(&p[i], 0.5, 0.5, expected, 3.0, what));
            free(p[i].rgb);
        }
    }
}

static void facilities(void) {
    Pint buffer[8], err = -1, total = 0;
    Pint_list list = {0, buffer};
    const Pint types[3] = {PWST_OFFSCREEN, PWST_PDF, PWST_PNG};
    for (int t = 0; t < 3; ++t) {
        pinq_rendering_colr_model_facs(types[t], 8, 0, &err, &list, &total);
        CHECK(err == 0 && total == 4 && list.num_ints == 4);
        for (int k = 0; k < 4 && k < list.num_ints; ++k) CHECK(buffer[k] == models[k + 1]);
    }
    /* The element stores and answers every model, PRCM_WS_DEP included. */
    pdel_struct(1);
    popen_struct(1);
    for (int k = 0; k < 5; ++k) pset_rendering_colr_model(models[k]);
    pclose_struct();
    popen_struct(1);
    for (int k = 0; k < 5; ++k) {
        size_t size = 0;
        Pelem_type type;
        Pelem_data* data = NULL;
        Pstore store;
        pset_elem_ptr(k + 1);
        pinq_cur_elem_type_size(&err, &type, &size);
        CHECK(err == 0 && type == PELEM_RENDERING_COLR_MODEL);
        pcreate_store(&err, &store);
        pinq_cur_elem_content(store, &err, &data);
        CHECK(err == 0 && data && data->int_data == models[k]);
        pdel_store(store);
    }
    pclose_struct();
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    seed_random(0x9e3779b97f4a7c15ULL);
    files = picture_files(dir, "rendering_colour_model");
    snprintf(errors, sizeof errors, "%s/rendering_colour_model_errors.txt", dir);
    open_with_handler(errors);
    facilities();
    interpolated_triangles();
    depth_cued_triangles();
    pclose_phigs();
    return finish("test_rendering_colour_model");
}
