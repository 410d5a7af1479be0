/* Back faces and polyline shading drawn on the offscreen type (lavapipe, validation layer on)
 * and the PDF type (rasterised by pdftoppm at 144 dpi):
 * seeded random triangles, front or back facing, under every face distinguishing mode, face
 * culling mode and front and back interior style, show at their centre the front colour, the back colour
 * or the background exactly as the rules say; seeded random squares wound either way under random
 * front and back styles, face distinguishing and culling show a HOLLOW side's outline, in that
 * side's colour, exactly when that side faces the viewer and is not culled; and a polyline set with data
 * whose two vertex colours are random shows at its midpoint their mean with polyline shading PSD_COLOUR, its
 * first vertex's colour with PSD_NONE; and a lit square shows black with no light active, and its
 * lit colour clamped to 1 before the depth cue scales it; and a facet normal lights its facet; and
 * flat shading (PSD_NONE) fills each facet with its facet colour or the interior colour alone;
 * and in a perspective view the specular term takes V toward the centre of projection at each
 * point (Phong on the raster across a triangle, flat at its centroid on paper).
 * argv[1]: a directory for the files. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"

#include "picture.h"

/* Whether the pixel at NPC (x, y) is `rgb` (NULL: the background, the pixel at NPC (0.02, 0.02)),
 * within 2/255. */
static int pixel_is(const Picture* p, double x, double y, const double* rgb, const char* what) {
    const unsigned char* c = picture_pixel(p, x, y);
    const unsigned char* background = picture_pixel(p, 0.02, 0.02);
    double expected[3];
    int ok = 1;
    for (int k = 0; k < 3; ++k) expected[k] = rgb ? 255 * rgb[k] : background[k];
    for (int k = 0; k < 3; ++k) ok = ok && fabs(c[k] - expected[k]) <= 2.5;
    if (!ok)
        fprintf(stderr, "  %s, %s: pixel at NPC (%.3f, %.3f) is %d %d %d, expected %.1f %.1f %.1f\n", p->name,
                what, x, y, c[0], c[1], c[2], expected[0], expected[1], expected[2]);
    return ok;
}

static Pgcolr direct(const double c[3]) {
    Pgcolr g;
    g.type = PMODEL_RGB;
    g.val.general.x = (Pfloat)c[0], g.val.general.y = (Pfloat)c[1], g.val.general.z = (Pfloat)c[2];
    return g;
}

static void random_rgb(double c[3]) {
    /* Multiples of 1/255: what the picture can hold exactly. */
    for (int k = 0; k < 3; ++k) c[k] = (double)(next_random() % 256u) / 255.0;
}

static PictureFiles files;

/* Structure 1 anew: `area` under the given front and back interior styles and colours, face
 * distinguishing and culling. */
static void fill_with_sides(const Ppoint_list3* area, Pint_style frontStyle, Pint_style backStyle,
                            const Pgcolr* f, const Pgcolr* b, int distinguish, Pcull_mode cull) {
    pdel_struct(1);
    popen_struct(1);
    pset_int_style(frontStyle);
    pset_int_colr(f);
    pset_back_int_colr(b);
    pset_back_int_style(backStyle);
    pset_face_disting_mode(distinguish ? PDISTING_YES : PDISTING_NO);
    pset_face_cull_mode(cull);
    pfill_area3(area);
    pclose_struct();
}

static void back_faces(void) {
    int filledBackUnderOpenFront = 0;
    for (int round = 0; round < 32; ++round) {
        double front[3], back[3];
        /* Every fourth round a filled back under an open (HOLLOW or EMPTY) front, shown. */
        const int openFront = round % 4 == 0;
        const int backFacing = openFront || (int)(next_random() % 2),
                  distinguish = openFront || (int)(next_random() % 2);
        const Pcull_mode cull = (Pcull_mode)(next_random() % 3);
        const Pint_style frontStyle = (Pint_style)(next_random() % 3 == 0                ? PSTYLE_EMPTY
                                                   : next_random() % 2 == 0 || openFront ? PSTYLE_HOLLOW
                                                                                         : PSTYLE_SOLID);
        const Pint_style backStyle = (Pint_style)(openFront || next_random() % 3 != 0 ? PSTYLE_SOLID
                                                  : next_random() % 2 == 0            ? PSTYLE_HOLLOW
                                                                                      : PSTYLE_EMPTY);
        const double cx = random_real(0.3, 0.7), cy = random_real(0.3, 0.7), r = random_real(0.1, 0.2);
        Ppoint3 corners[3];
        Ppoint_list3 triangle = {3, corners};
        Pgcolr f, b;
        Picture p[2];
        const double* expected;
        random_rgb(front), random_rgb(back);
        f = direct(front), b = direct(back);
        for (int k = 0; k < 3; ++k) {
            /* Counter-clockwise seen from +z (front facing) or clockwise. */
            const double a = (backFacing ? -1 : 1) * k * 2.0943951 + 0.3;
            corners[k].x = (Pfloat)(cx + r * cos(a)), corners[k].y = (Pfloat)(cy + r * sin(a)),
            corners[k].z = 0;
        }
        fill_with_sides(&triangle, frontStyle, backStyle, &f, &b, distinguish, cull);
        /* Each side by its own style: a SOLID back shows under a HOLLOW or EMPTY front too; a
         * HOLLOW side shows its outline only, away from the centre. */
        if ((backFacing && cull == PCULL_BACKFACE) || (!backFacing && cull == PCULL_FRONTFACE))
            expected = NULL; /* the background */
        else if (!backFacing || !distinguish)
            expected = frontStyle == PSTYLE_SOLID ? front : NULL;
        else
            expected = backStyle == PSTYLE_SOLID ? back : NULL;
        if (expected == back && frontStyle != PSTYLE_SOLID) ++filledBackUnderOpenFront;
        CHECK(draw_offscreen_and_pdf(&files, p));
        for (int i = 0; i < 2; ++i) {
            char what[160];
            snprintf(what, sizeof what, "triangle %s, distinguishing %d, cull %d, styles %d / %d",
                     backFacing ? "back" : "front", distinguish, (int)cull, (int)frontStyle, (int)backStyle);
            if (p[i].rgb) CHECK(pixel_is(&p[i], cx, cy, expected, what));
            free(p[i].rgb);
        }
    }
    CHECK(filledBackUnderOpenFront >= 2); /* the sequence reaches the case */
}

/* The colour nearest `rgb` among the pixels within 3 of NPC (x, y) along the y axis: its largest
 * channel difference, in 1/255. */
static double nearest_along_y(const Picture* p, double x, double y, const double rgb[3]) {
    double best = 1e9;
    for (int d = -3; d <= 3; ++d) {
        const unsigned char* c = picture_pixel(p, x, y + d / p->side);
        double worst = 0;
        for (int k = 0; k < 3; ++k) worst = fmax(worst, fabs(c[k] - 255 * rgb[k]));
        best = fmin(best, worst);
    }
    return best;
}

static void hollow_outlines(void) {
    int backOutlines = 0, hiddenFrontOutlines = 0;
    for (int round = 0; round < 16; ++round) {
        double front[3], back[3];
        /* Every fourth round a HOLLOW front seen from the back, every fourth a HOLLOW back shown. */
        const int hollowFront = round % 4 == 1, hollowBack = round % 4 == 2;
        const int backFacing = hollowFront || hollowBack || (int)(next_random() % 2);
        const int distinguish = hollowFront || hollowBack || round % 3 != 0;
        const Pcull_mode cull =
            (Pcull_mode)(next_random() % 4 == 0 && !hollowFront && !hollowBack ? 1 + next_random() % 2
                                                                               : PCULL_NONE);
        const Pint_style styles[3] = {PSTYLE_HOLLOW, PSTYLE_SOLID, PSTYLE_EMPTY};
        const Pint_style frontStyle = hollowFront ? PSTYLE_HOLLOW : styles[next_random() % 3];
        const Pint_style backStyle = hollowBack    ? PSTYLE_HOLLOW
                                     : hollowFront ? styles[1 + next_random() % 2]
                                                   : styles[next_random() % 3];
        double x0, y0, side;
        Ppoint3 corners[4];
        Ppoint_list3 square = {4, corners};
        Pgcolr f, b;
        Picture p[2];
        random_square(corners, backFacing, &x0, &y0, &side);
        /* Bright, far from the black background and from each other. */
        do {
            for (int k = 0; k < 3; ++k)
                front[k] = (double)(128 + next_random() % 128u) / 255.0,
                back[k] = (double)(next_random() % 256u) / 255.0;
        } while (fabs(front[0] - back[0]) + fabs(front[1] - back[1]) + fabs(front[2] - back[2]) < 0.6 ||
                 back[0] + back[1] + back[2] < 0.8);
        f = direct(front), b = direct(back);
        fill_with_sides(&square, frontStyle, backStyle, &f, &b, distinguish, cull);
        const int culled = (backFacing && cull == PCULL_BACKFACE) || (!backFacing && cull == PCULL_FRONTFACE);
        const int useBack = backFacing && distinguish;
        const Pint_style shown = useBack ? backStyle : frontStyle;
        const double* colour = useBack ? back : front;
        const int outline = !culled && shown == PSTYLE_HOLLOW;
        backOutlines += outline && useBack;
        hiddenFrontOutlines += !outline && backFacing && frontStyle == PSTYLE_HOLLOW;
        CHECK(draw_offscreen_and_pdf(&files, p));
        for (int i = 0; i < 2; ++i) {
            if (!p[i].rgb) continue;
            /* The bottom edge's middle, and the middle of the square (a SOLID side covers both). */
            const double x = x0 + side / 2;
            if (shown == PSTYLE_SOLID && !culled) continue;
            const double onEdge = nearest_along_y(&p[i], x, y0, colour);
            const double otherSide = nearest_along_y(&p[i], x, y0, useBack ? front : back);
            if (outline ? onEdge > 24 : onEdge < 48 || otherSide < 48) {
                fprintf(
                    stderr,
                    "  %s: square %s, distinguishing %d, cull %d, styles %d / %d: outline %s (nearest %.0f, "
                    "the other side's %.0f)\n",
                    p[i].name, backFacing ? "back" : "front", distinguish, (int)cull, (int)frontStyle,
                    (int)backStyle, outline ? "missing" : "drawn", onEdge, otherSide);
                CHECK(0);
            }
            CHECK(pixel_is(&p[i], x, y0 + side / 2, NULL, "the middle of a square with an open side"));
        }
        for (int i = 0; i < 2; ++i) free(p[i].rgb);
    }
    CHECK(backOutlines >= 2); /* the sequence reaches the cases */
    CHECK(hiddenFrontOutlines >= 2);
}

static void line_shading(void) {
    for (int round = 0; round < 12; ++round) {
        double c0[3], c1[3], mid[3];
        const int shaded = round % 2;
        const double y = random_real(0.2, 0.8);
        Pptco3 vertices[2];
        Pline_vdata_list3 line;
        Picture p[2];
        random_rgb(c0), random_rgb(c1);
        for (int k = 0; k < 3; ++k) mid[k] = (c0[k] + c1[k]) / 2;
        vertices[0].point.x = 0.1f, vertices[1].point.x = 0.9f;
        vertices[0].point.y = vertices[1].point.y = (Pfloat)y;
        vertices[0].point.z = vertices[1].point.z = 0;
        vertices[0].colr.direct.rgb.red = (Pfloat)c0[0], vertices[0].colr.direct.rgb.green = (Pfloat)c0[1],
        vertices[0].colr.direct.rgb.blue = (Pfloat)c0[2];
        vertices[1].colr.direct.rgb.red = (Pfloat)c1[0], vertices[1].colr.direct.rgb.green = (Pfloat)c1[1],
        vertices[1].colr.direct.rgb.blue = (Pfloat)c1[2];
        line.num_vertices = 2, line.vertex_data.ptcolrs = vertices;
        pdel_struct(1);
        popen_struct(1);
        pset_linewidth(6);
        pset_line_shad_meth(shaded ? PSD_COLOUR : PSD_NONE);
        ppolyline_set3_data(PVERT_COORD_COLOUR, PMODEL_RGB, 1, &line);
        pclose_struct();
        CHECK(draw_offscreen_and_pdf(&files, p));
        for (int i = 0; i < 2; ++i) {
            if (p[i].rgb) {
                CHECK(
                    pixel_is(&p[i], 0.5, y, shaded ? mid : c0, shaded ? "shaded midpoint" : "flat midpoint"));
                CHECK(pixel_is(&p[i], 0.102, y, c0, "first end"));
                if (shaded) CHECK(pixel_is(&p[i], 0.898, y, c1, "last end"));
            }
            free(p[i].rgb);
        }
    }
}

/* The square [0.3, 0.7]^2 in the plane z = 0.5, counter-clockwise, vertex normals (0, 0, 1). */
static void square_facing_z(Pptnorm3 v[4]) {
    for (int i = 0; i < 4; ++i) {
        v[i].point.x = (Pfloat)(i == 1 || i == 2 ? 0.7 : 0.3), v[i].point.y = (Pfloat)(i >= 2 ? 0.7 : 0.3);
        v[i].point.z = 0.5f;
        v[i].norm.delta_x = 0, v[i].norm.delta_y = 0, v[i].norm.delta_z = 1;
    }
}

/* Opens structure 1 afresh with a SOLID interior in the reflectance's specular colour, lit
 * (ambient and diffuse) with those properties, the shading method and light source state. */
static void open_lit_structure(const Prefl_props* k, Pint shading, const Pint_list* on,
                               const Pint_list* off) {
    pdel_struct(1);
    popen_struct(1);
    pset_int_style(PSTYLE_SOLID);
    pset_int_colr(&k->specular_colr);
    pset_refl_props(k);
    pset_refl_eqn(PREFL_AMB_DIFF);
    pset_int_shad_meth(shading);
    pset_light_src_state(on, off);
}

/* Light 1 ambient and light 2 directional along -z, both white; depth cue 2 halves every colour
 * toward black. */
static void lights_and_cue(Pint ws) {
    const double white[3] = {1, 1, 1}, black[3] = {0, 0, 0};
    Plight_src_bundle ambient, directional;
    Pdcue_bundle cue;
    ambient.type = PLIGHT_AMBIENT;
    ambient.rec.ambient.colr = direct(white);
    directional.type = PLIGHT_DIRECTIONAL;
    directional.rec.directional.colr = direct(white);
    directional.rec.directional.dir.delta_x = 0, directional.rec.directional.dir.delta_y = 0;
    directional.rec.directional.dir.delta_z = -1;
    EXPECT_NO_ERROR(pset_light_src_rep(ws, 1, &ambient));
    EXPECT_NO_ERROR(pset_light_src_rep(ws, 2, &directional));
    cue.mode = PALLOWED;
    cue.ref_planes[0] = 1, cue.ref_planes[1] = 0;
    cue.scaling[0] = cue.scaling[1] = 0.5f;
    cue.colr = direct(black);
    EXPECT_NO_ERROR(pset_dcue_rep(ws, 2, &cue));
}

/* A lit square facing the directional light: with no light active the reflectance sums over no
 * lights and shows black; with both, (ka + kd) times the colour, clamped to 1 before the depth cue
 * halves it, under every interior shading method. */
static void lighting_sums(void) {
    for (int round = 0; round < 8; ++round) {
        double colour[3], expected[3];
        const int lit = round % 2;
        const Pint shading = PSD_NONE + (round / 2) % 4;
        Prefl_props k = {0};
        Pint active[2] = {1, 2};
        Pint_list on = {lit ? 2 : 0, active}, off = {0, NULL};
        Pptnorm3 v[4];
        Pfacet_vdata_list3 vertices;
        Pfacet_data3 facet;
        Picture p[2];
        random_rgb(colour);
        k.ambient_coef = (Pfloat)random_real(0.2, 1.0), k.diffuse_coef = (Pfloat)random_real(0.5, 1.0);
        k.specular_colr = direct(colour), k.specular_exp = 1;
        for (int c = 0; c < 3; ++c) {
            const double sum = (k.ambient_coef + k.diffuse_coef) * colour[c];
            expected[c] = lit ? 0.5 * (sum > 1 ? 1 : sum) : 0;
        }
        square_facing_z(v);
        vertices.num_vertices = 4, vertices.vertex_data.ptnorms = v;
        memset(&facet, 0, sizeof facet);
        open_lit_structure(&k, shading, &on, &off);
        pset_dcue_ind(2);
        pfill_area_set3_data(PFACET_NONE, PEDGE_NONE, PVERT_COORD_NORMAL, PMODEL_RGB, &facet, 1, NULL,
                             &vertices);
        pclose_struct();
        CHECK(draw_offscreen_and_pdf_with(&files, p, lights_and_cue));
        for (int i = 0; i < 2; ++i) {
            if (p[i].rgb)
                CHECK(pixel_is(&p[i], 0.5, 0.5, expected, lit ? "lit, clamped, cued" : "no light active"));
            free(p[i].rgb);
        }
    }
}

static double facet_normal[3];

/* Light 2 directional and white, shining against facet_normal (so N.L = 1 along it). */
static void light_along_facet_normal(Pint ws) {
    const double white[3] = {1, 1, 1};
    Plight_src_bundle directional;
    directional.type = PLIGHT_DIRECTIONAL;
    directional.rec.directional.colr = direct(white);
    directional.rec.directional.dir.delta_x = (Pfloat)-facet_normal[0];
    directional.rec.directional.dir.delta_y = (Pfloat)-facet_normal[1];
    directional.rec.directional.dir.delta_z = (Pfloat)-facet_normal[2];
    EXPECT_NO_ERROR(pset_light_src_rep(ws, 2, &directional));
}

/* A square in a z plane with a random tilted facet normal, lit (diffuse only) by a light along
 * that normal: without vertex normals every shading method lights it with the facet normal (full
 * white); with vertex normals (0, 0, 1) flat shading still does, Gouraud and Phong use them
 * (N.L = the facet normal's z). */
static void facet_normals(void) {
    for (int round = 0; round < 16; ++round) {
        const int vertexNormals = round % 2;
        const Pint shading = PSD_NONE + (round / 2) % 4;
        const double white[3] = {1, 1, 1};
        double expected[3], length = 0;
        Prefl_props k = {0};
        Pint active[1] = {2};
        Pint_list on = {1, active}, off = {0, NULL};
        Pptnorm3 v[4];
        Ppoint3 points[4];
        Pfacet_vdata_list3 vertices;
        Pfacet_data3 facet;
        Picture p[2];
        facet_normal[0] = random_real(-0.6, 0.6), facet_normal[1] = random_real(-0.6, 0.6),
        facet_normal[2] = 0.6;
        for (int c = 0; c < 3; ++c) length += facet_normal[c] * facet_normal[c];
        for (int c = 0; c < 3; ++c) facet_normal[c] /= sqrt(length);
        for (int c = 0; c < 3; ++c)
            expected[c] = vertexNormals && shading != PSD_NONE ? facet_normal[2] : 1.0;
        k.diffuse_coef = 1, k.specular_colr = direct(white), k.specular_exp = 1;
        square_facing_z(v);
        for (int i = 0; i < 4; ++i) points[i] = v[i].point;
        vertices.num_vertices = 4;
        if (vertexNormals)
            vertices.vertex_data.ptnorms = v;
        else
            vertices.vertex_data.points = points;
        memset(&facet, 0, sizeof facet);
        facet.norm.delta_x = (Pfloat)facet_normal[0], facet.norm.delta_y = (Pfloat)facet_normal[1];
        facet.norm.delta_z = (Pfloat)facet_normal[2];
        open_lit_structure(&k, shading, &on, &off);
        pfill_area_set3_data(PFACET_NORMAL, PEDGE_NONE, vertexNormals ? PVERT_COORD_NORMAL : PVERT_COORD,
                             PMODEL_RGB, &facet, 1, NULL, &vertices);
        pclose_struct();
        CHECK(draw_offscreen_and_pdf_with(&files, p, light_along_facet_normal));
        for (int i = 0; i < 2; ++i) {
            if (p[i].rgb)
                CHECK(pixel_is(&p[i], 0.5, 0.5, expected,
                               vertexNormals ? "facet and vertex normals" : "facet normal"));
            free(p[i].rgb);
        }
    }
}

/* Unlit facets with random vertex colours under interior shading method PSD_NONE: each facet is
 * one colour, its facet colour when it has one, else the interior colour; the vertex colours play
 * no part (they were interpolated). A fill area set with data, a 3 x 3 quadrilateral mesh and a
 * four-vertex triangle strip over the square [0.3, 0.7]^2, with and without facet colours. */
static void flat_colours(void) {
    for (int round = 0; round < 6; ++round) {
        const int shape = round % 3, withFacetColour = round / 3;
        double interior[3], facetColour[3], expected[3];
        Pptco3 v[9];
        Pcoval facets[4];
        Picture p[2];
        random_rgb(interior), random_rgb(facetColour);
        for (int c = 0; c < 3; ++c) expected[c] = withFacetColour ? facetColour[c] : interior[c];
        for (int i = 0; i < 9; ++i) {
            double c[3];
            random_rgb(c);
            v[i].colr.direct.rgb.red = (Pfloat)c[0], v[i].colr.direct.rgb.green = (Pfloat)c[1],
            v[i].colr.direct.rgb.blue = (Pfloat)c[2];
            v[i].point.z = 0.5f;
        }
        for (int k = 0; k < 4; ++k)
            facets[k].direct.rgb.red = (Pfloat)facetColour[0], facets[k].direct.rgb.green = (Pfloat)facetColour[1],
            facets[k].direct.rgb.blue = (Pfloat)facetColour[2];
        pdel_struct(1);
        popen_struct(1);
        pset_int_style(PSTYLE_SOLID);
        {
            const Pgcolr g = direct(interior);
            pset_int_colr(&g);
        }
        pset_refl_eqn(PREFL_NONE);
        pset_int_shad_meth(PSD_NONE);
        const Pint fflag = withFacetColour ? PFACET_COLOUR : PFACET_NONE;
        if (shape == 0) {
            /* The square, counter-clockwise. */
            Pfacet_vdata_list3 vertices;
            Pfacet_data3 facet;
            for (int i = 0; i < 4; ++i)
                v[i].point.x = (Pfloat)(i == 1 || i == 2 ? 0.7 : 0.3),
                v[i].point.y = (Pfloat)(i >= 2 ? 0.7 : 0.3);
            vertices.num_vertices = 4, vertices.vertex_data.ptcolrs = v;
            memset(&facet, 0, sizeof facet);
            facet.colr = facets[0];
            pfill_area_set3_data(fflag, PEDGE_NONE, PVERT_COORD_COLOUR, PMODEL_RGB, &facet, 1, NULL,
                                 &vertices);
        } else {
            Pfacet_vdata_arr3 vertices;
            Pfacet_data_arr3 facet;
            vertices.ptcolrs = v;
            facet.colrs = facets;
            if (shape == 1) {
                /* Point (i, j) of the 3 x 3 grid at index j * 3 + i. */
                const Pint_size dim = {3, 3};
                for (int i = 0; i < 9; ++i)
                    v[i].point.x = (Pfloat)(0.3 + 0.2 * (i % 3)),
                    v[i].point.y = (Pfloat)(0.3 + 0.2 * (i / 3));
                pquad_mesh3_data(fflag, PVERT_COORD_COLOUR, PMODEL_RGB, &dim, &facet, &vertices);
            } else {
                /* A strip zigzagging up the square: two triangles. */
                for (int i = 0; i < 4; ++i)
                    v[i].point.x = (Pfloat)(i % 2 ? 0.7 : 0.3), v[i].point.y = (Pfloat)(i >= 2 ? 0.7 : 0.3);
                ptri_strip3_data(fflag, PVERT_COORD_COLOUR, PMODEL_RGB, 4, &facet, &vertices);
            }
        }
        pclose_struct();
        CHECK(draw_offscreen_and_pdf(&files, p));
        for (int i = 0; i < 2; ++i) {
            if (p[i].rgb)
                for (int k = 0; k < 9; ++k)
                    CHECK(pixel_is(&p[i], 0.35 + 0.15 * (k % 3), 0.35 + 0.15 * (k / 3), expected,
                                   withFacetColour ? "flat: facet colour" : "flat: interior colour"));
            free(p[i].rgb);
        }
    }
}

static double prp[3], light_tilt;

/* View 1: perspective from prp onto the unit window at the view plane z = 0 (so points there keep
 * their x, y in NPC); light 2 directional and white, tilted light_tilt from -z toward +x. */
static void perspective_and_tilted_light(Pint ws) {
    Pview_rep3 rep;
    Pint err = 0;
    Ppoint3 vrp = {0, 0, 0};
    Pvec3 vpn = {0, 0, 1}, vup = {0, 1, 0};
    Pview_map3 map;
    const double white[3] = {1, 1, 1};
    Plight_src_bundle directional;
    peval_view_ori_matrix3(&vrp, &vpn, &vup, &err, rep.ori_matrix);
    map.win.x_min = 0, map.win.x_max = 1, map.win.y_min = 0, map.win.y_max = 1;
    map.proj_vp.x_min = 0, map.proj_vp.x_max = 1, map.proj_vp.y_min = 0, map.proj_vp.y_max = 1;
    map.proj_vp.z_min = 0, map.proj_vp.z_max = 1;
    map.proj_type = PTYPE_PERSPECT;
    map.proj_ref_point.x = (Pfloat)prp[0], map.proj_ref_point.y = (Pfloat)prp[1];
    map.proj_ref_point.z = (Pfloat)prp[2];
    map.view_plane = 0, map.back_plane = -1, map.front_plane = 1;
    peval_view_map_matrix3(&map, &err, rep.map_matrix);
    CHECK(err == 0);
    rep.clip_limit = map.proj_vp;
    rep.xy_clip = rep.back_clip = rep.front_clip = PIND_NO_CLIP;
    EXPECT_NO_ERROR(pset_view_rep3(ws, 1, &rep));
    directional.type = PLIGHT_DIRECTIONAL;
    directional.rec.directional.colr = direct(white);
    directional.rec.directional.dir.delta_x = (Pfloat)sin(light_tilt);
    directional.rec.directional.dir.delta_y = 0;
    directional.rec.directional.dir.delta_z = (Pfloat)-cos(light_tilt);
    EXPECT_NO_ERROR(pset_light_src_rep(ws, 2, &directional));
}

/* ks (R.V)^e for the square's normal (0, 0, 1) at (x, y, 0): R = (sin t, 0, cos t), V toward prp. */
static double specular_at(double x, double y, double exponent) {
    const double v[3] = {prp[0] - x, prp[1] - y, prp[2]};
    const double length = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    const double rv = (sin(light_tilt) * v[0] + cos(light_tilt) * v[2]) / length;
    return rv > 0 ? pow(rv, exponent) : 0;
}

/* A triangle at z = 0 lit by specular reflection alone (ks 1, white) in a perspective view from a
 * random centre of projection: its brightness follows V at each point. */
static void perspective_specular(void) {
    for (int round = 0; round < 6; ++round) {
        const double white[3] = {1, 1, 1};
        const Pint shading = round % 2 ? PSD_NONE : PSD_NORMAL;
        const double exponent = random_real(5, 40);
        Prefl_props k = {0};
        Pint active[1] = {2};
        Pint_list on = {1, active}, off = {0, NULL};
        Pptnorm3 v[4];
        Pfacet_vdata_list3 vertices;
        Pfacet_data3 facet;
        Picture p[2];
        prp[0] = random_real(0.2, 0.8), prp[1] = random_real(0.2, 0.8), prp[2] = random_real(1.0, 3.0);
        light_tilt = random_real(0.0, 0.45);
        k.specular_coef = 1, k.specular_colr = direct(white), k.specular_exp = (Pfloat)exponent;
        /* A triangle, its centroid at (0.5, 0.5). */
        for (int i = 0; i < 3; ++i) {
            v[i].point.x = (Pfloat)(i == 0 ? 0.05 : i == 1 ? 0.95 : 0.5);
            v[i].point.y = (Pfloat)(i == 2 ? 0.9 : 0.3);
            v[i].point.z = 0;
            v[i].norm.delta_x = 0, v[i].norm.delta_y = 0, v[i].norm.delta_z = 1;
        }
        vertices.num_vertices = 3, vertices.vertex_data.ptnorms = v;
        memset(&facet, 0, sizeof facet);
        pdel_struct(1);
        popen_struct(1);
        pset_view_ind(1);
        pset_int_style(PSTYLE_SOLID);
        pset_int_colr(&k.specular_colr);
        pset_refl_props(&k);
        pset_refl_eqn(PREFL_AMB_DIFF_SPEC);
        pset_int_shad_meth(shading);
        pset_light_src_state(&on, &off);
        pfill_area_set3_data(PFACET_NONE, PEDGE_NONE, PVERT_COORD_NORMAL, PMODEL_RGB, &facet, 1, NULL,
                             &vertices);
        pclose_struct();
        CHECK(draw_offscreen_and_pdf_with(&files, p, perspective_and_tilted_light));
        if (p[0].rgb && shading == PSD_NORMAL)
            for (int i = 0; i < 3; ++i) {
                const double x = 0.2 + 0.3 * i, s = specular_at(x, 0.45, exponent), expected[3] = {s, s, s};
                CHECK(pixel_is(&p[0], x, 0.45, expected, "perspective specular (Phong)"));
            }
        if (p[1].rgb && shading == PSD_NONE) {
            /* The vector output lights a facet once, at its centre. */
            const double s = specular_at(0.5, 0.5, exponent), expected[3] = {s, s, s};
            CHECK(pixel_is(&p[1], 0.5, 0.5, expected, "perspective specular (flat, on paper)"));
        }
        for (int i = 0; i < 2; ++i) free(p[i].rgb);
    }
}

int main(int argc, char** argv) {
    const char* dir = argc > 1 ? argv[1] : ".";
    char errors[512];
    seed_random(0x853c49e6748fea9bULL);
    files = picture_files(dir, "plus_shading");
    snprintf(errors, sizeof errors, "%s/plus_shading_errors.txt", dir);
    open_with_handler(errors);
    back_faces();
    hollow_outlines();
    line_shading();
    lighting_sums();
    facet_normals();
    flat_colours();
    perspective_specular();
    pclose_phigs();
    return finish("test_plus_shading");
}
