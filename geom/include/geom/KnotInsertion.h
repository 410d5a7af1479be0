#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <span>

namespace geom {

/// Inserts the knot value u `times` times (Boehm, The NURBS Book A5.1); the shape is unchanged.
/// u must lie in the curve's domain and its multiplicity may not rise above the degree.
Curve insertKnot(const Curve& curve, double u, int times = 1);

/// Inserts many knots at once (The NURBS Book A5.4); knotsToInsert may come in any order and
/// repeat values. Every value must lie in the domain and no multiplicity may exceed the degree.
Curve refineKnots(const Curve& curve, std::span<const double> knotsToInsert);

/// The same curve on its domain with clamped ends: each end of the domain inserted until it is a
/// knot of multiplicity p, and the knots and poles beyond it dropped (a clamped end stays).
Curve clampEnds(const Curve& curve);

/// The same surface on its domain with clamped ends in both directions (clampEnds per direction).
Surface clampEnds(const Surface& surface);

/// Knot insertion in the u direction of a surface (every column of the net at once).
Surface insertKnotU(const Surface& surface, double u, int times = 1);

/// Knot insertion in the v direction of a surface (every row of the net at once).
Surface insertKnotV(const Surface& surface, double v, int times = 1);

/// Refinement of the u knot vector by many knots at once.
Surface refineKnotsU(const Surface& surface, std::span<const double> knotsToInsert);

/// Refinement of the v knot vector by many knots at once.
Surface refineKnotsV(const Surface& surface, std::span<const double> knotsToInsert);

}  // namespace geom
