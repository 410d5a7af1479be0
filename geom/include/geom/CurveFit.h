#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace geom {

/// Parameters spaced evenly on [0, 1], one per point (count >= 2).
std::vector<double> uniformParameters(std::size_t count);

/// Chord-length parameters on [0, 1] for the points (The NURBS Book eq. 9.5); points that
/// coincide all along give uniform parameters.
std::vector<double> chordLengthParameters(std::span<const glm::dvec3> points);

/// Clamped knot vector for interpolation at the given parameters by averaging (The NURBS Book
/// eq. 9.8): params.size() control points of `degree`.
std::vector<double> averagedKnots(std::span<const double> params, int degree);

/// The clamped B-spline of `degree` with params.size() control points through points[i] at
/// params[i] (global interpolation, The NURBS Book A9.1, knots by averagedKnots). params must be
/// strictly increasing, start at 0 and end at 1. Throws GeometryError on bad input.
Curve interpolateCurve(std::span<const glm::dvec3> points, std::span<const double> params, int degree);

/// The clamped tensor-product B-spline of degrees (degreeU, degreeV) through a grid of points:
/// grid[i * paramsV.size() + j] at (paramsU[i], paramsV[j]), by interpolating along v and then
/// along u (The NURBS Book A9.4); the net has paramsU.size() x paramsV.size() control points.
Surface interpolateSurface(std::span<const glm::dvec3> grid, std::span<const double> paramsU,
                           std::span<const double> paramsV, int degreeU, int degreeV);

}  // namespace geom
