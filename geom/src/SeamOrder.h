#pragma once

// Private to geom: how smooth a closed shape is across its seam, so that a reduction can keep it.

#include "geom/Curve.h"
#include "geom/Surface.h"

namespace geom::detail {

/// The derivative order a clamped curve is continuous to across its seam (the end joined to the
/// start): -1 where the ends do not meet, 0 where they only meet, k in 1 .. degree - 1 where the
/// derivatives 1 .. k agree at both ends (order 1 also where only the tangent directions agree).
int seamOrder(const Curve& curve);

/// seamOrder of every control row running along u (`alongU`) or along v of a clamped surface:
/// the lowest, i.e. the order the surface is continuous to across that direction's seam.
int seamOrder(const Surface& surface, bool alongU);

}  // namespace geom::detail
