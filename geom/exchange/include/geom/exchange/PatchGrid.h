#pragma once
// A surface split into patches (one face per knot span pair in a file) and joined again.

#include "geom/Surface.h"

#include <optional>
#include <vector>

namespace geom::exchange {

/// One surface from pieces that tile a grid of parameter rectangles (a patch per rectangle, as
/// extractBezier gives them, or pieces of several spans each): the pieces are cut into Bézier
/// patches, joined with C0 knots, every interior knot is removed as often as the surface allows
/// within `tolerance` but kept once (each patch edge was a knot; The NURBS Book A5.8, each removal
/// measured by putting the knot back), and a direction in which the surface closes smoothly is
/// made periodic by construction (makePeriodic). Where weights span orders of magnitude the
/// removals allow at least the rounding that cutting the patches left (a multiple of machine
/// epsilon times the poles' reach times the weight ratio). nullopt where the
/// pieces do not tile a grid: other degrees or rationality, a gap or overlap, or a patch edge
/// farther than `tolerance` from its neighbour's.
std::optional<Surface> joinPatches(const std::vector<Surface>& pieces, double tolerance);

/// The surface unclamped in u (alongV false) or v to the periodic extension of its knots (the
/// gaps beyond each end repeat those inside the other, as OpenCASCADE's periodic knots do), when
/// its last `degree` poles then repeat its first (they are made equal) and the surface so made,
/// clamped again, is within `tolerance` of this one: the surface closes with continuity
/// C^(degree-1). nullopt when that direction is not clamped at both
/// ends, has fewer spans than its degree, or does not close so.
std::optional<Surface> makePeriodic(const Surface& surface, bool alongV, double tolerance);

}  // namespace geom::exchange
