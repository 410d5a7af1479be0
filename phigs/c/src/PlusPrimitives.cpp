// PHIGS PLUS primitives with data: FILL AREA SET 3 WITH DATA, TRIANGLE STRIP 3 WITH DATA,
// QUADRILATERAL MESH 3 WITH DATA, POLYLINE SET 3 WITH DATA, CELL ARRAY 3 PLUS, SET OF FILL AREA
// SETS 3 WITH DATA, SET RENDERING COLOUR MODEL, and COMPUTE FILL AREA SET GEOMETRIC NORMAL.

#include "Conversions.h"
#include "Inquiry.h"
#include "Insert.h"
#include "phigs.h"

#include <glm/geometric.hpp>

using namespace phigs;
using phigs::c::insertElement;

namespace {

struct VertexData {
    std::vector<glm::dvec3> points;
    std::vector<Colour> colours;
    std::vector<glm::dvec3> normals;
};

glm::dvec3 point(const Ppoint3& p) {
    return {p.x, p.y, p.z};
}
glm::dvec3 vec(const Pvec3& v) {
    return {v.delta_x, v.delta_y, v.delta_z};
}

void checkFlags(int vflag, int colrType, const char* name) {
    if (vflag < PVERT_COORD || vflag > PVERT_COORD_COLOUR_NORMAL)
        throw Error(PE_ENUM_TYPE_INVAL, name, "vertex flag");
    if (colrType != PINDIRECT && !isColourModel(colrType))
        throw Error(PE_ENUM_TYPE_INVAL, name, "colour type");
}

Colour colour(const Pcoval& c, int colrType) {
    if (colrType == PINDIRECT) return Colour::indexed(c.ind);
    return Colour::inModel(static_cast<ColourModel>(colrType),
                           {c.direct.rgb.red, c.direct.rgb.green, c.direct.rgb.blue});
}

/// `n` vertices of the form `vflag` says.
VertexData vertices(int vflag, int colrType, std::size_t n, const Pfacet_vdata_arr3& data, const char* name) {
    VertexData v;
    if (n) c::require(data.points, name);  // every member of the union is a pointer to the array
    for (std::size_t i = 0; i < n; ++i) switch (vflag) {
            case PVERT_COORD:
                v.points.push_back(point(data.points[i]));
                break;
            case PVERT_COORD_COLOUR:
                v.points.push_back(point(data.ptcolrs[i].point));
                v.colours.push_back(colour(data.ptcolrs[i].colr, colrType));
                break;
            case PVERT_COORD_NORMAL:
                v.points.push_back(point(data.ptnorms[i].point));
                v.normals.push_back(vec(data.ptnorms[i].norm));
                break;
            default:
                v.points.push_back(point(data.ptconorms[i].point));
                v.colours.push_back(colour(data.ptconorms[i].colr, colrType));
                v.normals.push_back(vec(data.ptconorms[i].norm));
                break;
        }
    return v;
}

/// Facet data of `facets` facets as `fflag` says (nothing for PFACET_NONE).
void facetList(Pint fflag, Pint colrType, std::size_t facets, const Pfacet_data_arr3* fdata,
               std::vector<Colour>& colours, std::vector<glm::dvec3>& normals, const char* name) {
    if (fflag < PFACET_NONE || fflag > PFACET_COLOUR_NORMAL)
        throw Error(PE_ENUM_TYPE_INVAL, name, "facet flag");
    if (fflag == PFACET_NONE || facets == 0) return;
    c::require(fdata, name);
    c::require(fdata->colrs, name);  // every member of the union is a pointer to the array
    for (std::size_t k = 0; k < facets; ++k) switch (fflag) {
            case PFACET_COLOUR:
                colours.push_back(colour(fdata->colrs[k], colrType));
                break;
            case PFACET_NORMAL:
                normals.push_back(vec(fdata->norms[k]));
                break;
            default:
                colours.push_back(colour(fdata->conorms[k].colr, colrType));
                normals.push_back(vec(fdata->conorms[k].norm));
                break;
        }
}

/// The edge flags of a fill area set with data: one list per contour, one flag per vertex.
std::vector<std::vector<int>> edgeFlags(std::size_t contours, const Pedge_data_list* edata,
                                        const char* name) {
    std::vector<std::vector<int>> out;
    if (contours) c::require(edata, name);
    for (std::size_t c = 0; c < contours; ++c) {
        const std::size_t k = c::count(edata[c].num_edges, name);
        if (k) c::require(edata[c].edgedata, name);
        auto& flags = out.emplace_back();
        for (std::size_t j = 0; j < k; ++j) {
            const int f = c::raw(edata[c].edgedata[j]);
            if (f != PEDGE_OFF && f != PEDGE_ON)
                throw Error(PE_ENUM_TYPE_INVAL, name, "edge visibility flag");
            flags.push_back(f == PEDGE_ON ? 1 : 0);
        }
    }
    return out;
}

/// Facet data of `sets` sets as `fflag` says (nothing for PFACET_NONE).
void facetData(SetOfFillAreaSetsElement& e, Pint fflag, Pint colrType, std::size_t sets,
               const Pfacet_data_arr3* fdata, const char* name) {
    facetList(fflag, colrType, sets, fdata, e.facetColours, e.facetNormals, name);
}

/// The contours of set `k` (vertex indices) and, with edge data, their edge flags.
void setContours(SetOfFillAreaSetsElement& e, const Pint_list_list& contours,
                 const Pedge_data_list_list* edges, const char* name) {
    const std::size_t n = c::count(contours.num_lists, name);
    if (n) c::require(contours.lists, name);
    auto& set = e.sets.emplace_back();
    for (std::size_t c = 0; c < n; ++c) set.push_back(c::ints(&contours.lists[c], name));
    if (!edges) return;
    auto& flags = e.edgeFlags.emplace_back();
    const std::size_t m = c::count(edges->num_lists, name);
    if (m) c::require(edges->edgelist, name);
    for (std::size_t c = 0; c < m; ++c) {
        const Pedge_data_list& list = edges->edgelist[c];
        const std::size_t k = c::count(list.num_edges, name);
        if (k) c::require(list.edgedata, name);
        auto& out = flags.emplace_back();
        for (std::size_t j = 0; j < k; ++j) {
            const int f = c::raw(list.edgedata[j]);
            if (f != PEDGE_OFF && f != PEDGE_ON)
                throw Error(PE_ENUM_TYPE_INVAL, name, "edge visibility flag");
            out.push_back(f == PEDGE_ON ? 1 : 0);
        }
    }
}

}  // namespace

extern "C" {

void ppolyline_set3_data(Pint vflag, Pint colr_type, Pint npl, const Pline_vdata_list3* vdata) {
    insertElement(Pfn_polyline_set3_data, [&](const char* n) -> Element {
        checkFlags(vflag, colr_type, n);
        if (vflag != PVERT_COORD && vflag != PVERT_COORD_COLOUR)
            throw Error(PE_ENUM_TYPE_INVAL, n, "vertex flag (a polyline carries no normals)");
        PolylineSetWithDataElement e;
        const std::size_t lines = c::count(npl, n);
        if (lines) c::require(vdata, n);
        for (std::size_t l = 0; l < lines; ++l) {
            Pfacet_vdata_arr3 data{};
            if (vflag == PVERT_COORD_COLOUR)
                data.ptcolrs = vdata[l].vertex_data.ptcolrs;
            else
                data.points = vdata[l].vertex_data.points;
            VertexData v = vertices(vflag, colr_type, c::count(vdata[l].num_vertices, n), data, n);
            e.polylines.push_back(std::move(v.points));
            if (vflag == PVERT_COORD_COLOUR) e.vertexColours.push_back(std::move(v.colours));
        }
        return e;
    });
}

void pcell_array3_plus(const Pparal* paral, const Pint_size* dim, Pint colr_type, const Pcoval* colrs) {
    insertElement(Pfn_cell_array3_plus, [&](const char* n) -> Element {
        c::require(paral, n);
        c::require(dim, n);
        if (colr_type != PINDIRECT && !isColourModel(colr_type))
            throw Error(PE_ENUM_TYPE_INVAL, n, "colour type");
        const std::size_t cells = c::cellCount(dim->size_x, dim->size_y, n);
        const std::size_t columns = c::count(dim->size_x, n), rows = c::count(dim->size_y, n);
        if (cells != 0) c::require(colrs, n);
        CellArrayPlusElement e{point(paral->p),           point(paral->q),        point(paral->r),
                               static_cast<int>(columns), static_cast<int>(rows), {}};
        for (std::size_t k = 0; k < cells; ++k) e.colours.push_back(colour(colrs[k], colr_type));
        return e;
    });
}

void pset_of_fill_area_set3_data(Pint fflag, Pint eflag, Pint vflag, Pint colr_type, Pint num_sets,
                                 const Pfacet_data_arr3* fdata, const Pedge_data_list_list* edata,
                                 const Pint_list_list* vlist, const Pfacet_vdata_list3* vdata) {
    insertElement(Pfn_set_of_fill_area_set3_data, [&](const char* n) -> Element {
        checkFlags(vflag, colr_type, n);
        if (eflag != PEDGE_NONE && eflag != PEDGE_VISIBILITY) throw Error(PE_ENUM_TYPE_INVAL, n, "edge flag");
        SetOfFillAreaSetsElement e;
        const std::size_t sets = c::count(num_sets, n);
        facetData(e, fflag, colr_type, sets, fdata, n);
        c::require(vdata, n);
        VertexData v = vertices(vflag, colr_type, c::count(vdata->num_vertices, n), vdata->vertex_data, n);
        e.vertices = std::move(v.points), e.vertexColours = std::move(v.colours);
        e.vertexNormals = std::move(v.normals);
        if (sets) c::require(vlist, n);
        if (sets && eflag == PEDGE_VISIBILITY) c::require(edata, n);
        for (std::size_t k = 0; k < sets; ++k)
            setContours(e, vlist[k], eflag == PEDGE_VISIBILITY ? &edata[k] : nullptr, n);
        return e;
    });
}

void pset_rendering_colr_model(Pint model) {
    insertElement(Pfn_set_rendering_colr_model, [&](const char*) -> Element {
        return IndexAttribute{ElementType::RenderingColourModel, model};
    });
}

void pfill_area_set3_data(Pint fflag, Pint eflag, Pint vflag, Pint colr_type, const Pfacet_data3* fdata,
                          Pint nfa, const Pedge_data_list* edata, const Pfacet_vdata_list3* vdata) {
    insertElement(Pfn_fill_area_set3_data, [&](const char* n) -> Element {
        checkFlags(vflag, colr_type, n);
        if (fflag < PFACET_NONE || fflag > PFACET_COLOUR_NORMAL)
            throw Error(PE_ENUM_TYPE_INVAL, n, "facet flag");
        if (eflag != PEDGE_NONE && eflag != PEDGE_VISIBILITY) throw Error(PE_ENUM_TYPE_INVAL, n, "edge flag");
        FillAreaSetWithDataElement e;
        if (fflag != PFACET_NONE) {
            c::require(fdata, n);
            e.hasFacetColour = fflag == PFACET_COLOUR || fflag == PFACET_COLOUR_NORMAL;
            e.hasFacetNormal = fflag == PFACET_NORMAL || fflag == PFACET_COLOUR_NORMAL;
            if (fflag == PFACET_COLOUR) e.facetColour = colour(fdata->colr, colr_type);
            if (fflag == PFACET_NORMAL) e.facetNormal = vec(fdata->norm);
            if (fflag == PFACET_COLOUR_NORMAL)
                e.facetColour = colour(fdata->conorm.colr, colr_type),
                e.facetNormal = vec(fdata->conorm.norm);
        }
        const std::size_t areas = c::count(nfa, n);
        if (areas) c::require(vdata, n);
        for (std::size_t a = 0; a < areas; ++a) {
            VertexData v =
                vertices(vflag, colr_type, c::count(vdata[a].num_vertices, n), vdata[a].vertex_data, n);
            e.contours.push_back(std::move(v.points));
            if (vflag == PVERT_COORD_COLOUR || vflag == PVERT_COORD_COLOUR_NORMAL)
                e.vertexColours.push_back(std::move(v.colours));
            if (vflag == PVERT_COORD_NORMAL || vflag == PVERT_COORD_COLOUR_NORMAL)
                e.vertexNormals.push_back(std::move(v.normals));
        }
        if (eflag == PEDGE_VISIBILITY) e.edgeFlags = edgeFlags(areas, edata, n);
        return e;
    });
}

void ptri_strip3_data(Pint fflag, Pint vflag, Pint colr_type, Pint nv, const Pfacet_data_arr3* fdata,
                      const Pfacet_vdata_arr3* vdata) {
    insertElement(Pfn_tri_strip3_data, [&](const char* n) -> Element {
        checkFlags(vflag, colr_type, n);
        c::require(vdata, n);
        const std::size_t count = c::count(nv, n);
        VertexData v = vertices(vflag, colr_type, count, *vdata, n);
        TriangleStripElement e{std::move(v.points), std::move(v.colours), std::move(v.normals)};
        facetList(fflag, colr_type, count < 3 ? 0 : count - 2, fdata, e.facetColours, e.facetNormals, n);
        return e;
    });
}

void pquad_mesh3_data(Pint fflag, Pint vflag, Pint colr_type, const Pint_size* dim,
                      const Pfacet_data_arr3* fdata, const Pfacet_vdata_arr3* vdata) {
    insertElement(Pfn_quad_mesh3_data, [&](const char* n) -> Element {
        checkFlags(vflag, colr_type, n);
        c::require(dim, n);
        c::require(vdata, n);
        const std::size_t vertexCount = c::cellCount(dim->size_x, dim->size_y, n);
        const std::size_t columns = c::count(dim->size_x, n), rows = c::count(dim->size_y, n);
        VertexData v = vertices(vflag, colr_type, vertexCount, *vdata, n);
        QuadrilateralMeshElement e{static_cast<int>(rows), static_cast<int>(columns), std::move(v.points),
                                   std::move(v.colours), std::move(v.normals)};
        const std::size_t quads = rows < 2 || columns < 2 ? 0 : (rows - 1) * (columns - 1);
        facetList(fflag, colr_type, quads, fdata, e.facetColours, e.facetNormals, n);
        return e;
    });
}

void pcomp_fill_area_set_gnorm(Pint vflag, Pint nfa, const Pfacet_vdata_list3* vdata, Pint* err_ind,
                               Pvec3* norm) {
    c::inquire(err_ind, [&](Phigs&) {
        const char* n = "COMPUTE FILL AREA SET GEOMETRIC NORMAL";
        checkFlags(vflag, PINDIRECT, n);
        c::require(norm, n);
        std::vector<glm::dvec3> all;
        const std::size_t areas = c::count(nfa, n);
        if (areas) c::require(vdata, n);
        for (std::size_t a = 0; a < areas; ++a) {
            const VertexData v =
                vertices(vflag, PINDIRECT, c::count(vdata[a].num_vertices, n), vdata[a].vertex_data, n);
            all.insert(all.end(), v.points.begin(), v.points.end());
        }
        for (std::size_t j = 1; j < all.size(); ++j) {
            if (all[j] == all[0]) continue;
            for (std::size_t k = j + 1; k < all.size(); ++k) {
                const glm::dvec3 c = glm::cross(all[j] - all[0], all[k] - all[0]);
                if (glm::length(c) == 0.0) continue;
                const glm::dvec3 u = glm::normalize(c);
                *norm = {static_cast<Pfloat>(u.x), static_cast<Pfloat>(u.y), static_cast<Pfloat>(u.z)};
                return;
            }
            break;
        }
        throw Error(errors::InvalidElementData, n, "no three vertices that are not collinear");
    });
}

}  // extern "C"
