#pragma once

#include "geom/Surface.h"

namespace geom::exchange {

/// A surface made a polynomial bicubic, and how.
struct BicubicSurface {
    Surface surface;
    bool exact = true;    ///< false: approximated
    double maxError = 0;  ///< the approximation's measured error, model units (0 when exact)
};

/// The surface as a polynomial bicubic B-spline on the same parameters: exact for a polynomial
/// surface of degree 3 or less in each direction (degree elevation); otherwise (rational, or of
/// higher degree) cut at its knots where it is less than C3, each piece the bicubic
/// interpolating it at 4, 8, 16, ... points per knot span each way (The NURBS Book A9.4) until
/// every piece is within `tolerance` halfway between them (that distance is maxError), the pieces
/// joined with C0 knots. Throws GeometryError when 513 points a direction are not enough.
BicubicSurface toBicubic(const Surface& surface, double tolerance);

}  // namespace geom::exchange
