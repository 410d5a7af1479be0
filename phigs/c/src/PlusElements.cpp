// PHIGS PLUS attribute elements and NURBS primitives: state first (error 5), then the
// arguments, then one element through the core at the element pointer.

#include "Binding.h"
#include "Conversions.h"
#include "Insert.h"
#include "phigs.h"

#include "geom/Split.h"

#include <algorithm>

using namespace phigs;
using phigs::c::insertElement;

namespace {

/// An integer attribute whose defined values are lo..hi (2202 outside).
void insertRanged(int fn, ElementType type, int v, int lo, int hi) {
    insertElement(fn, [&](const char* name) -> Element {
        if (v < lo || v > hi) throw Error(PE_ENUM_TYPE_INVAL, name, "value " + std::to_string(v));
        return IndexAttribute{type, v};
    });
}

Colour colour(const Pgcolr& c, const char* name) {
    if (c.type == PINDIRECT) return Colour::indexed(c.val.ind);
    if (!isColourModel(c.type)) throw Error(PE_ENUM_TYPE_INVAL, name, "colour type");
    return Colour::inModel(static_cast<ColourModel>(c.type),
                           {c.val.general.x, c.val.general.y, c.val.general.z});
}

Element properties(ElementType type, const Prefl_props* p, const char* name) {
    c::require(p, name);
    AreaPropertiesAttribute a{type};
    a.ambient = p->ambient_coef, a.diffuse = p->diffuse_coef, a.specular = p->specular_coef;
    a.specularColour = colour(p->specular_colr, name);
    a.specularExponent = p->specular_exp, a.transparency = p->transpar_coef;
    return a;
}

std::vector<double> floats(const Pfloat_list* list, const char* name) {
    c::require(list, name);
    std::vector<double> out(c::count(list->num_floats, name));
    if (!out.empty()) c::require(list->floats, name);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = list->floats[i];
    return out;
}

bool rational(const Prational& r, const char* name) {
    const int v = c::raw(r);
    if (v != PRATIONAL && v != PNON_RATIONAL) throw Error(PE_ENUM_TYPE_INVAL, name, "rationality");
    return v == PRATIONAL;
}

/// A B-spline as the geometry kernel keeps it (Cartesian points and weights), its rules checked
/// there: GeometryError becomes -202 naming the rule.
template <class Build>
auto checked(const char* name, Build&& build) {
    try {
        return build();
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(errors::InvalidElementData, name, e.what());
    }
}

/// Homogeneous (w x, w y, w z, w) to Cartesian point and weight; w must be positive.
void dehomogenize(const Ppoint4& p, std::vector<glm::dvec3>& points, std::vector<double>& weights,
                  const char* name) {
    if (!(p.w > 0)) throw Error(errors::InvalidElementData, name, "a control point weight is not positive");
    points.push_back(glm::dvec3(p.x, p.y, p.z) / static_cast<double>(p.w));
    weights.push_back(p.w);
}

/// The part of a trim curve over [tmin, tmax] that trims (tmin == tmax: the whole curve, as for
/// NON-UNIFORM B-SPLINE CURVE); a range outside the knots' domain is -202.
geom::Curve trimRange(const geom::Curve& curve, double tmin, double tmax, const char* name) {
    if (tmin == tmax) return curve;
    const double start = curve.domainStart(), end = curve.domainEnd();
    if (!(tmin < tmax) || tmin < start || tmax > end)
        throw Error(errors::InvalidElementData, name,
                    "a trim curve's range [" + std::to_string(tmin) + ", " + std::to_string(tmax) +
                        "] is not within its knots' domain [" + std::to_string(start) + ", " +
                        std::to_string(end) + "]");
    geom::Curve part = curve;
    if (tmin > start) part = geom::split(part, tmin).second;
    if (tmax < end) part = geom::split(part, tmax).first;
    return part;
}

geom::Curve trimCurve(const Ptrimcurve& t, const char* name) {
    const bool rat = rational(t.rationality, name);
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    if (rat) {
        const std::size_t n = c::count(t.cpts.point3d.num_points, name);
        if (n) c::require(t.cpts.point3d.points, name);
        for (std::size_t i = 0; i < n; ++i) {
            const Ppoint3& q = t.cpts.point3d.points[i];
            dehomogenize({q.x, q.y, 0.0f, q.z}, points, weights, name);
        }
    } else {
        const std::size_t n = c::count(t.cpts.point2d.num_points, name);
        if (n) c::require(t.cpts.point2d.points, name);
        for (std::size_t i = 0; i < n; ++i)
            points.push_back({t.cpts.point2d.points[i].x, t.cpts.point2d.points[i].y, 0});
    }
    const std::vector<double> knots = floats(&t.knots, name);
    const geom::Curve whole = checked(name, [&] { return geom::Curve(t.order - 1, knots, points, weights); });
    return trimRange(whole, t.tmin, t.tmax, name);
}

/// A trimming curve's visibility and approximation criteria (the store refuses a value that is
/// not finite).
TrimCurveDisplay trimDisplay(const Ptrimcurve& t, const char* name) {
    const int visible = c::raw(t.visible);
    if (visible != PEDGE_OFF && visible != PEDGE_ON)
        throw Error(PE_ENUM_TYPE_INVAL, name, "trim curve visibility");
    // PCURV_WS_DEP ignores its value: keep the default so equal elements compare equal.
    if (t.approx_type == PCURV_WS_DEP) return {visible == PEDGE_ON, PCURV_WS_DEP, 1.0};
    return {visible == PEDGE_ON, t.approx_type, t.approx_val};
}

/// Level curves (types 4 and 5; psc_4 and psc_5 have one layout): origin, direction and the
/// parameters of the planes. The store refuses a zero direction or values that are not finite.
SurfaceCharacteristicsAttribute levelCurves(Pint type, const Ppara_surf_characs* data, const char* n) {
    c::require(data, n);
    SurfaceCharacteristicsAttribute e{type, 0, 0, 0};
    auto read = [&](const auto& d) {
        e.origin = {d.origin.x, d.origin.y, d.origin.z};
        e.direction = {d.direction.delta_x, d.direction.delta_y, d.direction.delta_z};
        e.levels = floats(&d.params, n);
    };
    if (type == PSC_LEVEL_CURVES_MC)
        read(data->psc_4);
    else
        read(data->psc_5);
    return e;
}

}  // namespace

extern "C" {

void pset_line_shad_meth(Pint v) {
    insertRanged(Pfn_set_line_shad_meth, ElementType::PolylineShadingMethod, v, PSD_NONE, PSD_COLOUR);
}
void pset_int_shad_meth(Pint v) {
    insertRanged(Pfn_set_int_shad_meth, ElementType::InteriorShadingMethod, v, PSD_NONE, PSD_NORMAL);
}
void pset_back_int_shad_meth(Pint v) {
    insertRanged(Pfn_set_back_int_shad_meth, ElementType::BackInteriorShadingMethod, v, PSD_NONE, PSD_NORMAL);
}
void pset_refl_eqn(Pint v) {
    insertRanged(Pfn_set_refl_eqn, ElementType::InteriorReflectanceEquation, v, PREFL_NONE,
                 PREFL_AMB_DIFF_SPEC);
}
void pset_back_refl_eqn(Pint v) {
    insertRanged(Pfn_set_back_refl_eqn, ElementType::BackInteriorReflectanceEquation, v, PREFL_NONE,
                 PREFL_AMB_DIFF_SPEC);
}
void pset_back_int_style(Pint_style v) {
    insertRanged(Pfn_set_back_int_style, ElementType::BackInteriorStyle, c::raw(v), PSTYLE_HOLLOW,
                 PSTYLE_EMPTY);
}
void pset_back_int_style_ind(Pint v) {
    insertElement(Pfn_set_back_int_style_ind, [&](const char*) -> Element {
        return IndexAttribute{ElementType::BackInteriorStyleIndex, v};
    });
}
void pset_face_disting_mode(Pdisting_mode v) {
    insertRanged(Pfn_set_face_disting_mode, ElementType::FaceDistinguishingMode, c::raw(v), PDISTING_NO,
                 PDISTING_YES);
}
void pset_face_cull_mode(Pcull_mode v) {
    insertRanged(Pfn_set_face_cull_mode, ElementType::FaceCullingMode, c::raw(v), PCULL_NONE,
                 PCULL_FRONTFACE);
}
void pset_dcue_ind(Pint v) {
    insertElement(Pfn_set_dcue_ind, [&](const char*) -> Element {
        return IndexAttribute{ElementType::DepthCueIndex, v};
    });
}
void pset_colr_map_ind(Pint v) {
    insertElement(Pfn_set_colr_map_ind, [&](const char*) -> Element {
        return IndexAttribute{ElementType::ColourMappingIndex, v};
    });
}
void pset_back_int_colr(const Pgcolr* v) {
    insertElement(Pfn_set_back_int_colr, [&](const char* name) -> Element {
        c::require(v, name);
        return ColourAttribute{ElementType::BackInteriorColour, colour(*v, name)};
    });
}
void pset_refl_props(const Prefl_props* p) {
    insertElement(Pfn_set_refl_props,
                  [&](const char* n) { return properties(ElementType::AreaProperties, p, n); });
}
void pset_back_refl_props(const Prefl_props* p) {
    insertElement(Pfn_set_back_refl_props,
                  [&](const char* n) { return properties(ElementType::BackAreaProperties, p, n); });
}
void pset_light_src_state(const Pint_list* activation, const Pint_list* deactivation) {
    insertElement(Pfn_set_light_src_state, [&](const char* n) -> Element {
        return LightSourceStateAttribute{c::ints(activation, n), c::ints(deactivation, n)};
    });
}
void pset_curve_approx(Pint type, Pfloat value) {
    insertElement(Pfn_set_curve_approx, [&](const char*) -> Element {
        return ApproximationAttribute{ElementType::CurveApproximationCriteria, type, value, value};
    });
}
void pset_surf_approx(Pint type, Pfloat u, Pfloat v) {
    insertElement(Pfn_set_surf_approx, [&](const char*) -> Element {
        return ApproximationAttribute{ElementType::SurfaceApproximationCriteria, type, u, v};
    });
}
void pset_para_surf_characs(Pint type, const Ppara_surf_characs* data) {
    insertElement(Pfn_set_para_surf_characs, [&](const char* n) -> Element {
        if (type == PSC_NONE || type == PSC_WS_DEP) return SurfaceCharacteristicsAttribute{type, 0, 0, 0};
        if (type == PSC_LEVEL_CURVES_MC || type == PSC_LEVEL_CURVES_WC) return levelCurves(type, data, n);
        if (type != PSC_ISOPARAMETRIC_CURVES)
            throw Error(errors::InvalidElementData, n,
                        "surface characteristics type " + std::to_string(type));
        c::require(data, n);
        const int placement = c::raw(data->psc_3.placement);
        if (placement != PCP_UNIFORM && placement != PCP_NON_UNIFORM)
            throw Error(PE_ENUM_TYPE_INVAL, n, "curve placement");
        if (data->psc_3.u_count < 0 || data->psc_3.v_count < 0)
            throw Error(c::kBadArgument, n, "negative iso-curve count");
        return SurfaceCharacteristicsAttribute{type, placement, data->psc_3.u_count, data->psc_3.v_count};
    });
}

void pnuni_bsp_curv(Pint order, const Pfloat_list* knots, Prational rationality, const Ppoint_list34* cpts,
                    Pfloat min, Pfloat max) {
    insertElement(Pfn_nuni_bsp_curv, [&](const char* n) -> Element {
        c::require(cpts, n);
        const bool rat = rational(rationality, n);
        std::vector<glm::dvec3> points;
        std::vector<double> weights;
        if (rat) {
            const std::size_t count = c::count(cpts->point4d.num_points, n);
            if (count) c::require(cpts->point4d.points, n);
            for (std::size_t i = 0; i < count; ++i) dehomogenize(cpts->point4d.points[i], points, weights, n);
        } else {
            points = c::points(&cpts->point3d, n);
        }
        const std::vector<double> k = floats(knots, n);
        NurbsCurveElement e{checked(n, [&] { return geom::Curve(order - 1, k, points, weights); }), min, max};
        return e;
    });
}

void pnuni_bsp_surf(Pint uorder, Pint vorder, const Pfloat_list* uknots, const Pfloat_list* vknots,
                    Prational rationality, const Ppoint_grid34* grid, Pint num_trim_loops,
                    const Ptrimcurve_list* trim_loops) {
    insertElement(Pfn_nuni_bsp_surf, [&](const char* n) -> Element {
        c::require(grid, n);
        const bool rat = rational(rationality, n);
        const std::size_t nu = c::count(grid->num_points.size_x, n),
                          nv = c::count(grid->num_points.size_y, n);
        if (c::cellCount(grid->num_points.size_x, grid->num_points.size_y, n) > 0)
            c::require(rat ? static_cast<const void*>(grid->points.point4d) : grid->points.point3d, n);
        // The kernel keeps u as the slow index; the grid runs u fastest.
        std::vector<glm::dvec3> points;
        std::vector<double> weights;
        for (std::size_t i = 0; i < nu; ++i)
            for (std::size_t j = 0; j < nv; ++j) {
                const std::size_t at = j * nu + i;
                if (rat)
                    dehomogenize(grid->points.point4d[at], points, weights, n);
                else
                    points.push_back(
                        {grid->points.point3d[at].x, grid->points.point3d[at].y, grid->points.point3d[at].z});
            }
        const std::vector<double> ku = floats(uknots, n), kv = floats(vknots, n);
        NurbsSurfaceElement e{
            checked(n,
                    [&] { return geom::Surface(uorder - 1, vorder - 1, ku, kv, nu, nv, points, weights); }),
            {}};
        const std::size_t loops = c::count(num_trim_loops, n);
        if (loops) c::require(trim_loops, n);
        for (std::size_t l = 0; l < loops; ++l) {
            const std::size_t curves = c::count(trim_loops[l].num_curves, n);
            if (curves) c::require(trim_loops[l].curves, n);
            TrimLoop loop;
            for (std::size_t k = 0; k < curves; ++k) {
                const Ptrimcurve& t = trim_loops[l].curves[k];
                loop.push_back(trimCurve(t, n));
                e.trimDisplay.push_back(trimDisplay(t, n));
            }
            e.trimLoops.push_back(std::move(loop));
        }
        // Every curve hidden and workstation dependent is what an empty list says.
        if (std::all_of(e.trimDisplay.begin(), e.trimDisplay.end(),
                        [](const TrimCurveDisplay& d) { return d == TrimCurveDisplay{}; }))
            e.trimDisplay.clear();
        return e;
    });
}

}  // extern "C"
