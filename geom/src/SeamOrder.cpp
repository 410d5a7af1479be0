#include "SeamOrder.h"

#include "UnitScale.h"
#include "geom/Basis.h"
#include "geom/Evaluate.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace geom::detail {

namespace {

// Ends this close (relative to the coordinates) meet; derivatives this close (relative to the
// larger, or to the shape's largest of that order) agree, beyond their rounding (kRounding ulps
// of the coordinates through the basis derivatives: clamping a periodic curve and the points
// themselves round by that much, which a k-th derivative multiplies by about (p / h)^k).
constexpr double kMeet = 1e-12;
constexpr double kAgree = 1e-9;
constexpr double kRounding = 64.0 * std::numeric_limits<double>::epsilon();

/// A curve's derivatives 0 .. order at both ends of its domain, and how far rounding can move each.
struct EndDerivatives {
    std::vector<glm::dvec3> start, end;
    std::vector<double> rounding;  ///< by order: the two ends' together
    double extent = 0.0;           ///< the largest coordinate of the control points
};

/// The sum over the basis functions of |N^(k)| at u, k = 0 .. order, into sums (added).
void addBasisSums(const Curve& curve, double u, int order, std::vector<double>& sums) {
    const std::size_t p = std::size_t(curve.degree);
    const std::size_t span = findSpan(curve.degree, curve.knots, curve.points.size(), u);
    std::vector<double> ders(std::size_t(order + 1) * (p + 1));
    basisDerivatives(span, u, curve.degree, curve.knots, order, ders);
    for (std::size_t k = 0; k <= std::size_t(order); ++k)
        for (std::size_t j = 0; j <= p; ++j) sums[k] += std::abs(ders[k * (p + 1) + j]);
}

EndDerivatives endDerivatives(const Curve& curve, int order) {
    const double a = curve.knots[std::size_t(curve.degree)], b = curve.knots[curve.points.size()];
    EndDerivatives d{derivatives(curve, a, order), derivatives(curve, b, order),
                     std::vector<double>(std::size_t(order) + 1, 0.0)};
    addBasisSums(curve, a, order, d.rounding);
    addBasisSums(curve, b, order, d.rounding);
    for (const glm::dvec3& q : curve.points) d.extent = std::max(d.extent, largestCoordinate(q));
    // A rational curve's derivatives lean on its weights: their spread scales the rounding.
    double spread = 1.0;
    if (curve.rational()) {
        const auto [low, high] = std::minmax_element(curve.weights.begin(), curve.weights.end());
        spread = *high / *low;
    }
    for (double& r : d.rounding) r *= kRounding * d.extent * spread;
    return d;
}

/// seamOrder, with floor[k]: the size below which a k-th derivative counts as rounding (a
/// surface's collapsed row: a nose's derivatives round its point are a few ulps of nothing).
int seamOrderOf(const EndDerivatives& d, const std::vector<double>& floor) {
    if (!(glm::length(d.start[0] - d.end[0]) <= kMeet * d.extent + d.rounding[0])) return -1;
    const int top = int(d.start.size()) - 1;
    auto agree = [](const glm::dvec3& a, const glm::dvec3& b, double least, double rounding) {
        const double scale = std::max({glm::length(a), glm::length(b), least});
        return !(scale > rounding) || glm::length(a - b) <= kAgree * scale + rounding;
    };
    for (int k = 1; k <= top; ++k) {
        const std::size_t at = std::size_t(k);
        if (agree(d.start[at], d.end[at], floor[at], d.rounding[at])) continue;
        // Tangents of different lengths in one direction: geometrically smooth (G1).
        const double a = glm::length(d.start[1]), b = glm::length(d.end[1]);
        if (k == 1 && a > d.rounding[1] && b > d.rounding[1] &&
            agree(d.start[1] / a, d.end[1] / b, 0.0, d.rounding[1] / std::min(a, b)))
            return 1;
        return k - 1;
    }
    return top;
}

}  // namespace

int seamOrder(const Curve& curve) {
    const int top = std::max(0, curve.degree - 1);
    return seamOrderOf(endDerivatives(curve, top), std::vector<double>(std::size_t(top) + 1, 0.0));
}

int seamOrder(const Surface& surface, bool alongU) {
    const std::size_t rows = alongU ? surface.countV : surface.countU;
    const std::size_t length = alongU ? surface.countU : surface.countV;
    std::vector<EndDerivatives> ends(rows);
    const int top = std::max(0, (alongU ? surface.degreeU : surface.degreeV) - 1);
    std::vector<double> largest(std::size_t(top) + 1, 0.0);
    Curve line;  // each control row in turn
    line.degree = alongU ? surface.degreeU : surface.degreeV;
    line.knots = alongU ? surface.knotsU : surface.knotsV;
    line.points.resize(length);
    if (surface.rational()) line.weights.resize(length);
    for (std::size_t r = 0; r < rows; ++r) {
        for (std::size_t k = 0; k < length; ++k) {
            const std::size_t i = alongU ? k : r, j = alongU ? r : k;
            line.points[k] = surface.point(i, j);
            if (surface.rational()) line.weights[k] = surface.weight(i, j);
        }
        ends[r] = endDerivatives(line, top);
        for (std::size_t k = 0; k <= std::size_t(top); ++k)
            largest[k] = std::max({largest[k], glm::length(ends[r].start[k]), glm::length(ends[r].end[k])});
    }
    int order = top;
    for (std::size_t r = 0; r < rows && order >= 0; ++r)
        order = std::min(order, seamOrderOf(ends[r], largest));
    return order;
}

}  // namespace geom::detail
