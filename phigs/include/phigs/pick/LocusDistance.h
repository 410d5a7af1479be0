#pragma once

#include "phigs/traverse/DrawItem.h"

#include <glm/vec3.hpp>

namespace phigs {

/// How far a draw item's locus lies from a point in world coordinates, for INCREMENTAL SPATIAL
/// SEARCH. The locus: a polyline's or curve's segments, a polymarker's points (markers have no
/// size in world coordinates), a fill area set's even-odd interior and boundary whatever its
/// interior style, a mesh's triangles, a text's strokes, an annotation text's reference point.
/// With `clip` the item's model clipping volume cuts the locus first. +infinity when nothing is
/// left.
double locusDistance(const DrawItem& item, const glm::dvec3& point, bool clip);

}  // namespace phigs
