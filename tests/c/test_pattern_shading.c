/* PATTERN interiors lit and shaded, drawn on the offscreen type (lavapipe, validation layer on)
 * and the PDF type (rasterised by pdftoppm at 144 dpi): a square filled with a 2 x 2 pattern of
 * random colours, its vertex normals one random unit vector towards the viewer, lit by a random
 * ambient and a random directional light with random ambient, diffuse and specular coefficients,
 * under every interior shading method, shows in each cell the cell's colour lit by the PHIGS PLUS
 * reflectance equation (the colour lit is the pattern's, not the vertex colour or the interior
 * colour; flat shading with the plane's normal, the others with the vertex normals). argv[1]: a directory for
 * the files. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include "picture.h"

static Pgcolr direct(const double c[3]) {
    Pgcolr g;
    g.type = PMODEL_RGB;
    g.val.general.x = (Pfloat)c[0], g.val.general.y = (Pfloat)c[1], g.val.general.z = (Pfloat)c[2];
    return g;
}

static double dot(const double a[3], const double b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void random_unit(double v[3], double min_z) {
    do {
        for (int k = 0; k < 3; ++k) v[k] = random_real(-1, 1);
    } while (dot(v, v) < 0.1 || dot(v, v) > 1 || v[2] / sqrt(dot(v, v)) < min_z);
    const double n = sqrt(dot(v, v));
    for (int k = 0; k < 3; ++k) v[k] /= n;
}

/* One scene's random values. */
typedef struct {
    double cells[4][3], ambient[3], diffuse[3], normal[3], toward_light[3], ka, kd, ks, exponent, sc[3];
    Pint shading;
} Scene;

/* The colour a cell shows: the reflectance equation (ISO 9592-4) with the eye on +z. */
static void expected_colour(const Scene* s, const double cell[3], double out[3]) {
    /* PSD_NONE (flat) lights with the facet's plane normal, the others with the vertex normals. */
    static const double plane[3] = {0, 0, 1}, eye[3] = {0, 0, 1};
    const double* n = s->shading == PSD_NONE ? plane : s->normal;
    const double nl = dot(n, s->toward_light);
    double r[3];
    for (int k = 0; k < 3; ++k) r[k] = 2 * nl * n[k] - s->toward_light[k];
    const double rv = dot(r, eye) > 0 ? dot(r, eye) : 0;
    const double spec = nl > 0 ? s->ks * pow(rv, s->exponent) : 0;
    for (int k = 0; k < 3; ++k) {
        const double v = cell[k] * (s->ka * s->ambient[k] + s->kd * s->diffuse[k] * (nl > 0 ? nl : 0)) +
                         spec * s->diffuse[k] * s->sc[k];
        out[k] = v < 0 ? 0 : v > 1 ? 1 : v;
    }
}

static void build(const Scene* s) {
    Pptnorm3 corners[4];
    Pfacet_vdata_list3 vdata;
    Pfacet_data3 fdata;
    Pfloat_size size = {0.2f, 0.2f};
    Ppoint reference = {0.1f, 0.1f};
    Pint on[2] = {1, 2};
    Pint_list activate = {2, on}, none = {0, NULL};
    Prefl_props props;
    const double square[4][2] = {{0.1, 0.1}, {0.9, 0.1}, {0.9, 0.9}, {0.1, 0.9}};
    for (int i = 0; i < 4; ++i) {
        corners[i].point.x = (Pfloat)square[i][0], corners[i].point.y = (Pfloat)square[i][1];
        corners[i].point.z = 0;
        corners[i].norm.delta_x = (Pfloat)s->normal[0], corners[i].norm.delta_y = (Pfloat)s->normal[1];
        corners[i].norm.delta_z = (Pfloat)s->normal[2];
    }
    vdata.num_vertices = 4, vdata.vertex_data.ptnorms = corners;
    memset(&fdata, 0, sizeof fdata);
    props.ambient_coef = (Pfloat)s->ka, props.diffuse_coef = (Pfloat)s->kd,
    props.specular_coef = (Pfloat)s->ks;
    props.specular_colr = direct(s->sc), props.specular_exp = (Pfloat)s->exponent, props.transpar_coef = 0;
    pdel_struct(1);
    popen_struct(1);
    pset_int_style(PSTYLE_PAT);
    pset_int_style_ind(5);
    pset_pat_size(&size);
    pset_pat_ref_point(&reference);
    pset_int_shad_meth(s->shading);
    pset_refl_eqn(PREFL_AMB_DIFF_SPEC);
    pset_refl_props(&props);
    pset_light_src_state(&activate, &none);
    pfill_area_set3_data(PFACET_NONE, PEDGE_NONE, PVERT_COORD_NORMAL, PMODEL_RGB, &fdata, 1, NULL, &vdata);
    pclose_struct();
}

/* Opens workstation `ws` of `type` on `file`, sets the scene's pattern and lights, draws, closes. */
static void draw_on(const Scene* s, Pint ws, const char* file, Pint type) {
    Pint cells[4] = {20, 21, 22, 23};
    Ppat_rep pattern = {{2, 2}, cells};
    Plight_src_bundle ambient, directional;
    ambient.type = PLIGHT_AMBIENT, ambient.rec.ambient.colr = direct(s->ambient);
    directional.type = PLIGHT_DIRECTIONAL, directional.rec.directional.colr = direct(s->diffuse);
    directional.rec.directional.dir.delta_x = (Pfloat)-s->toward_light[0];
    directional.rec.directional.dir.delta_y = (Pfloat)-s->toward_light[1];
    directional.rec.directional.dir.delta_z = (Pfloat)-s->toward_light[2];
    EXPECT_NO_ERROR(popen_ws(ws, file, type));
    for (int i = 0; i < 4; ++i) {
        Pcolr_rep rep;
        rep.rgb.red = (Pfloat)s->cells[i][0], rep.rgb.green = (Pfloat)s->cells[i][1],
        rep.rgb.blue = (Pfloat)s->cells[i][2];
        EXPECT_NO_ERROR(pset_colr_rep(ws, 20 + i, &rep));
    }
    EXPECT_NO_ERROR(pset_pat_rep(ws, 5, &pattern));
    EXPECT_NO_ERROR(pset_light_src_rep(ws, 1, &ambient));
    EXPECT_NO_ERROR(pset_light_src_rep(ws, 2, &directional));
    EXPECT_NO_ERROR(ppost_struct(ws, 1, 0.5f));
    EXPECT_NO_ERROR(pupd_ws(ws, PFLAG_PERFORM));
    EXPECT_NO_ERROR(pclose_ws(ws));
}

static int shows(const Picture* p, double x, double y, const double rgb[3], const Scene* s) {
    const unsigned char* c = picture_pixel(p, x, y);
    int ok = 1;
    for (int k = 0; k < 3; ++k) ok = ok && fabs(c[k] - 255 * rgb[k]) <= 3.5;
    if (!ok)
        fprintf(stderr, "  %s, shading %d: pixel at NPC (%.2f, %.2f) is %d %d %d, expected %.1f %.1f %.1f\n",
                p->name, (int)s->shading, x, y, c[0], c[1], c[2], 255 * rgb[0], 255 * rgb[1], 255 * rgb[2]);
    return ok;
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512], command[2048], ppm[600];
    const PictureFiles files = picture_files(dir, "pattern_shading");
    seed_random(0x2545f4914f6cdd1dULL);
    snprintf(errors, sizeof errors, "%s/pattern_shading_errors.txt", dir);
    open_with_handler(errors);
    for (int round = 0; round < 12; ++round) {
        Scene s;
        Picture p[2];
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 3; ++k) s.cells[i][k] = (double)(next_random() % 256u) / 255.0;
        for (int k = 0; k < 3; ++k)
            s.ambient[k] = random_real(0.2, 1), s.diffuse[k] = random_real(0.2, 1),
            s.sc[k] = random_real(0, 1);
        random_unit(s.normal, 0.5);
        random_unit(s.toward_light, 0.2);
        s.ka = random_real(0.1, 0.6), s.kd = random_real(0.2, 0.8), s.ks = random_real(0, 0.5);
        s.exponent = random_real(1, 20);
        s.shading = PSD_NONE + round % 4;
        build(&s);
        remove(files.png), remove(files.pdf);
        draw_on(&s, 1, files.png, PWST_OFFSCREEN);
        draw_on(&s, 2, files.pdf, PWST_PDF);
        p[0].rgb = p[1].rgb = NULL;
        p[0].side = 768, p[0].name = "offscreen";
        p[1].side = 595.2756 * 2, p[1].name = "PDF";
        snprintf(command, sizeof command, "pdftoppm -r 144 -singlefile '%s' '%s'", files.pdf, files.ppm_root);
        snprintf(ppm, sizeof ppm, "%s.ppm", files.ppm_root);
        CHECK(read_png(files.png, &p[0]));
        CHECK(system(command) == 0 && read_ppm(ppm, &p[1]));
        for (int i = 0; i < 2; ++i) {
            for (int row = 0; row < 8 && p[i].rgb; ++row)
                for (int column = 0; column < 8; ++column) {
                    double want[3];
                    expected_colour(&s, s.cells[(row % 2) * 2 + column % 2], want);
                    CHECK(shows(&p[i], 0.15 + 0.1 * column, 0.15 + 0.1 * row, want, &s));
                }
            free(p[i].rgb);
        }
    }
    pclose_phigs();
    return finish("test_pattern_shading");
}
