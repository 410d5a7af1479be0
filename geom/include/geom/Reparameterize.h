#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

namespace geom {

/// The same curve traversed the other way: C'(u) = C(start + end - u), on the same domain.
Curve reverse(const Curve& curve);
/// The surface with its u (alongV false) or v direction reversed.
Surface reverse(const Surface& surface, bool alongV);

/// The same curve on the domain [start, end] by the affine map of its knots (start < end).
Curve reparameterize(const Curve& curve, double start, double end);
/// The same surface on the domain [u0, u1] x [v0, v1].
Surface reparameterize(const Surface& surface, double u0, double u1, double v0, double v1);

}  // namespace geom
