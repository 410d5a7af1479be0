/* Output primitives and attributes: each function stores one element whose type and contents
 * INQUIRE ELEMENT CONTENT gives back; bad pointers, counts, enumerations and non-finite values
 * are refused with their error numbers and change nothing. argv[1]: a directory for the error file. */
#include "check.h"

#include <limits.h>

static Pint n_elem = 0;
static Pstore store = NULL;

/* The content of the element just inserted, after checking its type. */
static Pelem_data* last(Pelem_type expected) {
    Pint err = -1;
    Pelem_type type = PELEM_ALL;
    size_t size = 0;
    Pelem_data* data = NULL;
    ++n_elem;
    pinq_elem_type_size(1, n_elem, &err, &type, &size);
    CHECK(err == 0 && type == expected);
    if (type != expected)
        fprintf(stderr, "  element %d: type %d, expected %d\n", (int)n_elem, (int)type, (int)expected);
    pinq_cur_elem_type_size(&err, &type, &size);
    CHECK(err == 0 && type == expected);
    pinq_elem_content(1, n_elem, store, &err, &data);
    CHECK(err == 0 && data != NULL);
    return data;
}

static void primitives(void) {
    Ppoint3 p3[3] = {{0, 0, 0}, {1, 2, 3}, {4, 5, 6}};
    Ppoint p2[3] = {{0, 0}, {1, 2}, {3, 4}};
    Ppoint_list3 l3 = {3, p3};
    Ppoint_list l2 = {3, p2};
    Ppoint_list3 sets3[2] = {{3, p3}, {3, p3}};
    Ppoint_list_list3 set3 = {2, sets3};
    Ppoint_list sets2[1] = {{3, p2}};
    Ppoint_list_list set2 = {1, sets2};
    Pvec3 dir[2] = {{1, 0, 0}, {0, 1, 0}};
    Pelem_data* d;

    ppolyline3(&l3);
    d = last(PELEM_POLYLINE3);
    CHECK(d->point_list3.num_points == 3 && d->point_list3.points[1].z == 3);
    ppolyline(&l2);
    d = last(PELEM_POLYLINE);
    CHECK(d->point_list.num_points == 3 && d->point_list.points[2].y == 4);
    ppolymarker3(&l3);
    CHECK(last(PELEM_POLYMARKER3)->point_list3.points[2].x == 4);
    ppolymarker(&l2);
    CHECK(last(PELEM_POLYMARKER)->point_list.points[1].x == 1);
    pfill_area3(&l3);
    CHECK(last(PELEM_FILL_AREA3)->point_list3.num_points == 3);
    pfill_area(&l2);
    CHECK(last(PELEM_FILL_AREA)->point_list.num_points == 3);
    pfill_area_set3(&set3);
    d = last(PELEM_FILL_AREA_SET3);
    CHECK(d->point_list_list3.num_point_lists == 2 && d->point_list_list3.point_lists[1].points[2].z == 6);
    pfill_area_set(&set2);
    d = last(PELEM_FILL_AREA_SET);
    CHECK(d->point_list_list.num_point_lists == 1 && d->point_list_list.point_lists[0].points[1].y == 2);
    ptext3(&p3[1], dir, "three");
    d = last(PELEM_TEXT3);
    CHECK(d->text3.pos.y == 2 && d->text3.dir[1].delta_y == 1 && strcmp(d->text3.char_string, "three") == 0);
    ptext(&p2[1], "two");
    d = last(PELEM_TEXT);
    CHECK(d->text.pos.x == 1 && strcmp(d->text.char_string, "two") == 0);
    panno_text_rel3(&p3[2], &dir[0], "anno");
    d = last(PELEM_ANNO_TEXT_REL3);
    CHECK(d->anno_text_rel3.ref_point.z == 6 && d->anno_text_rel3.offset.delta_x == 1);
    panno_text_rel(&p2[2], &(Pvec){0.5f, 0.25f}, "a");
    d = last(PELEM_ANNO_TEXT_REL);
    CHECK(d->anno_text_rel.offset.delta_y == 0.25f && strcmp(d->anno_text_rel.char_string, "a") == 0);
    {
        Pint colours[6] = {1, 2, 3, 4, 5, 6};
        Ppat_rep rep = {{3, 2}, colours};
        Prect rect = {{0, 0}, {3, 2}};
        Pparal paral = {{0, 0, 0}, {3, 0, 0}, {0, 2, 1}};
        pcell_array(&rect, &rep);
        d = last(PELEM_CELL_ARRAY);
        CHECK(d->cell_array.rect.q.x == 3 && d->cell_array.rect.q.y == 2);
        CHECK(d->cell_array.colr_array.dims.size_x == 3 && d->cell_array.colr_array.colr_array[5] == 6);
        pcell_array3(&paral, &rep);
        d = last(PELEM_CELL_ARRAY3);
        CHECK(d->cell_array3.paral.r.z == 1 && d->cell_array3.colr_array.dims.size_y == 2);
    }
}

static void attributes(void) {
    Ptext_align align = {PHOR_CTR, PVERT_HALF};
    Pgcolr rgb = {PMODEL_RGB, {0}};
    Pint names[3] = {4, 5, 6};
    Pint_list name_list = {3, names};
    Pelem_data* d;
    rgb.val.general.x = 0.25f, rgb.val.general.y = 0.5f, rgb.val.general.z = 1.0f;

    pset_line_ind(2);
    CHECK(last(PELEM_LINE_IND)->int_data == 2);
    pset_marker_ind(3);
    CHECK(last(PELEM_MARKER_IND)->int_data == 3);
    pset_text_ind(4);
    CHECK(last(PELEM_TEXT_IND)->int_data == 4);
    pset_int_ind(5);
    CHECK(last(PELEM_INT_IND)->int_data == 5);
    pset_edge_ind(6);
    CHECK(last(PELEM_EDGE_IND)->int_data == 6);
    pset_linetype(PLINE_DASH);
    CHECK(last(PELEM_LINETYPE)->int_data == PLINE_DASH);
    pset_linewidth(2.5f);
    CHECK(last(PELEM_LINEWIDTH)->float_data == 2.5f);
    pset_line_colr_ind(7);
    CHECK(last(PELEM_LINE_COLR_IND)->int_data == 7);
    pset_marker_type(PMARKER_CROSS);
    CHECK(last(PELEM_MARKER_TYPE)->int_data == PMARKER_CROSS);
    pset_marker_size(1.5f);
    CHECK(last(PELEM_MARKER_SIZE)->float_data == 1.5f);
    pset_marker_colr_ind(3);
    CHECK(last(PELEM_MARKER_COLR_IND)->int_data == 3);
    pset_text_font(2);
    CHECK(last(PELEM_TEXT_FONT)->int_data == 2);
    pset_text_prec(PPREC_STROKE);
    CHECK(last(PELEM_TEXT_PREC)->text_prec == PPREC_STROKE);
    pset_char_expan(0.75f);
    CHECK(last(PELEM_CHAR_EXPAN)->float_data == 0.75f);
    pset_char_space(0.125f);
    CHECK(last(PELEM_CHAR_SPACE)->float_data == 0.125f);
    pset_text_colr_ind(4);
    CHECK(last(PELEM_TEXT_COLR_IND)->int_data == 4);
    pset_char_ht(0.05f);
    CHECK(last(PELEM_CHAR_HT)->float_data == 0.05f);
    pset_char_up_vec(&(Pvec){1, 1});
    CHECK(last(PELEM_CHAR_UP_VEC)->char_up_vec.delta_x == 1);
    pset_text_path(PPATH_UP);
    CHECK(last(PELEM_TEXT_PATH)->text_path == PPATH_UP);
    pset_text_align(&align);
    d = last(PELEM_TEXT_ALIGN);
    CHECK(d->text_align.hor == PHOR_CTR && d->text_align.vert == PVERT_HALF);
    pset_anno_char_ht(0.02f);
    CHECK(last(PELEM_ANNO_CHAR_HT)->float_data == 0.02f);
    pset_anno_char_up_vec(&(Pvec){0, 1});
    CHECK(last(PELEM_ANNO_CHAR_UP_VEC)->char_up_vec.delta_y == 1);
    pset_anno_path(PPATH_LEFT);
    CHECK(last(PELEM_ANNO_PATH)->text_path == PPATH_LEFT);
    pset_anno_align(&align);
    CHECK(last(PELEM_ANNO_ALIGN)->text_align.hor == PHOR_CTR);
    pset_anno_style(PANNO_STYLE_LEAD_LINE);
    CHECK(last(PELEM_ANNO_STYLE)->int_data == PANNO_STYLE_LEAD_LINE);
    pset_int_style(PSTYLE_HATCH);
    CHECK(last(PELEM_INT_STYLE)->int_style == PSTYLE_HATCH);
    pset_int_style_ind(3);
    CHECK(last(PELEM_INT_STYLE_IND)->int_data == 3);
    pset_int_colr_ind(2);
    CHECK(last(PELEM_INT_COLR_IND)->int_data == 2);
    pset_edge_flag(PEDGE_ON);
    CHECK(last(PELEM_EDGE_FLAG)->edge_flag == PEDGE_ON);
    pset_edgetype(PLINE_DOT);
    CHECK(last(PELEM_EDGETYPE)->int_data == PLINE_DOT);
    pset_edgewidth(3.0f);
    CHECK(last(PELEM_EDGEWIDTH)->float_data == 3.0f);
    pset_edge_colr_ind(5);
    CHECK(last(PELEM_EDGE_COLR_IND)->int_data == 5);
    pset_pat_size(&(Pfloat_size){0.5f, 2.0f});
    d = last(PELEM_PAT_SIZE);
    CHECK(d->pat_size.size_x == 0.5f && d->pat_size.size_y == 2.0f);
    pset_pat_ref_point(&(Ppoint){3, 4});
    d = last(PELEM_PAT_REF_POINT);
    CHECK(d->pat_ref_point.x == 3 && d->pat_ref_point.y == 4);
    pset_pat_ref_point_vecs(&(Ppoint3){1, 2, 3}, (Pvec3[2]){{0, 1, 0}, {0, 0, 2}});
    d = last(PELEM_PAT_REF_POINT_VECS);
    CHECK(d->pat_ref_point_vecs.ref_point.z == 3 && d->pat_ref_point_vecs.ref_vec[0].delta_y == 1);
    CHECK(d->pat_ref_point_vecs.ref_vec[1].delta_z == 2 && d->pat_ref_point_vecs.ref_vec[1].delta_x == 0);
    pset_line_colr(&rgb);
    d = last(PELEM_LINE_COLR);
    CHECK(d->colr.type == PMODEL_RGB && d->colr.val.general.y == 0.5f);
    pset_marker_colr(&rgb);
    CHECK(last(PELEM_MARKER_COLR)->colr.val.general.x == 0.25f);
    pset_text_colr(&rgb);
    CHECK(last(PELEM_TEXT_COLR)->colr.type == PMODEL_RGB);
    pset_edge_colr(&(Pgcolr){PINDIRECT, {3}}); /* an index through the general form */
    CHECK(last(PELEM_EDGE_COLR_IND)->int_data == 3);
    pset_int_colr(&rgb);
    CHECK(last(PELEM_INT_COLR)->colr.val.general.z == 1.0f);
    pset_indiv_asf(PASPECT_EDGE_FLAG, PASF_INDIV);
    d = last(PELEM_INDIV_ASF);
    CHECK(d->asf.id == PASPECT_EDGE_FLAG && d->asf.source == PASF_INDIV);
    /* Every aspect, PHIGS PLUS's too (in the sample implementation's order), stores and reads back. */
    for (int a = PASPECT_LINETYPE; a <= PASPECT_SURF_APPROX_CRIT; ++a) {
        pset_indiv_asf((Paspect)a, a % 2 ? PASF_BUNDLED : PASF_INDIV);
        d = last(PELEM_INDIV_ASF);
        CHECK(d->asf.id == (Paspect)a && d->asf.source == (a % 2 ? PASF_BUNDLED : PASF_INDIV));
    }
    padd_names_set(&name_list);
    d = last(PELEM_ADD_NAMES_SET);
    CHECK(d->names.num_ints == 3 && d->names.ints[2] == 6);
    premove_names_set(&name_list);
    CHECK(last(PELEM_REMOVE_NAMES_SET)->names.ints[0] == 4);
    pset_view_ind(1);
    CHECK(last(PELEM_VIEW_IND)->int_data == 1);
    pset_hlhsr_id(1);
    CHECK(last(PELEM_HLHSR_ID)->int_data == 1);
    pset_pick_id(9);
    CHECK(last(PELEM_PICK_ID)->int_data == 9);
    plabel(12);
    CHECK(last(PELEM_LABEL)->int_data == 12);
    pexec_struct(2);
    CHECK(last(PELEM_EXEC_STRUCT)->int_data == 2);
    pappl_data(&(Pdata){4, "abcd"});
    d = last(PELEM_APPL_DATA);
    CHECK(d->appl_data.size == 4 && memcmp(d->appl_data.data, "abcd", 4) == 0);
}

/* GDPs: the two this implementation draws keep no record; any other identifier keeps its
 * record's bytes. GSEs keep identifier and record. */
static void generalized(void) {
    Ppoint3 circle3[3] = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    Ppoint arc2[3] = {{1, 0}, {0, 1}, {-1, 0}};
    Ppoint3 any3[1] = {{7, 8, 9}};
    Pgdp_data3 record3;
    Pgdp_data record2;
    Pgse_data gse;
    Pelem_data* d;
    record3.unsupp = (Pdata){3, "xyz"};
    pgdp3(&(Ppoint_list3){3, circle3}, PGDP_CIRCLE, NULL);
    d = last(PELEM_GDP3);
    CHECK(d->gdp3.id == PGDP_CIRCLE && d->gdp3.point_list.num_points == 3);
    CHECK(d->gdp3.point_list.points[1].x == 2 && d->gdp3.data.unsupp.size == 0);
    pgdp3(&(Ppoint_list3){1, any3}, 4711, &record3);
    d = last(PELEM_GDP3);
    CHECK(d->gdp3.id == 4711 && d->gdp3.point_list.points[0].z == 9);
    CHECK(d->gdp3.data.unsupp.size == 3 && memcmp(d->gdp3.data.unsupp.data, "xyz", 3) == 0);
    record2.unsupp = (Pdata){0, NULL};
    pgdp(&(Ppoint_list){3, arc2}, PGDP_ARC, &record2);
    d = last(PELEM_GDP);
    CHECK(d->gdp.id == PGDP_ARC && d->gdp.point_list.num_points == 3 && d->gdp.point_list.points[1].y == 1);
    gse.unsupp = (Pdata){2, "ok"};
    pgse(-12, &gse);
    d = last(PELEM_GSE);
    CHECK(d->gse.id == -12 && d->gse.data.unsupp.size == 2 && memcmp(d->gse.data.unsupp.data, "ok", 2) == 0);
    pgse(3, NULL);
    d = last(PELEM_GSE);
    CHECK(d->gse.id == 3 && d->gse.data.unsupp.size == 0);
}

static void transforms_and_clipping(void) {
    Pmatrix3 m3 = {{1, 0, 0, 5}, {0, 2, 0, 6}, {0, 0, 3, 7}, {0, 0, 0, 1}};
    Pmatrix m2 = {{1, 0, 5}, {0, 2, 6}, {0, 0, 1}};
    Phalf_space3 h3 = {{0, 0, 1}, {0, 0, 1}};
    Phalf_space h2 = {{1, 0}, {1, 0}};
    Phalf_space_list3 hl3 = {1, &h3};
    Phalf_space_list hl2 = {1, &h2};
    Pelem_data* d;
    pset_local_tran3(m3, PTYPE_POSTCONCAT);
    d = last(PELEM_LOCAL_MODEL_TRAN3);
    CHECK(d->local_tran3.compose_type == PTYPE_POSTCONCAT && d->local_tran3.matrix[0][3] == 5);
    CHECK(d->local_tran3.matrix[2][2] == 3);
    pset_local_tran(m2, PTYPE_REPLACE);
    d = last(PELEM_LOCAL_MODEL_TRAN);
    CHECK(d->local_tran.compose_type == PTYPE_REPLACE && d->local_tran.matrix[1][2] == 6);
    CHECK(d->local_tran.matrix[1][1] == 2 && d->local_tran.matrix[2][2] == 1);
    pset_global_tran3(m3);
    CHECK(last(PELEM_GLOBAL_MODEL_TRAN3)->global_tran3[1][3] == 6);
    pset_global_tran(m2);
    CHECK(last(PELEM_GLOBAL_MODEL_TRAN)->global_tran[0][2] == 5);
    pset_model_clip_vol3(PMC_INTERSECT, &hl3);
    d = last(PELEM_MODEL_CLIP_VOL3);
    CHECK(d->model_clip3.op == PMC_INTERSECT && d->model_clip3.half_spaces.half_spaces[0].norm.delta_z == 1);
    pset_model_clip_vol(PMC_REPLACE, &hl2);
    d = last(PELEM_MODEL_CLIP_VOL);
    CHECK(d->model_clip.half_spaces.num_half_spaces == 1 &&
          d->model_clip.half_spaces.half_spaces[0].point.x == 1);
    pset_model_clip_ind(PIND_CLIP);
    CHECK(last(PELEM_MODEL_CLIP_IND)->clip_ind == PIND_CLIP);
    prestore_model_clip_vol();
    last(PELEM_RESTORE_MODEL_CLIP_VOL);
}

/* Index attributes below their ISO range are refused with the standard's error and store
 * nothing: bundle indices from 1 (100), colour indices from 0 (113), view indices from 0 (114),
 * depth cue (119) and colour mapping indices (121) from 0. Interior style indices, hatch indices
 * too, may be anything (checked when drawn). */
static void index_ranges(void) {
    static const struct {
        void (*set)(Pint);
        Pint fn, lowest, error;
    } kinds[] = {
        {pset_line_ind, Pfn_set_line_ind, 1, 100},
        {pset_marker_ind, Pfn_set_marker_ind, 1, 100},
        {pset_text_ind, Pfn_set_text_ind, 1, 100},
        {pset_int_ind, Pfn_set_int_ind, 1, 100},
        {pset_edge_ind, Pfn_set_edge_ind, 1, 100},
        {pset_line_colr_ind, Pfn_set_line_colr_ind, 0, 113},
        {pset_marker_colr_ind, Pfn_set_marker_colr_ind, 0, 113},
        {pset_text_colr_ind, Pfn_set_text_colr_ind, 0, 113},
        {pset_int_colr_ind, Pfn_set_int_colr_ind, 0, 113},
        {pset_edge_colr_ind, Pfn_set_edge_colr_ind, 0, 113},
        {pset_view_ind, Pfn_set_view_ind, 0, 114},
        {pset_dcue_ind, Pfn_set_dcue_ind, 0, 119},
        {pset_colr_map_ind, Pfn_set_colr_map_ind, 0, 121},
    };
    seed_random(20261205);
    for (int round = 0; round < 200; ++round) {
        const int k = (int)(next_random() % (sizeof kinds / sizeof kinds[0]));
        const Pint value = (Pint)(next_random() % 7) - 3 + kinds[k].lowest;
        if (value >= kinds[k].lowest) {
            EXPECT_NO_ERROR(kinds[k].set(value));
            ++n_elem;
        } else {
            EXPECT_REFUSED(kinds[k].set(value), kinds[k].error, kinds[k].fn);
        }
    }
    EXPECT_REFUSED(pset_int_colr(&(Pgcolr){PINDIRECT, {.ind = -1}}), 113, Pfn_set_int_colr);
    EXPECT_NO_ERROR(pset_int_style_ind(-2));
    EXPECT_NO_ERROR(pset_back_int_style_ind(0));
    n_elem += 2;
}

static void refusals(void) {
    Ppoint3 p3[2] = {{0, 0, 0}, {1, 1, 1}};
    Ppoint_list3 negative = {-1, p3};
    Ppoint_list3 no_points = {2, NULL};
    Ppoint3 nan_point[2] = {{0, 0, 0}, {NAN, 1, 1}};
    Ppoint_list3 with_nan = {2, nan_point};
    Pgcolr bad_colour = {9, {0}};
    EXPECT_REFUSED(ppolyline3(NULL), -204, Pfn_polyline3);
    EXPECT_REFUSED(ppolyline3(&negative), -204, Pfn_polyline3);
    EXPECT_REFUSED(ppolyline3(&no_points), -204, Pfn_polyline3);
    EXPECT_REFUSED(ppolyline3(&with_nan), -202, Pfn_polyline3);
    EXPECT_REFUSED(ptext(NULL, "x"), -204, Pfn_text);
    EXPECT_REFUSED(ptext(&(Ppoint){0, 0}, NULL), -204, Pfn_text);
    EXPECT_REFUSED(padd_names_set(NULL), -204, Pfn_add_names_set);
    EXPECT_REFUSED(pset_int_style((Pint_style)17), PE_ENUM_TYPE_INVAL, Pfn_set_int_style);
    EXPECT_REFUSED(pset_text_prec((Ptext_prec)-1), PE_ENUM_TYPE_INVAL, Pfn_set_text_prec);
    EXPECT_REFUSED(pset_text_align(&(Ptext_align){PHOR_LEFT, (Pvert_text_align)9}), PE_ENUM_TYPE_INVAL,
                   Pfn_set_text_align);
    EXPECT_REFUSED(pset_line_colr(&bad_colour), PE_ENUM_TYPE_INVAL, Pfn_line_colr);
    EXPECT_REFUSED(pset_local_tran3(NULL, PTYPE_REPLACE), -204, Pfn_set_local_tran3);
    EXPECT_REFUSED(pset_char_ht(INFINITY), -202, Pfn_set_char_ht);
    EXPECT_REFUSED(pappl_data(&(Pdata){-2, NULL}), -204, Pfn_appl_data);
    EXPECT_REFUSED(pset_pat_size(NULL), -204, Pfn_set_pat_size);
    EXPECT_REFUSED(pset_pat_ref_point(NULL), -204, Pfn_set_pat_ref_point);
    EXPECT_REFUSED(pset_pat_ref_point_vecs(&(Ppoint3){0, 0, 0}, NULL), -204, Pfn_set_pat_ref_point_vecs);
    EXPECT_REFUSED(pset_pat_size(&(Pfloat_size){NAN, 1}), -202, Pfn_set_pat_size);
    /* a 3D circle needs three points, and an arc three that are not collinear */
    EXPECT_REFUSED(pgdp3(&(Ppoint_list3){2, p3}, PGDP_CIRCLE, NULL), -202, Pfn_gdp3);
    EXPECT_REFUSED(pgdp(&(Ppoint_list){3, (Ppoint[3]){{0, 0}, {1, 1}, {2, 2}}}, PGDP_ARC, NULL), -202,
                   Pfn_gdp);
    EXPECT_REFUSED(pgdp3(NULL, 5, NULL), -204, Pfn_gdp3);
    EXPECT_REFUSED(pgse(1, &(Pgse_data){.unsupp = {-1, NULL}}), -204, Pfn_gse);
    {
        /* cell arrays too large to hold (past any container's size, past the memory): storage
         * overflow, before the colour indices are read */
        Pint one[1] = {1};
        const Pparal paral = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        const Prect rect = {{0, 0}, {1, 1}};
        const Ppat_rep past_size = {{INT_MAX, INT_MAX}, one}, past_memory = {{1 << 30, 1 << 30}, one};
        EXPECT_REFUSED(pcell_array3(&paral, &past_size), 900, Pfn_cell_array3);
        EXPECT_REFUSED(pcell_array(&rect, &past_size), 900, Pfn_cell_array);
        EXPECT_REFUSED(pcell_array3(&paral, &past_memory), 900, Pfn_cell_array3);
    }
    index_ranges();
    pclose_struct();
    /* with no structure open the state error comes first, whatever the arguments */
    EXPECT_REFUSED(ppolyline3(NULL), 5, Pfn_polyline3);
    EXPECT_REFUSED(pset_linetype(1), 5, Pfn_set_linetype);
}

int main(int argc, char** argv) {
    char file[512];
    Pint err = -1;
    snprintf(file, sizeof file, "%s/elements_errors.txt", argc > 1 ? argv[1] : ".");
    open_with_handler(file);
    pcreate_store(&err, &store);
    popen_struct(1);
    primitives();
    attributes();
    generalized();
    transforms_and_clipping();
    refusals();
    CHECK(file_has_line(file,
                        "ERROR -204 in POLYLINE 3 (function 8): Ignoring function, a required argument is "
                        "a null pointer or a negative count"));
    CHECK(
        file_has_line(file, "ERROR 2202 in SET INTERIOR STYLE (function 49): Enumeration type out of range"));
    pdel_store(store);
    pclose_phigs();
    return finish("test_elements");
}
