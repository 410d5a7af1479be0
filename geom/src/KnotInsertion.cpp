#include "geom/KnotInsertion.h"

#include "geom/ControlNet.h"

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
