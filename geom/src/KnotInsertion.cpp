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

Curve clampEnds(const Curve& curve) {
    validate(curve, "clampEnds");
    const int p = curve.degree;
    const double start = curve.domainStart(), end = curve.domainEnd();
    auto multiplicity = [](const Curve& c, double t) {
        return int(std::count(c.knots.begin(), c.knots.end(), t));
    };
    Curve c = curve;
    for (const double t : {start, end})
        if (const int times = p - multiplicity(c, t); times > 0) c = insertKnot(c, t, times);
    // p + 1 knots at each end: the last p + 1 up to the last copy of the start, the first p + 1
    // from the first copy of the end (the outer one set to the end's value where it was beyond).
    const auto begin = std::find(c.knots.begin(), c.knots.end(), start) + multiplicity(c, start) - 1 - p;
    const auto finish = std::find(c.knots.begin(), c.knots.end(), end) + p + 1;
    std::vector<double> knots(begin, finish);
    knots.front() = start, knots.back() = end;
    const std::size_t from = std::size_t(begin - c.knots.begin()), count = knots.size() - std::size_t(p) - 1;
    std::vector<glm::dvec3> points(c.points.begin() + std::ptrdiff_t(from),
                                   c.points.begin() + std::ptrdiff_t(from + count));
    std::vector<double> weights;
    if (c.rational())
        weights.assign(c.weights.begin() + std::ptrdiff_t(from),
                       c.weights.begin() + std::ptrdiff_t(from + count));
    return Curve(p, std::move(knots), std::move(points), std::move(weights));
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
