/* Colour models: random colours set into the colour table under each workstation colour model
 * (RGB, CIELUV, HSV, HLS) and inquired SET (as given) and REALIZED (the RGB drawn, clamped, in
 * the current model), converted here by the textbook formulas (HSV by hue sector; HLS through
 * HSV; CIELUV through CIE XYZ and the BT.709 matrix, reference white D65); direct general colours
 * in elements keep their model; light source and depth cue colours (random indices and models)
 * are answered SET as given and REALIZED as the clamped RGB drawn, their other REALIZED values
 * differing from SET exactly where the clamping rules say; PSEUDO and PSEUDO_N colour mapping
 * entries in a random model keep it and map a square's colour as the formulas say; an HSV
 * and an HLS colour paint the right RGB pixels on the offscreen type (lavapipe); and a random
 * colour given in each model as an interior, polyline and vertex colour draws as its RGB on the
 * offscreen type and the PDF type (pdftoppm), its element answering it as given. argv[1]: a
 * directory for the files. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include "picture.h"

static double clamp01(double v) {
    return v < 0 ? 0 : v > 1 ? 1 : v;
}

static void hsv_to_rgb(double h, double s, double v, double out[3]) {
    const double f6 = h * 6.0;
    const int sector = (int)floor(f6) % 6;
    const double f = f6 - floor(f6);
    const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    const double table[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
    for (int k = 0; k < 3; ++k) out[k] = table[sector][k];
}

static void hls_to_rgb(double h, double l, double s, double out[3]) {
    const double v = l + s * (l < 1 - l ? l : 1 - l);
    hsv_to_rgb(h, v > 0 ? 2 * (1 - l / v) : 0, v, out);
}

/* CIE XYZ to RGB: the inverse (by Cramer's rule) of IEC 61966-2-1's RGB to XYZ matrix. */
static void cieluv_to_rgb(double u, double v, double y, double out[3]) {
    static const double m[3][3] = {
        {0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};
    const double xyz[3] = {y * 9 * u / (4 * v), y, y * (12 - 3 * u - 20 * v) / (4 * v)};
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    for (int c = 0; c < 3; ++c) {
        double a[3][3];
        memcpy(a, m, sizeof a);
        for (int r = 0; r < 3; ++r) a[r][c] = xyz[r];
        out[c] = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                  a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                  a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])) /
                 det;
    }
}

static void to_rgb(Pint model, const double c[3], double out[3]) {
    if (model == PMODEL_HSV)
        hsv_to_rgb(c[0], c[1], c[2], out);
    else if (model == PMODEL_HLS)
        hls_to_rgb(c[0], c[1], c[2], out);
    else if (model == PMODEL_CIELUV)
        cieluv_to_rgb(c[0], c[1], c[2], out);
    else
        for (int k = 0; k < 3; ++k) out[k] = c[k];
}

/* The components of a Pcolr_rep as the model reads them. */
static void components(Pint model, const Pcolr_rep* r, double out[3]) {
    if (model == PMODEL_HSV)
        out[0] = r->hsv.hue, out[1] = r->hsv.satur, out[2] = r->hsv.value;
    else if (model == PMODEL_HLS)
        out[0] = r->hls.hue, out[1] = r->hls.lightness, out[2] = r->hls.satur;
    else if (model == PMODEL_CIELUV)
        out[0] = r->cieluv.cieluv_x, out[1] = r->cieluv.cieluv_y, out[2] = r->cieluv.cieluv_y_lum;
    else
        out[0] = r->rgb.red, out[1] = r->rgb.green, out[2] = r->rgb.blue;
}

static Pcolr_rep representation(Pint model, const double c[3]) {
    Pcolr_rep r;
    memset(&r, 0, sizeof r);
    if (model == PMODEL_HSV)
        r.hsv.hue = (Pfloat)c[0], r.hsv.satur = (Pfloat)c[1], r.hsv.value = (Pfloat)c[2];
    else if (model == PMODEL_HLS)
        r.hls.hue = (Pfloat)c[0], r.hls.lightness = (Pfloat)c[1], r.hls.satur = (Pfloat)c[2];
    else if (model == PMODEL_CIELUV)
        r.cieluv.cieluv_x = (Pfloat)c[0], r.cieluv.cieluv_y = (Pfloat)c[1],
        r.cieluv.cieluv_y_lum = (Pfloat)c[2];
    else
        r.rgb.red = (Pfloat)c[0], r.rgb.green = (Pfloat)c[1], r.rgb.blue = (Pfloat)c[2];
    return r;
}

/* A random colour of `model` in its canonical range (a defined hue for HSV and HLS; CIELUV
 * chromaticities around the white point, some outside the RGB gamut). */
static void random_colour(Pint model, double c[3]) {
    if (model == PMODEL_HSV || model == PMODEL_HLS) {
        c[0] = random_real(0, 0.999), c[1] = random_real(0.05, 0.95), c[2] = random_real(0.05, 0.95);
    } else if (model == PMODEL_CIELUV) {
        c[0] = random_real(0.12, 0.28), c[1] = random_real(0.38, 0.54), c[2] = random_real(0, 1);
    } else {
        for (int k = 0; k < 3; ++k) c[k] = random_real(0, 1);
    }
}

static int close3(const double a[3], const double b[3], double eps) {
    return fabs(a[0] - b[0]) <= eps && fabs(a[1] - b[1]) <= eps && fabs(a[2] - b[2]) <= eps;
}

static void colour_tables(void) {
    const Pint models[4] = {PMODEL_RGB, PMODEL_CIELUV, PMODEL_HSV, PMODEL_HLS};
    Pint err = -1, model = 0;
    for (int m = 0; m < 4; ++m) {
        EXPECT_NO_ERROR(pset_colr_model(1, models[m]));
        pinq_colr_model(1, &err, &model);
        CHECK(err == 0 && model == models[m]);
        for (int i = 0; i < 60; ++i) {
            double c[3], got[3], rgb[3], drawn[3], expected[3];
            const Pint index = 8 + (Pint)(next_random() % 100);
            Pcolr_rep rep, answer;
            random_colour(models[m], c);
            rep = representation(models[m], c);
            EXPECT_NO_ERROR(pset_colr_rep(1, index, &rep));
            pinq_colr_rep(1, index, PINQ_SET, &err, &answer);
            components(models[m], &answer, got);
            CHECK(err == 0 && close3(got, c, 1e-6)); /* as given */
            pinq_colr_rep(1, index, PINQ_REALIZED, &err, &answer);
            components(models[m], &answer, got);
            to_rgb(models[m], got, drawn);
            to_rgb(models[m], c, rgb);
            for (int k = 0; k < 3; ++k) expected[k] = clamp01(rgb[k]);
            CHECK(err == 0 && close3(drawn, expected, 1e-4));            /* the RGB drawn, in the model */
            if (models[m] != PMODEL_CIELUV) CHECK(close3(got, c, 1e-5)); /* inside the gamut: the same */
        }
    }
    /* An entry given in HSV, inquired under RGB and HLS: converted. */
    {
        const double hsv[3] = {random_real(0, 0.999), random_real(0.1, 1), random_real(0.1, 1)};
        double rgb[3], got[3], back[3];
        Pcolr_rep rep = representation(PMODEL_HSV, hsv), answer;
        EXPECT_NO_ERROR(pset_colr_model(1, PMODEL_HSV));
        EXPECT_NO_ERROR(pset_colr_rep(1, 5, &rep));
        EXPECT_NO_ERROR(pset_colr_model(1, PMODEL_RGB));
        pinq_colr_rep(1, 5, PINQ_SET, &err, &answer);
        components(PMODEL_RGB, &answer, got);
        hsv_to_rgb(hsv[0], hsv[1], hsv[2], rgb);
        CHECK(err == 0 && close3(got, rgb, 1e-6));
        EXPECT_NO_ERROR(pset_colr_model(1, PMODEL_HLS));
        pinq_colr_rep(1, 5, PINQ_SET, &err, &answer);
        components(PMODEL_HLS, &answer, got);
        to_rgb(PMODEL_HLS, got, back);
        CHECK(err == 0 && close3(back, rgb, 1e-6));
    }
    /* Out of range components and models are refused, the entry unchanged. */
    {
        const double bad[3] = {0.5, 1.5, 0.5};
        Pcolr_rep rep = representation(PMODEL_HLS, bad);
        EXPECT_ERROR(pset_colr_rep(1, 5, &rep), 118, Pfn_set_colr_rep);
        EXPECT_ERROR(pset_colr_model(1, 0), 110, Pfn_set_colr_model);
        pinq_colr_model(1, &err, &model);
        CHECK(err == 0 && model == PMODEL_HLS);
    }
    EXPECT_NO_ERROR(pset_colr_model(1, PMODEL_RGB));
}

static void element_colours(Pstore store) {
    Pint err = -1;
    Pelem_data* data = NULL;
    popen_struct(7);
    for (Pint m = PMODEL_RGB; m <= PMODEL_HLS; ++m) {
        Pgcolr g;
        g.type = m;
        g.val.general.x = (Pfloat)random_real(0, 1), g.val.general.y = (Pfloat)random_real(0, 1),
        g.val.general.z = (Pfloat)random_real(0, 1);
        EXPECT_NO_ERROR(pset_int_colr(&g));
        pinq_cur_elem_content(store, &err, &data);
        CHECK(err == 0 && data && data->colr.type == m && data->colr.val.general.x == g.val.general.x &&
              data->colr.val.general.z == g.val.general.z);
    }
    {
        Pgcolr g;
        g.type = 5;
        g.val.general.x = g.val.general.y = g.val.general.z = 0.5f;
        EXPECT_ERROR(pset_int_colr(&g), PE_ENUM_TYPE_INVAL, Pfn_set_int_colr);
    }
    pclose_struct();
}

static Pfloat realized_f(Pfloat v, Pfloat lo, Pfloat hi) {
    return v < lo ? lo : v > hi ? hi : v;
}

/* A random general colour: an index into the colour table (0 .. 9, some undefined), or direct in
 * a random model (RGB components partly outside [0, 1]: SET keeps them, REALIZED clamps). */
static Pgcolr random_general_colour(void) {
    Pgcolr g;
    double c[3];
    memset(&g, 0, sizeof g);
    g.type = (Pint)(next_random() % 5);
    if (g.type == PINDIRECT) {
        g.val.ind = (Pint)(next_random() % 10);
        return g;
    }
    random_colour(g.type, c);
    if (g.type == PMODEL_RGB) c[0] = random_real(-0.5, 1.5), c[2] = random_real(-0.5, 1.5);
    g.val.general.x = (Pfloat)c[0], g.val.general.y = (Pfloat)c[1], g.val.general.z = (Pfloat)c[2];
    return g;
}

static int same_general_colour(const Pgcolr* a, const Pgcolr* b) {
    if (a->type != b->type) return 0;
    if (a->type == PINDIRECT) return a->val.ind == b->val.ind;
    return a->val.general.x == b->val.general.x && a->val.general.y == b->val.general.y &&
           a->val.general.z == b->val.general.z;
}

/* The RGB a workstation draws for a general colour: clamped, an index through the colour table
 * (inquired REALIZED, under the RGB colour model). */
static void drawn_rgb(const Pgcolr* g, double out[3]) {
    if (g->type == PINDIRECT) {
        Pint err = -1;
        Pcolr_rep rep;
        pinq_colr_rep(1, g->val.ind, PINQ_REALIZED, &err, &rep);
        CHECK(err == 0);
        out[0] = rep.rgb.red, out[1] = rep.rgb.green, out[2] = rep.rgb.blue;
        return;
    }
    {
        const double c[3] = {g->val.general.x, g->val.general.y, g->val.general.z};
        to_rgb(g->type, c, out);
        for (int k = 0; k < 3; ++k) out[k] = clamp01(out[k]);
    }
}

static int drawn_as(const Pgcolr* realized, const double rgb[3]) {
    const double got[3] = {realized->val.general.x, realized->val.general.y, realized->val.general.z};
    return realized->type == PMODEL_RGB && close3(got, rgb, 1e-4);
}

static void lights_and_cues(void) {
    Pint err = -1;
    for (int i = 0; i < 60; ++i) {
        Plight_src_bundle spot, got, real;
        Pdcue_bundle cue, cue_got, cue_real;
        double rgb[3];
        memset(&spot, 0, sizeof spot);
        spot.type = PLIGHT_SPOT;
        spot.rec.spot.colr = random_general_colour();
        spot.rec.spot.pos.x = (Pfloat)random_real(-1, 1);
        spot.rec.spot.dir.delta_z = -2;
        spot.rec.spot.exp = (Pfloat)random_real(-10, 200);
        spot.rec.spot.coef[0] = (Pfloat)random_real(-1, 1), spot.rec.spot.coef[1] = (Pfloat)random_real(0, 1);
        spot.rec.spot.angle = (Pfloat)random_real(0, 4);
        EXPECT_NO_ERROR(pset_light_src_rep(1, 2, &spot));
        pinq_light_src_rep(1, 2, PINQ_SET, &err, &got);
        CHECK(err == 0 && got.rec.spot.exp == spot.rec.spot.exp &&
              got.rec.spot.angle == spot.rec.spot.angle &&
              same_general_colour(&got.rec.spot.colr, &spot.rec.spot.colr) && /* as given */
              got.rec.spot.coef[0] == spot.rec.spot.coef[0] && got.rec.spot.dir.delta_z == -2);
        pinq_light_src_rep(1, 2, PINQ_REALIZED, &err, &real);
        CHECK(err == 0 && real.type == PLIGHT_SPOT);
        drawn_rgb(&spot.rec.spot.colr, rgb);
        CHECK(drawn_as(&real.rec.spot.colr, rgb)); /* the clamped RGB drawn */
        CHECK(real.rec.spot.exp == realized_f(spot.rec.spot.exp, 0, 128));
        CHECK(real.rec.spot.coef[0] == realized_f(spot.rec.spot.coef[0], 0, 1e30f));
        CHECK(real.rec.spot.coef[1] == spot.rec.spot.coef[1]);
        CHECK(near(real.rec.spot.angle, realized_f(spot.rec.spot.angle, 0, 3.14159265f)));
        CHECK(real.rec.spot.dir.delta_z == -1 && real.rec.spot.pos.x == spot.rec.spot.pos.x);

        memset(&cue, 0, sizeof cue);
        cue.mode = PALLOWED;
        cue.ref_planes[0] = (Pfloat)random_real(-0.2, 1.2),
        cue.ref_planes[1] = (Pfloat)random_real(-0.2, 1.2);
        cue.scaling[0] = (Pfloat)random_real(0, 1), cue.scaling[1] = (Pfloat)random_real(0, 1);
        cue.colr = random_general_colour();
        EXPECT_NO_ERROR(pset_dcue_rep(1, 1, &cue));
        pinq_dcue_rep(1, 1, PINQ_SET, &err, &cue_got);
        CHECK(err == 0 && cue_got.ref_planes[0] == cue.ref_planes[0] &&
              cue_got.ref_planes[1] == cue.ref_planes[1]);
        CHECK(same_general_colour(&cue_got.colr, &cue.colr));
        pinq_dcue_rep(1, 1, PINQ_REALIZED, &err, &cue_real);
        drawn_rgb(&cue.colr, rgb);
        CHECK(err == 0 && drawn_as(&cue_real.colr, rgb));
        {
            const Pfloat f = realized_f(cue.ref_planes[0], 0, 1), b = realized_f(cue.ref_planes[1], 0, 1);
            const int swapped = f < b;
            CHECK(cue_real.ref_planes[0] == (swapped ? b : f) && cue_real.ref_planes[1] == (swapped ? f : b));
            CHECK(cue_real.scaling[0] == cue.scaling[swapped ? 1 : 0] &&
                  cue_real.scaling[1] == cue.scaling[swapped ? 0 : 1]);
            CHECK(cue_real.ref_planes[0] >= cue_real.ref_planes[1]);
        }
    }
    /* An indexed light colour is drawn through the colour table as it is now. */
    {
        Plight_src_bundle ambient, real;
        Pcolr_rep rep;
        double rgb[3];
        memset(&ambient, 0, sizeof ambient);
        ambient.type = PLIGHT_AMBIENT;
        ambient.rec.ambient.colr.type = PINDIRECT;
        ambient.rec.ambient.colr.val.ind = 12;
        EXPECT_NO_ERROR(pset_light_src_rep(1, 3, &ambient));
        for (int i = 0; i < 5; ++i) {
            rgb[0] = random_real(0, 1), rgb[1] = random_real(0, 1), rgb[2] = random_real(0, 1);
            rep = representation(PMODEL_RGB, rgb);
            EXPECT_NO_ERROR(pset_colr_rep(1, 12, &rep));
            pinq_light_src_rep(1, 3, PINQ_REALIZED, &err, &real);
            CHECK(err == 0 && drawn_as(&real.rec.ambient.colr, rgb));
        }
        ambient.rec.ambient.colr.val.ind = -1;
        EXPECT_ERROR(pset_light_src_rep(1, 3, &ambient), 113, Pfn_set_light_src_rep);
        ambient.rec.ambient.colr.type = 7;
        EXPECT_ERROR(pset_light_src_rep(1, 3, &ambient), PE_ENUM_TYPE_INVAL, Pfn_set_light_src_rep);
        pinq_light_src_rep(1, 3, PINQ_SET, &err, &real);
        CHECK(err == 0 && real.rec.ambient.colr.type == PINDIRECT && real.rec.ambient.colr.val.ind == 12);
    }
}

/* The pixel at NPC (x, y) on the 1024 x 768 offscreen picture (NPC [0, 1]^2 on 768 x 768). */
static int pixel_is(const Picture* p, double x, double y, const double rgb[3]) {
    const int i = (int)(x * 768), j = (int)(p->height - y * 768);
    const unsigned char* c = p->rgb + ((size_t)j * (size_t)p->width + (size_t)i) * 3;
    int ok = 1;
    for (int k = 0; k < 3; ++k) ok = ok && abs((int)c[k] - (int)lround(255 * rgb[k])) <= 2;
    if (!ok)
        fprintf(stderr, "  pixel (%d, %d) is %d %d %d, expected %.1f %.1f %.1f\n", i, j, c[0], c[1], c[2],
                255 * rgb[0], 255 * rgb[1], 255 * rgb[2]);
    return ok;
}

static void square(double x0, double y0) {
    Ppoint3 p[4] = {{(Pfloat)x0, (Pfloat)y0, 0},
                    {(Pfloat)(x0 + 0.3), (Pfloat)y0, 0},
                    {(Pfloat)(x0 + 0.3), (Pfloat)(y0 + 0.3), 0},
                    {(Pfloat)x0, (Pfloat)(y0 + 0.3), 0}};
    Ppoint_list3 area = {4, p};
    pfill_area3(&area);
}

static void picture(const char* dir) {
    char png[512];
    snprintf(png, sizeof png, "%s/colour_models.png", dir);
    for (int round = 0; round < 3; ++round) {
        const double hsv[3] = {random_real(0, 0.999), random_real(0.2, 1), random_real(0.3, 1)};
        const double hls[3] = {random_real(0, 0.999), random_real(0.2, 0.8), random_real(0.2, 1)};
        double rgb_hsv[3], rgb_hls[3];
        Pgcolr g;
        Pcolr_rep rep = representation(PMODEL_HLS, hls);
        Picture p = {0};
        hsv_to_rgb(hsv[0], hsv[1], hsv[2], rgb_hsv);
        hls_to_rgb(hls[0], hls[1], hls[2], rgb_hls);
        remove(png);
        EXPECT_NO_ERROR(popen_ws(2, png, PWST_OFFSCREEN));
        EXPECT_NO_ERROR(pset_colr_model(2, PMODEL_HLS));
        EXPECT_NO_ERROR(pset_colr_rep(2, 9, &rep));
        pdel_struct(8);
        popen_struct(8);
        pset_int_style(PSTYLE_SOLID);
        g.type = PMODEL_HSV;
        g.val.general.x = (Pfloat)hsv[0], g.val.general.y = (Pfloat)hsv[1], g.val.general.z = (Pfloat)hsv[2];
        pset_int_colr(&g);
        square(0.1, 0.1);
        pset_int_colr_ind(9);
        square(0.6, 0.6);
        pclose_struct();
        EXPECT_NO_ERROR(ppost_struct(2, 8, 0.5f));
        EXPECT_NO_ERROR(pupd_ws(2, PFLAG_PERFORM));
        CHECK(read_png(png, &p));
        if (p.rgb) {
            CHECK(p.width == 1024 && p.height == 768);
            CHECK(pixel_is(&p, 0.25, 0.25, rgb_hsv)); /* direct HSV */
            CHECK(pixel_is(&p, 0.75, 0.75, rgb_hls)); /* table entry given in HLS */
            free(p.rgb);
        }
        EXPECT_NO_ERROR(pclose_ws(2));
    }
}

/* The components in `model` of an RGB colour: the inverse formulas of to_rgb. */
static void from_rgb(Pint model, const double rgb[3], double out[3]) {
    const double r = rgb[0], g = rgb[1], b = rgb[2];
    const double hi = fmax(r, fmax(g, b)), lo = fmin(r, fmin(g, b)), d = hi - lo;
    double h = 0;
    if (d > 0) {
        if (hi == r)
            h = fmod((g - b) / d + 6, 6) / 6;
        else if (hi == g)
            h = ((b - r) / d + 2) / 6;
        else
            h = ((r - g) / d + 4) / 6;
    }
    if (model == PMODEL_HSV) {
        out[0] = h, out[1] = hi > 0 ? d / hi : 0, out[2] = hi;
    } else if (model == PMODEL_HLS) {
        const double l = (hi + lo) / 2;
        out[0] = h, out[1] = l, out[2] = d > 0 ? d / (1 - fabs(2 * l - 1)) : 0;
    } else if (model == PMODEL_CIELUV) {
        const double x = 0.4124 * r + 0.3576 * g + 0.1805 * b, y = 0.2126 * r + 0.7152 * g + 0.0722 * b,
                     z = 0.0193 * r + 0.1192 * g + 0.9505 * b, den = x + 15 * y + 3 * z;
        out[0] = den > 0 ? 4 * x / den : 0.1978, out[1] = den > 0 ? 9 * y / den : 0.4683, out[2] = y;
    } else {
        for (int k = 0; k < 3; ++k) out[k] = rgb[k];
    }
}

/* A random RGB colour of 8-bit components, saturated enough that its hue is well defined. */
static void random_vivid(double rgb[3]) {
    do
        for (int k = 0; k < 3; ++k) rgb[k] = (double)(next_random() % 256u) / 255.0;
    while (fmax(rgb[0], fmax(rgb[1], rgb[2])) - fmin(rgb[0], fmin(rgb[1], rgb[2])) < 0.2);
}

/* round(clamp(v) (n - 1)), or -1 when v (n - 1) is too near a half for float and double to agree. */
static int ramp_slot(double v, int n) {
    const double x = (v < 0 ? 0 : v > 1 ? 1 : v) * (n - 1), f = x - floor(x);
    return fabs(f - 0.5) < 0.02 ? -1 : (int)lround(x);
}

/* Colour mapping on the offscreen type: a square of a random RGB colour drawn through a PSEUDO
 * entry (weights and ramp in a random model) and one through a PSEUDO_N entry (lists of a random
 * model) shows the mapped colour; the inquiry answers the model given. */
static void mapping_picture(const char* dir, Pstore store) {
    char png[512];
    snprintf(png, sizeof png, "%s/colour_mapping.png", dir);
    for (int round = 0; round < 8; ++round) {
        const Pint model = 1 + (Pint)(next_random() % 4);
        double rgb[3], c[3], pseudo_rgb[3], pseudo_n_rgb[3];
        Pfloat weights[3], values[3][5];
        Pcolr_rep ramp[6];
        Pfloat_list lists[3];
        Pcolr_map_data data, *got = NULL;
        Pint n = 2 + (Pint)(next_random() % 5), slot = -1, sum = 0, err = -1, method = 0;
        Picture p = {0};
        for (;;) { /* a colour away from the rounding boundaries of both entries */
            double v = 0;
            random_vivid(rgb);
            from_rgb(model, rgb, c);
            for (int k = 0; k < 3; ++k) weights[k] = (Pfloat)random_real(0, 0.6), v += weights[k] * c[k];
            slot = ramp_slot(v, n);
            sum = 0;
            for (int k = 0; k < 3; ++k) {
                const int m = 2 + (int)(next_random() % 4), at = ramp_slot(c[k], m);
                for (int i = 0; i < m; ++i) values[k][i] = (Pfloat)(next_random() % 3);
                lists[k].num_floats = m, lists[k].floats = values[k];
                if (at < 0)
                    slot = -1;
                else
                    sum += (Pint)values[k][at];
            }
            if (slot >= 0) break;
        }
        for (Pint i = 0; i < n; ++i) {
            double r[3];
            random_colour(model, r);
            ramp[i] = representation(model, r);
            if (i == slot) {
                to_rgb(model, r, pseudo_rgb);
                for (int k = 0; k < 3; ++k) pseudo_rgb[k] = clamp01(pseudo_rgb[k]);
            }
        }
        remove(png);
        EXPECT_NO_ERROR(popen_ws(2, png, PWST_OFFSCREEN));
        data.meth_r2.colr_model = model;
        data.meth_r2.weights.num_floats = 3, data.meth_r2.weights.floats = weights;
        data.meth_r2.colrs.num_colr_reps = n, data.meth_r2.colrs.colr_reps = ramp;
        EXPECT_NO_ERROR(pset_colr_map_rep(2, 1, PCOLR_MAP_PSEUDO, &data));
        pinq_colr_map_rep(2, 1, PINQ_SET, store, &err, &method, &got);
        CHECK(err == 0 && method == PCOLR_MAP_PSEUDO && got && got->meth_r2.colr_model == model &&
              got->meth_r2.colrs.num_colr_reps == n);
        if (err == 0 && got) {
            double given[3], back[3];
            components(model, &ramp[n - 1], given);
            components(model, &got->meth_r2.colrs.colr_reps[n - 1], back);
            CHECK(close3(given, back, 1e-6)); /* the ramp as given, in its model */
        }
        data.meth_r3.colr_model = model;
        data.meth_r3.colr_lists.num_lists = 3, data.meth_r3.colr_lists.lists = lists;
        EXPECT_NO_ERROR(pset_colr_map_rep(2, 2, PCOLR_MAP_PSEUDO_N, &data));
        pinq_colr_map_rep(2, 2, PINQ_REALIZED, store, &err, &method, &got);
        CHECK(err == 0 && method == PCOLR_MAP_PSEUDO_N && got && got->meth_r3.colr_model == model);
        {
            Pcolr_rep entry;
            pinq_colr_rep(2, sum, PINQ_REALIZED, &err, &entry);
            CHECK(err == 0);
            pseudo_n_rgb[0] = entry.rgb.red, pseudo_n_rgb[1] = entry.rgb.green,
            pseudo_n_rgb[2] = entry.rgb.blue;
        }
        pdel_struct(8);
        popen_struct(8);
        pset_int_style(PSTYLE_SOLID);
        {
            Pgcolr g;
            g.type = PMODEL_RGB;
            g.val.general.x = (Pfloat)rgb[0], g.val.general.y = (Pfloat)rgb[1], g.val.general.z = (Pfloat)rgb[2];
            pset_int_colr(&g);
        }
        square(0.1, 0.1); /* entry 0: TRUE */
        pset_colr_map_ind(1);
        square(0.6, 0.1);
        pset_colr_map_ind(2);
        square(0.1, 0.6);
        pclose_struct();
        EXPECT_NO_ERROR(ppost_struct(2, 8, 0.5f));
        EXPECT_NO_ERROR(pupd_ws(2, PFLAG_PERFORM));
        CHECK(read_png(png, &p));
        if (p.rgb) {
            CHECK(pixel_is(&p, 0.25, 0.25, rgb));
            CHECK(pixel_is(&p, 0.75, 0.25, pseudo_rgb));
            CHECK(pixel_is(&p, 0.25, 0.75, pseudo_n_rgb));
            free(p.rgb);
        }
        EXPECT_NO_ERROR(pclose_ws(2));
    }
}

/* The pixel at NPC (x, y) of a picture read back is `rgb`, within 2.5 / 255. */
static int picture_shows(const Picture* p, double x, double y, const double rgb[3], Pint model,
                         const char* what) {
    const int i = (int)(x * p->side), j = (int)(p->height - y * p->side);
    const unsigned char* c = p->rgb + ((size_t)j * (size_t)p->width + (size_t)i) * 3;
    int ok = 1;
    for (int k = 0; k < 3; ++k) ok = ok && fabs(c[k] - 255 * rgb[k]) <= 2.5;
    if (!ok)
        fprintf(stderr,
                "  %s, %s in model %d: pixel at NPC (%.2f, %.2f) is %d %d %d, expected %.1f %.1f %.1f\n",
                p->name, what, (int)model, x, y, c[0], c[1], c[2], 255 * rgb[0], 255 * rgb[1], 255 * rgb[2]);
    return ok;
}

/* Direct colours in every model on the offscreen type and the PDF type alike: per model a random
 * RGB colour given in that model as an interior colour, a polyline colour and the vertex colours
 * of a fill area set with data draws as that RGB colour; the elements answer the components and
 * model as given. */
static void every_model_drawn(const char* dir, Pstore store) {
    const PictureFiles files = picture_files(dir, "colour_models_targets");
    for (int round = 0; round < 3; ++round) {
        double rgb[4][3], given[4][3];
        Picture p[2];
        pdel_struct(1);
        popen_struct(1);
        pset_int_style(PSTYLE_SOLID);
        pset_linewidth(8);
        for (Pint m = PMODEL_RGB; m <= PMODEL_HLS; ++m) {
            const double x = 0.05 + 0.24 * (m - 1);
            double c[3];
            Pint err = -1;
            Pelem_data* data = NULL;
            Pgcolr g;
            Pptco3 corners[4];
            Pfacet_vdata_list3 vdata;
            Pfacet_data3 fdata;
            random_vivid(rgb[m - 1]);
            from_rgb(m, rgb[m - 1], c);
            g.type = m;
            g.val.general.x = (Pfloat)c[0], g.val.general.y = (Pfloat)c[1], g.val.general.z = (Pfloat)c[2];
            /* What is drawn: the components as stored (single precision) converted. */
            given[m - 1][0] = g.val.general.x, given[m - 1][1] = g.val.general.y,
                      given[m - 1][2] = g.val.general.z;
            to_rgb(m, given[m - 1], rgb[m - 1]);
            for (int k = 0; k < 3; ++k) rgb[m - 1][k] = clamp01(rgb[m - 1][k]);
            pset_int_colr(&g);
            square(x, 0.05);
            pset_line_colr(&g);
            pinq_cur_elem_content(store, &err, &data);
            CHECK(err == 0 && data && data->colr.type == m && data->colr.val.general.x == g.val.general.x &&
                  data->colr.val.general.y == g.val.general.y && data->colr.val.general.z == g.val.general.z);
            {
                Ppoint3 ends[2] = {{(Pfloat)x, 0.5f, 0}, {(Pfloat)(x + 0.2), 0.5f, 0}};
                Ppoint_list3 line = {2, ends};
                ppolyline3(&line);
            }
            for (int k = 0; k < 4; ++k) {
                corners[k].point.x = (Pfloat)(x + (k == 1 || k == 2 ? 0.2 : 0));
                corners[k].point.y = (Pfloat)(k >= 2 ? 0.85 : 0.6), corners[k].point.z = 0;
                corners[k].colr.direct.rgb.red = g.val.general.x, corners[k].colr.direct.rgb.green = g.val.general.y,
                corners[k].colr.direct.rgb.blue = g.val.general.z;
            }
            vdata.num_vertices = 4, vdata.vertex_data.ptcolrs = corners;
            memset(&fdata, 0, sizeof fdata);
            pfill_area_set3_data(PFACET_NONE, PEDGE_NONE, PVERT_COORD_COLOUR, m, &fdata, 1, NULL, &vdata);
        }
        pclose_struct();
        CHECK(draw_offscreen_and_pdf(&files, p));
        for (int i = 0; i < 2; ++i) {
            for (Pint m = PMODEL_RGB; m <= PMODEL_HLS && p[i].rgb; ++m) {
                const double x = 0.15 + 0.24 * (m - 1);
                CHECK(picture_shows(&p[i], x, 0.2, rgb[m - 1], m, "interior colour"));
                CHECK(picture_shows(&p[i], x, 0.5, rgb[m - 1], m, "polyline colour"));
                CHECK(picture_shows(&p[i], x, 0.72, rgb[m - 1], m, "vertex colours"));
            }
            free(p[i].rgb);
        }
    }
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512], svg[512];
    seed_random(0x2545f4914f6cdd1dULL);
    Pint err = -1;
    Pstore store;
    snprintf(errors, sizeof errors, "%s/colour_models_errors.txt", dir);
    snprintf(svg, sizeof svg, "%s/colour_models.svg", dir);
    open_with_handler(errors);
    pcreate_store(&err, &store);
    EXPECT_NO_ERROR(popen_ws(1, svg, PWST_SVG));
    colour_tables();
    element_colours(store);
    lights_and_cues();
    EXPECT_NO_ERROR(pclose_ws(1));
    picture(dir);
    mapping_picture(dir, store);
    every_model_drawn(dir, store);
    pdel_store(store);
    pclose_phigs();
    return finish("test_colour_models");
}
