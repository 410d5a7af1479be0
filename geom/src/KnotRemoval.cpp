#include "geom/KnotRemoval.h"
#include "NumberText.h"

#include "RemovalDetail.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace geom {
namespace {

/// How far a removal may move the homogeneous points: A5.8 compares the two values of the
/// point it eliminates, and the curve moves by their difference times a B-spline (at most 1).
/// The points are taken about the centre of their box (radius: the farthest point from it).
/// Polynomial: the difference itself within the tolerance. Rational (as The NURBS Book eq. 5.30,
/// but invariant under moving, scaling and reweighting the curve): with C = X / w and the
/// difference (dX, dw), C' - C = (dX - C dw) / w', so |dX| + radius |dw| <= tolerance (wmin - |dw|)
/// keeps the curve within the tolerance and every weight positive.
struct RemovalBound {
    double tolerance = 0.0, radius = 0.0, wmin = 1.0;
    bool rational = false;

    bool holds(const glm::dvec4& a, const glm::dvec4& b) const {
        const glm::dvec4 d = a - b;
        if (!rational) return glm::length(glm::dvec3(d)) <= tolerance;
        const double dw = std::abs(d.w);
        return glm::length(glm::dvec3(d)) + radius * dw <= tolerance * (wmin - dw);
    }
};

/// The index r of the last occurrence of knot u in the curve and its multiplicity s.
struct KnotPlace {
    int r, s;
};

/// Where knot u sits in the curve; throws where u is not an interior knot.
KnotPlace locateKnot(const Curve& curve, double u) {
    const int p = curve.degree;
    const int n = static_cast<int>(curve.points.size()) - 1;
    if (!(u > curve.domainStart() && u < curve.domainEnd()))
        throw GeometryError("removeKnot: " + detail::numberText(u) + " is not inside the curve's domain");
    int r = -1;
    for (int i = 0; i <= n + p + 1; ++i)
        if (curve.knots[static_cast<std::size_t>(i)] == u) r = i;
    if (r < 0) throw GeometryError("removeKnot: " + detail::numberText(u) + " is not a knot of the curve");
    int s = 0;
    for (int i = r; i >= 0 && curve.knots[static_cast<std::size_t>(i)] == u; --i) ++s;
    return {r, s};
}

/// The centre of the box of the curve's points, about which its homogeneous points are taken.
glm::dvec3 pointsCentre(const Curve& curve) {
    glm::dvec3 lo = curve.points.front(), hi = lo;
    for (const glm::dvec3& q : curve.points) lo = glm::min(lo, q), hi = glm::max(hi, q);
    return 0.5 * (lo + hi);
}

/// The curve's homogeneous points about `centre`, and the bound that keeps the curve within
/// tolerance.
std::vector<glm::dvec4> homogeneousPoints(const Curve& curve, const glm::dvec3& centre, double tolerance,
                                          RemovalBound& bound) {
    std::vector<glm::dvec4> pw(curve.points.size());
    bound = RemovalBound{tolerance, 0.0, curve.weight(0), curve.rational()};
    for (std::size_t i = 0; i < pw.size(); ++i) {
        pw[i] = glm::dvec4((curve.points[i] - centre) * curve.weight(i), curve.weight(i));
        bound.wmin = std::min(bound.wmin, curve.weight(i));
        bound.radius = std::max(bound.radius, glm::length(curve.points[i] - centre));
    }
    return pw;
}

/// Removes one occurrence of knot u (at `at`) from the homogeneous points pw and the knots when
/// the bound allows it, as The NURBS Book's A5.8 does once; returns whether it did. Inserting u
/// again would give P_i = a_i Q_i + (1 - a_i) Q_(i-1) for i = first..last, a_i = (u - U_i) /
/// (U_(i+p+1) - U_i), with Q_(first-1) and Q_last the unchanged neighbours: one equation more
/// than new points. A5.8 solves it from both ends (dividing by a_i from the left and by 1 - a_i
/// from the right) and meets in the middle; where the a_i are all near 1 (u near the clamped
/// end) the right side then divides by tiny numbers, and an exact removal is refused. So each
/// side runs only where it divides by at least one half, the left up to the equation k where
/// a_i falls below 1/2, the right down to it, and equation k is the one left over: the curve
/// moves by its residual times one B-spline (at most 1), which the bound checks.
bool removeOnce(std::vector<double>& U, std::vector<glm::dvec4>& pw, int p, double u, KnotPlace at,
                const RemovalBound& bound) {
    auto P = [&](int i) -> glm::dvec4& { return pw[static_cast<std::size_t>(i)]; };
    const int first = at.r - p, last = at.r - at.s;
    const auto begin = pw.begin() + first;
    if (last < first) {
        // A break (multiplicity p + 1): the two points on either side of it must meet.
        if (!bound.holds(P(first - 1), P(first))) return false;
        pw.erase(begin);
    } else {
        auto alpha = [&](int i) {
            return (u - U[static_cast<std::size_t>(i)]) /
                   (U[static_cast<std::size_t>(i + p + 1)] - U[static_cast<std::size_t>(i)]);
        };
        // q[i - first + 1] is the new point Q_i, i = first - 1 .. last.
        std::vector<glm::dvec4> q(static_cast<std::size_t>(last - first + 2));
        auto Q = [&](int i) -> glm::dvec4& { return q[static_cast<std::size_t>(i - first + 1)]; };
        Q(first - 1) = P(first - 1);
        Q(last) = P(last + 1);
        int k = first;
        while (k < last && alpha(k) >= 0.5) ++k;
        for (int i = first; i < k; ++i) Q(i) = (P(i) - (1.0 - alpha(i)) * Q(i - 1)) / alpha(i);
        for (int j = last; j > k; --j) Q(j - 1) = (P(j) - alpha(j) * Q(j)) / (1.0 - alpha(j));
        if (!bound.holds(P(k), alpha(k) * Q(k) + (1.0 - alpha(k)) * Q(k - 1))) return false;
        // P_first..P_last become Q_first..Q_(last-1).
        std::copy(q.begin() + 1, q.end() - 1, begin);
        pw.erase(pw.begin() + last);
    }
    U.erase(U.begin() + at.r);
    return true;
}

/// The curve of degree p on `knots` with homogeneous points pw about `centre`, projected back.
Curve curveFromHomogeneous(int p, std::vector<double> knots, const std::vector<glm::dvec4>& pw,
                           const glm::dvec3& centre, bool rational) {
    std::vector<glm::dvec3> points(pw.size());
    std::vector<double> weights;
    for (std::size_t k = 0; k < pw.size(); ++k) {
        points[k] = glm::dvec3(pw[k]) / pw[k].w + centre;
        if (rational) weights.push_back(pw[k].w);
    }
    return Curve(p, std::move(knots), std::move(points), std::move(weights));
}

/// The NURBS Book A5.8's removal loop for several occurrences, with its index names: removes knot u (at `at`)
/// up to `times` times while each removal keeps the bound, updating pw in place; returns the number of times
/// it was removed.
int removeTimes(const std::vector<double>& U, std::vector<glm::dvec4>& pw, int p, double u, KnotPlace at,
                int times, const RemovalBound& bound) {
    auto knot = [&](int i) { return U[static_cast<std::size_t>(i)]; };
    auto P = [&](int i) -> glm::dvec4& { return pw[static_cast<std::size_t>(i)]; };
    const int r = at.r, s = at.s, ord = p + 1;
    int first = r - p;
    int last = r - s;
    std::vector<glm::dvec4> temp(static_cast<std::size_t>(2 * p + 1));
    auto T = [&](int i) -> glm::dvec4& { return temp[static_cast<std::size_t>(i)]; };
    int t = 0;
    for (; t < times; ++t) {
        const int off = first - 1;
        T(0) = P(off);
        T(last + 1 - off) = P(last + 1);
        int i = first, j = last, ii = 1, jj = last - off;
        while (j - i > t) {
            const double alfi = (u - knot(i)) / (knot(i + ord + t) - knot(i));
            const double alfj = (u - knot(j - t)) / (knot(j + ord) - knot(j - t));
            T(ii) = (P(i) - (1.0 - alfi) * T(ii - 1)) / alfi;
            T(jj) = (P(j) - alfj * T(jj + 1)) / (1.0 - alfj);
            ++i, ++ii, --j, --jj;
        }
        bool removable = false;
        if (j - i < t) {
            removable = bound.holds(T(ii - 1), T(jj + 1));
        } else {
            const double alfi = (u - knot(i)) / (knot(i + ord + t) - knot(i));
            removable = bound.holds(P(i), alfi * T(ii + t + 1) + (1.0 - alfi) * T(ii - 1));
        }
        if (!removable) break;
        i = first;
        j = last;
        while (j - i > t) {
            P(i) = T(i - off);
            P(j) = T(j - off);
            ++i, --j;
        }
        --first;
        ++last;
    }
    return t;
}

/// The curve left after removing knot u (at `at`) t times: A5.8's closing shifts of the knots and
/// of the homogeneous points pw, projected back.
Curve compacted(const Curve& curve, std::vector<glm::dvec4>& pw, const glm::dvec3& centre, KnotPlace at,
                int t) {
    const int p = curve.degree;
    const int n = static_cast<int>(curve.points.size()) - 1;
    const int r = at.r, s = at.s;
    std::vector<double> knots = curve.knots;
    const int m = n + p + 1;
    for (int k = r + 1; k <= m; ++k)
        knots[static_cast<std::size_t>(k - t)] = knots[static_cast<std::size_t>(k)];
    knots.resize(knots.size() - static_cast<std::size_t>(t));
    const int fout = (2 * r - s - p) / 2;
    int j = fout, i = fout;
    for (int k = 1; k < t; ++k) {
        if (k % 2 == 1)
            ++i;
        else
            --j;
    }
    for (int k = i + 1; k <= n; ++k) pw[static_cast<std::size_t>(j++)] = pw[static_cast<std::size_t>(k)];
    pw.resize(pw.size() - static_cast<std::size_t>(t));

    std::vector<glm::dvec3> points(pw.size());
    std::vector<double> weights;
    for (std::size_t k = 0; k < pw.size(); ++k) {
        points[k] = glm::dvec3(pw[k]) / pw[k].w + centre;
        if (curve.rational()) weights.push_back(pw[k].w);
    }
    return Curve(p, std::move(knots), std::move(points), std::move(weights));
}

}  // namespace

ExactKnotRemoval removeKnot(const Curve& curve, double u, int times, double tolerance) {
    validate(curve, "removeKnot");
    if (times < 1) throw GeometryError("removeKnot: times must be at least 1, got " + std::to_string(times));
    if (!(tolerance >= 0.0)) throw GeometryError("removeKnot: tolerance must be non-negative");
    const KnotPlace at = locateKnot(curve, u);
    times = std::min(times, at.s);
    RemovalBound bound;
    const glm::dvec3 centre = pointsCentre(curve);
    std::vector<glm::dvec4> pw = homogeneousPoints(curve, centre, tolerance, bound);
    // Several occurrences: A5.8 first, which keeps the points the earlier removals settled and so
    // stays exact to rounding where removing one occurrence after another loses up to 1e-11 of
    // the size (a rational Bézier joint of degree 6).
    std::vector<glm::dvec4> several = pw;
    const int t = times > 1 ? removeTimes(curve.knots, several, curve.degree, u, at, times, bound) : 0;
    if (t == times) return {compacted(curve, several, centre, at, t), t};
    // Short of that (or one asked for): one at a time, each split where its recurrences stay well
    // conditioned (removeOnce), so asking for more never removes fewer than asking for one.
    std::vector<double> knots = curve.knots;
    int removed = 0;
    for (KnotPlace place = at; removed < times && removeOnce(knots, pw, curve.degree, u, place, bound);
         ++removed)
        --place.r, --place.s;
    if (removed <= t)
        return t == 0 ? ExactKnotRemoval{curve, 0}
                      : ExactKnotRemoval{compacted(curve, several, centre, at, t), t};
    return {curveFromHomogeneous(curve.degree, std::move(knots), pw, centre, curve.rational()), removed};
}

namespace {

/// Throws, naming `where`, where the spline or the removal request is malformed.
void checkRemovalInput(int degree, std::span<const double> knots, std::span<const glm::dvec3> points,
                       std::size_t sequences, std::span<const double> values, const EndConditions& ends,
                       int margin, const char* where) {
    if (degree < 1) throw GeometryError(std::string(where) + ": degree must be at least 1");
    if (sequences == 0 || points.size() % sequences != 0)
        throw GeometryError(std::string(where) + ": " + std::to_string(points.size()) +
                            " points do not split into " + std::to_string(sequences) + " sequences");
    if (values.empty()) throw GeometryError(std::string(where) + ": no knot values to remove");
    if (margin < 0 || ends.fixedDerivatives < 0)
        throw GeometryError(std::string(where) + ": margin and fixedDerivatives must be non-negative");
    const std::size_t p = static_cast<std::size_t>(degree);
    const std::size_t count = points.size() / sequences;
    if (knots.size() != count + p + 1)
        throw GeometryError(std::string(where) + ": " + std::to_string(knots.size()) + " knots for " +
                            std::to_string(count) + " coefficients of degree " + std::to_string(degree));
    // The knots are searched and compared below: a NaN or a knot out of order would be reported as
    // a value that is not a knot.
    for (std::size_t i = 0; i < knots.size(); ++i) {
        if (!std::isfinite(knots[i]))
            throw GeometryError(std::string(where) + ": knot " + std::to_string(i) +
                                " is not a finite number");
        if (i > 0 && knots[i] < knots[i - 1])
            throw GeometryError(std::string(where) + ": knots decrease at index " + std::to_string(i));
    }
}

/// The index of the last occurrence of each value (the one that goes), ascending; throws where a
/// value is no interior knot or is listed twice.
std::vector<std::size_t> lastOccurrences(std::span<const double> knots, std::size_t p, std::size_t count,
                                         std::span<const double> values, const char* where) {
    std::vector<std::size_t> removed;
    for (double v : values) {
        if (!(v > knots[p] && v < knots[count]))
            throw GeometryError(std::string(where) + ": " + detail::numberText(v) +
                                " is not an interior knot");
        const auto it = std::upper_bound(knots.begin(), knots.end(), v);
        const std::size_t r = static_cast<std::size_t>(it - knots.begin());
        if (r == 0 || knots[r - 1] != v)
            throw GeometryError(std::string(where) + ": " + detail::numberText(v) + " is not a knot");
        if (std::find(removed.begin(), removed.end(), r - 1) != removed.end())
            throw GeometryError(std::string(where) + ": value " + detail::numberText(v) + " listed twice");
        removed.push_back(r - 1);
    }
    std::sort(removed.begin(), removed.end());
    return removed;
}

/// knots without the entries at the ascending indices `removed`.
std::vector<double> withoutIndices(std::span<const double> knots, const std::vector<std::size_t>& removed) {
    std::vector<double> tau;
    tau.reserve(knots.size() - removed.size());
    for (std::size_t i = 0, k = 0; i < knots.size(); ++i) {
        if (k < removed.size() && removed[k] == i) {
            ++k;
            continue;
        }
        tau.push_back(knots[i]);
    }
    return tau;
}

/// The coefficients [cL, cH] of the reduced spline that the fit frees; the others keep their values.
struct FreeWindow {
    long cL, cH;
    std::size_t nr;  // knots removed

    /// Whether reduced coefficient c is free.
    bool frees(std::size_t c) const { return static_cast<long>(c) >= cL && static_cast<long>(c) <= cH; }
    /// The index before removal of a kept reduced coefficient c.
    std::size_t oldIndex(std::size_t c) const { return static_cast<long>(c) < cL ? c : c + nr; }
};

/// The reduced coefficients: the solution x for the free ones (none: the old values everywhere).
std::vector<glm::dvec3> reducedPoints(const FreeWindow& w, std::span<const glm::dvec3> points, std::size_t nt,
                                      std::size_t sequences, const std::vector<double>* x) {
    const std::size_t width = 3 * sequences;
    std::vector<glm::dvec3> out(nt * sequences);
    for (std::size_t c = 0; c < nt; ++c)
        for (std::size_t s = 0; s < sequences; ++s) {
            if (x && w.frees(c)) {
                const std::size_t row = (c - static_cast<std::size_t>(w.cL)) * width + 3 * s;
                out[c * sequences + s] = glm::dvec3((*x)[row], (*x)[row + 1], (*x)[row + 2]);
            } else {
                out[c * sequences + s] = points[w.oldIndex(c) * sequences + s];
            }
        }
    return out;
}

/// The least-squares solution for the free coefficients: each row of the knot insertion matrix
/// from tau to knots (over tau columns [c0, c1]) that touches them, scaled by the square root of
/// its B-spline's support length, against the old coefficient less the kept ones' share.
std::vector<double> solveFreeWindow(int degree, std::span<const double> knots,
                                    std::span<const glm::dvec3> points, std::size_t sequences,
                                    const FreeWindow& w, std::size_t c0, std::size_t c1,
                                    const std::vector<std::vector<double>>& rows, const char* where) {
    const std::size_t p = static_cast<std::size_t>(degree);
    const std::size_t freeCount = static_cast<std::size_t>(w.cH - w.cL + 1);
    std::vector<double> mat, rhs;
    std::size_t fitRows = 0;
    for (std::size_t r = 0; r < rows.size(); ++r) {
        bool touchesFree = false;
        for (long c = w.cL; c <= w.cH; ++c)
            if (rows[r][static_cast<std::size_t>(c) - c0] != 0.0) touchesFree = true;
        if (!touchesFree) continue;
        const std::size_t j = c0 + r;  // global coefficient index in the current knots
        const double scale = std::sqrt((knots[j + p + 1] - knots[j]) / static_cast<double>(p + 1));
        if (scale == 0.0) continue;
        for (long c = w.cL; c <= w.cH; ++c) mat.push_back(scale * rows[r][static_cast<std::size_t>(c) - c0]);
        for (std::size_t s = 0; s < sequences; ++s) {
            glm::dvec3 target = points[j * sequences + s];
            for (std::size_t c = c0; c <= c1; ++c) {
                if (w.frees(c)) continue;
                const double weight = rows[r][c - c0];
                if (weight != 0.0) target -= weight * points[w.oldIndex(c) * sequences + s];
            }
            rhs.push_back(scale * target.x);
            rhs.push_back(scale * target.y);
            rhs.push_back(scale * target.z);
        }
        ++fitRows;
    }
    if (fitRows < freeCount) throw GeometryError(std::string(where) + ": the local fit is under-determined");
    return detail::solveLeastSquares(std::move(mat), fitRows, freeCount, std::move(rhs), 3 * sequences);
}

// removeKnotsLeastSquares; with fit false the window's coefficients are left as placeholders
// (the caller refits them) and only the bookkeeping is done.
LeastSquaresRemoval removeKnots(int degree, std::span<const double> knots, std::span<const glm::dvec3> points,
                                std::size_t sequences, std::span<const double> values,
                                const EndConditions& ends, int margin, bool fit) {
    const char* where = "removeKnotsLeastSquares";
    checkRemovalInput(degree, knots, points, sequences, values, ends, margin, where);
    const std::size_t p = static_cast<std::size_t>(degree);
    const std::size_t count = points.size() / sequences;
    const std::vector<std::size_t> removed = lastOccurrences(knots, p, count, values, where);
    const std::size_t nr = removed.size();
    // The derivatives of order k at an end depend on the first p + k knots, so fixing them also
    // keeps the first (and last) fixedDerivatives interior knots.
    const std::size_t keep = static_cast<std::size_t>(ends.fixedDerivatives);
    if (removed.front() <= p + keep || removed.back() + keep >= count)
        throw GeometryError(std::string(where) + ": removing " + detail::numberText(knots[removed.front()]) +
                            " would change the end derivatives the end conditions fix");
    if (count < nr + p + 1)
        throw GeometryError(std::string(where) + ": removing " + std::to_string(nr) +
                            " knots leaves too few coefficients");
    std::vector<double> tau = withoutIndices(knots, removed);
    const std::size_t nt = count - nr;  // coefficients after removal
    const long a = static_cast<long>(removed.front());
    const long b = static_cast<long>(removed.back());
    const long fixedEnd = ends.fixedDerivatives + 1;
    const FreeWindow w{std::max(a - static_cast<long>(p) - margin, fixedEnd),
                       std::min(b - static_cast<long>(nr) + margin, static_cast<long>(nt) - 1 - fixedEnd),
                       nr};
    if (w.cL > w.cH)
        throw GeometryError(std::string(where) + ": the end conditions leave no coefficient free near " +
                            detail::numberText(knots[removed.front()]));

    LeastSquaresRemoval out;
    out.firstChanged = static_cast<std::size_t>(w.cL);
    out.lastChanged = static_cast<std::size_t>(w.cH);
    out.changedFrom = tau[out.firstChanged];
    out.changedTo = tau[out.lastChanged + p + 1];
    if (!fit) {
        out.points = reducedPoints(w, points, nt, sequences, nullptr);
        out.knots = std::move(tau);
        return out;
    }

    // Local knot insertion matrix from tau to knots over tau columns [c0, c1]: insert the removed
    // values into the identity, one Boehm step each.
    const std::size_t c0 = static_cast<std::size_t>(std::max(0L, w.cL - static_cast<long>(p) - 1));
    const std::size_t c1 = std::min(nt - 1, static_cast<std::size_t>(w.cH) + p + 1);
    std::vector<double> u(tau.begin() + static_cast<std::ptrdiff_t>(c0),
                          tau.begin() + static_cast<std::ptrdiff_t>(c1 + p + 2));
    std::vector<double> removedValues;
    for (std::size_t idx : removed) removedValues.push_back(knots[idx]);
    const std::vector<std::vector<double>> rows = detail::insertionRows(degree, u, removedValues, where);
    const std::vector<double> x = solveFreeWindow(degree, knots, points, sequences, w, c0, c1, rows, where);
    out.knots = std::move(tau);
    out.points = reducedPoints(w, points, nt, sequences, &x);
    return out;
}

}  // namespace

LeastSquaresRemoval removeKnotsLeastSquares(int degree, std::span<const double> knots,
                                            std::span<const glm::dvec3> points, std::size_t sequences,
                                            std::span<const double> values, const EndConditions& ends,
                                            int margin) {
    return removeKnots(degree, knots, points, sequences, values, ends, margin, true);
}

LeastSquaresRemoval detail::removalWindow(int degree, std::span<const double> knots,
                                          std::span<const glm::dvec3> points, std::size_t sequences,
                                          std::span<const double> values, const EndConditions& ends,
                                          int margin) {
    return removeKnots(degree, knots, points, sequences, values, ends, margin, false);
}

Curve removeKnotsLeastSquares(const Curve& curve, std::span<const double> values, const EndConditions& ends,
                              int margin) {
    validate(curve, "removeKnotsLeastSquares");
    if (curve.rational())
        throw GeometryError("removeKnotsLeastSquares: rational curves are not supported (polynomial only)");
    LeastSquaresRemoval r =
        removeKnotsLeastSquares(curve.degree, curve.knots, curve.points, 1, values, ends, margin);
    return Curve(curve.degree, std::move(r.knots), std::move(r.points));
}

}  // namespace geom
