/* Facet data of TRIANGLE STRIP 3 WITH DATA and QUADRILATERAL MESH 3 WITH DATA, per-edge
 * visibility of FILL AREA SET 3 WITH DATA and level curves (parametric surface characteristics 4
 * and 5), through the C binding: random members of each stored, read back through
 * pinq_elem_content, archived and retrieved unchanged; malformed data refused with the right error
 * and the structure unchanged. argv[1]: a directory. */
#include "check.h"

#define ROUNDS 24
#define MAX_POINTS 30
#define MAX_CONTOURS 3
#define MAX_LEVELS 6

static Pstore store;
static unsigned long rng_state = 0x2545F491UL;

static unsigned next_rng(void) {
    rng_state = (rng_state * 1103515245UL + 12345UL) & 0x7fffffffUL;
    return (unsigned)(rng_state >> 8);
}
static int below(int n) {
    return (int)(next_rng() % (unsigned)n);
}
/* A real with few significant bits, exact in float and double. */
static Pfloat real(void) {
    return (Pfloat)(below(257) - 128) / 16;
}

/* One random mesh element: what was asked for, to compare with what comes back. */
typedef struct {
    int quad; /* 0: triangle strip, 1: quadrilateral mesh */
    Pint fflag, vflag, colr_type, nv;
    Pint_size dim;
    Pptconorm3 vertex[MAX_POINTS];
    Pconorm3 facet[MAX_POINTS];
} Mesh;

typedef struct {
    Pint contours, sizes[MAX_CONTOURS];
    Pptco3 vertex[MAX_CONTOURS][8];
    Pedge_flag edges[MAX_CONTOURS][8];
} EdgedArea;

typedef struct {
    Pint type;
    Ppoint3 origin;
    Pvec3 direction;
    Pint count;
    Pfloat params[MAX_LEVELS];
} Levels;

static Mesh meshes[ROUNDS];
static EdgedArea areas[ROUNDS];
static Levels levels[ROUNDS];

static Pcoval random_colour(Pint colr_type) {
    Pcoval c;
    memset(&c, 0, sizeof c);
    if (colr_type == PINDIRECT)
        c.ind = below(16);
    else
        c.direct.rgb.red = (Pfloat)below(9) / 8, c.direct.rgb.green = (Pfloat)below(9) / 8,
        c.direct.rgb.blue = (Pfloat)below(9) / 8;
    return c;
}

static Pint facets_of(const Mesh* m) {
    return m->quad ? (m->dim.size_x - 1) * (m->dim.size_y - 1) : m->nv - 2;
}

static void random_mesh(Mesh* m) {
    memset(m, 0, sizeof *m);
    m->quad = below(2);
    m->fflag = below(4), m->vflag = below(4), m->colr_type = below(2) ? PINDIRECT : PMODEL_RGB;
    if (m->quad)
        m->dim.size_x = 2 + below(4), m->dim.size_y = 2 + below(4), m->nv = m->dim.size_x * m->dim.size_y;
    else
        m->nv = 3 + below(MAX_POINTS - 3);
    for (Pint i = 0; i < m->nv; ++i) {
        m->vertex[i].point = (Ppoint3){real(), real(), real()};
        m->vertex[i].colr = random_colour(m->colr_type);
        m->vertex[i].norm = (Pvec3){real(), real(), 1 + real() * real()};
    }
    for (Pint k = 0; k < facets_of(m); ++k) {
        m->facet[k].colr = random_colour(m->colr_type);
        m->facet[k].norm = (Pvec3){real(), real(), real() + 9};
    }
}

/* The vertex data of `m` in the form its flag asks for (in `points` .. `conorms`). */
static Pfacet_vdata_arr3 vertex_data(const Mesh* m, Ppoint3* points, Pptco3* colours, Pptnorm3* normals) {
    Pfacet_vdata_arr3 v;
    for (Pint i = 0; i < m->nv; ++i) {
        points[i] = m->vertex[i].point;
        colours[i] = (Pptco3){m->vertex[i].point, m->vertex[i].colr};
        normals[i] = (Pptnorm3){m->vertex[i].point, m->vertex[i].norm};
    }
    if (m->vflag == PVERT_COORD) v.points = points;
    if (m->vflag == PVERT_COORD_COLOUR) v.ptcolrs = colours;
    if (m->vflag == PVERT_COORD_NORMAL) v.ptnorms = normals;
    if (m->vflag == PVERT_COORD_COLOUR_NORMAL) v.ptconorms = (Pptconorm3*)m->vertex;
    return v;
}

static Pfacet_data_arr3 facet_data(const Mesh* m, Pcoval* colours, Pvec3* normals) {
    Pfacet_data_arr3 f;
    for (Pint k = 0; k < facets_of(m); ++k) colours[k] = m->facet[k].colr, normals[k] = m->facet[k].norm;
    f.colrs = colours;
    if (m->fflag == PFACET_NORMAL) f.norms = normals;
    if (m->fflag == PFACET_COLOUR_NORMAL) f.conorms = (Pconorm3*)m->facet;
    return f;
}

static void insert_mesh(const Mesh* m) {
    Ppoint3 points[MAX_POINTS];
    Pptco3 colours[MAX_POINTS];
    Pptnorm3 normals[MAX_POINTS];
    Pcoval fcolours[MAX_POINTS];
    Pvec3 fnormals[MAX_POINTS];
    Pfacet_vdata_arr3 v = vertex_data(m, points, colours, normals);
    Pfacet_data_arr3 f = facet_data(m, fcolours, fnormals);
    if (m->quad)
        EXPECT_NO_ERROR(pquad_mesh3_data(m->fflag, m->vflag, m->colr_type, &m->dim, &f, &v));
    else
        EXPECT_NO_ERROR(ptri_strip3_data(m->fflag, m->vflag, m->colr_type, m->nv, &f, &v));
}

static int same_colour(Pcoval a, Pcoval b, Pint colr_type) {
    if (colr_type == PINDIRECT) return a.ind == b.ind;
    return a.direct.rgb.red == b.direct.rgb.red && a.direct.rgb.green == b.direct.rgb.green && a.direct.rgb.blue == b.direct.rgb.blue;
}
static int same_vec(Pvec3 a, Pvec3 b) {
    return a.delta_x == b.delta_x && a.delta_y == b.delta_y && a.delta_z == b.delta_z;
}
static int same_point(Ppoint3 a, Ppoint3 b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

static Pelem_data* content(Pint structure, Pint pos, Pelem_type expected) {
    Pint err = -1;
    Pelem_data* data = NULL;
    pinq_elem_content(structure, pos, store, &err, &data);
    CHECK(err == 0 && data != NULL);
    (void)expected;
    return err == 0 ? data : NULL;
}

/* The element at `pos` of structure 1 is mesh `m`. */
static void check_mesh(const Mesh* m, Pint pos) {
    Pint err = -1, fflag, vflag, colr_type;
    Pelem_type type = PELEM_NIL;
    size_t size = 0;
    Pfacet_data_arr3 f;
    Pfacet_vdata_arr3 v;
    Pelem_data* d;
    const int colours = m->vflag == PVERT_COORD_COLOUR || m->vflag == PVERT_COORD_COLOUR_NORMAL;
    const int normals = m->vflag == PVERT_COORD_NORMAL || m->vflag == PVERT_COORD_COLOUR_NORMAL;
    const int fcolours = m->fflag == PFACET_COLOUR || m->fflag == PFACET_COLOUR_NORMAL;
    const int fnormals = m->fflag == PFACET_NORMAL || m->fflag == PFACET_COLOUR_NORMAL;
    pinq_elem_type_size(1, pos, &err, &type, &size);
    CHECK(err == 0 && type == (m->quad ? PELEM_QUAD_MESH3_DATA : PELEM_TRI_STRIP3_DATA));
    if (!(d = content(1, pos, type))) return;
    if (m->quad) {
        CHECK(d->quad_mesh3.dim.size_x == m->dim.size_x && d->quad_mesh3.dim.size_y == m->dim.size_y);
        fflag = d->quad_mesh3.fflag, vflag = d->quad_mesh3.vflag, colr_type = d->quad_mesh3.colr_type;
        f = d->quad_mesh3.fdata, v = d->quad_mesh3.vdata;
    } else {
        CHECK(d->tri_strip3.nv == m->nv);
        fflag = d->tri_strip3.fflag, vflag = d->tri_strip3.vflag, colr_type = d->tri_strip3.colr_type;
        f = d->tri_strip3.fdata, v = d->tri_strip3.vdata;
    }
    CHECK(fflag == m->fflag && vflag == m->vflag);
    if (colours || fcolours) CHECK(colr_type == m->colr_type);
    for (Pint i = 0; i < m->nv; ++i) {
        const Pptconorm3* e = &m->vertex[i];
        if (vflag == PVERT_COORD) CHECK(same_point(v.points[i], e->point));
        if (vflag == PVERT_COORD_COLOUR)
            CHECK(same_point(v.ptcolrs[i].point, e->point) &&
                  same_colour(v.ptcolrs[i].colr, e->colr, colr_type));
        if (vflag == PVERT_COORD_NORMAL)
            CHECK(same_point(v.ptnorms[i].point, e->point) && same_vec(v.ptnorms[i].norm, e->norm));
        if (vflag == PVERT_COORD_COLOUR_NORMAL)
            CHECK(same_point(v.ptconorms[i].point, e->point) &&
                  same_colour(v.ptconorms[i].colr, e->colr, colr_type) &&
                  same_vec(v.ptconorms[i].norm, e->norm));
    }
    (void)colours, (void)normals;
    for (Pint k = 0; k < facets_of(m) && fflag == m->fflag; ++k) {
        if (fcolours && !fnormals) CHECK(same_colour(f.colrs[k], m->facet[k].colr, colr_type));
        if (fnormals && !fcolours) CHECK(same_vec(f.norms[k], m->facet[k].norm));
        if (fcolours && fnormals)
            CHECK(same_colour(f.conorms[k].colr, m->facet[k].colr, colr_type) &&
                  same_vec(f.conorms[k].norm, m->facet[k].norm));
    }
}

static void random_area(EdgedArea* a) {
    memset(a, 0, sizeof *a);
    a->contours = 1 + below(MAX_CONTOURS);
    for (Pint c = 0; c < a->contours; ++c) {
        a->sizes[c] = 3 + below(6);
        for (Pint i = 0; i < a->sizes[c]; ++i) {
            a->vertex[c][i].point = (Ppoint3){real(), real(), real()};
            a->vertex[c][i].colr.ind = below(8);
            a->edges[c][i] = below(2) ? PEDGE_ON : PEDGE_OFF;
        }
    }
}

static void insert_area(EdgedArea* a) {
    Pedge_data_list edata[MAX_CONTOURS];
    Pfacet_vdata_list3 vdata[MAX_CONTOURS];
    for (Pint c = 0; c < a->contours; ++c) {
        edata[c].num_edges = a->sizes[c], edata[c].edgedata = a->edges[c];
        vdata[c].num_vertices = a->sizes[c], vdata[c].vertex_data.ptcolrs = a->vertex[c];
    }
    EXPECT_NO_ERROR(pfill_area_set3_data(PFACET_NONE, PEDGE_VISIBILITY, PVERT_COORD_COLOUR, PINDIRECT, NULL,
                                         a->contours, edata, vdata));
}

static void check_area(const EdgedArea* a, Pint pos) {
    Pelem_data* d = content(1, pos, PELEM_FILL_AREA_SET3_DATA);
    if (!d) return;
    CHECK(d->fas3_data.eflag == PEDGE_VISIBILITY && d->fas3_data.nfa == a->contours && d->fas3_data.edata);
    if (d->fas3_data.eflag != PEDGE_VISIBILITY || d->fas3_data.nfa != a->contours || !d->fas3_data.edata)
        return;
    for (Pint c = 0; c < a->contours; ++c) {
        CHECK(d->fas3_data.edata[c].num_edges == a->sizes[c] &&
              d->fas3_data.vdata[c].num_vertices == a->sizes[c]);
        for (Pint i = 0; i < a->sizes[c] && d->fas3_data.edata[c].num_edges == a->sizes[c]; ++i) {
            CHECK(d->fas3_data.edata[c].edgedata[i] == a->edges[c][i]);
            CHECK(same_point(d->fas3_data.vdata[c].vertex_data.ptcolrs[i].point, a->vertex[c][i].point));
        }
    }
}

static void random_levels(Levels* l) {
    memset(l, 0, sizeof *l);
    l->type = below(2) ? PSC_LEVEL_CURVES_MC : PSC_LEVEL_CURVES_WC;
    l->origin = (Ppoint3){real(), real(), real()};
    l->direction = (Pvec3){real(), real(), real() + 9};
    l->count = below(MAX_LEVELS + 1);
    for (Pint k = 0; k < l->count; ++k) l->params[k] = real();
}

static Ppara_surf_characs level_data(Levels* l) {
    Ppara_surf_characs d;
    memset(&d, 0, sizeof d);
    if (l->type == PSC_LEVEL_CURVES_MC)
        d.psc_4.origin = l->origin, d.psc_4.direction = l->direction,
        d.psc_4.params = (Pfloat_list){l->count, l->params};
    else
        d.psc_5.origin = l->origin, d.psc_5.direction = l->direction,
        d.psc_5.params = (Pfloat_list){l->count, l->params};
    return d;
}

static void check_levels(const Levels* l, Pint pos) {
    Pelem_data* d = content(1, pos, PELEM_PARA_SURF_CHARS);
    Ppoint3 origin;
    Pvec3 direction;
    Pfloat_list params;
    if (!d) return;
    CHECK(d->para_surf_characs.type == l->type);
    if (l->type == PSC_LEVEL_CURVES_MC)
        origin = d->para_surf_characs.data.psc_4.origin,
        direction = d->para_surf_characs.data.psc_4.direction,
        params = d->para_surf_characs.data.psc_4.params;
    else
        origin = d->para_surf_characs.data.psc_5.origin,
        direction = d->para_surf_characs.data.psc_5.direction,
        params = d->para_surf_characs.data.psc_5.params;
    CHECK(same_point(origin, l->origin) && same_vec(direction, l->direction) &&
          params.num_floats == l->count);
    for (Pint k = 0; k < l->count && params.num_floats == l->count; ++k)
        CHECK(params.floats[k] == l->params[k]);
}

/* Structure 1: per round a mesh, an area with edge data and level curves. */
static void build(void) {
    popen_struct(1);
    for (int r = 0; r < ROUNDS; ++r) {
        Ppara_surf_characs d;
        random_mesh(&meshes[r]);
        insert_mesh(&meshes[r]);
        random_area(&areas[r]);
        insert_area(&areas[r]);
        random_levels(&levels[r]);
        d = level_data(&levels[r]);
        EXPECT_NO_ERROR(pset_para_surf_characs(levels[r].type, &d));
    }
    pclose_struct();
}

static void read_back(void) {
    for (int r = 0; r < ROUNDS; ++r) {
        check_mesh(&meshes[r], 3 * r + 1);
        check_area(&areas[r], 3 * r + 2);
        check_levels(&levels[r], 3 * r + 3);
    }
}

static void archive(const char* path) {
    Pint one[1] = {1};
    Pint_list list = {1, one};
    remove(path);
    EXPECT_NO_ERROR(popen_ar_file(1, path));
    EXPECT_NO_ERROR(par_structs(1, &list));
    pdel_all_structs();
    EXPECT_NO_ERROR(pret_structs(1, &list));
    EXPECT_NO_ERROR(pclose_ar_file(1));
    read_back();
}

/* Malformed data: each refused with its error, the structure as it was. */
static void refusals(void) {
    Ppoint3 points[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    Pfacet_vdata_arr3 v;
    Pcoval colours[2];
    Pvec3 normals[2] = {{0, 0, 1}, {0, 0, 1}};
    Pfacet_data_arr3 f, none;
    Pint_size dim = {2, 2};
    Pedge_flag flags[4] = {PEDGE_ON, PEDGE_ON, PEDGE_OFF, PEDGE_ON};
    Pedge_data_list edata = {4, flags};
    Pfacet_vdata_list3 vdata;
    Pfloat params[2] = {0, 1};
    Ppara_surf_characs psc;
    memset(colours, 0, sizeof colours);
    memset(&none, 0, sizeof none);
    memset(&psc, 0, sizeof psc);
    v.points = points, f.norms = normals;
    vdata.num_vertices = 4, vdata.vertex_data.points = points;
    popen_struct(1);
    EXPECT_REFUSED(ptri_strip3_data(PFACET_NORMAL, PVERT_COORD, PINDIRECT, 4, NULL, &v), -204,
                   Pfn_tri_strip3_data);
    EXPECT_REFUSED(ptri_strip3_data(PFACET_COLOUR, PVERT_COORD, PINDIRECT, 4, &none, &v), -204,
                   Pfn_tri_strip3_data);
    EXPECT_REFUSED(ptri_strip3_data(7, PVERT_COORD, PINDIRECT, 4, &f, &v), PE_ENUM_TYPE_INVAL,
                   Pfn_tri_strip3_data);
    normals[0].delta_y = NAN;
    EXPECT_REFUSED(ptri_strip3_data(PFACET_NORMAL, PVERT_COORD, PINDIRECT, 4, &f, &v), -202,
                   Pfn_tri_strip3_data);
    EXPECT_REFUSED(pquad_mesh3_data(PFACET_NORMAL, PVERT_COORD, PINDIRECT, &dim, &f, &v), -202,
                   Pfn_quad_mesh3_data);
    EXPECT_REFUSED(pquad_mesh3_data(PFACET_COLOUR, PVERT_COORD, PINDIRECT, &dim, NULL, &v), -204,
                   Pfn_quad_mesh3_data);
    normals[0].delta_y = 0, f.colrs = colours, colours[0].ind = 3;
    EXPECT_NO_ERROR(pquad_mesh3_data(PFACET_COLOUR, PVERT_COORD, PINDIRECT, &dim, &f, &v));
    pdel_elem();
    EXPECT_REFUSED(
        pfill_area_set3_data(PFACET_NONE, PEDGE_VISIBILITY, PVERT_COORD, PINDIRECT, NULL, 1, NULL, &vdata),
        -204, Pfn_fill_area_set3_data);
    edata.num_edges = 3;
    EXPECT_REFUSED(
        pfill_area_set3_data(PFACET_NONE, PEDGE_VISIBILITY, PVERT_COORD, PINDIRECT, NULL, 1, &edata, &vdata),
        -202, Pfn_fill_area_set3_data);
    edata.num_edges = 4, flags[2] = (Pedge_flag)5;
    EXPECT_REFUSED(
        pfill_area_set3_data(PFACET_NONE, PEDGE_VISIBILITY, PVERT_COORD, PINDIRECT, NULL, 1, &edata, &vdata),
        PE_ENUM_TYPE_INVAL, Pfn_fill_area_set3_data);
    EXPECT_REFUSED(pfill_area_set3_data(PFACET_NONE, 3, PVERT_COORD, PINDIRECT, NULL, 1, &edata, &vdata),
                   PE_ENUM_TYPE_INVAL, Pfn_fill_area_set3_data);
    EXPECT_REFUSED(pset_para_surf_characs(PSC_LEVEL_CURVES_MC, NULL), -204, Pfn_set_para_surf_characs);
    psc.psc_4.params = (Pfloat_list){2, params};
    EXPECT_REFUSED(pset_para_surf_characs(PSC_LEVEL_CURVES_MC, &psc), -202, Pfn_set_para_surf_characs);
    psc.psc_5.direction.delta_z = 1, psc.psc_5.params = (Pfloat_list){-1, params};
    EXPECT_REFUSED(pset_para_surf_characs(PSC_LEVEL_CURVES_WC, &psc), -204, Pfn_set_para_surf_characs);
    psc.psc_5.params = (Pfloat_list){2, params}, params[1] = NAN;
    EXPECT_REFUSED(pset_para_surf_characs(PSC_LEVEL_CURVES_WC, &psc), -202, Pfn_set_para_surf_characs);
    params[1] = 1;
    EXPECT_REFUSED(pset_para_surf_characs(6, &psc), -202, Pfn_set_para_surf_characs);
    EXPECT_NO_ERROR(pset_para_surf_characs(PSC_LEVEL_CURVES_WC, &psc));
    pdel_elem();
    pclose_struct();
}

int main(int argc, char** argv) {
    char file[512], ar[512];
    Pint err = -1;
    const char* dir = argc > 1 ? argv[1] : ".";
    snprintf(file, sizeof file, "%s/plus_facets_errors.txt", dir);
    snprintf(ar, sizeof ar, "%s/plus_facets.phar", dir);
    open_with_handler(file);
    pcreate_store(&err, &store);
    build();
    read_back();
    refusals();
    read_back();
    archive(ar);
    pdel_store(store);
    pclose_phigs();
    return finish("test_plus_facets");
}
