/* The transformation utilities: matrices act on column vectors with the translation in the
 * last column; BUILD scales, rotates about x, y, z around the fixed point, then shifts; COMPOSE
 * TRANSFORMATION MATRIX is matrix x built; the view matrices, parallel and perspective. */
#include "check.h"

static int is_point(const Ppoint3* p, double x, double y, double z) {
    return near(p->x, x) && near(p->y, y) && near(p->z, z);
}

static void basics(void) {
    Pint err = -1;
    Pmatrix3 t, s, r, c;
    Pmatrix t2, r2;
    Ppoint3 out;
    Ppoint out2;
    const double half_pi = 1.5707963267948966;
    ptranslate3(&(Pvec3){1, 2, 3}, &err, t);
    CHECK(err == 0 && t[0][3] == 1 && t[2][3] == 3 && t[3][3] == 1);
    pscale3(&(Pvec3){2, 3, 4}, &err, s);
    CHECK(err == 0 && s[1][1] == 3);
    protate_z((Pfloat)half_pi, &err, r);
    ptran_point3(&(Ppoint3){1, 0, 0}, r, &err, &out);
    CHECK(err == 0 && is_point(&out, 0, 1, 0));
    protate_x((Pfloat)half_pi, &err, r);
    ptran_point3(&(Ppoint3){0, 1, 0}, r, &err, &out);
    CHECK(is_point(&out, 0, 0, 1));
    protate_y((Pfloat)half_pi, &err, r);
    ptran_point3(&(Ppoint3){0, 0, 1}, r, &err, &out);
    CHECK(is_point(&out, 1, 0, 0));
    pcompose_matrix3(t, s, &err, c); /* t x s: scale first */
    ptran_point3(&(Ppoint3){1, 1, 1}, c, &err, &out);
    CHECK(err == 0 && is_point(&out, 3, 5, 7));
    ptranslate(&(Pvec){5, 6}, &err, t2);
    protate((Pfloat)half_pi, &err, r2);
    {
        Pmatrix both;
        pcompose_matrix(t2, r2, &err, both);
        ptran_point(&(Ppoint){1, 0}, both, &err, &out2);
        CHECK(err == 0 && near(out2.x, 5) && near(out2.y, 7));
    }
    {
        Pmatrix3 zero = {{0}};
        ptran_point3(&(Ppoint3){1, 1, 1}, zero, &err, &out); /* w = 0 */
        CHECK(err == 908);
    }
    ptranslate3(NULL, &err, t);
    CHECK(err == -204);
}

static void build_and_compose(void) {
    Pint err = -1;
    Pmatrix3 b, c, id = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    Pmatrix b2;
    Ppoint3 out;
    Ppoint out2;
    const float half_pi = 1.5707964f;
    /* about the fixed point (1, 1, 0): scale 2, rotate z by 90 degrees, shift (0, 0, 5) */
    pbuild_tran_matrix3(&(Ppoint3){1, 1, 0}, &(Pvec3){0, 0, 5}, 0, 0, half_pi, &(Pvec3){2, 2, 2}, &err, b);
    ptran_point3(&(Ppoint3){2, 1, 0}, b, &err, &out);
    CHECK(err == 0 && is_point(&out, 1, 3, 5));
    pcompose_tran_matrix3(id, &(Ppoint3){1, 1, 0}, &(Pvec3){0, 0, 5}, 0, 0, half_pi, &(Pvec3){2, 2, 2}, &err,
                          c);
    CHECK(err == 0 && near(c[0][3], b[0][3]) && near(c[1][0], b[1][0]));
    {
        Pmatrix3 t, composed;
        ptranslate3(&(Pvec3){10, 0, 0}, &err, t);
        pcompose_tran_matrix3(t, &(Ppoint3){1, 1, 0}, &(Pvec3){0, 0, 5}, 0, 0, half_pi, &(Pvec3){2, 2, 2},
                              &err, composed);
        ptran_point3(&(Ppoint3){2, 1, 0}, composed, &err, &out); /* t first, then built */
        CHECK(is_point(&out, 1, 23, 5));
    }
    pbuild_tran_matrix(&(Ppoint){1, 1}, &(Pvec){1, 0}, half_pi, &(Pvec){1, 1}, &err, b2);
    ptran_point(&(Ppoint){2, 1}, b2, &err, &out2);
    CHECK(err == 0 && near(out2.x, 2) && near(out2.y, 2));
}

static void views(void) {
    Pint err = -1;
    Pmatrix3 ori, map;
    Pmatrix ori2, map2;
    Ppoint3 out;
    Ppoint out2;
    Pview_map3 m;
    peval_view_ori_matrix3(&(Ppoint3){1, 2, 3}, &(Pvec3){0, 0, 1}, &(Pvec3){0, 1, 0}, &err, ori);
    ptran_point3(&(Ppoint3){2, 2, 3}, ori, &err, &out);
    CHECK(err == 0 && is_point(&out, 1, 0, 0));
    peval_view_ori_matrix3(&(Ppoint3){0, 0, 0}, &(Pvec3){0, 0, 0}, &(Pvec3){0, 1, 0}, &err, ori);
    CHECK(err == 159);
    peval_view_ori_matrix3(&(Ppoint3){0, 0, 0}, &(Pvec3){0, 1, 0}, &(Pvec3){0, 2, 0}, &err, ori);
    CHECK(err == 161);
    peval_view_ori_matrix(&(Ppoint){1, 1}, &(Pvec){-1, 0}, &err, ori2); /* up is -x: x goes to v */
    ptran_point(&(Ppoint){1, 2}, ori2, &err, &out2);
    CHECK(err == 0 && near(out2.x, 1) && near(out2.y, 0));

    memset(&m, 0, sizeof m);
    m.win = (Plimit){-1, 1, -1, 1};
    m.proj_vp = (Plimit3){0, 1, 0, 1, 0, 1};
    m.proj_type = PTYPE_PARAL;
    m.proj_ref_point = (Ppoint3){0, 0, 5};
    m.view_plane = 0, m.back_plane = -1, m.front_plane = 1;
    peval_view_map_matrix3(&m, &err, map);
    ptran_point3(&(Ppoint3){1, 1, 1}, map, &err, &out);
    CHECK(err == 0 && is_point(&out, 1, 1, 1));
    m.proj_type = PTYPE_PERSPECT;
    peval_view_map_matrix3(&m, &err, map);
    ptran_point3(&(Ppoint3){0, 0, 0}, map, &err, &out);
    CHECK(err == 0 && near(out.x, 0.5) && near(out.y, 0.5));
    ptran_point3(&(Ppoint3){1, 1, 0}, map, &err, &out); /* on the view plane: the window corner */
    CHECK(near(out.x, 1) && near(out.y, 1));
    m.front_plane = -1;
    peval_view_map_matrix3(&m, &err, map);
    CHECK(err == 158);
    m.proj_type = (Pproj_type)5;
    peval_view_map_matrix3(&m, &err, map);
    CHECK(err == PE_ENUM_TYPE_INVAL);
    peval_view_map_matrix(&(Pview_map){{0, 2, 0, 2}, {0, 0.5f, 0, 0.5f}}, &err, map2);
    ptran_point(&(Ppoint){2, 1}, map2, &err, &out2);
    CHECK(err == 0 && near(out2.x, 0.5) && near(out2.y, 0.25));
}

/* A NaN or infinite argument, or a product that overflows, is the arithmetic error 908, and the
 * result matrix keeps what it held. */
static void non_finite(void) {
    const Pfloat bad[] = {NAN, INFINITY, -INFINITY};
    for (int k = 0; k < 3; ++k) {
        const Pfloat x = bad[k];
        Pint err = -1;
        Pmatrix3 m3, kept, huge = {{1e30f, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
        Pmatrix m2;
        memset(m3, 0, sizeof m3);
        memcpy(kept, m3, sizeof m3);
        ptranslate3(&(Pvec3){x, 0, 0}, &err, m3);
        CHECK(err == 908);
        pscale3(&(Pvec3){1, x, 1}, &err, m3);
        CHECK(err == 908);
        pscale(&(Pvec){x, 1}, &err, m2);
        CHECK(err == 908);
        protate_x(x, &err, m3);
        CHECK(err == 908);
        protate(x, &err, m2);
        CHECK(err == 908);
        pbuild_tran_matrix3(&(Ppoint3){0, 0, 0}, &(Pvec3){0, 0, 0}, 0, x, 0, &(Pvec3){1, 1, 1}, &err, m3);
        CHECK(err == 908);
        pbuild_tran_matrix(&(Ppoint){x, 0}, &(Pvec){0, 0}, 0, &(Pvec){1, 1}, &err, m2);
        CHECK(err == 908);
        {
            Pmatrix3 with_bad = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
            with_bad[1][2] = x;
            pcompose_matrix3(with_bad, huge, &err, m3);
            CHECK(err == 908);
        }
        CHECK(memcmp(m3, kept, sizeof m3) == 0);
        pcompose_matrix3(huge, huge, &err, m3); /* 1e60 overflows a Pfloat */
        CHECK(err == 908);
    }
}

int main(void) {
    Pint err = -1;
    Pmatrix3 m;
    ptranslate3(&(Pvec3){1, 2, 3}, &err, m);
    CHECK(err == 2); /* PHIGS closed */
    open_with_handler(NULL);
    error_count = 0;
    basics();
    build_and_compose();
    views();
    non_finite();
    CHECK(error_count == 0); /* the utilities answer in err_ind only */
    pclose_phigs();
    return finish("test_utilities");
}
