#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

namespace geom {

/// The same curve of degree + times: every distinct knot's multiplicity rises by times, so
/// the continuity at each knot is kept, and the control points are found by collocation at the
/// Greville abscissae (exact: the old spline lies in the new spline space), one banded solve.
/// GeometryError for times < 0 or a degree above 64.
Curve elevateDegree(const Curve& curve, int times = 1);

/// Degree elevation of a surface in u (alongV false) or in v.
Surface elevateDegree(const Surface& surface, int times, bool alongV);

}  // namespace geom
