/* Colour models: random colours set into the colour table under each workstation colour model
 * (RGB, CIELUV, HSV, HLS) and inquired SET (as given) and REALIZED (the RGB drawn, clamped, in
 * the current model), converted here by the textbook formulas (HSV by hue sector; HLS through
 * HSV; CIELUV through CIE XYZ and the BT.709 matrix, reference white D65); direct general colours
 * in elements keep their model; light source and depth cue REALIZED values differ from SET
 * exactly where the clamping rules say; and an HSV and an HLS colour paint the right RGB pixels
 * on the offscreen type (lavapipe). argv[1]: a directory for the files. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include <png.h>

static double random_real(double lo, double hi) {
    return lo + (hi - lo) * (next_random() % 100001u) / 100000.0;
}

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
        g.val.direct.x = (Pfloat)random_real(0, 1), g.val.direct.y = (Pfloat)random_real(0, 1),
        g.val.direct.z = (Pfloat)random_real(0, 1);
        EXPECT_NO_ERROR(pset_int_colr(&g));
        pinq_cur_elem_content(store, &err, &data);
        CHECK(err == 0 && data && data->colr.type == m && data->colr.val.direct.x == g.val.direct.x &&
              data->colr.val.direct.z == g.val.direct.z);
    }
    {
        Pgcolr g;
        g.type = 5;
        g.val.direct.x = g.val.direct.y = g.val.direct.z = 0.5f;
        EXPECT_ERROR(pset_int_colr(&g), PE_ENUM_TYPE_INVAL, Pfn_set_int_colr);
    }
    pclose_struct();
}

static Pfloat realized_f(Pfloat v, Pfloat lo, Pfloat hi) {
    return v < lo ? lo : v > hi ? hi : v;
}

static void lights_and_cues(void) {
    Pint err = -1;
    for (int i = 0; i < 40; ++i) {
        Plight_src_bundle spot, got, real;
        Pdcue_bundle cue, cue_got, cue_real;
        memset(&spot, 0, sizeof spot);
        spot.type = PLIGHT_SPOT;
        spot.rec.spot.colr.type = PMODEL_RGB;
        spot.rec.spot.colr.val.direct.x = (Pfloat)random_real(-0.5, 1.5);
        spot.rec.spot.colr.val.direct.y = (Pfloat)random_real(0, 1);
        spot.rec.spot.colr.val.direct.z = (Pfloat)random_real(-0.5, 1.5);
        spot.rec.spot.pos.x = (Pfloat)random_real(-1, 1);
        spot.rec.spot.dir.delta_z = -2;
        spot.rec.spot.exp = (Pfloat)random_real(-10, 200);
        spot.rec.spot.coef[0] = (Pfloat)random_real(-1, 1), spot.rec.spot.coef[1] = (Pfloat)random_real(0, 1);
        spot.rec.spot.angle = (Pfloat)random_real(0, 4);
        EXPECT_NO_ERROR(pset_light_src_rep(1, 2, &spot));
        pinq_light_src_rep(1, 2, PINQ_SET, &err, &got);
        CHECK(err == 0 && got.rec.spot.exp == spot.rec.spot.exp &&
              got.rec.spot.angle == spot.rec.spot.angle &&
              got.rec.spot.colr.val.direct.x == spot.rec.spot.colr.val.direct.x &&
              got.rec.spot.coef[0] == spot.rec.spot.coef[0] && got.rec.spot.dir.delta_z == -2);
        pinq_light_src_rep(1, 2, PINQ_REALIZED, &err, &real);
        CHECK(err == 0 && real.type == PLIGHT_SPOT);
        CHECK(real.rec.spot.colr.val.direct.x == realized_f(spot.rec.spot.colr.val.direct.x, 0, 1));
        CHECK(real.rec.spot.colr.val.direct.y == spot.rec.spot.colr.val.direct.y);
        CHECK(real.rec.spot.colr.val.direct.z == realized_f(spot.rec.spot.colr.val.direct.z, 0, 1));
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
        cue.colr.type = PMODEL_HSV; /* held as its RGB */
        cue.colr.val.direct.x = 0, cue.colr.val.direct.y = 1, cue.colr.val.direct.z = 0.5f;
        EXPECT_NO_ERROR(pset_dcue_rep(1, 1, &cue));
        pinq_dcue_rep(1, 1, PINQ_SET, &err, &cue_got);
        CHECK(err == 0 && cue_got.ref_planes[0] == cue.ref_planes[0] &&
              cue_got.ref_planes[1] == cue.ref_planes[1]);
        CHECK(cue_got.colr.type == PMODEL_RGB && near(cue_got.colr.val.direct.x, 0.5) &&
              cue_got.colr.val.direct.y == 0);
        pinq_dcue_rep(1, 1, PINQ_REALIZED, &err, &cue_real);
        {
            const Pfloat f = realized_f(cue.ref_planes[0], 0, 1), b = realized_f(cue.ref_planes[1], 0, 1);
            const int swapped = f < b;
            CHECK(err == 0 && cue_real.ref_planes[0] == (swapped ? b : f) &&
                  cue_real.ref_planes[1] == (swapped ? f : b));
            CHECK(cue_real.scaling[0] == cue.scaling[swapped ? 1 : 0] &&
                  cue_real.scaling[1] == cue.scaling[swapped ? 0 : 1]);
            CHECK(cue_real.ref_planes[0] >= cue_real.ref_planes[1]);
        }
    }
}

typedef struct {
    int width, height;
    unsigned char* rgb;
} Picture;

static int read_png(const char* path, Picture* out) {
    png_image image;
    memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path)) return 0;
    image.format = PNG_FORMAT_RGB;
    out->width = (int)image.width, out->height = (int)image.height;
    out->rgb = malloc(PNG_IMAGE_SIZE(image));
    return out->rgb && png_image_finish_read(&image, NULL, out->rgb, 0, NULL);
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
        Picture p = {0, 0, NULL};
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
        g.val.direct.x = (Pfloat)hsv[0], g.val.direct.y = (Pfloat)hsv[1], g.val.direct.z = (Pfloat)hsv[2];
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
    pdel_store(store);
    pclose_phigs();
    return finish("test_colour_models");
}
