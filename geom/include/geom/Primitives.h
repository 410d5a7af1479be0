#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <glm/vec3.hpp>

#include <vector>

namespace geom {

/// The exact rational circle of the given radius about center in the plane of xAxis and yAxis:
/// degree 2, nine control points, parameter [0, 1] from center + r * xAxis / |xAxis|, turning
/// towards yAxis. The axes need not be unit length or perpendicular (yAxis's part perpendicular
/// to xAxis is taken); zero, parallel or non-finite axes are refused.
Curve makeCircle(const glm::dvec3& center, const glm::dvec3& xAxis, const glm::dvec3& yAxis, double radius);

/// The exact rational arc of the given radius about center, from startAngle to endAngle
/// (radians, counterclockwise from xAxis towards yAxis, taken as makeCircle takes them;
/// 0 < endAngle - startAngle <= 2 pi): degree 2, one rational segment per quarter turn or less,
/// parameter [0, 1].
Curve makeArc(const glm::dvec3& center, const glm::dvec3& xAxis, const glm::dvec3& yAxis, double radius,
              double startAngle, double endAngle);

/// A closed (periodic) curve of the given degree through the cyclic control polygon `points`:
/// uniform unclamped knots and the first `degree` points repeated at the end, so the curve
/// closes with continuity C^(degree-1); domain [0, 1]. Weights, when given, wrap the same way.
Curve makePeriodicCurve(int degree, const std::vector<glm::dvec3>& points,
                        const std::vector<double>& weights = {});

/// The surface swept by a profile curve given in the xz-plane (x = distance from the axis, y
/// ignored) turning once about the z axis: u follows the profile, v the full turn (knots [0,1]).
/// A control point with negative x (a profile crossing the axis) is refused.
Surface makeRevolution(const Curve& profile);

/// Sphere of the given radius about the origin; u runs from the south pole to the north pole.
Surface makeSphere(double radius);
/// Cylinder of the given radius about the z axis from z = 0 to z = height.
Surface makeCylinder(double radius, double height);
/// Cone with base radius at z = 0 and apex at z = height.
Surface makeCone(double radius, double height);
/// Torus about the z axis: tube radius minor around a circle of radius major.
Surface makeTorus(double major, double minor);

}  // namespace geom
