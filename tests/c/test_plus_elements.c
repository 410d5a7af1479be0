/* PHIGS PLUS through the C binding: every attribute element and the NURBS curve and surface
 * stored and read back through pinq_elem_content (types, values, homogeneous points, trimming
 * loops), refusals (state 5, bad enumerations, bad B-spline data), and the light source and
 * depth cue representations set and inquired on a workstation. */
#include "check.h"

static Pstore store;

static Pelem_data* content(Pint pos, Pelem_type expected) {
    Pint err = -1;
    Pelem_type type = PELEM_NIL;
    size_t size = 0;
    Pelem_data* data = NULL;
    pinq_elem_type_size(1, pos, &err, &type, &size);
    CHECK(err == 0 && type == expected);
    if (type != expected)
        fprintf(stderr, "  element %d: type %d, expected %d\n", (int)pos, (int)type, (int)expected);
    pinq_elem_content(1, pos, store, &err, &data);
    CHECK(err == 0 && data != NULL);
    return err == 0 ? data : NULL;
}

static void attributes(void) {
    Prefl_props props = {0.25f, 0.5f, 0.75f, {PMODEL_RGB, {.general = {1, 0.5f, 0}}}, 8, 0.125f};
    Pgcolr back = {PINDIRECT, {.ind = 3}};
    Pint on[2] = {1, 2}, off[1] = {3};
    Pint_list activation = {2, on}, deactivation = {1, off};
    Ppara_surf_characs iso;
    Pelem_data* d;
    iso.psc_3.placement = PCP_NON_UNIFORM, iso.psc_3.u_count = 4, iso.psc_3.v_count = 5;
    popen_struct(1);
    EXPECT_NO_ERROR(pset_line_shad_meth(PSD_COLOUR));                                /* 1 */
    EXPECT_NO_ERROR(pset_int_shad_meth(PSD_NORMAL));                                 /* 2 */
    EXPECT_NO_ERROR(pset_back_int_shad_meth(PSD_DOT_PRODUCT));                       /* 3 */
    EXPECT_NO_ERROR(pset_refl_eqn(PREFL_AMB_DIFF_SPEC));                             /* 4 */
    EXPECT_NO_ERROR(pset_back_refl_eqn(PREFL_AMBIENT));                              /* 5 */
    EXPECT_NO_ERROR(pset_refl_props(&props));                                        /* 6 */
    EXPECT_NO_ERROR(pset_back_refl_props(&props));                                   /* 7 */
    EXPECT_NO_ERROR(pset_back_int_style(PSTYLE_SOLID));                              /* 8 */
    EXPECT_NO_ERROR(pset_back_int_style_ind(6));                                     /* 9 */
    EXPECT_NO_ERROR(pset_back_int_colr(&back));                                      /* 10 */
    EXPECT_NO_ERROR(pset_face_disting_mode(PDISTING_YES));                           /* 11 */
    EXPECT_NO_ERROR(pset_face_cull_mode(PCULL_BACKFACE));                            /* 12 */
    EXPECT_NO_ERROR(pset_light_src_state(&activation, &deactivation));               /* 13 */
    EXPECT_NO_ERROR(pset_dcue_ind(2));                                               /* 14 */
    EXPECT_NO_ERROR(pset_colr_map_ind(0));                                           /* 15 */
    EXPECT_NO_ERROR(pset_curve_approx(PCURV_CHORDAL_DEVIATION_WC, 0.5f));            /* 16 */
    EXPECT_NO_ERROR(pset_surf_approx(PSURF_CONST_PARAM_SUBDIV_BETWEEN_KNOTS, 3, 4)); /* 17 */
    EXPECT_NO_ERROR(pset_para_surf_characs(PSC_ISOPARAMETRIC_CURVES, &iso));         /* 18 */
    EXPECT_NO_ERROR(pset_para_surf_characs(PSC_WS_DEP, NULL));                       /* 19 */
    EXPECT_REFUSED(pset_int_shad_meth(5), PE_ENUM_TYPE_INVAL, Pfn_set_int_shad_meth);
    EXPECT_REFUSED(pset_line_shad_meth(PSD_NORMAL), PE_ENUM_TYPE_INVAL, Pfn_set_line_shad_meth);
    EXPECT_REFUSED(pset_face_cull_mode((Pcull_mode)3), PE_ENUM_TYPE_INVAL, Pfn_set_face_cull_mode);
    EXPECT_REFUSED(pset_refl_props(NULL), -204, Pfn_set_refl_props);
    EXPECT_REFUSED(pset_para_surf_characs(6, &iso), -202, Pfn_set_para_surf_characs);
    pclose_struct();
    EXPECT_ERROR(pset_dcue_ind(1), 5, Pfn_set_dcue_ind);

    if ((d = content(1, PELEM_LINE_SHAD_METH))) CHECK(d->int_data == PSD_COLOUR);
    if ((d = content(2, PELEM_INT_SHAD_METH))) CHECK(d->int_data == PSD_NORMAL);
    if ((d = content(3, PELEM_BACK_INT_SHAD_METH))) CHECK(d->int_data == PSD_DOT_PRODUCT);
    if ((d = content(4, PELEM_REFL_EQN))) CHECK(d->int_data == PREFL_AMB_DIFF_SPEC);
    if ((d = content(5, PELEM_BACK_REFL_EQN))) CHECK(d->int_data == PREFL_AMBIENT);
    if ((d = content(6, PELEM_REFL_PROPS)))
        CHECK(d->props.ambient_coef == 0.25f && d->props.diffuse_coef == 0.5f &&
              d->props.specular_coef == 0.75f && d->props.specular_colr.type == PMODEL_RGB &&
              d->props.specular_colr.val.general.y == 0.5f && d->props.specular_exp == 8 &&
              d->props.transpar_coef == 0.125f);
    if ((d = content(7, PELEM_BACK_REFL_PROPS))) CHECK(d->props.specular_exp == 8);
    if ((d = content(8, PELEM_BACK_INT_STYLE))) CHECK(d->int_style == PSTYLE_SOLID);
    if ((d = content(9, PELEM_BACK_INT_STYLE_IND))) CHECK(d->int_data == 6);
    if ((d = content(10, PELEM_BACK_INT_COLR_IND))) CHECK(d->int_data == 3);
    if ((d = content(11, PELEM_FACE_DISTING_MODE))) CHECK(d->disting_mode == PDISTING_YES);
    if ((d = content(12, PELEM_FACE_CULL_MODE))) CHECK(d->cull_mode == PCULL_BACKFACE);
    if ((d = content(13, PELEM_LIGHT_SRC_STATE)))
        CHECK(d->lss.activation.num_ints == 2 && d->lss.activation.ints[1] == 2 &&
              d->lss.deactivation.num_ints == 1 && d->lss.deactivation.ints[0] == 3);
    if ((d = content(14, PELEM_DCUE_IND))) CHECK(d->int_data == 2);
    if ((d = content(15, PELEM_COLR_MAP_IND))) CHECK(d->int_data == 0);
    if ((d = content(16, PELEM_CURVE_APPROX_CRIT)))
        CHECK(d->curv_approx.type == PCURV_CHORDAL_DEVIATION_WC && d->curv_approx.value == 0.5f);
    if ((d = content(17, PELEM_SURF_APPROX_CRIT)))
        CHECK(d->surf_approx.type == PSURF_CONST_PARAM_SUBDIV_BETWEEN_KNOTS && d->surf_approx.u_val == 3 &&
              d->surf_approx.v_val == 4);
    if ((d = content(18, PELEM_PARA_SURF_CHARS)))
        CHECK(d->para_surf_characs.type == PSC_ISOPARAMETRIC_CURVES &&
              d->para_surf_characs.data.psc_3.placement == PCP_NON_UNIFORM &&
              d->para_surf_characs.data.psc_3.u_count == 4 && d->para_surf_characs.data.psc_3.v_count == 5);
    if ((d = content(19, PELEM_PARA_SURF_CHARS))) CHECK(d->para_surf_characs.type == PSC_WS_DEP);
}

static void nurbs(void) {
    /* A rational quadratic arc (a quarter circle): weights 1, sqrt(2)/2, 1. */
    const Pfloat h = 0.70710678f;
    Pfloat knots[6] = {0, 0, 0, 1, 1, 1};
    Pfloat_list knot_list = {6, knots};
    Ppoint4 arc[3] = {{1, 0, 0, 1}, {h, h, 0, h}, {0, 1, 0, 1}};
    Ppoint_list34 arc_points;
    /* A bilinear patch (orders 2 x 2), 3 x 2 points, u fastest, with a triangular trim loop. */
    Pfloat uk[5] = {0, 0, 0.5f, 1, 1}, vk[4] = {0, 0, 1, 1};
    Pfloat_list uknots = {5, uk}, vknots = {4, vk};
    Ppoint3 grid_points[6] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 1}, {2, 1, 0}};
    Ppoint_grid34 grid;
    Pfloat tk[6] = {0, 0, 1, 2, 3, 3};
    Ppoint trim_points[4] = {{0.1f, 0.1f}, {0.9f, 0.1f}, {0.5f, 0.9f}, {0.1f, 0.1f}};
    Ptrimcurve trim;
    Ptrimcurve_list loop = {1, &trim};
    Pelem_data* d;
    arc_points.point4d.num_points = 3, arc_points.point4d.points = arc;
    grid.num_points.size_x = 3, grid.num_points.size_y = 2, grid.points.point3d = grid_points;
    memset(&trim, 0, sizeof trim);
    trim.visible = PEDGE_ON, trim.rationality = PNON_RATIONAL, trim.order = 2;
    trim.approx_type = PCURV_CONST_PARAM_SUBDIV_BETWEEN_KNOTS, trim.approx_val = 5;
    trim.knots.num_floats = 6, trim.knots.floats = tk;
    trim.cpts.point2d.num_points = 4, trim.cpts.point2d.points = trim_points;

    popen_struct(1);
    pempty_struct(1);
    EXPECT_NO_ERROR(pnuni_bsp_curv(3, &knot_list, PRATIONAL, &arc_points, 0, 0));
    EXPECT_NO_ERROR(pnuni_bsp_surf(2, 2, &uknots, &vknots, PNON_RATIONAL, &grid, 1, &loop));
    knot_list.num_floats = 5; /* order + points is 6 */
    EXPECT_REFUSED(pnuni_bsp_curv(3, &knot_list, PRATIONAL, &arc_points, 0, 0), -202, Pfn_nuni_bsp_curv);
    knot_list.num_floats = 6;
    arc[1].w = 0;
    EXPECT_REFUSED(pnuni_bsp_curv(3, &knot_list, PRATIONAL, &arc_points, 0, 0), -202, Pfn_nuni_bsp_curv);
    arc[1].w = h;
    EXPECT_REFUSED(pnuni_bsp_curv(3, &knot_list, (Prational)5, &arc_points, 0, 0), PE_ENUM_TYPE_INVAL,
                   Pfn_nuni_bsp_curv);
    EXPECT_REFUSED(pnuni_bsp_surf(2, 2, &uknots, &vknots, PNON_RATIONAL, NULL, 0, NULL), -204,
                   Pfn_nuni_bsp_surf);
    /* A visibility other than PEDGE_OFF / PEDGE_ON, or an approximation value that is not
     * finite, is refused; PCURV_WS_DEP keeps no value (answered 1). */
    trim.visible = (Pedge_flag)3;
    EXPECT_REFUSED(pnuni_bsp_surf(2, 2, &uknots, &vknots, PNON_RATIONAL, &grid, 1, &loop), PE_ENUM_TYPE_INVAL,
                   Pfn_nuni_bsp_surf);
    trim.visible = PEDGE_OFF, trim.approx_val = (Pfloat)NAN;
    EXPECT_REFUSED(pnuni_bsp_surf(2, 2, &uknots, &vknots, PNON_RATIONAL, &grid, 1, &loop), -202,
                   Pfn_nuni_bsp_surf);
    trim.approx_type = PCURV_WS_DEP, trim.approx_val = 3;
    /* A trim curve trims over [tmin, tmax] only: the part from t = 1 to 2 is the edge
     * (0.9, 0.1) - (0.5, 0.9); a range outside the knots' domain or reversed is refused. */
    trim.tmin = 1, trim.tmax = 2;
    EXPECT_NO_ERROR(pnuni_bsp_surf(2, 2, &uknots, &vknots, PNON_RATIONAL, &grid, 1, &loop));
    trim.tmin = 2, trim.tmax = 1;
    EXPECT_REFUSED(pnuni_bsp_surf(2, 2, &uknots, &vknots, PNON_RATIONAL, &grid, 1, &loop), -202,
                   Pfn_nuni_bsp_surf);
    trim.tmin = -1, trim.tmax = 2;
    EXPECT_REFUSED(pnuni_bsp_surf(2, 2, &uknots, &vknots, PNON_RATIONAL, &grid, 1, &loop), -202,
                   Pfn_nuni_bsp_surf);
    trim.tmin = 0, trim.tmax = 3.5f;
    EXPECT_REFUSED(pnuni_bsp_surf(2, 2, &uknots, &vknots, PNON_RATIONAL, &grid, 1, &loop), -202,
                   Pfn_nuni_bsp_surf);
    pclose_struct();

    if ((d = content(1, PELEM_NUNI_BSP_CURVE))) {
        CHECK(d->nuni_bsp_curv.order == 3 && d->nuni_bsp_curv.rationality == PRATIONAL);
        CHECK(d->nuni_bsp_curv.knots.num_floats == 6 && d->nuni_bsp_curv.knots.floats[3] == 1);
        CHECK(d->nuni_bsp_curv.cpts.point4d.num_points == 3);
        CHECK(near(d->nuni_bsp_curv.cpts.point4d.points[1].x, h) &&
              near(d->nuni_bsp_curv.cpts.point4d.points[1].w, h));
    }
    if ((d = content(2, PELEM_NUNI_BSP_SURF))) {
        CHECK(d->nuni_bsp_surf.u_order == 2 && d->nuni_bsp_surf.v_order == 2);
        CHECK(d->nuni_bsp_surf.uknots.num_floats == 5 && d->nuni_bsp_surf.vknots.num_floats == 4);
        CHECK(d->nuni_bsp_surf.grid.num_points.size_x == 3 && d->nuni_bsp_surf.grid.num_points.size_y == 2);
        CHECK(d->nuni_bsp_surf.grid.points.point3d[4].z == 1 &&
              d->nuni_bsp_surf.grid.points.point3d[2].x == 2);
        CHECK(d->nuni_bsp_surf.num_trim_loops == 1 && d->nuni_bsp_surf.trim_loops[0].num_curves == 1);
        if (d->nuni_bsp_surf.num_trim_loops == 1) {
            const Ptrimcurve* t = &d->nuni_bsp_surf.trim_loops[0].curves[0];
            CHECK(t->order == 2 && t->rationality == PNON_RATIONAL && t->knots.num_floats == 6);
            CHECK(t->cpts.point2d.num_points == 4 && near(t->cpts.point2d.points[2].y, 0.9));
            CHECK(t->tmin == 0 && t->tmax == 3); /* tmin == tmax: the whole domain */
            CHECK(t->visible == PEDGE_ON && t->approx_type == PCURV_CONST_PARAM_SUBDIV_BETWEEN_KNOTS &&
                  t->approx_val == 5);
        }
    }
    d = content(3, PELEM_NUNI_BSP_SURF);
    CHECK(d && d->nuni_bsp_surf.num_trim_loops == 1 && d->nuni_bsp_surf.trim_loops[0].num_curves == 1);
    if (d && d->nuni_bsp_surf.num_trim_loops == 1 && d->nuni_bsp_surf.trim_loops[0].num_curves == 1) {
        const Ptrimcurve* t = &d->nuni_bsp_surf.trim_loops[0].curves[0];
        CHECK(t->order == 2 && t->tmin == 1 && t->tmax == 2 && t->cpts.point2d.num_points == 2);
        CHECK(t->visible == PEDGE_OFF && t->approx_type == PCURV_WS_DEP && t->approx_val == 1);
        CHECK(t->knots.num_floats == 4 && t->knots.floats[0] == 1 && t->knots.floats[3] == 2);
        if (t->cpts.point2d.num_points == 2) {
            CHECK(near(t->cpts.point2d.points[0].x, 0.9) && near(t->cpts.point2d.points[0].y, 0.1));
            CHECK(near(t->cpts.point2d.points[1].x, 0.5) && near(t->cpts.point2d.points[1].y, 0.9));
        }
    }
}

static void with_data(void) {
    Pptconorm3 square[4] = {{{0, 0, 0}, {.direct = {.rgb = {1, 0, 0}}}, {0, 0, 1}},
                            {{1, 0, 0}, {.direct = {.rgb = {0, 1, 0}}}, {0, 0, 1}},
                            {{1, 1, 0}, {.direct = {.rgb = {0, 0, 1}}}, {0, 0, 1}},
                            {{0, 1, 0}, {.direct = {.rgb = {1, 1, 1}}}, {0, 0, 1}}};
    Pfacet_vdata_list3 area;
    Pfacet_data3 facet;
    Pptnorm3 strip[3] = {{{0, 0, 0}, {0, 0, 1}}, {{1, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 1, 0}}};
    Pfacet_vdata_arr3 strip_data, mesh_data;
    Ppoint3 mesh[6] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 1}};
    Pint_size dim = {3, 2};
    Pvec3 normal = {0, 0, 0};
    Pint err = -1;
    Pelem_data* d;
    area.num_vertices = 4, area.vertex_data.ptconorms = square;
    facet.conorm.colr.direct.rgb.red = 0.5f, facet.conorm.colr.direct.rgb.green = 0.25f, facet.conorm.colr.direct.rgb.blue = 0;
    facet.conorm.norm.delta_x = 0, facet.conorm.norm.delta_y = 0, facet.conorm.norm.delta_z = 1;
    strip_data.ptnorms = strip;
    mesh_data.points = mesh;
    popen_struct(1);
    pempty_struct(1);
    EXPECT_NO_ERROR(pfill_area_set3_data(PFACET_COLOUR_NORMAL, PEDGE_NONE, PVERT_COORD_COLOUR_NORMAL,
                                         PMODEL_RGB, &facet, 1, NULL, &area));
    EXPECT_NO_ERROR(ptri_strip3_data(PFACET_NONE, PVERT_COORD_NORMAL, PINDIRECT, 3, NULL, &strip_data));
    EXPECT_NO_ERROR(pquad_mesh3_data(PFACET_NONE, PVERT_COORD, PINDIRECT, &dim, NULL, &mesh_data));
    EXPECT_REFUSED(ptri_strip3_data(PFACET_NORMAL, PVERT_COORD_NORMAL, PINDIRECT, 3, NULL, &strip_data), -204,
                   Pfn_tri_strip3_data);
    EXPECT_REFUSED(
        pfill_area_set3_data(PFACET_NONE, PEDGE_VISIBILITY, PVERT_COORD, PINDIRECT, NULL, 1, NULL, &area),
        -204, Pfn_fill_area_set3_data);
    EXPECT_REFUSED(pquad_mesh3_data(PFACET_NONE, 7, PINDIRECT, &dim, NULL, &mesh_data), PE_ENUM_TYPE_INVAL,
                   Pfn_quad_mesh3_data);
    pclose_struct();
    if ((d = content(1, PELEM_FILL_AREA_SET3_DATA))) {
        CHECK(d->fas3_data.fflag == PFACET_COLOUR_NORMAL && d->fas3_data.vflag == PVERT_COORD_COLOUR_NORMAL);
        CHECK(d->fas3_data.colr_type == PMODEL_RGB && d->fas3_data.fdata.conorm.colr.direct.rgb.green == 0.25f);
        CHECK(d->fas3_data.nfa == 1 && d->fas3_data.vdata[0].num_vertices == 4);
        CHECK(d->fas3_data.vdata[0].vertex_data.ptconorms[2].colr.direct.rgb.blue == 1 &&
              d->fas3_data.vdata[0].vertex_data.ptconorms[2].point.y == 1);
    }
    if ((d = content(2, PELEM_TRI_STRIP3_DATA)))
        CHECK(d->tri_strip3.nv == 3 && d->tri_strip3.vflag == PVERT_COORD_NORMAL &&
              d->tri_strip3.vdata.ptnorms[2].norm.delta_y == 1);
    if ((d = content(3, PELEM_QUAD_MESH3_DATA)))
        CHECK(d->quad_mesh3.dim.size_x == 3 && d->quad_mesh3.dim.size_y == 2 &&
              d->quad_mesh3.vflag == PVERT_COORD && d->quad_mesh3.vdata.points[5].z == 1);
    /* The geometric normal of the square (counter-clockwise seen from +z). */
    pcomp_fill_area_set_gnorm(PVERT_COORD_COLOUR_NORMAL, 1, &area, &err, &normal);
    CHECK(err == 0 && near(normal.delta_z, 1) && near(normal.delta_x, 0));
    area.num_vertices = 2;
    pcomp_fill_area_set_gnorm(PVERT_COORD_COLOUR_NORMAL, 1, &area, &err, &normal);
    CHECK(err == -202);
}

static void representations(const char* pdf) {
    Plight_src_bundle spot, got;
    Pdcue_bundle cue = {PALLOWED, {0.9f, 0.1f}, {1, 0.25f}, {PMODEL_RGB, {.general = {0.5f, 0.5f, 0.5f}}}},
                 cue_got;
    Pint buffer[8], total = -1, err = -1;
    Pint_list inds = {0, buffer};
    memset(&spot, 0, sizeof spot);
    spot.type = PLIGHT_SPOT;
    spot.rec.spot.colr.type = PMODEL_RGB;
    spot.rec.spot.colr.val.general.x = 1;
    spot.rec.spot.pos.z = 5;
    spot.rec.spot.dir.delta_z = -1;
    spot.rec.spot.exp = 2;
    spot.rec.spot.coef[0] = 1, spot.rec.spot.coef[1] = 0.5f;
    spot.rec.spot.angle = 0.5f;
    EXPECT_ERROR(pset_light_src_rep(1, 2, &spot), 3, Pfn_set_light_src_rep);
    popen_ws(1, pdf, PWST_PDF);
    EXPECT_NO_ERROR(pset_light_src_rep(1, 2, &spot));
    EXPECT_ERROR(pset_light_src_rep(1, 0, &spot), 100, Pfn_set_light_src_rep);
    spot.type = 9;
    EXPECT_ERROR(pset_light_src_rep(1, 3, &spot), PE_ENUM_TYPE_INVAL, Pfn_set_light_src_rep);
    pinq_light_src_rep(1, 2, PINQ_SET, &err, &got);
    CHECK(err == 0 && got.type == PLIGHT_SPOT && got.rec.spot.pos.z == 5 && got.rec.spot.exp == 2 &&
          got.rec.spot.coef[1] == 0.5f && near(got.rec.spot.angle, 0.5) &&
          got.rec.spot.colr.val.general.x == 1);
    pinq_light_src_rep(1, 3, PINQ_REALIZED, &err, &got);
    CHECK(err == 101);
    pinq_list_light_src_inds(1, 8, 0, &err, &inds, &total);
    CHECK(err == 0 && total == 2 && buffer[0] == 1 && buffer[1] == 2);
    cue.colr.type = PINDIRECT, cue.colr.val.ind = -1;
    EXPECT_ERROR(pset_dcue_rep(1, 1, &cue), 113, Pfn_set_dcue_rep);
    cue.colr.type = PMODEL_RGB, cue.colr.val.general.x = cue.colr.val.general.y = cue.colr.val.general.z = 0.5f;
    EXPECT_NO_ERROR(pset_dcue_rep(1, 1, &cue));
    pinq_dcue_rep(1, 1, PINQ_SET, &err, &cue_got);
    CHECK(err == 0 && cue_got.mode == PALLOWED && cue_got.ref_planes[0] == 0.9f &&
          cue_got.scaling[1] == 0.25f && cue_got.colr.val.general.z == 0.5f);
    pinq_dcue_rep(1, 0, PINQ_SET, &err, &cue_got);
    CHECK(err == 0 && cue_got.mode == PSUPPRESSED);
    pinq_list_dcue_inds(1, 8, 0, &err, &inds, &total);
    CHECK(err == 0 && total == 2 && buffer[0] == 0 && buffer[1] == 1);
    pinq_dcue_rep(2, 0, PINQ_SET, &err, &cue_got);
    CHECK(err == 54);
    pclose_ws(1);
    pinq_pred_light_src_rep(PWST_PDF, 1, &err, &got);
    CHECK(err == 0 && got.type == PLIGHT_AMBIENT && got.rec.ambient.colr.val.general.y == 1);
    pinq_pred_light_src_rep(PWST_PDF, 2, &err, &got);
    CHECK(err == 102);
    pinq_pred_light_src_rep(99, 1, &err, &got);
    CHECK(err == 52);
    pinq_pred_dcue_rep(PWST_OFFSCREEN, 0, &err, &cue_got);
    CHECK(err == 0 && cue_got.mode == PSUPPRESSED);
    {
        Plight_src_facs facs;
        facs.types.ints = buffer;
        pinq_light_src_facs(PWST_PDF, 8, 0, &err, &facs, &total);
        CHECK(err == 0 && total == 4 && facs.types.num_ints == 4 && buffer[3] == PLIGHT_SPOT &&
              facs.max > 1 && facs.num_pred_inds == 1);
    }
    pinq_dcue_facs(PWST_SVG, &err, &total);
    CHECK(err == 0 && total == 1);
    inds.ints = buffer;
    pinq_rendering_colr_model_facs(PWST_PNG, 8, 0, &err, &inds, &total);
    CHECK(err == 0 && total == 4 && inds.num_ints == 4 && buffer[0] == PRCM_RGB && buffer[1] == PRCM_CIE &&
          buffer[2] == PRCM_HSV && buffer[3] == PRCM_HLS);
    pinq_rendering_colr_model_facs(PWST_PNG, 1, 2, &err, &inds, &total);
    CHECK(err == 0 && total == 4 && inds.num_ints == 1 && buffer[0] == PRCM_HSV);
    buffer[0] = 0;
    pinq_direct_colr_model_facs(PWST_PNG, 8, 0, &err, &total, &inds);
    CHECK(err == 0 && total == 4 && inds.num_ints == 4 && buffer[0] == PMODEL_RGB && buffer[3] == PMODEL_HLS);
    {
        Pint a[4], b[4], c[4], e[4], totals[4] = {0, 0, 0, 0};
        Pcurvsurf_facs facs;
        facs.cat_types.ints = a, facs.sat_types.ints = b, facs.tcat_types.ints = c, facs.psc_types.ints = e;
        pinq_curv_surf_facs(PWST_OFFSCREEN, 4, 0, 4, 1, 4, 0, 4, 0, &err, &facs, &totals[0], &totals[1],
                            &totals[2], &totals[3]);
        CHECK(err == 0 && totals[0] == 3 && totals[1] == 3 && totals[2] == 1 && totals[3] == 5);
        CHECK(facs.sat_types.num_ints == 2 && b[1] == PSURF_CHORDAL_DEVIATION_WC &&
              e[2] == PSC_ISOPARAMETRIC_CURVES);
        CHECK(facs.max_bsp_order >= 4);
        pinq_curv_surf_facs(PWST_OFFSCREEN, 4, 5, 4, 0, 4, 0, 4, 0, &err, &facs, &totals[0], &totals[1],
                            &totals[2], &totals[3]);
        CHECK(err == PE_START_IND_INVAL);
    }
}

int main(int argc, char** argv) {
    char file[512], pdf[512];
    Pint err = -1;
    const char* dir = argc > 1 ? argv[1] : ".";
    snprintf(file, sizeof file, "%s/plus_errors.txt", dir);
    snprintf(pdf, sizeof pdf, "%s/plus.pdf", dir);
    open_with_handler(file);
    pcreate_store(&err, &store);
    attributes();
    nurbs();
    with_data();
    representations(pdf);
    pdel_store(store);
    pclose_phigs();
    return finish("test_plus_elements");
}
