#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <utility>
#include <vector>

namespace geom {

/// Splits a curve at u strictly inside its domain into the curves over [start, u] and [u, end]
/// (knot insertion up to multiplicity degree, then both halves clamped at u).
std::pair<Curve, Curve> split(const Curve& curve, double u);
/// The continuous pieces of a curve, in order: it is cut at each knot inside its domain of
/// multiplicity degree + 1, a break the curve jumps across (its control points fall apart there).
/// A curve without breaks comes back alone.
std::vector<Curve> splitAtBreaks(const Curve& curve);

/// Splits a surface at u (alongV false) or at v (alongV true) into its two halves.
std::pair<Surface, Surface> split(const Surface& surface, double t, bool alongV);

}  // namespace geom
