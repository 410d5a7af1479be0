#include "geom/KnotInsertion.h"

#include "geom/ControlNet.h"

#include <algorithm>

namespace geom {

Curve insertKnot(const Curve& curve, double u, int times) {
    validate(curve, "insertKnot");
    Curve out = curve;
    ControlNet net = homogeneousNet(curve);
    insertKnotInNet(curve.degree, out.knots, net, u, times, "insertKnot");
    setFromNet(out, net, curve.rational());
    return out;
}

Curve refineKnots(const Curve& curve, std::span<const double> knotsToInsert) {
    validate(curve, "refineKnots");
    Curve out = curve;
    ControlNet net = homogeneousNet(curve);
    refineNet(curve.degree, out.knots, net, {knotsToInsert.begin(), knotsToInsert.end()}, "refineKnots");
    setFromNet(out, net, curve.rational());
    return out;
}

namespace {

int multiplicity(const std::vector<double>& knots, double t) {
    return int(std::count(knots.begin(), knots.end(), t));
}

/// Which knots and poles a clamped form keeps, once each end of the domain has multiplicity p.
struct ClampedRange {
    std::vector<double> knots;
    std::size_t from = 0;   ///< index of the first pole kept
    std::size_t count = 0;  ///< poles kept
};

// p + 1 knots at each end: the last p + 1 up to the last copy of the start, the first p + 1 from
// the first copy of the end (the outer one set to the end's value where it was beyond).
ClampedRange clampedRange(const std::vector<double>& knots, int p, double start, double end) {
    const auto begin = std::find(knots.begin(), knots.end(), start) + multiplicity(knots, start) - 1 - p;
    const auto finish = std::find(knots.begin(), knots.end(), end) + p + 1;
    ClampedRange r;
    r.knots.assign(begin, finish);
    r.knots.front() = start, r.knots.back() = end;
    r.from = std::size_t(begin - knots.begin());
    r.count = r.knots.size() - std::size_t(p) - 1;
    return r;
}

}  // namespace

Curve clampEnds(const Curve& curve) {
    validate(curve, "clampEnds");
    const int p = curve.degree;
    const double start = curve.domainStart(), end = curve.domainEnd();
    Curve c = curve;
    for (const double t : {start, end})
        if (const int times = p - multiplicity(c.knots, t); times > 0) c = insertKnot(c, t, times);
    const ClampedRange r = clampedRange(c.knots, p, start, end);
    const auto first = std::ptrdiff_t(r.from), last = std::ptrdiff_t(r.from + r.count);
    std::vector<glm::dvec3> points(c.points.begin() + first, c.points.begin() + last);
    std::vector<double> weights;
    if (c.rational()) weights.assign(c.weights.begin() + first, c.weights.begin() + last);
    return Curve(p, r.knots, std::move(points), std::move(weights));
}

Surface clampEnds(const Surface& surface) {
    validate(surface, "clampEnds");
    Surface s = surface;
    const double startU = s.domainStartU(), endU = s.domainEndU();
    const double startV = s.domainStartV(), endV = s.domainEndV();
    for (const double u : {startU, endU})
        if (const int times = s.degreeU - multiplicity(s.knotsU, u); times > 0) s = insertKnotU(s, u, times);
    for (const double v : {startV, endV})
        if (const int times = s.degreeV - multiplicity(s.knotsV, v); times > 0) s = insertKnotV(s, v, times);
    const ClampedRange ru = clampedRange(s.knotsU, s.degreeU, startU, endU);
    const ClampedRange rv = clampedRange(s.knotsV, s.degreeV, startV, endV);
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    points.reserve(ru.count * rv.count);
    for (std::size_t i = ru.from; i < ru.from + ru.count; ++i)
        for (std::size_t j = rv.from; j < rv.from + rv.count; ++j) {
            points.push_back(s.point(i, j));
            if (s.rational()) weights.push_back(s.weight(i, j));
        }
    return Surface(s.degreeU, s.degreeV, ru.knots, rv.knots, ru.count, rv.count, std::move(points),
                   std::move(weights));
}

Surface insertKnotU(const Surface& surface, double u, int times) {
    validate(surface, "insertKnotU");
    Surface out = surface;
    ControlNet net = homogeneousNet(surface, false);
    insertKnotInNet(surface.degreeU, out.knotsU, net, u, times, "insertKnotU");
    setFromNet(out, net, false, surface.rational());
    return out;
}

Surface insertKnotV(const Surface& surface, double v, int times) {
    validate(surface, "insertKnotV");
    Surface out = surface;
    ControlNet net = homogeneousNet(surface, true);
    insertKnotInNet(surface.degreeV, out.knotsV, net, v, times, "insertKnotV");
    setFromNet(out, net, true, surface.rational());
    return out;
}

Surface refineKnotsU(const Surface& surface, std::span<const double> knotsToInsert) {
    validate(surface, "refineKnotsU");
    Surface out = surface;
    ControlNet net = homogeneousNet(surface, false);
    refineNet(surface.degreeU, out.knotsU, net, {knotsToInsert.begin(), knotsToInsert.end()}, "refineKnotsU");
    setFromNet(out, net, false, surface.rational());
    return out;
}

Surface refineKnotsV(const Surface& surface, std::span<const double> knotsToInsert) {
    validate(surface, "refineKnotsV");
    Surface out = surface;
    ControlNet net = homogeneousNet(surface, true);
    refineNet(surface.degreeV, out.knotsV, net, {knotsToInsert.begin(), knotsToInsert.end()}, "refineKnotsV");
    setFromNet(out, net, true, surface.rational());
    return out;
}

}  // namespace geom
