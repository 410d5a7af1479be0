#include "ElementContent.h"

#include "Conversions.h"

#include <algorithm>
#include <span>
#include <type_traits>

namespace phigs::c {

namespace {

Ppoint3 p3(const glm::dvec3& v) {
    return {static_cast<Pfloat>(v.x), static_cast<Pfloat>(v.y), static_cast<Pfloat>(v.z)};
}
Ppoint p2(const glm::dvec3& v) {
    return {static_cast<Pfloat>(v.x), static_cast<Pfloat>(v.y)};
}
Pvec3 v3(const glm::dvec3& v) {
    return {static_cast<Pfloat>(v.x), static_cast<Pfloat>(v.y), static_cast<Pfloat>(v.z)};
}
Pvec v2(const glm::dvec3& v) {
    return {static_cast<Pfloat>(v.x), static_cast<Pfloat>(v.y)};
}

// Lists of lists: every point goes into one vector first, so growing it cannot move what a
// list already points at.
void pointLists(const std::vector<std::vector<glm::dvec3>>& contours, bool twoD, Phigs_store& s) {
    for (const auto& c : contours)
        for (const auto& v : c) twoD ? s.points.push_back(p2(v)) : s.points3.push_back(p3(v));
    std::size_t at = 0;
    for (const auto& c : contours) {
        const Pint n = static_cast<Pint>(c.size());
        if (twoD)
            s.lists.push_back({n, s.points.data() + at});
        else
            s.lists3.push_back({n, s.points3.data() + at});
        at += c.size();
    }
    if (twoD)
        s.data.point_list_list = {static_cast<Pint>(s.lists.size()), s.lists.data()};
    else
        s.data.point_list_list3 = {static_cast<Pint>(s.lists3.size()), s.lists3.data()};
}

void pointList(std::span<const glm::dvec3> points, bool twoD, Phigs_store& s) {
    for (const auto& v : points) twoD ? s.points.push_back(p2(v)) : s.points3.push_back(p3(v));
    if (twoD)
        s.data.point_list = {static_cast<Pint>(s.points.size()), s.points.data()};
    else
        s.data.point_list3 = {static_cast<Pint>(s.points3.size()), s.points3.data()};
}

void textContent(const TextElement& e, Phigs_store& s) {
    s.text = e.text;
    if (e.twoD) {
        s.data.text = {p2(e.position), s.text.data()};
    } else {
        s.data.text3.pos = p3(e.position);
        s.data.text3.dir[0] = v3(e.direction1);
        s.data.text3.dir[1] = v3(e.direction2);
        s.data.text3.char_string = s.text.data();
    }
}

void annotationContent(const AnnotationTextElement& e, Phigs_store& s) {
    s.text = e.text;
    if (e.twoD)
        s.data.anno_text_rel = {p2(e.reference), v2(e.offset), s.text.data()};
    else
        s.data.anno_text_rel3 = {p3(e.reference), v3(e.offset), s.text.data()};
}

// The point list first (pointList writes the union's leading point list), then id and record.
void gdpContent(const GdpElement& e, Phigs_store& s) {
    s.text = e.data;
    const Pdata record{static_cast<Pint>(s.text.size()), s.text.data()};
    for (const auto& v : e.points) e.twoD ? s.points.push_back(p2(v)) : s.points3.push_back(p3(v));
    const Pint n = static_cast<Pint>(e.points.size());
    if (e.twoD) {
        s.data.gdp.id = e.identifier;
        s.data.gdp.point_list = {n, s.points.data()};
        s.data.gdp.data.unsupp = record;
    } else {
        s.data.gdp3.id = e.identifier;
        s.data.gdp3.point_list = {n, s.points3.data()};
        s.data.gdp3.data.unsupp = record;
    }
}

void cellArrayContent(const CellArrayElement& e, Phigs_store& s) {
    s.ints.assign(e.colourIndices.begin(), e.colourIndices.end());
    const Ppat_rep rep{{e.columns, e.rows}, s.ints.data()};
    if (e.twoD)
        s.data.cell_array = {{p2(e.p), p2(e.q)}, rep};
    else
        s.data.cell_array3 = {{p3(e.p), p3(e.q), p3(e.r)}, rep};
}

void transformContent(const TransformElement& e, Phigs_store& s) {
    const auto compose = static_cast<Pcompose_type>(e.composition);
    switch (e.type) {
        case ElementType::LocalModellingTransformation3:
            s.data.local_tran3.compose_type = compose;
            fromGlm(e.matrix, s.data.local_tran3.matrix);
            break;
        case ElementType::LocalModellingTransformation:
            s.data.local_tran.compose_type = compose;
            fromGlm(lower(e.matrix), s.data.local_tran.matrix);
            break;
        case ElementType::GlobalModellingTransformation3:
            fromGlm(e.matrix, s.data.global_tran3);
            break;
        default:
            fromGlm(lower(e.matrix), s.data.global_tran);
            break;
    }
}

void modelClipContent(const ModelClipElement& e, Phigs_store& s) {
    for (const auto& [point, normal] : e.halfSpaces)
        e.twoD ? s.halfSpaces.push_back({p2(point), v2(normal)})
               : s.halfSpaces3.push_back({p3(point), v3(normal)});
    if (e.twoD)
        s.data.model_clip = {e.op, {static_cast<Pint>(s.halfSpaces.size()), s.halfSpaces.data()}};
    else
        s.data.model_clip3 = {e.op, {static_cast<Pint>(s.halfSpaces3.size()), s.halfSpaces3.data()}};
}

void colourContent(const ColourAttribute& e, Phigs_store& s) {
    if (!e.colour.direct) {
        s.data.int_data = e.colour.index;
        return;
    }
    s.data.colr.type = static_cast<Pint>(e.colour.model);
    s.data.colr.val.general = {static_cast<Pfloat>(e.colour.rgb.x), static_cast<Pfloat>(e.colour.rgb.y),
                               static_cast<Pfloat>(e.colour.rgb.z)};
}

void patternContent(const PatternAttribute& e, Phigs_store& s) {
    if (e.type == ElementType::PatternSize)
        s.data.pat_size = {static_cast<Pfloat>(e.size.x), static_cast<Pfloat>(e.size.y)};
    else if (e.type == ElementType::PatternReferencePoint)
        s.data.pat_ref_point = p2(e.referencePoint);
    else
        s.data.pat_ref_point_vecs = {p3(e.referencePoint), {v3(e.vectorX), v3(e.vectorY)}};
}

void propertiesContent(const AreaPropertiesAttribute& e, Phigs_store& s) {
    Prefl_props& p = s.data.props;
    p.ambient_coef = static_cast<Pfloat>(e.ambient), p.diffuse_coef = static_cast<Pfloat>(e.diffuse);
    p.specular_coef = static_cast<Pfloat>(e.specular);
    p.specular_exp = static_cast<Pfloat>(e.specularExponent),
    p.transpar_coef = static_cast<Pfloat>(e.transparency);
    if (e.specularColour.direct) {
        p.specular_colr.type = static_cast<Pint>(e.specularColour.model);
        p.specular_colr.val.general = {static_cast<Pfloat>(e.specularColour.rgb.x),
                                       static_cast<Pfloat>(e.specularColour.rgb.y),
                                       static_cast<Pfloat>(e.specularColour.rgb.z)};
    } else {
        p.specular_colr.type = PINDIRECT;
        p.specular_colr.val.ind = e.specularColour.index;
    }
}

void approximationContent(const ApproximationAttribute& e, Phigs_store& s) {
    if (e.type == ElementType::CurveApproximationCriteria)
        s.data.curv_approx = {e.criteria, static_cast<Pfloat>(e.valueU)};
    else
        s.data.surf_approx = {e.criteria, static_cast<Pfloat>(e.valueU), static_cast<Pfloat>(e.valueV)};
}

void characteristicsContent(const SurfaceCharacteristicsAttribute& e, Phigs_store& s) {
    s.data.para_surf_characs.type = e.style;
    if (e.style == PSC_ISOPARAMETRIC_CURVES)
        s.data.para_surf_characs.data.psc_3 = {static_cast<Pcurve_placement>(e.placement), e.curvesU,
                                               e.curvesV};
    if (e.style != PSC_LEVEL_CURVES_MC && e.style != PSC_LEVEL_CURVES_WC) return;
    for (double t : e.levels) s.floats.push_back(static_cast<Pfloat>(t));
    auto write = [&](auto& d) {
        d.origin = p3(e.origin);
        d.direction = v3(e.direction);
        d.params = {static_cast<Pint>(s.floats.size()), s.floats.data()};
    };
    if (e.style == PSC_LEVEL_CURVES_MC)
        write(s.data.para_surf_characs.data.psc_4);
    else
        write(s.data.para_surf_characs.data.psc_5);
}

void lightStateContent(const LightSourceStateAttribute& e, Phigs_store& s) {
    s.ints.assign(e.activate.begin(), e.activate.end());
    s.ints.insert(s.ints.end(), e.deactivate.begin(), e.deactivate.end());
    const Pint on = static_cast<Pint>(e.activate.size()), off = static_cast<Pint>(e.deactivate.size());
    s.data.lss.activation = {on, s.ints.data()};
    s.data.lss.deactivation = {off, s.ints.data() + on};
}

// Knots into s.floats at `at`; returns their list once every float is in (the vector is
// reserved first, so earlier lists stay valid).
Pfloat_list knotList(const std::vector<double>& knots, Phigs_store& s) {
    const std::size_t at = s.floats.size();
    for (double k : knots) s.floats.push_back(static_cast<Pfloat>(k));
    return {static_cast<Pint>(knots.size()), s.floats.data() + at};
}

Ppoint4 homogeneous(const glm::dvec3& p, double w) {
    return {static_cast<Pfloat>(p.x * w), static_cast<Pfloat>(p.y * w), static_cast<Pfloat>(p.z * w),
            static_cast<Pfloat>(w)};
}

void curveContent(const NurbsCurveElement& e, Phigs_store& s) {
    const geom::Curve& c = e.curve;
    s.floats.reserve(c.knots.size());
    auto& d = s.data.nuni_bsp_curv;
    d.order = c.degree + 1;
    d.knots = knotList(c.knots, s);
    d.rationality = c.rational() ? PRATIONAL : PNON_RATIONAL;
    for (std::size_t i = 0; i < c.points.size(); ++i)
        c.rational() ? s.points4.push_back(homogeneous(c.points[i], c.weights[i]))
                     : s.points3.push_back(p3(c.points[i]));
    if (c.rational())
        d.cpts.point4d = {static_cast<Pint>(s.points4.size()), s.points4.data()};
    else
        d.cpts.point3d = {static_cast<Pint>(s.points3.size()), s.points3.data()};
    d.min = static_cast<Pfloat>(e.rangeStart), d.max = static_cast<Pfloat>(e.rangeEnd);
}

void trimContent(const NurbsSurfaceElement& e, Phigs_store& s) {
    const std::vector<TrimLoop>& loops = e.trimLoops;
    std::size_t points = 0, curves = 0;
    for (const auto& loop : loops)
        for (const auto& c : loop) points += c.points.size(), curves += 1;
    // Reserved first: the curves point into these vectors as they fill.
    s.points.reserve(s.points.size() + points), s.points3.reserve(s.points3.size() + points);
    s.trimCurves.reserve(curves);
    for (const auto& loop : loops)
        for (const auto& c : loop) {
            Ptrimcurve t{};
            const TrimCurveDisplay display = e.displayOf(s.trimCurves.size());
            t.visible = display.visible ? PEDGE_ON : PEDGE_OFF;
            t.rationality = c.rational() ? PRATIONAL : PNON_RATIONAL;
            t.order = c.degree + 1;
            t.approx_type = display.approximation;
            t.approx_val = static_cast<Pfloat>(display.approximationValue);
            t.knots = knotList(c.knots, s);
            t.tmin = static_cast<Pfloat>(c.domainStart()), t.tmax = static_cast<Pfloat>(c.domainEnd());
            for (std::size_t i = 0; i < c.points.size(); ++i) {
                const double w = c.weight(i);
                if (c.rational())
                    s.points3.push_back({static_cast<Pfloat>(c.points[i].x * w),
                                         static_cast<Pfloat>(c.points[i].y * w), static_cast<Pfloat>(w)});
                else
                    s.points.push_back(p2(c.points[i]));
            }
            const Pint n = static_cast<Pint>(c.points.size());
            if (c.rational())
                t.cpts.point3d = {n, s.points3.data() + s.points3.size() - c.points.size()};
            else
                t.cpts.point2d = {n, s.points.data() + s.points.size() - c.points.size()};
            s.trimCurves.push_back(t);
        }
    std::size_t at = 0;
    for (const auto& loop : loops) {
        s.trimLoops.push_back({static_cast<Pint>(loop.size()), s.trimCurves.data() + at});
        at += loop.size();
    }
}

void surfaceContent(const NurbsSurfaceElement& e, Phigs_store& s) {
    const geom::Surface& f = e.surface;
    std::size_t knots = f.knotsU.size() + f.knotsV.size();
    for (const auto& loop : e.trimLoops)
        for (const auto& c : loop) knots += c.knots.size();
    s.floats.reserve(knots);
    auto& d = s.data.nuni_bsp_surf;
    d.u_order = f.degreeU + 1, d.v_order = f.degreeV + 1;
    d.uknots = knotList(f.knotsU, s);
    d.vknots = knotList(f.knotsV, s);
    d.rationality = f.rational() ? PRATIONAL : PNON_RATIONAL;
    d.grid.num_points = {static_cast<Pint>(f.countU), static_cast<Pint>(f.countV)};
    for (std::size_t j = 0; j < f.countV; ++j)  // u runs fastest in the grid
        for (std::size_t i = 0; i < f.countU; ++i)
            f.rational() ? s.points4.push_back(homogeneous(f.point(i, j), f.weight(i, j)))
                         : s.points3.push_back(p3(f.point(i, j)));
    if (f.rational())
        d.grid.points.point4d = s.points4.data();
    else
        d.grid.points.point3d = s.points3.data();
    trimContent(e, s);
    if (!f.rational()) d.grid.points.point3d = s.points3.data();  // trimContent may have grown it
    d.num_trim_loops = static_cast<Pint>(s.trimLoops.size());
    d.trim_loops = s.trimLoops.empty() ? nullptr : s.trimLoops.data();
}

Pcoval coval(const Colour& c) {
    Pcoval v{};
    if (c.direct)
        v.direct.rgb = {static_cast<Pfloat>(c.rgb.x), static_cast<Pfloat>(c.rgb.y),
                        static_cast<Pfloat>(c.rgb.z)};
    else
        v.ind = c.index;
    return v;
}

Pint vertexFlag(bool colours, bool normals) {
    return colours ? (normals ? PVERT_COORD_COLOUR_NORMAL : PVERT_COORD_COLOUR)
                   : (normals ? PVERT_COORD_NORMAL : PVERT_COORD);
}

// Vertices with their data appended to the store's array for `flag` (reserved by the caller, so
// the answer stays valid while more are appended); the union points at the first one.
Pfacet_vdata_arr3 vertexData(Pint flag, const std::vector<glm::dvec3>& points,
                             const std::vector<Colour>* colours, const std::vector<glm::dvec3>* normals,
                             Phigs_store& s) {
    Pfacet_vdata_arr3 out{};
    for (std::size_t i = 0; i < points.size(); ++i) switch (flag) {
            case PVERT_COORD:
                s.points3.push_back(p3(points[i]));
                break;
            case PVERT_COORD_COLOUR:
                s.ptcolrs.push_back({p3(points[i]), coval((*colours)[i])});
                break;
            case PVERT_COORD_NORMAL:
                s.ptnorms.push_back({p3(points[i]), v3((*normals)[i])});
                break;
            default:
                s.ptconorms.push_back({p3(points[i]), coval((*colours)[i]), v3((*normals)[i])});
                break;
        }
    const std::size_t n = points.size();
    switch (flag) {
        case PVERT_COORD:
            out.points = s.points3.data() + s.points3.size() - n;
            break;
        case PVERT_COORD_COLOUR:
            out.ptcolrs = s.ptcolrs.data() + s.ptcolrs.size() - n;
            break;
        case PVERT_COORD_NORMAL:
            out.ptnorms = s.ptnorms.data() + s.ptnorms.size() - n;
            break;
        default:
            out.ptconorms = s.ptconorms.data() + s.ptconorms.size() - n;
            break;
    }
    return out;
}

void reserveVertices(Phigs_store& s, std::size_t n) {
    s.points3.reserve(n), s.ptcolrs.reserve(n), s.ptnorms.reserve(n), s.ptconorms.reserve(n);
}

Pint colourType(const std::vector<Colour>& colours, bool facet, const Colour& facetColour) {
    if (!colours.empty() && colours.front().direct) return static_cast<Pint>(colours.front().model);
    return facet && facetColour.direct ? static_cast<Pint>(facetColour.model) : PINDIRECT;
}

void fasDataContent(const FillAreaSetWithDataElement& e, Phigs_store& s) {
    auto& d = s.data.fas3_data;
    const bool colours = !e.vertexColours.empty(), normals = !e.vertexNormals.empty();
    d.fflag = e.hasFacetColour ? (e.hasFacetNormal ? PFACET_COLOUR_NORMAL : PFACET_COLOUR)
                               : (e.hasFacetNormal ? PFACET_NORMAL : PFACET_NONE);
    d.eflag = PEDGE_NONE;
    d.vflag = vertexFlag(colours, normals);
    d.colr_type = colourType(colours ? e.vertexColours.front() : std::vector<Colour>{}, e.hasFacetColour,
                             e.facetColour);
    if (d.fflag == PFACET_COLOUR) d.fdata.colr = coval(e.facetColour);
    if (d.fflag == PFACET_NORMAL) d.fdata.norm = v3(e.facetNormal);
    if (d.fflag == PFACET_COLOUR_NORMAL) d.fdata.conorm = {coval(e.facetColour), v3(e.facetNormal)};
    std::size_t total = 0;
    for (const auto& c : e.contours) total += c.size();
    reserveVertices(s, total);
    for (std::size_t i = 0; i < e.contours.size(); ++i)
        s.vertexLists.push_back({static_cast<Pint>(e.contours[i].size()),
                                 vertexData(d.vflag, e.contours[i], colours ? &e.vertexColours[i] : nullptr,
                                            normals ? &e.vertexNormals[i] : nullptr, s)});
    d.nfa = static_cast<Pint>(e.contours.size());
    d.edata = nullptr;
    d.vdata = s.vertexLists.data();
    if (e.edgeFlags.empty()) return;
    d.eflag = PEDGE_VISIBILITY;
    for (const auto& flags : e.edgeFlags)
        for (int f : flags) s.edgeFlags.push_back(f ? PEDGE_ON : PEDGE_OFF);
    std::size_t at = 0;
    for (const auto& flags : e.edgeFlags) {
        s.edgeLists.push_back({static_cast<Pint>(flags.size()), s.edgeFlags.data() + at});
        at += flags.size();
    }
    d.edata = s.edgeLists.data();
}

/// The colour type of a primitive's colours: that of the first one (the binding gives one type to all).
template <class Lists>
Pint firstColourType(const Lists& lists) {
    for (const auto& list : lists)
        if (!list.empty()) return list.front().direct ? static_cast<Pint>(list.front().model) : PINDIRECT;
    return PINDIRECT;
}

void polylineSetContent(const PolylineSetWithDataElement& e, Phigs_store& s) {
    auto& d = s.data.plsd3;
    const bool colours = !e.vertexColours.empty();
    d.vflag = colours ? PVERT_COORD_COLOUR : PVERT_COORD;
    d.colr_type = firstColourType(e.vertexColours);
    std::size_t total = 0;
    for (const auto& line : e.polylines) total += line.size();
    reserveVertices(s, total);
    for (std::size_t i = 0; i < e.polylines.size(); ++i) {
        const Pfacet_vdata_arr3 a =
            vertexData(d.vflag, e.polylines[i], colours ? &e.vertexColours[i] : nullptr, nullptr, s);
        Pline_vdata_list3 line{};
        line.num_vertices = static_cast<Pint>(e.polylines[i].size());
        if (colours)
            line.vertex_data.ptcolrs = a.ptcolrs;
        else
            line.vertex_data.points = a.points;
        s.lineLists.push_back(line);
    }
    d.npl = static_cast<Pint>(e.polylines.size());
    d.vdata = s.lineLists.data();
}

void cellArrayPlusContent(const CellArrayPlusElement& e, Phigs_store& s) {
    for (const Colour& c : e.colours) s.covals.push_back(coval(c));
    auto& d = s.data.cell_array_plus;
    d.paral = {p3(e.p), p3(e.q), p3(e.r)};
    d.dims = {e.columns, e.rows};
    d.colr_type = firstColourType(std::vector<std::vector<Colour>>{e.colours});
    d.colr_array = s.covals.data();
}

/// The facet data of a set of fill area sets, one per set, in the store's arrays.
void sofasFacets(const SetOfFillAreaSetsElement& e, Pint fflag, Phigs_store& s) {
    auto& d = s.data.sofas3;
    for (std::size_t k = 0; k < e.sets.size(); ++k) switch (fflag) {
            case PFACET_COLOUR:
                s.covals.push_back(coval(e.facetColours[k]));
                break;
            case PFACET_NORMAL:
                s.norms.push_back(v3(e.facetNormals[k]));
                break;
            case PFACET_COLOUR_NORMAL:
                s.conorms.push_back({coval(e.facetColours[k]), v3(e.facetNormals[k])});
                break;
            default:
                break;
        }
    if (fflag == PFACET_COLOUR) d.fdata.colrs = s.covals.data();
    if (fflag == PFACET_NORMAL) d.fdata.norms = s.norms.data();
    if (fflag == PFACET_COLOUR_NORMAL) d.fdata.conorms = s.conorms.data();
}

/// The contours' vertex indices (and edge flags) of every set: flat arrays first, then the
/// lists pointing into them, so no pointer moves.
void sofasContours(const SetOfFillAreaSetsElement& e, Phigs_store& s) {
    auto& d = s.data.sofas3;
    const bool edges = !e.edgeFlags.empty();
    for (std::size_t k = 0; k < e.sets.size(); ++k)
        for (std::size_t c = 0; c < e.sets[k].size(); ++c) {
            s.ints.insert(s.ints.end(), e.sets[k][c].begin(), e.sets[k][c].end());
            if (edges)
                for (int f : e.edgeFlags[k][c]) s.edgeFlags.push_back(f ? PEDGE_ON : PEDGE_OFF);
        }
    std::size_t at = 0;
    for (const auto& set : e.sets)
        for (const auto& contour : set) {
            const auto n = static_cast<Pint>(contour.size());
            s.intLists.push_back({n, s.ints.data() + at});
            if (edges) s.edgeLists.push_back({n, s.edgeFlags.data() + at});
            at += contour.size();
        }
    std::size_t list = 0;
    for (const auto& set : e.sets) {
        const auto n = static_cast<Pint>(set.size());
        s.intListLists.push_back({n, s.intLists.data() + list});
        if (edges) s.edgeListLists.push_back({n, s.edgeLists.data() + list});
        list += set.size();
    }
    d.vlist = s.intListLists.data();
    d.edata = edges ? s.edgeListLists.data() : nullptr;
}

void sofasContent(const SetOfFillAreaSetsElement& e, Phigs_store& s) {
    auto& d = s.data.sofas3;
    const bool fc = !e.facetColours.empty(), fn = !e.facetNormals.empty();
    d.fflag = fc ? (fn ? PFACET_COLOUR_NORMAL : PFACET_COLOUR) : (fn ? PFACET_NORMAL : PFACET_NONE);
    d.eflag = e.edgeFlags.empty() ? PEDGE_NONE : PEDGE_VISIBILITY;
    d.vflag = vertexFlag(!e.vertexColours.empty(), !e.vertexNormals.empty());
    d.colr_type = firstColourType(std::vector<std::vector<Colour>>{e.vertexColours, e.facetColours});
    d.num_sets = static_cast<Pint>(e.sets.size());
    sofasFacets(e, d.fflag, s);
    sofasContours(e, s);
    reserveVertices(s, e.vertices.size());
    d.vdata.num_vertices = static_cast<Pint>(e.vertices.size());
    d.vdata.vertex_data = vertexData(d.vflag, e.vertices, &e.vertexColours, &e.vertexNormals, s);
}

template <class Mesh>
Pfacet_vdata_arr3 meshData(const Mesh& e, Pint& vflag, Pint& colrType, Phigs_store& s) {
    const bool colours = !e.vertexColours.empty(), normals = !e.vertexNormals.empty();
    vflag = vertexFlag(colours, normals);
    colrType = firstColourType(std::vector<std::vector<Colour>>{e.vertexColours, e.facetColours});
    reserveVertices(s, e.points.size());
    return vertexData(vflag, e.points, &e.vertexColours, &e.vertexNormals, s);
}

/// The facet data of a triangle strip or quadrilateral mesh in the store's arrays.
template <class Mesh>
Pfacet_data_arr3 meshFacets(const Mesh& e, Pint& fflag, Phigs_store& s) {
    const bool fc = !e.facetColours.empty(), fn = !e.facetNormals.empty();
    fflag = fc ? (fn ? PFACET_COLOUR_NORMAL : PFACET_COLOUR) : (fn ? PFACET_NORMAL : PFACET_NONE);
    Pfacet_data_arr3 out{};
    const std::size_t n = std::max(e.facetColours.size(), e.facetNormals.size());
    for (std::size_t k = 0; k < n; ++k) switch (fflag) {
            case PFACET_COLOUR:
                s.covals.push_back(coval(e.facetColours[k]));
                break;
            case PFACET_NORMAL:
                s.norms.push_back(v3(e.facetNormals[k]));
                break;
            default:
                s.conorms.push_back({coval(e.facetColours[k]), v3(e.facetNormals[k])});
                break;
        }
    if (fflag == PFACET_COLOUR) out.colrs = s.covals.data();
    if (fflag == PFACET_NORMAL) out.norms = s.norms.data();
    if (fflag == PFACET_COLOUR_NORMAL) out.conorms = s.conorms.data();
    return out;
}

}  // namespace

int fillContent(const Element& element, Phigs_store& s) {
    s.clear();
    return std::visit(
        [&](const auto& e) -> int {
            using E = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<E, PolylineElement> || std::is_same_v<E, PolymarkerElement> ||
                          std::is_same_v<E, FillAreaElement>)
                pointList(e.points, e.twoD, s);
            else if constexpr (std::is_same_v<E, FillAreaSetElement>)
                pointLists(e.contours, e.twoD, s);
            else if constexpr (std::is_same_v<E, TextElement>)
                textContent(e, s);
            else if constexpr (std::is_same_v<E, AnnotationTextElement>)
                annotationContent(e, s);
            else if constexpr (std::is_same_v<E, CellArrayElement>)
                cellArrayContent(e, s);
            else if constexpr (std::is_same_v<E, IndexAttribute>)
                s.data.int_data = e.value;
            else if constexpr (std::is_same_v<E, RealAttribute>)
                s.data.float_data = static_cast<Pfloat>(e.value);
            else if constexpr (std::is_same_v<E, ColourAttribute>)
                colourContent(e, s);
            else if constexpr (std::is_same_v<E, UpVectorAttribute>)
                s.data.char_up_vec = {static_cast<Pfloat>(e.up.x), static_cast<Pfloat>(e.up.y)};
            else if constexpr (std::is_same_v<E, PatternAttribute>)
                patternContent(e, s);
            else if constexpr (std::is_same_v<E, AlignmentAttribute>)
                s.data.text_align = {static_cast<Phor_text_align>(e.horizontal),
                                     static_cast<Pvert_text_align>(e.vertical)};
            else if constexpr (std::is_same_v<E, AsfAttribute>)
                s.data.asf = {c::paspectOf(e.aspect), e.individual ? PASF_INDIV : PASF_BUNDLED};
            else if constexpr (std::is_same_v<E, NameSetElement>) {
                s.ints.assign(e.names.begin(), e.names.end());
                s.data.names = {static_cast<Pint>(s.ints.size()), s.ints.data()};
            } else if constexpr (std::is_same_v<E, TransformElement>)
                transformContent(e, s);
            else if constexpr (std::is_same_v<E, ModelClipElement>)
                modelClipContent(e, s);
            else if constexpr (std::is_same_v<E, RestoreModelClipElement>)
                return 0;  // no data
            else if constexpr (std::is_same_v<E, ExecuteStructureElement>)
                s.data.int_data = e.structureId;
            else if constexpr (std::is_same_v<E, LabelElement>)
                s.data.int_data = e.label;
            else if constexpr (std::is_same_v<E, ApplicationDataElement>) {
                s.text = e.data;
                s.data.appl_data = {static_cast<Pint>(s.text.size()), s.text.data()};
            } else if constexpr (std::is_same_v<E, GdpElement>)
                gdpContent(e, s);
            else if constexpr (std::is_same_v<E, AreaPropertiesAttribute>)
                propertiesContent(e, s);
            else if constexpr (std::is_same_v<E, ApproximationAttribute>)
                approximationContent(e, s);
            else if constexpr (std::is_same_v<E, SurfaceCharacteristicsAttribute>)
                characteristicsContent(e, s);
            else if constexpr (std::is_same_v<E, LightSourceStateAttribute>)
                lightStateContent(e, s);
            else if constexpr (std::is_same_v<E, NurbsCurveElement>)
                curveContent(e, s);
            else if constexpr (std::is_same_v<E, NurbsSurfaceElement>)
                surfaceContent(e, s);
            else if constexpr (std::is_same_v<E, FillAreaSetWithDataElement>)
                fasDataContent(e, s);
            else if constexpr (std::is_same_v<E, TriangleStripElement>) {
                auto& d = s.data.tri_strip3;
                d.nv = static_cast<Pint>(e.points.size());
                d.vdata = meshData(e, d.vflag, d.colr_type, s);
                d.fdata = meshFacets(e, d.fflag, s);
            } else if constexpr (std::is_same_v<E, QuadrilateralMeshElement>) {
                auto& d = s.data.quad_mesh3;
                d.dim = {e.columns, e.rows};
                d.vdata = meshData(e, d.vflag, d.colr_type, s);
                d.fdata = meshFacets(e, d.fflag, s);
            } else if constexpr (std::is_same_v<E, PolylineSetWithDataElement>)
                polylineSetContent(e, s);
            else if constexpr (std::is_same_v<E, CellArrayPlusElement>)
                cellArrayPlusContent(e, s);
            else if constexpr (std::is_same_v<E, SetOfFillAreaSetsElement>)
                sofasContent(e, s);
            else if constexpr (std::is_same_v<E, GseElement>) {
                s.text = e.data;
                s.data.gse.id = e.identifier;
                s.data.gse.data.unsupp = {static_cast<Pint>(s.text.size()), s.text.data()};
            } else
                return kNoContentForm;
            return 0;
        },
        element);
}

}  // namespace phigs::c
