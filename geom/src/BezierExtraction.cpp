#include "geom/BezierExtraction.h"

#include "geom/ControlNet.h"

#include <algorithm>

namespace geom {
namespace {

/// The knots to insert so every distinct knot value in [lo, hi] reaches multiplicity `degree`.
std::vector<double> knotsToFillSpans(const std::vector<double>& knots, int degree, double lo, double hi) {
    std::vector<double> extra;
    for (std::size_t i = 0; i < knots.size();) {
        std::size_t j = i;
        while (j < knots.size() && knots[j] == knots[i]) ++j;
        if (knots[i] >= lo && knots[i] <= hi)
            for (int m = static_cast<int>(j - i); m < degree; ++m) extra.push_back(knots[i]);
        i = j;
    }
    return extra;
}

/// The spans k of a refined knot vector whose Bézier points are blocks k-p..k, with the index
/// of the span in the original knot vector holding the same interval.
struct SpanMap {
    std::size_t refined;
    std::size_t original;
};

std::vector<SpanMap> bezierSpans(const std::vector<double>& refined, const std::vector<double>& original,
                                 int degree, std::size_t refinedCount) {
    std::vector<SpanMap> spans;
    const std::size_t p = static_cast<std::size_t>(degree);
    for (std::size_t k = p; k < refinedCount; ++k) {
        if (!(refined[k] < refined[k + 1])) continue;
        const auto it = std::upper_bound(original.begin(), original.end(), refined[k]);
        spans.push_back({k, static_cast<std::size_t>(it - original.begin()) - 1});
    }
    return spans;
}

std::vector<double> bezierKnots(int degree, double a, double b) {
    std::vector<double> k(2 * static_cast<std::size_t>(degree + 1), a);
    std::fill(k.begin() + degree + 1, k.end(), b);
    return k;
}

}  // namespace

std::vector<BezierCurvePiece> extractBezier(const Curve& curve) {
    validate(curve, "extractBezier");
    std::vector<double> knots = curve.knots;
    ControlNet net = homogeneousNet(curve);
    refineNet(curve.degree, knots, net,
              knotsToFillSpans(knots, curve.degree, curve.domainStart(), curve.domainEnd()), "extractBezier");
    const std::size_t p = static_cast<std::size_t>(curve.degree);
    std::vector<BezierCurvePiece> pieces;
    for (const SpanMap& s : bezierSpans(knots, curve.knots, curve.degree, net.blocks())) {
        BezierCurvePiece piece;
        piece.start = knots[s.refined];
        piece.end = knots[s.refined + 1];
        piece.span = s.original;
        piece.curve.degree = curve.degree;
        piece.curve.knots = bezierKnots(curve.degree, piece.start, piece.end);
        ControlNet part;
        part.data.assign(net.data.begin() + static_cast<std::ptrdiff_t>(s.refined - p),
                         net.data.begin() + static_cast<std::ptrdiff_t>(s.refined + 1));
        setFromNet(piece.curve, part, curve.rational());
        pieces.push_back(std::move(piece));
    }
    return pieces;
}

std::vector<BezierSurfacePiece> extractBezier(const Surface& surface) {
    validate(surface, "extractBezier");
    std::vector<double> knotsU = surface.knotsU;
    std::vector<double> knotsV = surface.knotsV;
    ControlNet netU = homogeneousNet(surface, false);
    refineNet(surface.degreeU, knotsU, netU,
              knotsToFillSpans(knotsU, surface.degreeU, surface.domainStartU(), surface.domainEndU()),
              "extractBezier (u)");
    Surface refined = surface;
    refined.knotsU = knotsU;
    setFromNet(refined, netU, false, true);
    ControlNet netV = homogeneousNet(refined, true);
    refineNet(surface.degreeV, knotsV, netV,
              knotsToFillSpans(knotsV, surface.degreeV, surface.domainStartV(), surface.domainEndV()),
              "extractBezier (v)");
    // netV holds blocks along v, each block one column of countU homogeneous points.
    const std::size_t countU = netV.stride;
    const std::size_t countV = netV.blocks();
    const std::size_t p = static_cast<std::size_t>(surface.degreeU);
    const std::size_t q = static_cast<std::size_t>(surface.degreeV);
    const auto spansU = bezierSpans(knotsU, surface.knotsU, surface.degreeU, countU);
    const auto spansV = bezierSpans(knotsV, surface.knotsV, surface.degreeV, countV);
    std::vector<BezierSurfacePiece> pieces;
    pieces.reserve(spansU.size() * spansV.size());
    for (const SpanMap& su : spansU)
        for (const SpanMap& sv : spansV) {
            BezierSurfacePiece piece;
            piece.u0 = knotsU[su.refined];
            piece.u1 = knotsU[su.refined + 1];
            piece.v0 = knotsV[sv.refined];
            piece.v1 = knotsV[sv.refined + 1];
            piece.spanU = su.original;
            piece.spanV = sv.original;
            Surface& patch = piece.surface;
            patch.degreeU = surface.degreeU;
            patch.degreeV = surface.degreeV;
            patch.knotsU = bezierKnots(surface.degreeU, piece.u0, piece.u1);
            patch.knotsV = bezierKnots(surface.degreeV, piece.v0, piece.v1);
            ControlNet part;
            part.stride = q + 1;
            part.data.resize((p + 1) * (q + 1));
            for (std::size_t i = 0; i <= p; ++i)
                for (std::size_t j = 0; j <= q; ++j)
                    part.data[i * (q + 1) + j] =
                        netV.data[(sv.refined - q + j) * countU + (su.refined - p + i)];
            setFromNet(patch, part, false, surface.rational());
            pieces.push_back(std::move(piece));
        }
    return pieces;
}

}  // namespace geom
