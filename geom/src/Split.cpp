#include "geom/Split.h"

#include "geom/ControlNet.h"
#include "geom/GeometryError.h"

#include <algorithm>
#include <string>

namespace geom {
namespace {

struct Halves {
    std::vector<double> leftKnots, rightKnots;
    ControlNet left, right;
};

/// Inserts t up to multiplicity degree and cuts knots and net there.
Halves splitNet(int degree, std::vector<double> knots, ControlNet net, double t, const char* where) {
    const double lo = knots[static_cast<std::size_t>(degree)], hi = knots[net.blocks()];
    if (!(t > lo && t < hi))
        throw GeometryError(std::string(where) + ": parameter " + std::to_string(t) +
                            " is not inside the domain (" + std::to_string(lo) + ", " + std::to_string(hi) +
                            ")");
    const int s = static_cast<int>(std::count(knots.begin(), knots.end(), t));
    if (s > degree)
        throw GeometryError(
            std::string(where) + ": parameter " + std::to_string(t) +
            " is a knot of multiplicity degree + 1 (a break in the curve); split there by hand");
    insertKnotInNet(degree, knots, net, t, degree - s, where);
    // Now t sits at indices r .. r+degree-1.
    const std::size_t p = static_cast<std::size_t>(degree);
    const auto r = static_cast<std::size_t>(std::lower_bound(knots.begin(), knots.end(), t) - knots.begin());
    Halves h;
    h.leftKnots.assign(knots.begin(), knots.begin() + static_cast<std::ptrdiff_t>(r + p));
    h.leftKnots.push_back(t);
    h.rightKnots.push_back(t);
    h.rightKnots.insert(h.rightKnots.end(), knots.begin() + static_cast<std::ptrdiff_t>(r), knots.end());
    h.left.stride = h.right.stride = net.stride;
    h.left.data.assign(net.data.begin(), net.data.begin() + static_cast<std::ptrdiff_t>(r * net.stride));
    h.right.data.assign(net.data.begin() + static_cast<std::ptrdiff_t>((r - 1) * net.stride), net.data.end());
    return h;
}

}  // namespace

std::vector<Curve> splitAtBreaks(const Curve& curve) {
    validate(curve, "splitAtBreaks");
    const std::size_t p = static_cast<std::size_t>(curve.degree), n = curve.points.size();
    // Control points [first, last) with knots [first, last + p + 1): one piece.
    auto piece = [&](std::size_t first, std::size_t last) {
        auto slice = [&](const auto& v, std::size_t from, std::size_t to) {
            return std::vector(v.begin() + long(from), v.begin() + long(to));
        };
        return Curve(curve.degree, slice(curve.knots, first, last + p + 1), slice(curve.points, first, last),
                     curve.weights.empty() ? std::vector<double>{} : slice(curve.weights, first, last));
    };
    std::vector<Curve> pieces;
    std::size_t first = 0;  // the current piece's first control point (and knot)
    for (std::size_t i = p + 1; i < n; ++i) {
        // knots[i .. i + p] equal and inside the domain: points before i and from i on part.
        if (!(curve.knots[i] == curve.knots[i + p] && curve.knots[i] > curve.knots[p] &&
              curve.knots[i] < curve.knots[n]))
            continue;
        pieces.push_back(piece(first, i));
        first = i;
        i += p;
    }
    if (first == 0) return {curve};
    pieces.push_back(piece(first, n));
    return pieces;
}

std::pair<Curve, Curve> split(const Curve& curve, double u) {
    validate(curve, "split");
    Halves h = splitNet(curve.degree, curve.knots, homogeneousNet(curve), u, "split");
    std::pair<Curve, Curve> out{curve, curve};
    out.first.knots = std::move(h.leftKnots);
    out.second.knots = std::move(h.rightKnots);
    setFromNet(out.first, h.left, curve.rational());
    setFromNet(out.second, h.right, curve.rational());
    return out;
}

std::pair<Surface, Surface> split(const Surface& surface, double t, bool alongV) {
    validate(surface, "split");
    Halves h = splitNet(alongV ? surface.degreeV : surface.degreeU, alongV ? surface.knotsV : surface.knotsU,
                        homogeneousNet(surface, alongV), t, "split");
    std::pair<Surface, Surface> out{surface, surface};
    (alongV ? out.first.knotsV : out.first.knotsU) = std::move(h.leftKnots);
    (alongV ? out.second.knotsV : out.second.knotsU) = std::move(h.rightKnots);
    setFromNet(out.first, h.left, alongV, surface.rational());
    setFromNet(out.second, h.right, alongV, surface.rational());
    return out;
}

}  // namespace geom
