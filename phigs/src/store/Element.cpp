#include "phigs/store/Element.h"

#include "ElementFields.h"
#include "phigs/core/TransformUtilities.h"
#include "phigs/store/Gdp.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <span>
#include <type_traits>

namespace phigs {

namespace {

constexpr std::array<std::string_view, static_cast<std::size_t>(ElementType::Count_)> kNames = {
    "ALL",
    "NIL",
    "POLYLINE 3",
    "POLYLINE",
    "POLYMARKER 3",
    "POLYMARKER",
    "FILL AREA 3",
    "FILL AREA",
    "FILL AREA SET 3",
    "FILL AREA SET",
    "TEXT 3",
    "TEXT",
    "ANNOTATION TEXT RELATIVE 3",
    "ANNOTATION TEXT RELATIVE",
    "CELL ARRAY 3",
    "CELL ARRAY",
    "NON-UNIFORM B-SPLINE CURVE",
    "NON-UNIFORM B-SPLINE SURFACE",
    "FILL AREA SET 3 WITH DATA",
    "TRIANGLE STRIP 3 WITH DATA",
    "QUADRILATERAL MESH 3 WITH DATA",
    "POLYLINE SET 3 WITH DATA",
    "CELL ARRAY 3 PLUS",
    "SET OF FILL AREA SETS 3 WITH DATA",
    "SET POLYLINE INDEX",
    "SET POLYMARKER INDEX",
    "SET TEXT INDEX",
    "SET INTERIOR INDEX",
    "SET EDGE INDEX",
    "SET LINETYPE",
    "SET LINEWIDTH SCALE FACTOR",
    "SET POLYLINE COLOUR",
    "SET POLYLINE SHADING METHOD",
    "SET MARKER TYPE",
    "SET MARKER SIZE SCALE FACTOR",
    "SET POLYMARKER COLOUR",
    "SET TEXT FONT",
    "SET TEXT PRECISION",
    "SET CHARACTER EXPANSION FACTOR",
    "SET CHARACTER SPACING",
    "SET TEXT COLOUR",
    "SET CHARACTER HEIGHT",
    "SET CHARACTER UP VECTOR",
    "SET TEXT PATH",
    "SET TEXT ALIGNMENT",
    "SET ANNOTATION TEXT CHARACTER HEIGHT",
    "SET ANNOTATION TEXT CHARACTER UP VECTOR",
    "SET ANNOTATION TEXT PATH",
    "SET ANNOTATION TEXT ALIGNMENT",
    "SET ANNOTATION STYLE",
    "SET INTERIOR STYLE",
    "SET INTERIOR STYLE INDEX",
    "SET INTERIOR COLOUR",
    "SET BACK INTERIOR STYLE",
    "SET BACK INTERIOR STYLE INDEX",
    "SET BACK INTERIOR COLOUR",
    "SET INTERIOR SHADING METHOD",
    "SET BACK INTERIOR SHADING METHOD",
    "SET INTERIOR REFLECTANCE EQUATION",
    "SET BACK INTERIOR REFLECTANCE EQUATION",
    "SET AREA PROPERTIES",
    "SET BACK AREA PROPERTIES",
    "SET FACE DISTINGUISHING MODE",
    "SET FACE CULLING MODE",
    "SET EDGE FLAG",
    "SET EDGETYPE",
    "SET EDGEWIDTH SCALE FACTOR",
    "SET EDGE COLOUR",
    "SET INDIVIDUAL ASF",
    "SET CURVE APPROXIMATION CRITERIA",
    "SET SURFACE APPROXIMATION CRITERIA",
    "SET PARAMETRIC SURFACE CHARACTERISTICS",
    "SET LIGHT SOURCE STATE",
    "SET DEPTH CUE INDEX",
    "SET COLOUR MAPPING INDEX",
    "SET RENDERING COLOUR MODEL",
    "ADD NAMES TO SET",
    "REMOVE NAMES FROM SET",
    "SET LOCAL TRANSFORMATION 3",
    "SET LOCAL TRANSFORMATION",
    "SET GLOBAL TRANSFORMATION 3",
    "SET GLOBAL TRANSFORMATION",
    "SET MODEL CLIPPING VOLUME 3",
    "SET MODEL CLIPPING VOLUME",
    "SET MODEL CLIPPING INDICATOR",
    "RESTORE MODEL CLIPPING VOLUME",
    "SET VIEW INDEX",
    "EXECUTE STRUCTURE",
    "LABEL",
    "APPLICATION DATA",
    "SET PICK IDENTIFIER",
    "SET HLHSR IDENTIFIER",
    "GENERALIZED DRAWING PRIMITIVE 3",
    "GENERALIZED DRAWING PRIMITIVE",
    "GENERALIZED STRUCTURE ELEMENT",
    "SET PATTERN SIZE",
    "SET PATTERN REFERENCE POINT",
    "SET PATTERN REFERENCE POINT AND VECTORS",
};

template <class T>
constexpr int indexOf() {
    int index = -1;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((std::is_same_v<T, std::variant_alternative_t<I, Element>> ? (index = static_cast<int>(I)) : 0),
         ...);
    }
    (std::make_index_sequence<std::variant_size_v<Element>>{});
    return index;
}

bool sameCurve(const geom::Curve& a, const geom::Curve& b) {
    return a.degree == b.degree && a.knots == b.knots && a.points == b.points && a.weights == b.weights;
}

std::string checkPoints(std::span<const glm::dvec3> points, std::size_t minimum, const char* what) {
    if (points.size() < minimum)
        return std::string(what) + " needs at least " + std::to_string(minimum) + " points, has " +
               std::to_string(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!allFinite(points[i]))
            return std::string(what) + " point " + std::to_string(i) + " is not finite";
    return {};
}

template <class List>
std::string checkPerVertex(const List& list, std::size_t count, const char* what) {
    if (!list.empty() && list.size() != count)
        return std::string(what) + " has " + std::to_string(list.size()) + " entries for " +
               std::to_string(count) + " vertices";
    return {};
}

std::string checkCurve(const geom::Curve& curve) {
    try {
        geom::validate(curve);
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

/// A NURBS curve's parameter range: equal ends (the whole domain), or start below end, both
/// inside the domain (a rounding's worth past an end is drawn to the end).
std::string checkCurveRange(const NurbsCurveElement& e) {
    const double a = e.curve.domainStart(), b = e.curve.domainEnd();
    const double slack = 1e-12 * std::max({1.0, std::abs(a), std::abs(b)});
    if (e.rangeStart == e.rangeEnd) return {};
    auto number = [](double x) {
        char text[32];
        std::snprintf(text, sizeof text, "%.17g", x);
        return std::string(text);
    };
    if (!(e.rangeStart < e.rangeEnd) || e.rangeStart < a - slack || e.rangeEnd > b + slack)
        return "parameter range [" + number(e.rangeStart) + ", " + number(e.rangeEnd) +
               "] is not an interval inside the domain [" + number(a) + ", " + number(b) + "]";
    return {};
}

/// Hands every real of a payload's fields to `on`, and where `whole` those of its point lists,
/// curves and surfaces too (a rational pole also in homogeneous form, w P, as the C binding
/// answers it).
template <class On>
struct EachReal {
    On on;
    bool whole;
    void operator()(double x) { on(x); }
    void operator()(const glm::dvec2& p) { (*this)(p.x), (*this)(p.y); }
    void operator()(const glm::dvec3& p) { (*this)(p.x), (*this)(p.y), (*this)(p.z); }
    void operator()(const glm::dmat4& m) {
        for (int c = 0; c < 4; ++c) (*this)(glm::dvec3(m[c])), (*this)(m[c].w);
    }
    void operator()(const Colour& c) {
        if (c.direct) (*this)(c.rgb);
    }
    template <class A, class B>
    void operator()(const std::pair<A, B>& p) {
        (*this)(p.first), (*this)(p.second);
    }
    template <class T>
    void operator()(const std::vector<T>& list) {
        for (const T& item : list) (*this)(item);
    }
    void operator()(const PointList& points) {
        if (whole)
            for (const glm::dvec3& p : points.span()) (*this)(p);
    }
    void operator()(const geom::Curve& c) {
        if (whole) (*this)(c.knots), poles(c.points, c.weights);
    }
    void operator()(const geom::Surface& s) {
        if (whole) (*this)(s.knotsU), (*this)(s.knotsV), poles(s.points, s.weights);
    }
    void poles(const std::vector<glm::dvec3>& points, const std::vector<double>& weights) {
        (*this)(points), (*this)(weights);
        for (std::size_t i = 0; i < points.size() && i < weights.size(); ++i) (*this)(points[i] * weights[i]);
    }
    void operator()(const TrimCurveDisplay& d) { (*this)(d.approximationValue); }
    template <class T>
    void operator()(const T&) {}  // integers, flags, strings, enumerations
};

template <class On>
void eachReal(const Element& element, bool whole, On on) {
    EachReal<On> visit{std::move(on), whole};
    std::visit([&](const auto& e) { detail::fields(visit, const_cast<std::decay_t<decltype(e)>&>(e)); },
               element);
}

bool allFinite(const Element& element) {
    // Point lists are left to validatePayload: every family holding one runs checkPoints on it,
    // which names the point that is not finite (a second pass here would only cost inserts);
    // curves and surfaces to geom::validate.
    bool finite = true;
    eachReal(element, false, [&](double x) { finite = finite && std::isfinite(x); });
    return finite;
}

/// The rules of each payload family: counts, consistent lists, finite points, valid curves.
// Each pattern element type carries only its own fields; the others keep their defaults (SET
// PATTERN REFERENCE POINT resets the vectors to the axes), so equal elements compare equal.
std::string checkPattern(const PatternAttribute& e) {
    const PatternAttribute defaults;
    const bool sizeOnly = e.type == ElementType::PatternSize;
    if (sizeOnly && (e.referencePoint != defaults.referencePoint || e.vectorX != defaults.vectorX ||
                     e.vectorY != defaults.vectorY))
        return "a pattern size element carries a reference point or vectors";
    if (!sizeOnly && e.size != defaults.size) return "a pattern reference element carries a size";
    if (e.type == ElementType::PatternReferencePoint &&
        (e.referencePoint.z != 0.0 || e.vectorX != defaults.vectorX || e.vectorY != defaults.vectorY))
        return "a 2D pattern reference point has a z coordinate or vectors";
    return {};
}

std::string checkCells(int columns, int rows, std::size_t colours) {
    if (columns < 0 || rows < 0) return "cell array dimensions are negative";
    if (colours != static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows))
        return "cell array has " + std::to_string(colours) + " colours for " + std::to_string(columns) +
               " x " + std::to_string(rows) + " cells";
    return {};
}

std::string checkPolylineSet(const PolylineSetWithDataElement& e) {
    if (!e.vertexColours.empty() && e.vertexColours.size() != e.polylines.size())
        return "vertex colours are not given for every polyline";
    for (std::size_t i = 0; i < e.polylines.size(); ++i) {
        if (auto r = checkPoints(e.polylines[i], 0, "polyline"); !r.empty())
            return r + " (polyline " + std::to_string(i) + ")";
        if (!e.vertexColours.empty() && e.vertexColours[i].size() != e.polylines[i].size())
            return "polyline " + std::to_string(i) + " has " + std::to_string(e.vertexColours[i].size()) +
                   " vertex colours for " + std::to_string(e.polylines[i].size()) + " vertices";
    }
    return {};
}

/// The contours of a set of fill area sets index the vertex list; facet data is per set, edge
/// flags (0 or 1) per contour vertex.
std::string checkSetOfFillAreaSets(const SetOfFillAreaSetsElement& e) {
    if (auto r = checkPoints(e.vertices, 0, "set of fill area sets"); !r.empty()) return r;
    if (auto r = checkPerVertex(e.vertexColours, e.vertices.size(), "vertex colours"); !r.empty()) return r;
    if (auto r = checkPerVertex(e.vertexNormals, e.vertices.size(), "vertex normals"); !r.empty()) return r;
    auto perSet = [&](std::size_t n, const char* what) -> std::string {
        if (n == 0 || n == e.sets.size()) return {};
        return std::to_string(n) + " " + what + " for " + std::to_string(e.sets.size()) + " sets";
    };
    if (auto r = perSet(e.facetColours.size(), "facet colours"); !r.empty()) return r;
    if (auto r = perSet(e.facetNormals.size(), "facet normals"); !r.empty()) return r;
    if (!e.edgeFlags.empty() && e.edgeFlags.size() != e.sets.size())
        return "edge flags are not given for every set";
    for (std::size_t s = 0; s < e.sets.size(); ++s) {
        const std::string where = "set " + std::to_string(s);
        if (!e.edgeFlags.empty() && e.edgeFlags[s].size() != e.sets[s].size())
            return where + ": edge flags are not given for every contour";
        for (std::size_t c = 0; c < e.sets[s].size(); ++c) {
            for (int v : e.sets[s][c])
                if (v < 0 || static_cast<std::size_t>(v) >= e.vertices.size())
                    return where + " contour " + std::to_string(c) + ": vertex index " + std::to_string(v) +
                           " outside 0.." + std::to_string(static_cast<long long>(e.vertices.size()) - 1);
            if (e.edgeFlags.empty()) continue;
            const auto& flags = e.edgeFlags[s][c];
            if (flags.size() != e.sets[s][c].size())
                return where + " contour " + std::to_string(c) + " has " + std::to_string(flags.size()) +
                       " edge flags for " + std::to_string(e.sets[s][c].size()) + " edges";
            for (int f : flags)
                if (f != 0 && f != 1)
                    return where + " contour " + std::to_string(c) + ": edge flag " + std::to_string(f) +
                           " is neither 0 nor 1";
        }
    }
    return {};
}

/// Facet data of a mesh: none, or one colour / normal per facet.
std::string checkFacets(std::size_t colours, std::size_t normals, std::size_t facets, const char* what) {
    for (auto [n, name] : {std::pair{colours, "facet colours"}, std::pair{normals, "facet normals"}})
        if (n != 0 && n != facets)
            return std::to_string(n) + " " + name + " for " + std::to_string(facets) + " " + what;
    return {};
}

/// Edge flags of a fill area set with data: none, or one flag (0 or 1) per contour vertex.
std::string checkEdgeFlags(const FillAreaSetWithDataElement& e) {
    if (e.edgeFlags.empty()) return {};
    if (e.edgeFlags.size() != e.contours.size())
        return std::to_string(e.edgeFlags.size()) + " edge flag lists for " +
               std::to_string(e.contours.size()) + " contours";
    for (std::size_t c = 0; c < e.contours.size(); ++c) {
        if (e.edgeFlags[c].size() != e.contours[c].size())
            return "contour " + std::to_string(c) + " has " + std::to_string(e.edgeFlags[c].size()) +
                   " edge flags for " + std::to_string(e.contours[c].size()) + " edges";
        for (int f : e.edgeFlags[c])
            if (f != 0 && f != 1)
                return "contour " + std::to_string(c) + ": edge flag " + std::to_string(f) +
                       " is neither 0 nor 1";
    }
    return {};
}

/// Surface characteristics: styles 1 to 5; iso-curve counts not negative; level curves with a
/// direction that is not zero (the planes are perpendicular to it).
std::string checkCharacteristics(const SurfaceCharacteristicsAttribute& e) {
    if (e.style < 1 || e.style > 5) return "surface characteristics type " + std::to_string(e.style);
    if (e.curvesU < 0 || e.curvesV < 0) return "negative iso-curve count";
    if (e.placement != 0 && e.placement != 1) return "iso-curve placement " + std::to_string(e.placement);
    if (e.style >= 4 && glm::dot(e.direction, e.direction) == 0.0) return "level curve direction is zero";
    return {};
}

std::string validatePayload(const Element& element) {
    return std::visit(
        [](const auto& e) -> std::string {
            using E = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<E, PolylineElement>)
                return checkPoints(e.points, 0, "polyline");
            else if constexpr (std::is_same_v<E, PolymarkerElement>)
                return checkPoints(e.points, 0, "polymarker");
            else if constexpr (std::is_same_v<E, FillAreaElement>)
                return checkPoints(e.points, 0, "fill area");
            else if constexpr (std::is_same_v<E, FillAreaSetElement>) {
                for (const auto& c : e.contours)
                    if (auto r = checkPoints(c, 0, "fill area set contour"); !r.empty()) return r;
                return {};
            } else if constexpr (std::is_same_v<E, CellArrayElement>) {
                return checkCells(e.columns, e.rows, e.colourIndices.size());
            } else if constexpr (std::is_same_v<E, NurbsCurveElement>) {
                if (auto r = checkCurve(e.curve); !r.empty()) return r;
                return checkCurveRange(e);
            } else if constexpr (std::is_same_v<E, NurbsSurfaceElement>) {
                try {
                    geom::validate(e.surface);
                } catch (const std::exception& x) {
                    return x.what();
                }
                std::size_t curves = 0;
                for (const auto& loop : e.trimLoops)
                    for (const auto& c : loop) {
                        if (auto r = checkCurve(c); !r.empty()) return "trimming curve: " + r;
                        ++curves;
                    }
                if (!e.trimDisplay.empty() && e.trimDisplay.size() != curves)
                    return "trimming curve display is given for " + std::to_string(e.trimDisplay.size()) +
                           " curves, not for each of the " + std::to_string(curves);
                return {};
            } else if constexpr (std::is_same_v<E, FillAreaSetWithDataElement>) {
                if (!e.vertexColours.empty() && e.vertexColours.size() != e.contours.size())
                    return "vertex colours are not given for every contour";
                if (!e.vertexNormals.empty() && e.vertexNormals.size() != e.contours.size())
                    return "vertex normals are not given for every contour";
                for (std::size_t i = 0; i < e.contours.size(); ++i) {
                    if (auto r = checkPoints(e.contours[i], 0, "contour"); !r.empty()) return r;
                    if (!e.vertexColours.empty())
                        if (auto r =
                                checkPerVertex(e.vertexColours[i], e.contours[i].size(), "vertex colours");
                            !r.empty() || e.vertexColours[i].empty())
                            return r.empty() && !e.contours[i].empty() ? "contour without vertex colours" : r;
                    if (!e.vertexNormals.empty())
                        if (auto r =
                                checkPerVertex(e.vertexNormals[i], e.contours[i].size(), "vertex normals");
                            !r.empty())
                            return r;
                }
                return checkEdgeFlags(e);
            } else if constexpr (std::is_same_v<E, TriangleStripElement>) {
                if (auto r = checkPoints(e.points, 0, "triangle strip"); !r.empty()) return r;
                if (auto r = checkPerVertex(e.vertexColours, e.points.size(), "vertex colours"); !r.empty())
                    return r;
                if (auto r = checkPerVertex(e.vertexNormals, e.points.size(), "vertex normals"); !r.empty())
                    return r;
                return checkFacets(e.facetColours.size(), e.facetNormals.size(),
                                   e.points.size() < 3 ? 0 : e.points.size() - 2, "triangles");
            } else if constexpr (std::is_same_v<E, QuadrilateralMeshElement>) {
                if (e.rows < 0 || e.columns < 0) return "quadrilateral mesh dimensions are negative";
                std::size_t n = static_cast<std::size_t>(e.rows) * static_cast<std::size_t>(e.columns);
                if (e.points.size() != n)
                    return "quadrilateral mesh has " + std::to_string(e.points.size()) + " points for " +
                           std::to_string(e.rows) + " x " + std::to_string(e.columns);
                if (auto r = checkPoints(e.points, 0, "quadrilateral mesh"); !r.empty()) return r;
                if (auto r = checkPerVertex(e.vertexColours, n, "vertex colours"); !r.empty()) return r;
                if (auto r = checkPerVertex(e.vertexNormals, n, "vertex normals"); !r.empty()) return r;
                const std::size_t quads =
                    e.rows < 2 || e.columns < 2
                        ? 0
                        : static_cast<std::size_t>(e.rows - 1) * static_cast<std::size_t>(e.columns - 1);
                return checkFacets(e.facetColours.size(), e.facetNormals.size(), quads, "quadrilaterals");
            } else if constexpr (std::is_same_v<E, PolylineSetWithDataElement>) {
                return checkPolylineSet(e);
            } else if constexpr (std::is_same_v<E, CellArrayPlusElement>) {
                return checkCells(e.columns, e.rows, e.colours.size());
            } else if constexpr (std::is_same_v<E, SetOfFillAreaSetsElement>) {
                return checkSetOfFillAreaSets(e);
            } else if constexpr (std::is_same_v<E, GdpElement>) {
                if (auto r = checkPoints(e.points, 0, "generalized drawing primitive"); !r.empty()) return r;
                return checkGdp(e);
            } else if constexpr (std::is_same_v<E, AsfAttribute>) {
                if (static_cast<int>(e.aspect) < 0 || e.aspect >= AspectId::Count_) return "unknown aspect";
                return {};
            } else if constexpr (std::is_same_v<E, PatternAttribute>) {
                return checkPattern(e);
            } else if constexpr (std::is_same_v<E, SurfaceCharacteristicsAttribute>) {
                return checkCharacteristics(e);
            } else {
                return {};
            }
        },
        element);
}

}  // namespace

bool NurbsCurveElement::operator==(const NurbsCurveElement& o) const {
    return sameCurve(curve, o.curve) && rangeStart == o.rangeStart && rangeEnd == o.rangeEnd;
}

bool NurbsSurfaceElement::operator==(const NurbsSurfaceElement& o) const {
    const geom::Surface& a = surface;
    const geom::Surface& b = o.surface;
    if (!(a.degreeU == b.degreeU && a.degreeV == b.degreeV && a.knotsU == b.knotsU && a.knotsV == b.knotsV &&
          a.countU == b.countU && a.countV == b.countV && a.points == b.points && a.weights == b.weights))
        return false;
    if (trimLoops.size() != o.trimLoops.size()) return false;
    for (std::size_t i = 0; i < trimLoops.size(); ++i) {
        if (trimLoops[i].size() != o.trimLoops[i].size()) return false;
        for (std::size_t j = 0; j < trimLoops[i].size(); ++j)
            if (!sameCurve(trimLoops[i][j], o.trimLoops[i][j])) return false;
    }
    // An empty display list reads as every curve's default.
    for (std::size_t k = 0; k < std::max(trimDisplay.size(), o.trimDisplay.size()); ++k)
        if (!(displayOf(k) == o.displayOf(k))) return false;
    return true;
}

std::string_view elementTypeName(ElementType type) {
    auto i = static_cast<std::size_t>(type);
    return i < kNames.size() ? kNames[i] : std::string_view("UNKNOWN");
}

ElementType elementTypeFromName(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i)
        if (kNames[i] == name) return static_cast<ElementType>(i);
    return ElementType::Count_;
}

ElementType elementType(const Element& element) {
    using T = ElementType;
    return std::visit(
        [](const auto& e) -> ElementType {
            using E = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<E, PolylineElement>)
                return e.twoD ? T::Polyline : T::Polyline3;
            else if constexpr (std::is_same_v<E, PolymarkerElement>)
                return e.twoD ? T::Polymarker : T::Polymarker3;
            else if constexpr (std::is_same_v<E, FillAreaElement>)
                return e.twoD ? T::FillArea : T::FillArea3;
            else if constexpr (std::is_same_v<E, FillAreaSetElement>)
                return e.twoD ? T::FillAreaSet : T::FillAreaSet3;
            else if constexpr (std::is_same_v<E, TextElement>)
                return e.twoD ? T::Text : T::Text3;
            else if constexpr (std::is_same_v<E, AnnotationTextElement>)
                return e.twoD ? T::AnnotationTextRelative : T::AnnotationTextRelative3;
            else if constexpr (std::is_same_v<E, CellArrayElement>)
                return e.twoD ? T::CellArray : T::CellArray3;
            else if constexpr (std::is_same_v<E, NurbsCurveElement>)
                return T::NonUniformBSplineCurve;
            else if constexpr (std::is_same_v<E, NurbsSurfaceElement>)
                return T::NonUniformBSplineSurface;
            else if constexpr (std::is_same_v<E, FillAreaSetWithDataElement>)
                return T::FillAreaSetWithData;
            else if constexpr (std::is_same_v<E, TriangleStripElement>)
                return T::TriangleStrip;
            else if constexpr (std::is_same_v<E, QuadrilateralMeshElement>)
                return T::QuadrilateralMesh;
            else if constexpr (std::is_same_v<E, PolylineSetWithDataElement>)
                return T::PolylineSetWithData;
            else if constexpr (std::is_same_v<E, CellArrayPlusElement>)
                return T::CellArrayPlus;
            else if constexpr (std::is_same_v<E, SetOfFillAreaSetsElement>)
                return T::SetOfFillAreaSetsWithData;
            else if constexpr (std::is_same_v<E, AsfAttribute>)
                return T::IndividualAsf;
            else if constexpr (std::is_same_v<E, SurfaceCharacteristicsAttribute>)
                return T::ParametricSurfaceCharacteristics;
            else if constexpr (std::is_same_v<E, LightSourceStateAttribute>)
                return T::LightSourceState;
            else if constexpr (std::is_same_v<E, ModelClipElement>)
                return e.twoD ? T::ModelClippingVolume : T::ModelClippingVolume3;
            else if constexpr (std::is_same_v<E, RestoreModelClipElement>)
                return T::RestoreModelClippingVolume;
            else if constexpr (std::is_same_v<E, NameSetElement>)
                return e.add ? T::AddNamesToSet : T::RemoveNamesFromSet;
            else if constexpr (std::is_same_v<E, ExecuteStructureElement>)
                return T::ExecuteStructure;
            else if constexpr (std::is_same_v<E, LabelElement>)
                return T::Label;
            else if constexpr (std::is_same_v<E, ApplicationDataElement>)
                return T::ApplicationData;
            else if constexpr (std::is_same_v<E, GdpElement>)
                return e.twoD ? T::GeneralizedDrawingPrimitive : T::GeneralizedDrawingPrimitive3;
            else if constexpr (std::is_same_v<E, GseElement>)
                return T::GeneralizedStructureElement;
            else
                return e.type;  // the tagged families
        },
        element);
}

int payloadIndexOf(ElementType type) {
    using T = ElementType;
    // A tag cast from outside the enumeration (the default below would take it as an index).
    if (static_cast<int>(type) < 0 || static_cast<int>(type) >= static_cast<int>(T::Count_)) return -1;
    switch (type) {
        case T::Polyline3:
        case T::Polyline:
            return indexOf<PolylineElement>();
        case T::Polymarker3:
        case T::Polymarker:
            return indexOf<PolymarkerElement>();
        case T::FillArea3:
        case T::FillArea:
            return indexOf<FillAreaElement>();
        case T::FillAreaSet3:
        case T::FillAreaSet:
            return indexOf<FillAreaSetElement>();
        case T::Text3:
        case T::Text:
            return indexOf<TextElement>();
        case T::AnnotationTextRelative3:
        case T::AnnotationTextRelative:
            return indexOf<AnnotationTextElement>();
        case T::CellArray3:
        case T::CellArray:
            return indexOf<CellArrayElement>();
        case T::NonUniformBSplineCurve:
            return indexOf<NurbsCurveElement>();
        case T::NonUniformBSplineSurface:
            return indexOf<NurbsSurfaceElement>();
        case T::FillAreaSetWithData:
            return indexOf<FillAreaSetWithDataElement>();
        case T::TriangleStrip:
            return indexOf<TriangleStripElement>();
        case T::QuadrilateralMesh:
            return indexOf<QuadrilateralMeshElement>();
        case T::PolylineSetWithData:
            return indexOf<PolylineSetWithDataElement>();
        case T::CellArrayPlus:
            return indexOf<CellArrayPlusElement>();
        case T::SetOfFillAreaSetsWithData:
            return indexOf<SetOfFillAreaSetsElement>();
        case T::LinewidthScaleFactor:
        case T::MarkerSizeScaleFactor:
        case T::CharacterExpansionFactor:
        case T::CharacterSpacing:
        case T::CharacterHeight:
        case T::AnnotationTextCharacterHeight:
        case T::EdgewidthScaleFactor:
            return indexOf<RealAttribute>();
        case T::PolylineColour:
        case T::PolymarkerColour:
        case T::TextColour:
        case T::InteriorColour:
        case T::BackInteriorColour:
        case T::EdgeColour:
            return indexOf<ColourAttribute>();
        case T::CharacterUpVector:
        case T::AnnotationTextCharacterUpVector:
            return indexOf<UpVectorAttribute>();
        case T::TextAlignment:
        case T::AnnotationTextAlignment:
            return indexOf<AlignmentAttribute>();
        case T::AreaProperties:
        case T::BackAreaProperties:
            return indexOf<AreaPropertiesAttribute>();
        case T::IndividualAsf:
            return indexOf<AsfAttribute>();
        case T::CurveApproximationCriteria:
        case T::SurfaceApproximationCriteria:
            return indexOf<ApproximationAttribute>();
        case T::ParametricSurfaceCharacteristics:
            return indexOf<SurfaceCharacteristicsAttribute>();
        case T::LightSourceState:
            return indexOf<LightSourceStateAttribute>();
        case T::LocalModellingTransformation3:
        case T::LocalModellingTransformation:
        case T::GlobalModellingTransformation3:
        case T::GlobalModellingTransformation:
            return indexOf<TransformElement>();
        case T::ModelClippingVolume3:
        case T::ModelClippingVolume:
            return indexOf<ModelClipElement>();
        case T::RestoreModelClippingVolume:
            return indexOf<RestoreModelClipElement>();
        case T::AddNamesToSet:
        case T::RemoveNamesFromSet:
            return indexOf<NameSetElement>();
        case T::ExecuteStructure:
            return indexOf<ExecuteStructureElement>();
        case T::Label:
            return indexOf<LabelElement>();
        case T::ApplicationData:
            return indexOf<ApplicationDataElement>();
        case T::GeneralizedDrawingPrimitive3:
        case T::GeneralizedDrawingPrimitive:
            return indexOf<GdpElement>();
        case T::GeneralizedStructureElement:
            return indexOf<GseElement>();
        case T::PatternSize:
        case T::PatternReferencePoint:
        case T::PatternReferencePointAndVectors:
            return indexOf<PatternAttribute>();
        case T::All:
        case T::Nil:
        case T::Count_:
            return -1;
        default:
            return indexOf<IndexAttribute>();
    }
}

double largestMagnitude(const Element& element) {
    double largest = 0.0;  // NaN once a real is NaN
    eachReal(element, true, [&](double x) {
        largest = std::isnan(x) || std::isnan(largest) ? NAN : std::max(largest, std::abs(x));
    });
    return largest;
}

std::string validateElement(const Element& element) {
    if (payloadIndexOf(elementType(element)) != static_cast<int>(element.index()))
        return "element type " + std::string(elementTypeName(elementType(element))) +
               " does not belong to this payload";
    std::string reason = validatePayload(element);
    if (reason.empty() && !allFinite(element)) reason = "a coordinate or real value is not finite";
    return reason;
}

std::size_t elementSize(const Element& element) {
    auto curveBytes = [](const geom::Curve& c) {
        return c.knots.size() * sizeof(double) + c.points.size() * sizeof(glm::dvec3) +
               c.weights.size() * sizeof(double);
    };
    return std::visit(
        [&](const auto& e) -> std::size_t {
            using E = std::decay_t<decltype(e)>;
            std::size_t bytes = sizeof(E);
            if constexpr (requires { e.points; }) bytes += e.points.size() * sizeof(glm::dvec3);
            if constexpr (std::is_same_v<E, TriangleStripElement> ||
                          std::is_same_v<E, QuadrilateralMeshElement>)
                bytes += e.facetColours.size() * sizeof(Colour) + e.facetNormals.size() * sizeof(glm::dvec3);
            if constexpr (std::is_same_v<E, FillAreaSetWithDataElement>)
                for (const auto& flags : e.edgeFlags) bytes += flags.size() * sizeof(int);
            if constexpr (std::is_same_v<E, SurfaceCharacteristicsAttribute>)
                bytes += e.levels.size() * sizeof(double);
            if constexpr (requires { e.contours; })
                for (const auto& c : e.contours) bytes += c.size() * sizeof(glm::dvec3);
            if constexpr (std::is_same_v<E, TextElement> || std::is_same_v<E, AnnotationTextElement>)
                bytes += e.text.size();
            if constexpr (std::is_same_v<E, ApplicationDataElement> || std::is_same_v<E, GdpElement> ||
                          std::is_same_v<E, GseElement>)
                bytes += e.data.size();
            if constexpr (std::is_same_v<E, NameSetElement>) bytes += e.names.size() * sizeof(int);
            if constexpr (std::is_same_v<E, CellArrayElement>) bytes += e.colourIndices.size() * sizeof(int);
            if constexpr (std::is_same_v<E, CellArrayPlusElement>) bytes += e.colours.size() * sizeof(Colour);
            if constexpr (std::is_same_v<E, PolylineSetWithDataElement>)
                for (std::size_t i = 0; i < e.polylines.size(); ++i)
                    bytes += e.polylines[i].size() * sizeof(glm::dvec3) +
                             (e.vertexColours.empty() ? 0 : e.vertexColours[i].size() * sizeof(Colour));
            if constexpr (std::is_same_v<E, SetOfFillAreaSetsElement>) {
                bytes += e.vertices.size() * sizeof(glm::dvec3) + e.vertexColours.size() * sizeof(Colour) +
                         e.vertexNormals.size() * sizeof(glm::dvec3) +
                         e.facetColours.size() * sizeof(Colour) + e.facetNormals.size() * sizeof(glm::dvec3);
                for (std::size_t s = 0; s < e.sets.size(); ++s)
                    for (std::size_t c = 0; c < e.sets[s].size(); ++c)
                        bytes += e.sets[s][c].size() * sizeof(int) * (e.edgeFlags.empty() ? 1 : 2);
            }
            if constexpr (std::is_same_v<E, NurbsCurveElement>) bytes += curveBytes(e.curve);
            if constexpr (std::is_same_v<E, NurbsSurfaceElement>) {
                bytes += (e.surface.knotsU.size() + e.surface.knotsV.size() + e.surface.weights.size()) *
                             sizeof(double) +
                         e.surface.points.size() * sizeof(glm::dvec3);
                for (const auto& loop : e.trimLoops)
                    for (const auto& c : loop) bytes += curveBytes(c);
                bytes += e.trimDisplay.size() * sizeof(TrimCurveDisplay);
            }
            return bytes;
        },
        element);
}

}  // namespace phigs
