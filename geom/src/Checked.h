#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>

// Private to geom: the checks a per-point entry (evaluate, derivatives, normal, curvature) makes
// instead of a full validate(), which would cost O(control points) per point: the sizes agree
// and the domain is finite and not empty (constant time), the knots of the span it reads are in
// order (O(degree)), the parameter is finite and in the domain, and the result is finite (which
// catches a non-finite point or a non-positive weight among those it read).
namespace geom::detail {

void checkShape(const Curve& curve, const char* where);
void checkShape(const Surface& surface, const char* where);

/// The parameter `name`, finite and inside [start, end] up to rounding (1e-9 of the width, and
/// clamped there); else GeometryError naming where and name.
double checkedParameter(double value, double start, double end, const char* where, const char* name);

/// knots[span - degree + 1 .. span + degree] non-decreasing (no NaN), knots[span] < knots[span + 1]:
/// the window the basis functions of one span read.
void checkSpan(std::span<const double> knots, std::size_t span, int degree, const char* where);

/// Throws when a computed point or vector is not finite: the data it came from is not.
void checkResult(const glm::dvec3& value, const char* where);

}  // namespace geom::detail
