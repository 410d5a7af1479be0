#include "geom/exchange/PatchGrid.h"

#include "geom/BezierExtraction.h"
#include "geom/Curve.h"
#include "geom/GeometryError.h"
#include "geom/KnotInsertion.h"
#include "geom/KnotRemoval.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace geom::exchange {

namespace {

/// The distinct parameter values at which patches meet, merged within `eps`.
struct Breaks {
    std::vector<double> values;
    double eps = 0;

    std::optional<std::size_t> find(double t) const {
        const auto it = std::lower_bound(values.begin(), values.end(), t - eps);
        if (it == values.end() || std::abs(*it - t) > eps) return std::nullopt;
        return std::size_t(it - values.begin());
    }
};

Breaks breaksOf(std::vector<double> all) {
    std::sort(all.begin(), all.end());
    Breaks b;
    b.eps = 1e-12 * (all.back() - all.front());
    for (double t : all)
        if (b.values.empty() || t - b.values.back() > b.eps) b.values.push_back(t);
    return b;
}

/// The curve along u (alongV false) or v through row or column `line` of the net.
Curve lineCurve(const Surface& s, std::size_t line, bool alongV) {
    const std::size_t count = alongV ? s.countV : s.countU;
    std::vector<glm::dvec3> points(count);
    std::vector<double> weights;
    for (std::size_t k = 0; k < count; ++k) {
        const std::size_t i = alongV ? line : k, j = alongV ? k : line;
        points[k] = s.point(i, j);
        if (s.rational()) weights.push_back(s.weight(i, j));
    }
    return Curve(alongV ? s.degreeV : s.degreeU, alongV ? s.knotsV : s.knotsU, std::move(points),
                 std::move(weights));
}

/// The surface whose lines along u (alongV false) or v are `lines`.
Surface fromLines(const Surface& shape, const std::vector<Curve>& lines, bool alongV) {
    const std::size_t count = lines.front().points.size(), other = lines.size();
    const std::size_t countU = alongV ? other : count, countV = alongV ? count : other;
    std::vector<glm::dvec3> points(countU * countV);
    std::vector<double> weights(shape.rational() ? points.size() : 0);
    for (std::size_t l = 0; l < other; ++l)
        for (std::size_t k = 0; k < count; ++k) {
            const std::size_t index = alongV ? l * countV + k : k * countV + l;
            points[index] = lines[l].points[k];
            if (shape.rational()) weights[index] = lines[l].weights[k];
        }
    return Surface(shape.degreeU, shape.degreeV, alongV ? shape.knotsU : lines.front().knots,
                   alongV ? lines.front().knots : shape.knotsV, countU, countV, std::move(points),
                   std::move(weights));
}

/// How far the curve `changed` can be from `original` (same knots): by the poles' distances and
/// the weights' relative differences. Each point of either is a convex combination of its poles
/// with coefficients N_i w_i / sum N_k w_k; weights off by a factor within 1 +- d move those
/// coefficients by at most 2 d / (1 - d) of themselves, and so the point by that much of the
/// poles' spread. Unlike the homogeneous bound (The NURBS Book eq. 5.30), nothing here divides by
/// the smallest weight, which with weights over 1e-2..1e2 asks for less than rounding.
double euclideanDeviation(const Curve& original, const Curve& changed) {
    double poles = 0.0, weights = 0.0;
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (std::size_t k = 0; k < original.points.size(); ++k) {
        poles = std::max(poles, glm::length(changed.points[k] - original.points[k]));
        weights = std::max(weights, std::abs(changed.weight(k) / original.weight(k) - 1.0));
        lo = glm::min(lo, original.points[k]), hi = glm::max(hi, original.points[k]);
    }
    if (!(weights < 0.5)) return std::numeric_limits<double>::infinity();
    return poles + 2.0 * weights / (1.0 - weights) * glm::length(hi - lo);
}

/// The line with the interior knot `value` removed `times` times where that moves it by at most
/// `tolerance`, measured by putting the knot back (euclideanDeviation); nullopt otherwise.
std::optional<Curve> removedWithin(const Curve& line, double value, int times, double tolerance) {
    ExactKnotRemoval r;
    try {
        r = removeKnot(line, value, times, std::numeric_limits<double>::infinity());
    } catch (const GeometryError&) {
        return std::nullopt;  // a forced removal far from exact: a weight at or below zero
    }
    if (r.removed != times) return std::nullopt;
    const Curve back = insertKnot(r.curve, value, times);
    if (back.knots != line.knots || !(euclideanDeviation(line, back) <= tolerance)) return std::nullopt;
    return std::move(r.curve);
}

/// Removes the interior knot `value` from every line along u or v as often as all of them allow,
/// but keeps it once: each patch edge was a knot.
Surface removeKnotEverywhere(const Surface& s, double value, bool alongV, double tolerance) {
    const std::size_t other = alongV ? s.countU : s.countV;
    std::vector<Curve> original;
    for (std::size_t l = 0; l < other; ++l) original.push_back(lineCurve(s, l, alongV));
    for (int times = (alongV ? s.degreeV : s.degreeU) - 1; times > 0; --times) {
        std::vector<Curve> lines;
        for (const Curve& line : original) {
            std::optional<Curve> removed = removedWithin(line, value, times, tolerance);
            if (!removed) break;
            lines.push_back(std::move(*removed));
        }
        if (lines.size() == other) return fromLines(s, lines, alongV);
    }
    return s;
}

bool near(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    return glm::length(a - b) <= tolerance;
}

/// The pieces' Bézier patches on the grid of their breaks, joined with C0 knots; nullopt when
/// they do not tile the grid or neighbouring edges differ.
std::optional<Surface> assemble(const std::vector<BezierSurfacePiece>& cells, double tolerance) {
    std::vector<double> us, vs;
    for (const auto& c : cells) {
        us.insert(us.end(), {c.u0, c.u1});
        vs.insert(vs.end(), {c.v0, c.v1});
    }
    const Breaks bu = breaksOf(us), bv = breaksOf(vs);
    const std::size_t mu = bu.values.size() - 1, mv = bv.values.size() - 1;
    if (mu * mv != cells.size()) return std::nullopt;
    const std::size_t p = std::size_t(cells.front().surface.degreeU),
                      q = std::size_t(cells.front().surface.degreeV);
    const std::size_t countU = mu * p + 1, countV = mv * q + 1;
    const bool rational = cells.front().surface.rational();
    std::vector<glm::dvec3> points(countU * countV);
    std::vector<double> weights(rational ? points.size() : 0);
    std::vector<char> filled(points.size(), 0), used(mu * mv, 0);
    for (const auto& c : cells) {
        const auto i0 = bu.find(c.u0), i1 = bu.find(c.u1), j0 = bv.find(c.v0), j1 = bv.find(c.v1);
        if (!i0 || !i1 || !j0 || !j1 || *i1 != *i0 + 1 || *j1 != *j0 + 1 || used[*i0 * mv + *j0])
            return std::nullopt;
        used[*i0 * mv + *j0] = 1;
        for (std::size_t a = 0; a <= p; ++a)
            for (std::size_t b = 0; b <= q; ++b) {
                const std::size_t index = (*i0 * p + a) * countV + *j0 * q + b;
                const glm::dvec3& point = c.surface.point(a, b);
                const double w = c.surface.weight(a, b);
                if (filled[index] && (!near(points[index], point, tolerance) ||
                                      (rational && std::abs(weights[index] - w) > tolerance * w)))
                    return std::nullopt;
                points[index] = point;
                if (rational) weights[index] = w;
                filled[index] = 1;
            }
    }
    auto knots = [](const Breaks& b, std::size_t degree) {
        std::vector<double> k(degree + 1, b.values.front());
        for (std::size_t i = 1; i + 1 < b.values.size(); ++i) k.insert(k.end(), degree, b.values[i]);
        k.insert(k.end(), degree + 1, b.values.back());
        return k;
    };
    return Surface(int(p), int(q), knots(bu, p), knots(bv, q), countU, countV, std::move(points),
                   std::move(weights));
}

/// Unclamps the start of a spline clamped there to the periodic extension of its knots, by
/// undoing, last first, the `degree` insertions of the start knot that would clamp it again.
void unclampStart(int degree, std::vector<double>& knots, std::vector<glm::dvec4>& poles) {
    const std::size_t p = std::size_t(degree), n = poles.size() - 1;
    const std::vector<double> U = knots;
    const double a = U[p];
    for (std::size_t k = 0; k < p; ++k) knots[p - 1 - k] = knots[p - k] - (U[n + 1 - k] - U[n - k]);
    std::vector<glm::dvec4> r(n + 1 + p);
    std::copy(poles.begin(), poles.end(), r.begin() + std::ptrdiff_t(p));
    for (std::size_t j = p; j-- > 0;) {
        // Inserting the start knot once more (j + 1 times there) maps r_j to r: r[i] = alpha
        // r_j[i] + (1 - alpha) r_j[i - 1] for i in j + 1 .. p - 1, a shift above; solved downwards.
        std::vector<glm::dvec4> previous(n + 1 + j);
        for (std::size_t i = p; i <= n + j + 1; ++i) previous[i - 1] = r[i];
        for (std::size_t i = p - 1; i >= j + 1; --i) {
            const double alpha = (a - knots[i]) / (U[p + i - j] - knots[i]);
            previous[i - 1] = (r[i] - alpha * previous[i]) / (1.0 - alpha);
        }
        r = std::move(previous);
    }
    poles = std::move(r);
}

/// The same spline with its parameter reversed (t -> -t), so its end becomes its start.
void mirror(std::vector<double>& knots, std::vector<glm::dvec4>& poles) {
    std::reverse(knots.begin(), knots.end());
    for (double& t : knots) t = -t;
    std::reverse(poles.begin(), poles.end());
}

bool clamped(const std::vector<double>& knots, int degree) {
    const std::size_t p = std::size_t(degree), m = knots.size() - 1;
    return knots[0] == knots[p] && knots[m] == knots[m - p];
}

/// The poles (homogeneous) of the spline clamped on `knots` unclamped at both ends, and in
/// `unclamped` its knots: the periodic extension's.
std::vector<glm::dvec4> unclampedPoles(int degree, const std::vector<double>& knots,
                                       std::vector<glm::dvec4> poles, std::vector<double>& unclamped) {
    unclamped = knots;
    unclampStart(degree, unclamped, poles);
    mirror(unclamped, poles);
    unclampStart(degree, unclamped, poles);
    mirror(unclamped, poles);
    return poles;
}

/// The last `degree` of the poles made the same as the first `degree`: each pair from the copy
/// the fewer unclamping steps made (the start's recurrence ends at pole 0, the end's at the last).
void wrap(std::vector<glm::dvec4>& poles, std::size_t period) {
    const std::size_t degree = poles.size() - period;
    for (std::size_t k = 0; k < degree; ++k) {
        if (2 * k + 1 < degree)
            poles[k] = poles[k + period];
        else
            poles[k + period] = poles[k];
    }
}

/// The clamped line as a periodic spline where it closes within `tolerance`: unclamped, wrapped,
/// and measured by clamping it again (euclideanDeviation). The unclamping recurrences lose digits
/// at degree 6 and 7 (the two copies of a wrapped pole can differ by 1e-9 of the size), clamping
/// again (knot insertion) none: the measure is the curve's, not the copies'.
std::optional<Curve> periodicLine(const Curve& line, std::size_t period, double tolerance) {
    const std::size_t count = line.points.size();
    std::vector<glm::dvec4> clampedNet(count);
    for (std::size_t k = 0; k < count; ++k)
        clampedNet[k] = glm::dvec4(line.points[k] * line.weight(k), line.weight(k));
    std::vector<double> unclamped;
    std::vector<glm::dvec4> poles = unclampedPoles(line.degree, line.knots, clampedNet, unclamped);
    wrap(poles, period);
    std::vector<glm::dvec3> points(count);
    std::vector<double> weights(count);
    for (std::size_t k = 0; k < count; ++k) {
        weights[k] = poles[k].w;
        if (!(weights[k] > 0.0) || !std::isfinite(weights[k])) return std::nullopt;
        points[k] = glm::dvec3(poles[k]) / weights[k];
        if (!std::isfinite(points[k].x + points[k].y + points[k].z)) return std::nullopt;
    }
    if (!line.rational()) weights.clear();
    Curve periodic(line.degree, std::move(unclamped), std::move(points), std::move(weights));
    const Curve again = clampEnds(periodic);
    if (again.knots != line.knots || !(euclideanDeviation(line, again) <= tolerance)) return std::nullopt;
    return periodic;  // its wrapped poles the same bits (wrap), as periodicByConstruction asks
}

}  // namespace

std::optional<Surface> makePeriodic(const Surface& surface, bool alongV, double tolerance) {
    validate(surface, "makePeriodic");
    const int degree = alongV ? surface.degreeV : surface.degreeU;
    const std::vector<double>& knots = alongV ? surface.knotsV : surface.knotsU;
    const std::size_t count = alongV ? surface.countV : surface.countU,
                      other = alongV ? surface.countU : surface.countV;
    const std::size_t period = count - std::size_t(degree);
    if (!clamped(knots, degree) || period < std::size_t(degree)) return std::nullopt;
    std::vector<Curve> lines;
    for (std::size_t l = 0; l < other; ++l) {
        std::optional<Curve> periodic = periodicLine(lineCurve(surface, l, alongV), period, tolerance);
        if (!periodic) return std::nullopt;
        lines.push_back(std::move(*periodic));
    }
    return fromLines(surface, lines, alongV);
}

namespace {

/// The affine map taking the pieces' poles into the unit box about the origin, and back. Knot
/// removal's rational error bound divides the tolerance by 1 + |P|max (The NURBS Book A5.8), which
/// far from the origin or at large sizes asks for less than the rounding of the poles; the join is
/// affine invariant, so it runs on the normalised poles.
struct UnitFrame {
    glm::dvec3 centre{0.0};
    double size = 1.0;

    explicit UnitFrame(const std::vector<Surface>& pieces) {
        glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        for (const Surface& s : pieces)
            for (const glm::dvec3& p : s.points) lo = glm::min(lo, p), hi = glm::max(hi, p);
        centre = 0.5 * (lo + hi);
        const glm::dvec3 extent = hi - lo;
        size = std::max({extent.x, extent.y, extent.z});
        if (!(size > 0.0) || !std::isfinite(size)) size = 1.0;
    }
    Surface into(Surface s) const {
        for (glm::dvec3& p : s.points) p = (p - centre) / size;
        return s;
    }
    Surface outOf(Surface s) const {
        for (glm::dvec3& p : s.points) p = p * size + centre;
        return s;
    }
};

}  // namespace

/// What rounding can leave in the poles of Bézier patches cut from a rational surface: knot
/// insertion works on w P, so a pole whose weight is r times below its neighbours' takes their
/// rounding (|P| w eps) magnified r times, |P| measured from the origin the patches were cut at,
/// and more with the degree: 16 (p + 1)^2 eps. Past degree 4 with weights over 1e-2..1e2 that is
/// more than 1e-11 of the size.
double roundingFloor(const std::vector<Surface>& pieces) {
    double reach = 0.0, wmin = std::numeric_limits<double>::infinity(), wmax = 0.0;
    int degree = 1;
    for (const Surface& s : pieces) {
        degree = std::max({degree, s.degreeU, s.degreeV});
        for (const glm::dvec3& p : s.points) reach = std::max(reach, glm::length(p));
        for (std::size_t k = 0; k < s.points.size(); ++k) {
            const double w = s.weight(k / s.countV, k % s.countV);
            wmin = std::min(wmin, w), wmax = std::max(wmax, w);
        }
    }
    const double factor = 16.0 * (degree + 1) * (degree + 1);
    return factor * std::numeric_limits<double>::epsilon() * reach * (wmax / wmin);
}

std::optional<Surface> joinPatches(const std::vector<Surface>& pieces, double tolerance) {
    if (pieces.empty()) return std::nullopt;
    const UnitFrame frame(pieces);
    tolerance = std::max(tolerance, roundingFloor(pieces)) / frame.size;
    std::vector<BezierSurfacePiece> cells;
    for (const Surface& s : pieces) {
        const Surface& first = pieces.front();
        if (s.degreeU != first.degreeU || s.degreeV != first.degreeV || s.rational() != first.rational())
            return std::nullopt;
        for (auto& c : extractBezier(frame.into(s))) cells.push_back(std::move(c));
    }
    std::optional<Surface> joined = assemble(cells, tolerance);
    if (!joined) return std::nullopt;
    Surface s = std::move(*joined);
    for (const bool alongV : {false, true}) {
        const std::vector<double> knots = alongV ? s.knotsV : s.knotsU;
        const int degree = alongV ? s.degreeV : s.degreeU;
        for (std::size_t i = std::size_t(degree) + 1; i + std::size_t(degree) + 1 < knots.size(); ++i)
            if (knots[i] != knots[i - 1]) s = removeKnotEverywhere(s, knots[i], alongV, tolerance);
    }
    for (const bool alongV : {false, true})
        if (auto periodic = makePeriodic(s, alongV, tolerance)) s = std::move(*periodic);
    return frame.outOf(std::move(s));
}

}  // namespace geom::exchange
