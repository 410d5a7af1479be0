#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <cstddef>
#include <vector>

namespace geom {

/// One Bézier piece of a B-spline curve. The piece keeps the original parameter interval:
/// its knots are start (degree+1 times) then end (degree+1 times), so piece and curve agree
/// at the same u. span is the index s of the original curve's knot span knots[s] <= u < knots[s+1].
struct BezierCurvePiece {
    Curve curve;
    double start = 0.0;
    double end = 0.0;
    std::size_t span = 0;
};

/// Splits a curve into its polynomial (or rational) Bézier pieces, one per non-empty knot span
/// of the domain, in increasing parameter order. Works for clamped and unclamped curves.
std::vector<BezierCurvePiece> extractBezier(const Curve& curve);

/// One Bézier patch of a B-spline surface over [u0, u1] x [v0, v1] (original parameters, as for
/// curves); spanU and spanV are the knot span indices of the original surface.
struct BezierSurfacePiece {
    Surface surface;
    double u0 = 0.0, u1 = 0.0, v0 = 0.0, v1 = 0.0;
    std::size_t spanU = 0, spanV = 0;
};

/// Splits a surface into its Bézier patches, ordered with the u span slow and the v span fast.
std::vector<BezierSurfacePiece> extractBezier(const Surface& surface);

}  // namespace geom
