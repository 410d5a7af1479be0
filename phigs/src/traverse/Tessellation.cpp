#include "Tessellation.h"

#include "FacetMesh.h"

#include "phigs/traverse/TessellationCache.h"

#include "geom/Evaluate.h"
#include "geom/EvenOdd.h"
#include "geom/Split.h"
#include "geom/Tessellate.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace phigs::detail {

int segmentsPerSpan(const std::vector<glm::dvec3>& controlPolygon, int criteria, double value) {
    if (criteria == 2) return std::clamp(static_cast<int>(std::lround(value)), 1, 256);
    if (criteria >= 3 && criteria <= 8 && value > 0.0) {
        // A span of a degree-p piece deviates from its chord by about |second difference| / 8
        // per segment squared: choose the count that brings it under the tolerance.
        double bend = 0.0;
        for (std::size_t i = 2; i < controlPolygon.size(); ++i)
            bend = std::max(
                bend, glm::length(controlPolygon[i] - 2.0 * controlPolygon[i - 1] + controlPolygon[i - 2]));
        return std::clamp(static_cast<int>(std::ceil(std::sqrt(bend / (8.0 * value)))), 1, 64);
    }
    return 8;
}

std::vector<double> spanBreaks(const std::vector<double>& knots, double start, double end) {
    std::vector<double> breaks{start};
    for (double k : knots)
        if (k > breaks.back() && k < end) breaks.push_back(k);
    breaks.push_back(end);
    return breaks;
}

namespace {

/// Keeps any tessellation to at most about this many segments in one parameter direction.
constexpr int kMaxSegments = 2048;

/// A tolerance no finer than 1e-9 of the control polygon's extent, so a tiny criteria value
/// cannot ask for an unbounded mesh.
double boundedTolerance(const std::vector<glm::dvec3>& points, double tolerance) {
    glm::dvec3 low(0.0), high(0.0);
    if (!points.empty()) low = high = points.front();
    for (const auto& p : points) low = glm::min(low, p), high = glm::max(high, p);
    return std::max(tolerance, 1e-9 * std::max(glm::length(high - low), 1e-300));
}

std::vector<double> samples(const std::vector<double>& breaks, int perSpan) {
    const int spans = std::max(1, static_cast<int>(breaks.size()) - 1);
    perSpan = std::clamp(perSpan, 1, std::max(1, kMaxSegments / spans));
    std::vector<double> out;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
        for (int s = 0; s < perSpan; ++s)
            out.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * static_cast<double>(s) / perSpan);
    out.push_back(breaks.back());
    return out;
}

/// Each trimming curve's (u, v) points (z ignored), loop by loop, followed as its approximation
/// criteria ask: made once for both the trimming polygons and the drawn trim edges.
std::vector<std::vector<glm::dvec3>> trimCurveSamples(const NurbsSurfaceElement& element) {
    std::vector<std::vector<glm::dvec3>> curves;
    for (const TrimLoop& loop : element.trimLoops)
        for (const geom::Curve& c : loop) {
            const TrimCurveDisplay display = element.displayOf(curves.size());
            curves.push_back(tessellateCurve(c, c.domainStart(), c.domainEnd(), display.approximation,
                                             display.approximationValue));
        }
    return curves;
}

/// Each trimming loop as a polygon in (u, v), from its curves' samples.
std::vector<std::vector<glm::dvec2>> trimPolygons(const NurbsSurfaceElement& element,
                                                  const std::vector<std::vector<glm::dvec3>>& curves) {
    std::vector<std::vector<glm::dvec2>> loops;
    std::size_t curve = 0;
    for (const TrimLoop& loop : element.trimLoops) {
        std::vector<glm::dvec2>& polygon = loops.emplace_back();
        for (std::size_t k = 0; k < loop.size(); ++k)
            for (const glm::dvec3& p : curves[curve++]) polygon.push_back({p.x, p.y});
    }
    return loops;
}

/// The visible trimming curves on the surface: their samples' points appended to the mesh (with
/// normals, and (u, v) when the mesh keeps them), one polyline each in `trimEdges`. (u, v)
/// outside the domain is brought to its nearest border.
void addTrimEdges(MeshData& mesh, const NurbsSurfaceElement& element,
                  const std::vector<std::vector<glm::dvec3>>& curves, bool withUv) {
    const geom::Surface& s = element.surface;
    for (std::size_t curve = 0; curve < curves.size(); ++curve) {
        if (!element.displayOf(curve).visible) continue;
        std::vector<std::uint32_t> line;
        for (const glm::dvec3& p : curves[curve]) {
            const double u = std::clamp(p.x, s.domainStartU(), s.domainEndU());
            const double v = std::clamp(p.y, s.domainStartV(), s.domainEndV());
            line.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
            mesh.positions.push_back(glm::vec3(geom::evaluate(s, u, v)));
            mesh.normals.push_back(glm::vec3(geom::normal(s, u, v)));
            if (withUv) mesh.uv.push_back(glm::vec2(static_cast<float>(u), static_cast<float>(v)));
        }
        if (line.size() >= 2) mesh.trimEdges.push_back(std::move(line));
    }
}

bool insideTrim(const std::vector<std::vector<glm::dvec2>>& loops, glm::dvec2 p) {
    return geom::insideEvenOdd(p, loops, [](glm::dvec2 q) { return q; });
}

}  // namespace
}  // namespace phigs::detail

namespace phigs {

bool MeshData::keeps(glm::dvec2 uv) const {
    return trimLoops.empty() || detail::insideTrim(trimLoops, uv);
}

}  // namespace phigs

namespace phigs::detail {
namespace {

bool chordal(int criteria, double value) {
    return criteria >= 3 && criteria <= 8 && value > 0.0;
}

/// Whether a surface mesh keeps (u, v) per position: its readers are the level curves (styles 4
/// and 5 place their points on the exact surface) and the patch edges drawn along knot lines
/// inside the domain; a one-span surface without level curves has neither.
bool keepsUv(const geom::Surface& s, const SurfaceCharacteristicsAttribute& characteristics) {
    if (characteristics.style == 4 || characteristics.style == 5) return true;
    return spanBreaks(s.knotsU, s.domainStartU(), s.domainEndU()).size() > 2 ||
           spanBreaks(s.knotsV, s.domainStartV(), s.domainEndV()).size() > 2;
}

}  // namespace

std::vector<glm::dvec3> tessellateCurve(const geom::Curve& curve, double start, double end, int criteria,
                                        double value) {
    const bool whole = !(end > start) || (start <= curve.domainStart() && end >= curve.domainEnd());
    if (whole && chordal(criteria, value))
        return geom::tessellate(curve, boundedTolerance(curve.points, value));
    if (!(end > start)) start = curve.domainStart(), end = curve.domainEnd();
    // The store refuses a range past the domain; a rounding's worth past it draws to its end.
    start = std::max(start, curve.domainStart()), end = std::min(end, curve.domainEnd());
    int perSpan = segmentsPerSpan(curve.points, criteria, value);
    std::vector<glm::dvec3> points;
    for (double u : samples(spanBreaks(curve.knots, start, end), perSpan))
        points.push_back(geom::evaluate(curve, u));
    return points;
}

std::vector<TessellationCache::CurveRun> curveRuns(geom::Curve curve, double start, double end, int criteria,
                                                   double value) {
    std::vector<geom::Curve> pieces = geom::splitAtBreaks(curve);
    std::vector<TessellationCache::CurveRun> runs;
    if (pieces.size() == 1) {
        std::vector<glm::dvec3> points = tessellateCurve(curve, start, end, criteria, value);
        runs.push_back(
            {std::make_shared<const geom::Curve>(std::move(curve)), std::move(points), start, end});
        return runs;
    }
    const bool whole = !(end > start);
    for (geom::Curve& piece : pieces) {
        const double a = whole ? piece.domainStart() : std::max(start, piece.domainStart());
        const double b = whole ? piece.domainEnd() : std::min(end, piece.domainEnd());
        if (!(b > a)) continue;
        std::vector<glm::dvec3> points = tessellateCurve(piece, a, b, criteria, value);
        runs.push_back({std::make_shared<const geom::Curve>(std::move(piece)), std::move(points), a, b});
    }
    return runs;
}

namespace {

/// geom's adaptive mesh (within the tolerance everywhere), trimmed like the grid.
MeshData adaptiveMesh(const NurbsSurfaceElement& element, double tolerance, bool withUv) {
    geom::SurfaceMesh adaptive =
        geom::tessellateAdaptive(element.surface, boundedTolerance(element.surface.points, tolerance));
    MeshData mesh;
    mesh.positions.reserve(adaptive.positions.size()), mesh.normals.reserve(adaptive.positions.size());
    if (withUv) mesh.uv.reserve(adaptive.positions.size());
    for (std::size_t i = 0; i < adaptive.positions.size(); ++i) {
        mesh.positions.push_back(glm::vec3(adaptive.positions[i]));
        mesh.normals.push_back(glm::vec3(adaptive.normals[i]));
        if (withUv) mesh.uv.push_back(glm::vec2(adaptive.uv[i]));
    }
    const std::vector<std::vector<glm::dvec3>> trimCurves = trimCurveSamples(element);
    const std::vector<std::vector<glm::dvec2>> loops = trimPolygons(element, trimCurves);
    mesh.trimLoops = loops;             // the pick keeps what the loops keep, exactly
    std::vector<std::uint32_t> cellOf;  // the grid cell (two triangles) of each triangle kept
    for (std::size_t t = 0; t + 2 < adaptive.triangles.size(); t += 3) {
        glm::dvec2 centre = (adaptive.uv[adaptive.triangles[t]] + adaptive.uv[adaptive.triangles[t + 1]] +
                             adaptive.uv[adaptive.triangles[t + 2]]) /
                            3.0;
        if (!loops.empty() && !insideTrim(loops, centre)) continue;
        mesh.triangles.insert(mesh.triangles.end(), adaptive.triangles.begin() + static_cast<long>(t),
                              adaptive.triangles.begin() + static_cast<long>(t + 3));
        cellOf.push_back(static_cast<std::uint32_t>(t / 6));
    }
    setFacets(mesh, cellOf);
    addTrimEdges(mesh, element, trimCurves, withUv);
    return mesh;
}

/// The closest two grid rows (ascending parameters) in [from, to] lie; to - from where fewer than
/// two lie there.
double closestRows(const std::vector<double>& rows, double from, double to) {
    double gap = to - from;
    auto r = std::lower_bound(rows.begin(), rows.end(), from);
    for (; r != rows.end() && r + 1 != rows.end() && *(r + 1) <= to; ++r)
        if (*(r + 1) > *r) gap = std::min(gap, *(r + 1) - *r);
    return gap;
}

/// Calls `at(t)` for the parameters of `count` iso-curves over [a, b] (ISO 9592-4 SET PARAMETRIC
/// SURFACE CHARACTERISTICS type 3): uniform placement spaces them evenly inside the domain;
/// non-uniform places one at each interior knot and `count` evenly inside each knot span. A
/// count spaced closer than half the closest grid rows there reaches every row a larger one
/// would: it is taken at that spacing (and at most 4e6 a run), so any count costs about the grid.
template <class At>
void forEachIsoParameter(int placement, int count, const std::vector<double>& knots,
                         const std::vector<double>& rows, double a, double b, At&& at) {
    auto evenly = [&](double from, double to) {
        const double gap = closestRows(rows, from, to);
        const double dense = gap > 0.0 ? 2.0 * (to - from) / gap + 1.0 : 1.0;
        const double n = std::min<double>(count, std::min(dense, 4e6));
        for (int c = 0; c < static_cast<int>(n); ++c) at(from + (to - from) * (c + 1.0) / (n + 1.0));
    };
    if (placement != 1) {
        evenly(a, b);
        return;
    }
    double from = a;
    for (double k : knots)
        if (k > from && k < b) {
            evenly(from, k);
            at(k);
            from = k;
        }
    evenly(from, b);
}

/// The index of the grid row (ascending parameters) nearest to t.
std::uint32_t nearestRow(const std::vector<double>& rows, double t) {
    const auto above = std::lower_bound(rows.begin(), rows.end(), t);
    if (above == rows.begin()) return 0;
    if (above == rows.end()) return static_cast<std::uint32_t>(rows.size() - 1);
    const auto below = above - 1;
    return static_cast<std::uint32_t>((t - *below <= *above - t ? below : above) - rows.begin());
}

}  // namespace

MeshData tessellateSurface(const NurbsSurfaceElement& element, const ApproximationAttribute& criteria,
                           const SurfaceCharacteristicsAttribute& characteristics, TessellationCache* grids) {
    const geom::Surface& s = element.surface;
    const bool withUv = keepsUv(s, characteristics);
    if (chordal(criteria.criteria, criteria.valueU) && characteristics.style != 3)
        return adaptiveMesh(element, criteria.valueU, withUv);
    std::vector<glm::dvec3> rowU, rowV;  // control polygons along u (first column) and v (first row)
    for (std::size_t i = 0; i < s.countU; ++i) rowU.push_back(s.point(i, 0));
    for (std::size_t j = 0; j < s.countV; ++j) rowV.push_back(s.point(0, j));
    std::vector<double> us = samples(spanBreaks(s.knotsU, s.domainStartU(), s.domainEndU()),
                                     segmentsPerSpan(rowU, criteria.criteria, criteria.valueU));
    std::vector<double> vs = samples(
        spanBreaks(s.knotsV, s.domainStartV(), s.domainEndV()),
        segmentsPerSpan(rowV, criteria.criteria, criteria.criteria == 2 ? criteria.valueV : criteria.valueU));
    MeshData mesh;
    const auto nu = static_cast<std::uint32_t>(us.size()), nv = static_cast<std::uint32_t>(vs.size());
    // Exact room: cached meshes live as long as their elements, and growth slack with them.
    mesh.positions.reserve(std::size_t{nu} * nv), mesh.normals.reserve(std::size_t{nu} * nv);
    if (withUv) mesh.uv.reserve(std::size_t{nu} * nv);
    for (double u : us)
        for (double v : vs) {
            mesh.positions.push_back(glm::vec3(geom::evaluate(s, u, v)));
            mesh.normals.push_back(glm::vec3(geom::normal(s, u, v)));
            if (withUv) mesh.uv.push_back(glm::vec2(static_cast<float>(u), static_cast<float>(v)));
        }
    const std::vector<std::vector<glm::dvec3>> trimCurves = trimCurveSamples(element);
    const std::vector<std::vector<glm::dvec2>> loops = trimPolygons(element, trimCurves);
    mesh.trimLoops = loops;  // the pick keeps what the loops keep, exactly
    auto at = [nv](std::uint32_t i, std::uint32_t j) { return i * nv + j; };
    auto cells = [&] {
        std::vector<std::uint32_t> triangles;
        triangles.reserve(6 * std::size_t{nu > 0 ? nu - 1 : 0} * (nv > 0 ? nv - 1 : 0));
        for (std::uint32_t i = 0; i + 1 < nu; ++i)
            for (std::uint32_t j = 0; j + 1 < nv; ++j) {
                if (!loops.empty() && !insideTrim(loops, {(us[i] + us[i + 1]) / 2, (vs[j] + vs[j + 1]) / 2}))
                    continue;
                // Counter-clockwise in (u, v) is counter-clockwise seen along Su x Sv.
                triangles.insert(triangles.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                triangles.insert(triangles.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        if (!loops.empty()) triangles.shrink_to_fit();  // trimmed: fewer than the room made
        return triangles;
    };
    // Untrimmed grids of one size have the same triangles: the cache shares them.
    mesh.triangles = grids && loops.empty() ? SharedIndexList::shared(grids->gridTriangles(nu, nv, cells))
                                            : SharedIndexList(cells());
    mesh.trianglesPerFacet = 2;  // trimming keeps or drops whole cells
    if (characteristics.style == 3) {
        // Iso-curves through the grid rows and columns nearest to their parameters (isoParameters:
        // uniform, or at and between the knots, which are rows), each row once. A trimmed
        // surface's iso-curve stops where its cells are trimmed away: a step is kept when its
        // middle is (the cells' own rule), runs of kept steps are lines.
        auto isoLine = [&](std::uint32_t k, bool constantU) {
            std::vector<std::uint32_t> line;
            const std::uint32_t steps = (constantU ? nv : nu) - 1;
            for (std::uint32_t t = 0; t < steps; ++t) {
                const glm::dvec2 middle = constantU ? glm::dvec2(us[k], (vs[t] + vs[t + 1]) / 2)
                                                    : glm::dvec2((us[t] + us[t + 1]) / 2, vs[k]);
                if (!loops.empty() && !insideTrim(loops, middle)) {
                    if (line.size() >= 2) mesh.isoLines.push_back(std::move(line));
                    line.clear();
                    continue;
                }
                if (line.empty()) line.push_back(constantU ? at(k, t) : at(t, k));
                line.push_back(constantU ? at(k, t + 1) : at(t + 1, k));
            }
            if (line.size() >= 2) mesh.isoLines.push_back(std::move(line));
        };
        auto lines = [&](int count, const std::vector<double>& rows, bool constantU) {
            const std::vector<double>& knots = constantU ? s.knotsU : s.knotsV;
            const double a = constantU ? s.domainStartU() : s.domainStartV();
            const double b = constantU ? s.domainEndU() : s.domainEndV();
            std::vector<char> drawn(rows.size(), 0);
            forEachIsoParameter(characteristics.placement, count, knots, rows, a, b, [&](double t) {
                const std::uint32_t k = nearestRow(rows, t);
                if (drawn[k]) return;
                drawn[k] = 1;
                isoLine(k, constantU);
            });
        };
        lines(characteristics.curvesU, us, true);
        lines(characteristics.curvesV, vs, false);
    }
    addTrimEdges(mesh, element, trimCurves, withUv);
    return mesh;
}

}  // namespace phigs::detail
