#include "geom/KnotSignificance.h"
#include "Checked.h"
#include "NumberText.h"

#include "geom/GeometryError.h"

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace geom {
namespace {

// Checks that knotIndex names an interior knot value and returns the index of its last
// occurrence and its multiplicity.
std::pair<std::size_t, int> interiorKnot(int degree, std::span<const double> knots, std::size_t count,
                                         std::size_t knotIndex, const char* where) {
    const std::size_t p = static_cast<std::size_t>(degree);
    if (knots.size() != count + p + 1)
        throw GeometryError(std::string(where) + ": " + std::to_string(knots.size()) + " knots for " +
                            std::to_string(count) + " coefficients of degree " + std::to_string(degree));
    if (knotIndex >= knots.size())
        throw GeometryError(std::string(where) + ": knot index " + std::to_string(knotIndex) +
                            " is past the end");
    const double z = knots[knotIndex];
    if (!(z > knots[p] && z < knots[count]))
        throw GeometryError(std::string(where) + ": knot " + std::to_string(knotIndex) + " (value " +
                            detail::numberText(z) + ") is not an interior knot");
    std::size_t r = knotIndex;
    while (r + 1 < knots.size() && knots[r + 1] == z) ++r;
    std::size_t first = knotIndex;
    while (first > 0 && knots[first - 1] == z) --first;
    return {r, static_cast<int>(r - first + 1)};
}

// Lyche and Morken's l-infinity removal error. Removing one occurrence of z = knots[r] (last
// occurrence, multiplicity s) and inserting it again maps the p-s+2 local coefficients c of the
// reduced spline to the p-s+3 coefficients d by a bidiagonal matrix B (rows [1 0..], then
// (1-alpha, alpha) pairs, then [..0 1]). The best max-norm fit of d by B c equioscillates, so
// the square system [B | (-1)^i] [c; h] = d gives the error |h| directly. The thesis listing
// computed the residual of this square system instead, which is zero (Marcaly 1991, section 4.3).
template <class V>
double removalWeightDense(int degree, std::span<const double> knots, std::span<const V> points,
                          std::size_t sequences, std::size_t r, int s);

// The same system solved in O(p): c_q = A_q + B_q h by forward substitution through the rows
// whose alpha is at least one half (dividing by alpha) and backward through the others
// (dividing by 1 - alpha), as The NURBS Book's A5.8 computes from both ends; the row where the
// two meet gives h. Every pivot is then at least one half where the alphas descend, as they do
// for one knot removed; elsewhere (or for a knot of multiplicity p + 1, which has no middle
// rows) the dense elimination with partial pivoting answers.
template <class V>
double removalWeight(int degree, std::span<const double> knots, std::span<const V> points,
                     std::size_t sequences, std::size_t r, int s) {
    const std::size_t p = static_cast<std::size_t>(degree);
    const std::size_t m = p - static_cast<std::size_t>(s) + 3;
    constexpr std::size_t kMost = 16;
    if (m < 3 || m > kMost) return removalWeightDense<V>(degree, knots, points, sequences, r, s);
    const std::size_t firstRow = r - p - 1;
    const double z = knots[r];
    auto reduced = [&](std::size_t i) { return i < r ? knots[i] : knots[i + 1]; };
    double alpha[kMost];
    for (std::size_t q = 1; q + 1 < m; ++q) {
        const std::size_t i = firstRow + q;
        const double denom = reduced(i + p) - reduced(i);
        alpha[q] = denom > 0.0 ? (z - reduced(i)) / denom : 0.0;
    }
    // Rows 1..last go forward, rows m-2 down to last+2 backward, row last+1 meets.
    std::size_t last = 0;
    while (last + 1 <= m - 3 && alpha[last + 1] >= 0.5) ++last;
    for (std::size_t q = last + 2; q + 1 < m; ++q)
        if (alpha[q] > 0.5) return removalWeightDense<V>(degree, knots, points, sequences, r, s);
    auto sign = [](std::size_t q) { return q % 2 == 0 ? 1.0 : -1.0; };
    double bLeft = -1.0;
    for (std::size_t q = 1; q <= last; ++q) bLeft = (-(1.0 - alpha[q]) * bLeft - sign(q)) / alpha[q];
    double bRight = -sign(m - 1);
    for (std::size_t q = m - 2; q >= last + 2; --q)
        bRight = (-alpha[q] * bRight - sign(q)) / (1.0 - alpha[q]);
    const std::size_t meet = last + 1;
    const double denominator = (1.0 - alpha[meet]) * bLeft + alpha[meet] * bRight + sign(meet);
    if (!(std::abs(denominator) > 1e-300)) return std::numeric_limits<double>::infinity();
    double worst = 0.0;
    for (std::size_t k = 0; k < sequences; ++k) {
        auto d = [&](std::size_t q) { return points[(firstRow + q) * sequences + k]; };
        V aLeft = d(0);
        for (std::size_t q = 1; q <= last; ++q) aLeft = (d(q) - (1.0 - alpha[q]) * aLeft) / alpha[q];
        V aRight = d(m - 1);
        for (std::size_t q = m - 2; q >= last + 2; --q)
            aRight = (d(q) - alpha[q] * aRight) / (1.0 - alpha[q]);
        const V h = (d(meet) - (1.0 - alpha[meet]) * aLeft - alpha[meet] * aRight) / denominator;
        worst = std::max(worst, glm::length(h));
    }
    return worst;
}

template <class V>
double removalWeightDense(int degree, std::span<const double> knots, std::span<const V> points,
                          std::size_t sequences, std::size_t r, int s) {
    const std::size_t p = static_cast<std::size_t>(degree);
    const std::size_t mult = static_cast<std::size_t>(s);
    const std::size_t m = p - mult + 3;  // rows = unknowns (c and h)
    const std::size_t firstRow = r - p - 1;
    const double z = knots[r];
    auto reduced = [&](std::size_t i) { return i < r ? knots[i] : knots[i + 1]; };

    // Small systems (every degree up to 8 with one sequence) stay on the stack: this runs for
    // every knot in every ranking of the reduction loop.
    double smallA[100];
    V smallRhs[10];
    std::vector<double> heapA(m * m > 100 ? m * m : 0);
    std::vector<V> heapRhs(m * sequences > 10 ? m * sequences : 0);
    const std::span<double> a = m * m > 100 ? std::span<double>(heapA) : std::span<double>(smallA, m * m);
    std::fill(a.begin(), a.end(), 0.0);
    a[0] = 1.0;
    for (std::size_t q = 1; q + 1 < m; ++q) {
        const std::size_t i = firstRow + q;
        const double denom = reduced(i + p) - reduced(i);
        const double alpha = denom > 0.0 ? (z - reduced(i)) / denom : 0.0;
        a[q * m + q - 1] = 1.0 - alpha;
        a[q * m + q] = alpha;
    }
    a[(m - 1) * m + m - 2] = 1.0;
    for (std::size_t q = 0; q < m; ++q) a[q * m + m - 1] = (q % 2 == 0) ? 1.0 : -1.0;

    // One matrix, one right-hand side per sequence: eliminate with partial pivoting once.
    const std::span<V> rhs =
        m * sequences > 10 ? std::span<V>(heapRhs) : std::span<V>(smallRhs, m * sequences);
    for (std::size_t q = 0; q < m; ++q)
        for (std::size_t k = 0; k < sequences; ++k)
            rhs[q * sequences + k] = points[(firstRow + q) * sequences + k];
    for (std::size_t col = 0; col < m; ++col) {
        std::size_t pivot = col;
        for (std::size_t q = col + 1; q < m; ++q)
            if (std::abs(a[q * m + col]) > std::abs(a[pivot * m + col])) pivot = q;
        if (std::abs(a[pivot * m + col]) < 1e-300) return std::numeric_limits<double>::infinity();
        if (pivot != col) {
            for (std::size_t c = 0; c < m; ++c) std::swap(a[pivot * m + c], a[col * m + c]);
            for (std::size_t k = 0; k < sequences; ++k)
                std::swap(rhs[pivot * sequences + k], rhs[col * sequences + k]);
        }
        for (std::size_t q = col + 1; q < m; ++q) {
            const double f = a[q * m + col] / a[col * m + col];
            if (f == 0.0) continue;
            for (std::size_t c = col; c < m; ++c) a[q * m + c] -= f * a[col * m + c];
            for (std::size_t k = 0; k < sequences; ++k)
                rhs[q * sequences + k] -= f * rhs[col * sequences + k];
        }
    }
    // Only the last unknown, h, is needed: it comes straight out of the triangular system.
    double worst = 0.0;
    for (std::size_t k = 0; k < sequences; ++k) {
        const V h = rhs[(m - 1) * sequences + k] / a[(m - 1) * m + m - 1];
        worst = std::max(worst, glm::length(h));
    }
    return worst;
}

std::vector<glm::dvec4> homogeneous(const Curve& curve) {
    std::vector<glm::dvec4> h(curve.points.size());
    for (std::size_t i = 0; i < h.size(); ++i)
        h[i] = glm::dvec4(curve.points[i] * curve.weight(i), curve.weight(i));
    return h;
}

template <class V>
std::vector<KnotSignificance> rankImpl(int degree, std::span<const double> knots, std::span<const V> points,
                                       std::size_t sequences) {
    if (sequences == 0 || points.size() % sequences != 0)
        throw GeometryError("rankKnots: " + std::to_string(points.size()) + " points do not split into " +
                            std::to_string(sequences) + " sequences");
    const std::size_t count = points.size() / sequences;
    const std::size_t p = static_cast<std::size_t>(degree);
    std::vector<KnotSignificance> out;
    for (std::size_t i = p + 1; i < count; ++i) {
        if (knots[i] == knots[i + 1] || !(knots[i] > knots[p]) || !(knots[i] < knots[count])) continue;
        const auto [r, s] = interiorKnot(degree, knots, count, i, "rankKnots");
        out.push_back({r, knots[r], s, removalWeight<V>(degree, knots, points, sequences, r, s)});
    }
    std::stable_sort(out.begin(), out.end(), [](const KnotSignificance& a, const KnotSignificance& b) {
        return a.weight < b.weight;
    });
    return out;
}

}  // namespace

double knotRemovalWeight(int degree, std::span<const double> knots, std::span<const glm::dvec3> points,
                         std::size_t sequences, std::size_t knotIndex) {
    if (degree < 1) throw GeometryError("knotRemovalWeight: degree must be at least 1");
    if (sequences == 0 || points.size() % sequences != 0)
        throw GeometryError("knotRemovalWeight: " + std::to_string(points.size()) +
                            " points do not split into " + std::to_string(sequences) + " sequences");
    const auto [r, s] =
        interiorKnot(degree, knots, points.size() / sequences, knotIndex, "knotRemovalWeight");
    return removalWeight<glm::dvec3>(degree, knots, points, sequences, r, s);
}

double knotRemovalWeight(const Curve& curve, std::size_t knotIndex) {
    // A per-knot entry (called for every knot of a curve): the sizes, the knots it reads and its
    // result are checked rather than the whole curve.
    detail::checkShape(curve, "knotRemovalWeight");
    const std::size_t p = static_cast<std::size_t>(curve.degree);
    const std::size_t from = knotIndex > p + 1 ? knotIndex - p - 1 : 0;
    for (std::size_t i = from; i < std::min(knotIndex + p + 1, curve.knots.size() - 1); ++i)
        if (!std::isfinite(curve.knots[i + 1]) || !(curve.knots[i] <= curve.knots[i + 1]))
            throw GeometryError("knotRemovalWeight: the knots around index " + std::to_string(knotIndex) +
                                " are not finite and non-decreasing");
    for (std::size_t i = from; i < std::min(knotIndex + 1, curve.points.size()); ++i) {
        const glm::dvec3& c = curve.points[i];
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z) ||
            !detail::usableWeight(curve.weight(i)))
            throw GeometryError("knotRemovalWeight: control point " + std::to_string(i) +
                                " is not finite or its weight is not a positive normal number");
    }
    double weight = 0.0;
    if (!curve.rational()) {
        weight = knotRemovalWeight(curve.degree, curve.knots, curve.points, 1, knotIndex);
    } else {
        const auto [r, s] =
            interiorKnot(curve.degree, curve.knots, curve.points.size(), knotIndex, "knotRemovalWeight");
        const std::vector<glm::dvec4> h = homogeneous(curve);
        weight =
            removalWeight<glm::dvec4>(curve.degree, curve.knots, std::span<const glm::dvec4>(h), 1, r, s);
    }
    if (!std::isfinite(weight))
        throw GeometryError("knotRemovalWeight: the weight of knot " + std::to_string(knotIndex) +
                            " is not finite (control points or weights near it are not finite or positive)");
    return weight;
}

std::vector<KnotSignificance> rankKnots(int degree, std::span<const double> knots,
                                        std::span<const glm::dvec3> points, std::size_t sequences) {
    if (degree < 1) throw GeometryError("rankKnots: degree must be at least 1");
    return rankImpl<glm::dvec3>(degree, knots, points, sequences);
}

std::vector<KnotSignificance> rankKnots(const Curve& curve) {
    validate(curve, "rankKnots");
    if (!curve.rational()) return rankImpl<glm::dvec3>(curve.degree, curve.knots, std::span(curve.points), 1);
    const std::vector<glm::dvec4> h = homogeneous(curve);
    return rankImpl<glm::dvec4>(curve.degree, curve.knots, std::span<const glm::dvec4>(h), 1);
}

}  // namespace geom
