#pragma once

#include "geom/Curve.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace phigs::hardcopy {

/// Points of a B-spline curve over [start, end] (equal: the whole domain), in its modelling
/// coordinates, whose chords stay within `tolerance` points of the curve on the page: each knot
/// span starts with four pieces, and a piece is halved while its middle or quarter points stray
/// from the chord by more than the tolerance (at most 2^12 pieces per span). `modelToPage` maps
/// modelling coordinates to homogeneous page points (x / w, y / w in points); a piece reaching
/// behind the eye (w <= 0) is left as it is.
std::vector<glm::dvec3> refineCurve(const geom::Curve& curve, double start, double end,
                                    const glm::dmat4& modelToPage, double tolerance);

}  // namespace phigs::hardcopy
