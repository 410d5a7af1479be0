/* PHIGS PLUS primitives with data and colour mapping through the C binding: POLYLINE SET 3 WITH
 * DATA, CELL ARRAY 3 PLUS, SET OF FILL AREA SETS 3 WITH DATA and SET RENDERING COLOUR MODEL
 * stored, read back through pinq_elem_content, archived and retrieved, and refused on bad data;
 * the colour mapping table of a workstation (SVG type, no GPU) set and inquired with SET and
 * REALIZED values, its deferral, the predefined entry, the facilities and the errors.
 * argv[1]: a directory. */
#include "check.h"

static Pstore store;

static Pelem_data* content(Pint structure, Pint pos, Pelem_type expected) {
    Pint err = -1;
    Pelem_type type = PELEM_NIL;
    size_t size = 0;
    Pelem_data* data = NULL;
    pinq_elem_type_size(structure, pos, &err, &type, &size);
    CHECK(err == 0 && type == expected);
    pinq_elem_content(structure, pos, store, &err, &data);
    CHECK(err == 0 && data != NULL);
    return err == 0 && type == expected ? data : NULL;
}

/* Structure 1: a polyline set with vertex colours, one without, a cell array plus, a set of fill
 * area sets with facet colours, edge data and vertex normals, and a rendering colour model. */
static void build(void) {
    Pptco3 coloured[3] = {{{0, 0, 0}, {.ind = 2}}, {{1, 0, 0}, {.ind = 3}}, {{1, 1, 0}, {.ind = 4}}};
    Pptco3 second[2] = {{{0, 2, 0}, {.ind = 5}}, {{2, 2, 0}, {.ind = 6}}};
    Ppoint3 plain[2] = {{0, 0, 1}, {0, 1, 1}};
    Pline_vdata_list3 lines[2], plain_line;
    Pparal paral = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    Pint_size dim = {3, 2};
    Pcoval cells[6];
    Pptnorm3 vertices[5] = {{{0, 0, 0}, {0, 0, 1}},
                            {{1, 0, 0}, {0, 0, 1}},
                            {{1, 1, 0}, {0, 0, 1}},
                            {{0, 1, 0}, {0, 0, 1}},
                            {{2, 0, 0}, {0, 0, 1}}};
    Pfacet_vdata_list3 vdata;
    Pint quad[4] = {0, 1, 2, 3}, tri[3] = {1, 4, 2};
    Pint_list contours_a[1] = {{4, quad}}, contours_b[1] = {{3, tri}};
    Pint_list_list vlist[2] = {{1, contours_a}, {1, contours_b}};
    Pedge_flag edges_a[4] = {PEDGE_ON, PEDGE_OFF, PEDGE_ON, PEDGE_ON},
               edges_b[3] = {PEDGE_OFF, PEDGE_ON, PEDGE_OFF};
    Pedge_data_list elist_a[1] = {{4, edges_a}}, elist_b[1] = {{3, edges_b}};
    Pedge_data_list_list edata[2] = {{1, elist_a}, {1, elist_b}};
    Pcoval facet_colours[2];
    Pfacet_data_arr3 fdata;
    for (int k = 0; k < 6; ++k)
        cells[k].direct.rgb.red = (Pfloat)k / 8, cells[k].direct.rgb.green = 0.5f, cells[k].direct.rgb.blue = 1 - (Pfloat)k / 8;
    facet_colours[0].ind = 2, facet_colours[1].ind = 7;
    fdata.colrs = facet_colours;
    lines[0].num_vertices = 3, lines[0].vertex_data.ptcolrs = coloured;
    lines[1].num_vertices = 2, lines[1].vertex_data.ptcolrs = second;
    plain_line.num_vertices = 2, plain_line.vertex_data.points = plain;
    vdata.num_vertices = 5, vdata.vertex_data.ptnorms = vertices;

    popen_struct(1);
    EXPECT_NO_ERROR(ppolyline_set3_data(PVERT_COORD_COLOUR, PINDIRECT, 2, lines)); /* 1 */
    EXPECT_NO_ERROR(ppolyline_set3_data(PVERT_COORD, PMODEL_RGB, 1, &plain_line)); /* 2 */
    EXPECT_NO_ERROR(pcell_array3_plus(&paral, &dim, PMODEL_RGB, cells));           /* 3 */
    EXPECT_NO_ERROR(pset_of_fill_area_set3_data(PFACET_COLOUR, PEDGE_VISIBILITY, PVERT_COORD_NORMAL,
                                                PINDIRECT, 2, &fdata, edata, vlist, &vdata)); /* 4 */
    EXPECT_NO_ERROR(pset_rendering_colr_model(PRCM_HSV));                                     /* 5 */
    EXPECT_NO_ERROR(pset_colr_map_ind(1));                                                    /* 6 */

    /* Refusals: nothing is inserted. */
    EXPECT_REFUSED(ppolyline_set3_data(PVERT_COORD_NORMAL, PINDIRECT, 1, &plain_line), PE_ENUM_TYPE_INVAL,
                   Pfn_polyline_set3_data);
    EXPECT_REFUSED(ppolyline_set3_data(PVERT_COORD, 7, 1, &plain_line), PE_ENUM_TYPE_INVAL,
                   Pfn_polyline_set3_data);
    EXPECT_REFUSED(ppolyline_set3_data(PVERT_COORD, PINDIRECT, -1, &plain_line), -204,
                   Pfn_polyline_set3_data);
    EXPECT_REFUSED(ppolyline_set3_data(PVERT_COORD, PINDIRECT, 1, NULL), -204, Pfn_polyline_set3_data);
    EXPECT_REFUSED(pcell_array3_plus(&paral, &dim, PMODEL_RGB, NULL), -204, Pfn_cell_array3_plus);
    EXPECT_REFUSED(pcell_array3_plus(NULL, &dim, PMODEL_RGB, cells), -204, Pfn_cell_array3_plus);
    dim.size_x = -1;
    EXPECT_REFUSED(pcell_array3_plus(&paral, &dim, PMODEL_RGB, cells), -204, Pfn_cell_array3_plus);
    dim.size_x = 3;
    tri[1] = 5; /* outside the five vertices */
    EXPECT_REFUSED(pset_of_fill_area_set3_data(PFACET_COLOUR, PEDGE_VISIBILITY, PVERT_COORD_NORMAL, PINDIRECT,
                                               2, &fdata, edata, vlist, &vdata),
                   -202, Pfn_set_of_fill_area_set3_data);
    tri[1] = 4;
    elist_b[0].num_edges = 2; /* edge data unlike the contour */
    EXPECT_REFUSED(pset_of_fill_area_set3_data(PFACET_COLOUR, PEDGE_VISIBILITY, PVERT_COORD_NORMAL, PINDIRECT,
                                               2, &fdata, edata, vlist, &vdata),
                   -202, Pfn_set_of_fill_area_set3_data);
    elist_b[0].num_edges = 3;
    edges_b[0] = (Pedge_flag)5;
    EXPECT_REFUSED(pset_of_fill_area_set3_data(PFACET_COLOUR, PEDGE_VISIBILITY, PVERT_COORD_NORMAL, PINDIRECT,
                                               2, &fdata, edata, vlist, &vdata),
                   PE_ENUM_TYPE_INVAL, Pfn_set_of_fill_area_set3_data);
    edges_b[0] = PEDGE_OFF;
    EXPECT_REFUSED(
        pset_of_fill_area_set3_data(9, PEDGE_NONE, PVERT_COORD, PINDIRECT, 0, NULL, NULL, NULL, &vdata),
        PE_ENUM_TYPE_INVAL, Pfn_set_of_fill_area_set3_data);
    EXPECT_REFUSED(pset_of_fill_area_set3_data(PFACET_NONE, PEDGE_NONE, PVERT_COORD, PINDIRECT, 1, NULL, NULL,
                                               NULL, &vdata),
                   -204, Pfn_set_of_fill_area_set3_data);
    pclose_struct();
    EXPECT_ERROR(pset_rendering_colr_model(PRCM_RGB), 5, Pfn_set_rendering_colr_model);
    EXPECT_ERROR(pcell_array3_plus(&paral, &dim, PMODEL_RGB, cells), 5, Pfn_cell_array3_plus);
}

/* Structure `s` holds what build() stored. */
static void read_back(Pint s) {
    Pelem_data* d;
    if ((d = content(s, 1, PELEM_POLYLINE_SET3_DATA))) {
        CHECK(d->plsd3.vflag == PVERT_COORD_COLOUR && d->plsd3.colr_type == PINDIRECT && d->plsd3.npl == 2);
        CHECK(d->plsd3.vdata[0].num_vertices == 3 && d->plsd3.vdata[1].num_vertices == 2);
        CHECK(d->plsd3.vdata[0].vertex_data.ptcolrs[2].point.y == 1 &&
              d->plsd3.vdata[0].vertex_data.ptcolrs[2].colr.ind == 4);
        CHECK(d->plsd3.vdata[1].vertex_data.ptcolrs[1].point.x == 2 &&
              d->plsd3.vdata[1].vertex_data.ptcolrs[1].colr.ind == 6);
    }
    if ((d = content(s, 2, PELEM_POLYLINE_SET3_DATA)))
        CHECK(d->plsd3.vflag == PVERT_COORD && d->plsd3.npl == 1 && d->plsd3.vdata[0].num_vertices == 2 &&
              d->plsd3.vdata[0].vertex_data.points[1].y == 1 &&
              d->plsd3.vdata[0].vertex_data.points[1].z == 1);
    if ((d = content(s, 3, PELEM_CELL_ARRAY3_PLUS))) {
        CHECK(d->cell_array_plus.dims.size_x == 3 && d->cell_array_plus.dims.size_y == 2);
        CHECK(d->cell_array_plus.colr_type == PMODEL_RGB && d->cell_array_plus.paral.q.x == 2 &&
              d->cell_array_plus.paral.r.y == 1);
        CHECK(near(d->cell_array_plus.colr_array[5].direct.rgb.red, 5.0 / 8) &&
              near(d->cell_array_plus.colr_array[5].direct.rgb.blue, 3.0 / 8));
    }
    if ((d = content(s, 4, PELEM_SET_OF_FILL_AREA_SET3_DATA))) {
        CHECK(d->sofas3.fflag == PFACET_COLOUR && d->sofas3.eflag == PEDGE_VISIBILITY &&
              d->sofas3.vflag == PVERT_COORD_NORMAL && d->sofas3.num_sets == 2);
        CHECK(d->sofas3.fdata.colrs[0].ind == 2 && d->sofas3.fdata.colrs[1].ind == 7);
        CHECK(d->sofas3.vlist[0].num_lists == 1 && d->sofas3.vlist[0].lists[0].num_ints == 4 &&
              d->sofas3.vlist[1].lists[0].ints[1] == 4);
        CHECK(d->sofas3.edata != NULL && d->sofas3.edata[0].edgelist[0].edgedata[1] == PEDGE_OFF &&
              d->sofas3.edata[1].edgelist[0].edgedata[1] == PEDGE_ON);
        CHECK(d->sofas3.vdata.num_vertices == 5 && d->sofas3.vdata.vertex_data.ptnorms[4].point.x == 2 &&
              d->sofas3.vdata.vertex_data.ptnorms[4].norm.delta_z == 1);
    }
    if ((d = content(s, 5, PELEM_RENDERING_COLR_MODEL))) CHECK(d->int_data == PRCM_HSV);
    if ((d = content(s, 6, PELEM_COLR_MAP_IND))) CHECK(d->int_data == 1);
}

/* Archive structure 1, delete it, retrieve it: the same contents. */
static void archive(const char* path) {
    Pint one[1] = {1};
    Pint_list list = {1, one};
    remove(path);
    EXPECT_NO_ERROR(popen_ar_file(1, path));
    EXPECT_NO_ERROR(par_structs(1, &list));
    pdel_all_structs();
    EXPECT_NO_ERROR(pret_structs(1, &list));
    EXPECT_NO_ERROR(pclose_ar_file(1));
    read_back(1);
}

static void pseudo_entry(Pcolr_map_data* data, Pfloat* weights, Pcolr_rep* ramp, Pint n) {
    data->meth_r2.colr_model = PMODEL_RGB;
    data->meth_r2.weights.num_floats = 3, data->meth_r2.weights.floats = weights;
    data->meth_r2.colrs.num_colr_reps = n, data->meth_r2.colrs.colr_reps = ramp;
}

static void set_and_inquire(void) {
    Pint err = -1, method = 0, total = 0, buffer[8];
    Pint_list inds = {0, buffer};
    Pcolr_map_data data, *got = NULL;
    Pfloat weights[3] = {0.25f, 0.5f, 0.25f};
    Pcolr_rep ramp[3];
    Pfloat red[2] = {0, 8}, green[3] = {0, 2, 4}, blue[2] = {0, 1};
    Pfloat_list lists[3] = {{2, red}, {3, green}, {2, blue}};
    for (int k = 0; k < 3; ++k) ramp[k].rgb.red = (Pfloat)k / 2, ramp[k].rgb.green = 0, ramp[k].rgb.blue = 1;
    pseudo_entry(&data, weights, ramp, 3);
    EXPECT_NO_ERROR(pset_colr_map_rep(1, 2, PCOLR_MAP_PSEUDO, &data));
    pinq_colr_map_rep(1, 2, PINQ_SET, store, &err, &method, &got);
    CHECK(err == 0 && method == PCOLR_MAP_PSEUDO && got != NULL);
    if (err == 0 && got) {
        CHECK(got->meth_r2.colr_model == PMODEL_RGB && got->meth_r2.weights.num_floats == 3 &&
              got->meth_r2.weights.floats[1] == 0.5f);
        CHECK(got->meth_r2.colrs.num_colr_reps == 3 && got->meth_r2.colrs.colr_reps[2].rgb.red == 1);
    }
    data.meth_r3.colr_model = PMODEL_RGB, data.meth_r3.colr_lists.num_lists = 3,
    data.meth_r3.colr_lists.lists = lists;
    EXPECT_NO_ERROR(pset_colr_map_rep(1, 3, PCOLR_MAP_PSEUDO_N, &data));
    pinq_colr_map_rep(1, 3, PINQ_REALIZED, store, &err, &method, &got);
    CHECK(err == 0 && method == PCOLR_MAP_PSEUDO_N && got != NULL);
    if (err == 0 && got)
        CHECK(got->meth_r3.colr_lists.num_lists == 3 && got->meth_r3.colr_lists.lists[1].num_floats == 3 &&
              got->meth_r3.colr_lists.lists[1].floats[2] == 4 &&
              got->meth_r3.colr_lists.lists[0].floats[1] == 8);
    EXPECT_NO_ERROR(pset_colr_map_rep(1, 4, PCOLR_MAP_TRUE, NULL));
    /* Undefined: SET answers 101, REALIZED the entry used (0, TRUE). */
    pinq_colr_map_rep(1, 9, PINQ_SET, store, &err, &method, &got);
    CHECK(err == 101);
    pinq_colr_map_rep(1, 9, PINQ_REALIZED, store, &err, &method, &got);
    CHECK(err == 0 && method == PCOLR_MAP_TRUE);
    pinq_colr_map_rep(1, -1, PINQ_SET, store, &err, &method, &got);
    CHECK(err == 121);
    pinq_colr_map_rep(1, 2, (Pinq_type)7, store, &err, &method, &got);
    CHECK(err == PE_ENUM_TYPE_INVAL);
    pinq_colr_map_rep(1, 2, PINQ_SET, NULL, &err, &method, &got);
    CHECK(err == 2203);
    pinq_colr_map_rep(2, 2, PINQ_SET, store, &err, &method, &got);
    CHECK(err == 54);
    pinq_list_colr_map_inds(1, 8, 0, &err, &inds, &total);
    CHECK(err == 0 && total == 4 && inds.num_ints == 4 && buffer[0] == 0 && buffer[1] == 2 && buffer[3] == 4);
    pinq_list_colr_map_inds(1, 2, 3, &err, &inds, &total);
    CHECK(err == 0 && inds.num_ints == 1 && buffer[0] == 4);
    pinq_list_colr_map_inds(1, 2, 5, &err, &inds, &total);
    CHECK(err == PE_START_IND_INVAL);
}

static void refusals(void) {
    Pint err = -1, method = 0;
    Pcolr_map_data data, *got = NULL;
    Pfloat weights[3] = {1, 0, 0};
    Pcolr_rep ramp[2];
    Pfloat list[1] = {0};
    Pfloat_list lists[2] = {{1, list}, {1, list}};
    ramp[0].rgb.red = ramp[0].rgb.green = ramp[0].rgb.blue = 0;
    ramp[1].rgb.red = 2, ramp[1].rgb.green = ramp[1].rgb.blue = 0;
    pseudo_entry(&data, weights, ramp, 2);
    EXPECT_ERROR(pset_colr_map_rep(1, -1, PCOLR_MAP_PSEUDO, &data), 121, Pfn_set_colr_map_rep);
    EXPECT_ERROR(pset_colr_map_rep(1, 5, 4, &data), 126, Pfn_set_colr_map_rep);
    EXPECT_ERROR(pset_colr_map_rep(1, 5, PCOLR_MAP_PSEUDO, &data), 118, Pfn_set_colr_map_rep);
    pseudo_entry(&data, weights, ramp, 0);
    EXPECT_ERROR(pset_colr_map_rep(1, 5, PCOLR_MAP_PSEUDO, &data), -207, Pfn_set_colr_map_rep);
    pseudo_entry(&data, weights, ramp, 1);
    data.meth_r2.weights.num_floats = 2;
    EXPECT_ERROR(pset_colr_map_rep(1, 5, PCOLR_MAP_PSEUDO, &data), -207, Pfn_set_colr_map_rep);
    data.meth_r2.weights.num_floats = 3, data.meth_r2.colr_model = 5;
    EXPECT_ERROR(pset_colr_map_rep(1, 5, PCOLR_MAP_PSEUDO, &data), 110, Pfn_set_colr_map_rep);
    EXPECT_ERROR(pset_colr_map_rep(1, 5, PCOLR_MAP_PSEUDO, NULL), -204, Pfn_set_colr_map_rep);
    data.meth_r3.colr_model = PMODEL_RGB, data.meth_r3.colr_lists.num_lists = 2,
    data.meth_r3.colr_lists.lists = lists;
    EXPECT_ERROR(pset_colr_map_rep(1, 5, PCOLR_MAP_PSEUDO_N, &data), -207, Pfn_set_colr_map_rep);
    EXPECT_ERROR(pset_colr_map_rep(7, 5, PCOLR_MAP_TRUE, NULL), 54, Pfn_set_colr_map_rep);
    pinq_colr_map_rep(1, 5, PINQ_SET, store, &err, &method, &got);
    CHECK(err == 101); /* every refusal left the table as it was */
    for (Pint i = 5; i < 21; ++i) EXPECT_NO_ERROR(pset_colr_map_rep(1, i, PCOLR_MAP_TRUE, NULL));
    EXPECT_ERROR(pset_colr_map_rep(1, 21, PCOLR_MAP_TRUE, NULL), 103, Pfn_set_colr_map_rep);
}

/* Under ASTI / NIVE a new mapping waits for the update: the visual state is DEFER until then;
 * under UQUM it is simulated at once. */
static void deferral(void) {
    Pint err = -1;
    Pdefer_mode defer;
    Pmod_mode mod;
    Pdisp_surf_empty empty;
    Pvisual_st visual = PVISUAL_ST_CORRECT;
    Pcolr_map_data data;
    Pfloat weights[3] = {1, 0, 0};
    Pcolr_rep ramp[1];
    ramp[0].rgb.red = 0, ramp[0].rgb.green = 1, ramp[0].rgb.blue = 0;
    pseudo_entry(&data, weights, ramp, 1);
    EXPECT_NO_ERROR(pset_disp_upd_st(1, PDEFER_ASTI, PMODE_NIVE));
    EXPECT_NO_ERROR(pupd_ws(1, PFLAG_PERFORM));
    pinq_disp_upd_st(1, &err, &defer, &mod, &empty, &visual);
    CHECK(err == 0 && visual == PVISUAL_ST_CORRECT);
    EXPECT_NO_ERROR(pset_colr_map_rep(1, 2, PCOLR_MAP_PSEUDO, &data));
    pinq_disp_upd_st(1, &err, &defer, &mod, &empty, &visual);
    CHECK(err == 0 && visual == PVISUAL_ST_DEFER);
    EXPECT_NO_ERROR(pupd_ws(1, PFLAG_PERFORM));
    pinq_disp_upd_st(1, &err, &defer, &mod, &empty, &visual);
    CHECK(err == 0 && visual == PVISUAL_ST_CORRECT);
    EXPECT_NO_ERROR(pset_disp_upd_st(1, PDEFER_ASTI, PMODE_UQUM));
    EXPECT_NO_ERROR(pset_colr_map_rep(1, 2, PCOLR_MAP_TRUE, NULL));
    pinq_disp_upd_st(1, &err, &defer, &mod, &empty, &visual);
    CHECK(err == 0 && visual == PVISUAL_ST_SIMULATED);
    EXPECT_NO_ERROR(pset_disp_upd_st(1, PDEFER_ASAP, PMODE_NIVE));
}

static void facilities(void) {
    Pint err = -1, method = 0, total = 0, buffer[4];
    Pcolr_map_facs facs;
    Pcolr_map_st st;
    Pcolr_map_data* got = NULL;
    facs.meths.ints = buffer;
    pinq_colr_map_facs(PWST_SVG, 4, 0, &err, &facs, &total);
    CHECK(err == 0 && total == 3 && facs.meths.num_ints == 3 && buffer[2] == PCOLR_MAP_PSEUDO_N &&
          facs.num_pred_inds == 1);
    pinq_colr_map_facs(PWST_SVG, 4, 4, &err, &facs, &total);
    CHECK(err == PE_START_IND_INVAL);
    pinq_colr_map_facs(99, 4, 0, &err, &facs, &total);
    CHECK(err == 52);
    pinq_colr_map_method_facs(PWST_OFFSCREEN, PCOLR_MAP_TRUE, &err, &st);
    CHECK(err == 0 && st.int_data == 1 << 24);
    pinq_colr_map_method_facs(PWST_PDF, PCOLR_MAP_PSEUDO, &err, &st);
    CHECK(err == 0 && st.int_data == 256);
    pinq_colr_map_method_facs(PWST_PDF, 0, &err, &st);
    CHECK(err == 126);
    pinq_pred_colr_map_rep(PWST_PNG, 0, store, &err, &method, &got);
    CHECK(err == 0 && method == PCOLR_MAP_TRUE && got != NULL);
    pinq_pred_colr_map_rep(PWST_PNG, 1, store, &err, &method, &got);
    CHECK(err == 102);
    pinq_pred_colr_map_rep(PWST_PNG, -1, store, &err, &method, &got);
    CHECK(err == 121);
    pinq_colr_map_st(1, PCOLR_MAP_PSEUDO_N, &err, &st);
    CHECK(err == 3); /* no workstation open */
}

static void mapping(const char* svg) {
    Pint err = -1;
    Pcolr_map_st st;
    facilities();
    EXPECT_ERROR(pset_colr_map_rep(1, 2, PCOLR_MAP_TRUE, NULL), 3, Pfn_set_colr_map_rep);
    EXPECT_NO_ERROR(popen_ws(1, svg, PWST_SVG));
    pinq_colr_map_st(1, PCOLR_MAP_PSEUDO_N, &err, &st);
    CHECK(err == 0 && st.int_data == 256);
    pinq_colr_map_st(1, 9, &err, &st);
    CHECK(err == 126);
    set_and_inquire();
    refusals();
    deferral();
    pclose_ws(1);
}

int main(int argc, char** argv) {
    char file[512], ar[512], svg[512];
    Pint err = -1;
    const char* dir = argc > 1 ? argv[1] : ".";
    snprintf(file, sizeof file, "%s/plus_data_errors.txt", dir);
    snprintf(ar, sizeof ar, "%s/plus_data.phar", dir);
    snprintf(svg, sizeof svg, "%s/plus_data.svg", dir);
    open_with_handler(file);
    pcreate_store(&err, &store);
    build();
    read_back(1);
    archive(ar);
    mapping(svg);
    pdel_store(store);
    pclose_phigs();
    return finish("test_plus_data");
}
