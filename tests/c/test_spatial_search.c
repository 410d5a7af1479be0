/* INCREMENTAL SPATIAL SEARCH (3) through the C binding: a network with a transform, an
 * executed structure and model clipping; where the search starts, the ceiling, the filters,
 * the simple list of the found path and the errors in *err_ind (never the handler). */
#include "check.h"

static Ppoint3 pts[2];

static void line(Pfloat x0, Pfloat x1) {
    Ppoint_list3 l = {2, pts};
    pts[0].x = x0, pts[0].y = 0, pts[0].z = 0;
    pts[1].x = x1, pts[1].y = 0, pts[1].z = 0;
    ppolyline3(&l);
}

/* 1: a line x 0..1, a shift up by 5, EXECUTE 2, a marker at x 10 (shifted to y 5).
 * 2: names {1}, a line x 0..1, clipping to x >= 0.5, a short line x 0..0.2. */
static void network(void) {
    Pmatrix3 shift = {{1, 0, 0, 0}, {0, 1, 0, 5}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    Pint one = 1;
    Pint_list names = {1, &one};
    Phalf_space3 half = {{0.5f, 0, 0}, {1, 0, 0}};
    Phalf_space_list3 volume = {1, &half};
    Ppoint3 marker = {10, 0, 0};
    Ppoint_list3 markers = {1, &marker};
    popen_struct(2);
    padd_names_set(&names);
    line(0, 1);
    pset_model_clip_vol3(PMC_REPLACE, &volume);
    pset_model_clip_ind(PIND_CLIP);
    line(0, 0.2f);
    pclose_struct();
    popen_struct(1);
    line(0, 1);
    pset_local_tran3(shift, PTYPE_REPLACE);
    pexec_struct(2);
    ppolymarker3(&markers);
    pclose_struct();
}

/* Searches from `start` (n references); answers the found path's length or -error. */
static Pelem_ref found_refs[4];
static int search(Pfloat x, Pfloat y, Pfloat dist, Pelem_ref* start, Pint n, Pint ceiling, Pclip_ind clip,
                  const Pfilter_list* norm, const Pfilter_list* inv) {
    Ppoint3 ref = {x, y, 0};
    Pelem_ref_list sp = {n, start};
    Pelem_ref_list fp = {0, found_refs};
    Pfilter_list none = {0, NULL};
    Pint err = -1, total = -1;
    pincr_spa_search3(&ref, dist, &sp, clip, ceiling, norm ? norm : &none, inv ? inv : &none, 4, 0, &err, &fp,
                      &total);
    if (err != 0) return -err;
    CHECK(fp.num_elem_refs == total);
    return total;
}

static void starts(void) {
    Pelem_ref root0[1] = {{1, 0}}, root1[1] = {{1, 1}}, root3[1] = {{1, 3}}, in2[2] = {{1, 3}, {2, 0}};
    CHECK(search(0.5f, 0.05f, 0.1f, root0, 1, 1, PIND_NO_CLIP, NULL, NULL) == 1);
    CHECK(found_refs[0].struct_id == 1 && found_refs[0].elem_pos == 1);
    CHECK(search(0.5f, 0.05f, 0.1f, root1, 1, 1, PIND_NO_CLIP, NULL, NULL) == 0);
    CHECK(search(0.5f, 5, 0.1f, root1, 1, 1, PIND_NO_CLIP, NULL, NULL) == 2);
    CHECK(found_refs[0].elem_pos == 3 && found_refs[1].struct_id == 2 && found_refs[1].elem_pos == 2);
    /* The start path's element is processed in the setup: its structure is not searched. */
    CHECK(search(0.5f, 5, 0.1f, root3, 1, 1, PIND_NO_CLIP, NULL, NULL) == 0);
    CHECK(search(10, 5, 0.1f, root3, 1, 1, PIND_NO_CLIP, NULL, NULL) == 1);
    CHECK(found_refs[0].elem_pos == 4);
    /* The ceiling: the end of structure 2 ends the search. */
    CHECK(search(10, 5, 0.1f, in2, 2, 2, PIND_NO_CLIP, NULL, NULL) == 0);
    CHECK(search(10, 5, 0.1f, in2, 2, 1, PIND_NO_CLIP, NULL, NULL) == 1);
    /* 2D form: z = 0. */
    {
        Ppoint ref = {0.5f, 0};
        Pelem_ref_list sp = {1, root0}, fp = {0, found_refs};
        Pfilter_list none = {0, NULL};
        Pint err = -1, total = -1;
        pincr_spa_search(&ref, 0, &sp, PIND_NO_CLIP, 1, &none, &none, 4, 0, &err, &fp, &total);
        CHECK(err == 0 && total == 1 && found_refs[0].elem_pos == 1);
    }
}

static void clipping_and_filters(void) {
    Pelem_ref after[2] = {{1, 3}, {2, 2}}, root0[1] = {{1, 0}};
    Pint one = 1;
    Pfilter with_one = {{1, &one}, {0, NULL}};
    Pfilter_list filters = {1, &with_one};
    CHECK(search(0.1f, 5, 0.05f, after, 2, 1, PIND_NO_CLIP, NULL, NULL) == 2);
    CHECK(found_refs[1].elem_pos == 5);
    CHECK(search(0.1f, 5, 0.05f, after, 2, 1, PIND_CLIP, NULL, NULL) == 0); /* clipped away */
    /* Both long lines are within 3 of (0.5, 2.5): the filters choose. */
    CHECK(search(0.5f, 2.5f, 3, root0, 1, 1, PIND_NO_CLIP, NULL, NULL) == 1);
    CHECK(search(0.5f, 2.5f, 3, root0, 1, 1, PIND_NO_CLIP, &filters, NULL) == 2);
    CHECK(found_refs[1].elem_pos == 2);
    CHECK(search(0.5f, 2.5f, 3, root0, 1, 1, PIND_NO_CLIP, NULL, &filters) == 1);
}

static void errors(void) {
    Pelem_ref bad[1] = {{9, 0}}, root0[1] = {{1, 0}}, not_exec[2] = {{1, 2}, {2, 0}};
    Pelem_ref_list sp = {1, root0}, fp = {0, found_refs};
    Pfilter_list none = {0, NULL};
    Ppoint3 ref = {0, 0, 0};
    Pint err = -1, total = -1;
    error_count = 0;
    CHECK(search(0, 0, 1, bad, 1, 1, PIND_NO_CLIP, NULL, NULL) == -203);
    CHECK(search(0, 0, 1, not_exec, 2, 1, PIND_NO_CLIP, NULL, NULL) == -203);
    CHECK(search(0, 0, 1, root0, 1, 0, PIND_NO_CLIP, NULL, NULL) == -204);
    CHECK(search(0, 0, 1, root0, 1, 2, PIND_NO_CLIP, NULL, NULL) == -204);
    CHECK(search(0, 0, 1, root0, 1, 1, (Pclip_ind)7, NULL, NULL) == -PE_ENUM_TYPE_INVAL);
    pincr_spa_search3(&ref, 1, &sp, PIND_NO_CLIP, 1, &none, &none, -1, 0, &err, &fp, &total);
    CHECK(err == PE_LIST_LENGTH_LT_ZERO);
    pincr_spa_search3(&ref, 1, &sp, PIND_NO_CLIP, 1, &none, &none, 4, 2, &err, &fp, &total);
    CHECK(err == PE_START_IND_INVAL); /* the path found has one reference */
    pincr_spa_search3(&ref, 1, &sp, PIND_NO_CLIP, 1, &none, &none, 4, 0, &err, &fp, &total);
    CHECK(err == 0 && total == 1);
    pincr_spa_search3(NULL, 1, &sp, PIND_NO_CLIP, 1, &none, &none, 4, 0, &err, &fp, &total);
    CHECK(err == -204);
    CHECK(error_count == 0); /* inquiries never call the handler */
}

int main(int argc, char** argv) {
    char file[512];
    Pelem_ref root0[1] = {{1, 0}};
    snprintf(file, sizeof file, "%s/spatial_search_errors.txt", argc > 1 ? argv[1] : ".");
    {
        Ppoint3 ref = {0, 0, 0};
        Pelem_ref_list sp = {1, root0}, fp = {0, found_refs};
        Pfilter_list none = {0, NULL};
        Pint err = -1, total = -1;
        pincr_spa_search3(&ref, 1, &sp, PIND_NO_CLIP, 1, &none, &none, 4, 0, &err, &fp, &total);
        CHECK(err == 2); /* PHIGS closed */
    }
    open_with_handler(file);
    network();
    starts();
    clipping_and_filters();
    errors();
    pclose_phigs();
    return finish("test_spatial_search");
}
