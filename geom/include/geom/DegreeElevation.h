#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

namespace geom {

/// The same curve of degree + times: every distinct knot's multiplicity rises by times, so
/// the continuity at each knot is kept. The control points are blossoms of the raised Bezier
/// segments at the new knots (no linear solve): the result matches the input to rounding (about
/// 1e-15 of its size) at every degree up to 64. GeometryError for times < 0, a degree above 64,
/// or an interior knot of multiplicity degree + 1 (a break: elevate splitAtBreaks' pieces instead).
Curve elevateDegree(const Curve& curve, int times = 1);

/// Degree elevation of a surface in u (alongV false) or in v, with the same errors.
Surface elevateDegree(const Surface& surface, int times, bool alongV);

}  // namespace geom
