#pragma once

#include "geom/Curve.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace geom {

/// How data points are given curve parameters (the ACSYNT curve-mapping thesis's `param`: 1, 2, 3).
enum class Parameterization { Uniform = 1, ChordLength = 2, Centripetal = 3 };

/// Continuity of the interpolating cubic at a data point (the thesis's codes 0, 1, 2).
enum class Continuity { C0 = 0, C1 = 1, C2 = 2 };

/// Data for Fleming's constraint-based cubic interpolation (the ACSYNT curve-mapping thesis, §5.4.2): points,
/// one continuity per point and the tangent constraints in point order (2 per C0 point: incoming then
/// outgoing derivative; 1 per C1 point). Tangents are derivatives dC/dt in the chosen, un-normalised
/// parameter (uniform: 1 per point, chord length: distance, centripetal: its square root). A closed curve
/// repeats its first point at the end; that closing point takes its continuity and constraints from the first
/// point.
struct InterpolationData {
    std::vector<glm::dvec3> points;
    std::vector<Continuity> continuities;  ///< empty: C2 everywhere
    std::vector<glm::dvec3> tangents;
    Parameterization parameterization = Parameterization::ChordLength;
    bool closed = false;
};

/// Number of tangent constraints the continuities ask for (2 per C0, 1 per C1, in point order,
/// counting the closing point of a closed curve like any other point).
std::size_t constraintCount(const std::vector<Continuity>& continuities);

/// The thesis's knot count: points + 6 + 2 * (interior C0 points) + (interior C1 points), where
/// the end points of an open curve and the closing point of a closed one are not interior.
std::size_t interpolationKnotCount(const std::vector<Continuity>& continuities, std::size_t pointCount);

/// The curve parameter given to each data point (starting at 0, not normalised); GeometryError for a
/// `kind` outside the enumeration.
std::vector<double> interpolationParameters(const std::vector<glm::dvec3>& points, Parameterization kind);

/// The cubic B-spline through the data with the asked continuities (knot multiplicity 1, 2, 3
/// for C2, C1, C0) and tangent constraints. Open C2 ends get zero curvature, C1/C0 ends the
/// given tangent (for a C0 end the one on the curve's side). A closed curve is periodic (an
/// unclamped knot vector, last 3 control points repeat the first 3) when its closing point is
/// C2, and clamped at the closing point with the given tangent(s) when it is C1 or C0.
/// Throws GeometryError for inconsistent sizes, coincident consecutive points, an unclosed
/// closed curve or a singular system.
Curve interpolateCubic(const InterpolationData& data);

}  // namespace geom
