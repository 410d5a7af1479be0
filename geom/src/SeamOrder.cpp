#include "SeamOrder.h"

#include "UnitScale.h"
#include "geom/Evaluate.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <vector>

namespace geom::detail {

namespace {

// Ends this close (relative to the coordinates) meet; derivatives this close (relative to the
// larger, or to the shape's largest of that order) agree. Generous against the rounding of
// clamping a periodic curve (a few ulps per knot inserted, growing with the order), tight against
// any seam a user would call broken.
constexpr double kMeet = 1e-12;
constexpr double kAgree = 1e-9;

/// A curve's derivatives 0 .. order at both ends of its domain.
struct EndDerivatives {
    std::vector<glm::dvec3> start, end;
};

EndDerivatives endDerivatives(const Curve& curve, int order) {
    return {derivatives(curve, curve.knots[std::size_t(curve.degree)], order),
            derivatives(curve, curve.knots[curve.points.size()], order)};
}

/// seamOrder, with floor[k]: the size below which a k-th derivative counts as rounding (a
/// surface's collapsed row: a nose's derivatives round its point are a few ulps of nothing).
int seamOrderOf(const Curve& curve, const EndDerivatives& d, const std::vector<double>& floor) {
    double extent = 0.0;
    for (const glm::dvec3& q : curve.points) extent = std::max(extent, largestCoordinate(q));
    if (!(glm::length(d.start[0] - d.end[0]) <= kMeet * extent)) return -1;
    const int top = int(d.start.size()) - 1;
    auto agree = [](const glm::dvec3& a, const glm::dvec3& b, double least) {
        const double scale = std::max({glm::length(a), glm::length(b), least});
        return !(scale > 0.0) || glm::length(a - b) <= kAgree * scale;
    };
    for (int k = 1; k <= top; ++k) {
        if (agree(d.start[std::size_t(k)], d.end[std::size_t(k)], floor[std::size_t(k)])) continue;
        // Tangents of different lengths in one direction: geometrically smooth (G1).
        const double a = glm::length(d.start[1]), b = glm::length(d.end[1]);
        if (k == 1 && a > 0.0 && b > 0.0 && agree(d.start[1] / a, d.end[1] / b, 0.0)) return 1;
        return k - 1;
    }
    return top;
}

}  // namespace

int seamOrder(const Curve& curve) {
    const int top = std::max(0, curve.degree - 1);
    return seamOrderOf(curve, endDerivatives(curve, top), std::vector<double>(std::size_t(top) + 1, 0.0));
}

int seamOrder(const Surface& surface, bool alongU) {
    const std::size_t rows = alongU ? surface.countV : surface.countU;
    const std::size_t length = alongU ? surface.countU : surface.countV;
    std::vector<Curve> lines(rows);
    std::vector<EndDerivatives> ends(rows);
    const int top = std::max(0, (alongU ? surface.degreeU : surface.degreeV) - 1);
    std::vector<double> largest(std::size_t(top) + 1, 0.0);
    for (std::size_t r = 0; r < rows; ++r) {
        Curve& line = lines[r];
        line.degree = alongU ? surface.degreeU : surface.degreeV;
        line.knots = alongU ? surface.knotsU : surface.knotsV;
        for (std::size_t k = 0; k < length; ++k) {
            const std::size_t i = alongU ? k : r, j = alongU ? r : k;
            line.points.push_back(surface.point(i, j));
            if (surface.rational()) line.weights.push_back(surface.weight(i, j));
        }
        ends[r] = endDerivatives(line, top);
        for (std::size_t k = 0; k <= std::size_t(top); ++k)
            largest[k] = std::max({largest[k], glm::length(ends[r].start[k]), glm::length(ends[r].end[k])});
    }
    int order = top;
    for (std::size_t r = 0; r < rows && order >= 0; ++r)
        order = std::min(order, seamOrderOf(lines[r], ends[r], largest));
    return order;
}

}  // namespace geom::detail
