#pragma once

#include "geom/Curve.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace geom {

/// How much one interior knot matters: the l-infinity error of removing one occurrence of it
/// and inserting it again (Lyche and Morken's knot removal weight).
struct KnotSignificance {
    std::size_t index = 0;  ///< index of the knot's last occurrence in the knot vector
    double value = 0.0;     ///< the knot value
    int multiplicity = 0;   ///< multiplicity of the value before removal
    double weight = 0.0;    ///< the error; 0 means the knot can be removed exactly
};

/// The removal weight of the knot at knotIndex (any occurrence of an interior value) of a spline
/// with `count` coefficients in points[i * sequences + s] for s < sequences: the largest weight
/// over the sequences. Works for every degree and multiplicity; points may be homogeneous
/// coordinates scaled by weights (the caller decides). Throws GeometryError for a knot that is
/// not interior.
double knotRemovalWeight(int degree, std::span<const double> knots, std::span<const glm::dvec3> points,
                         std::size_t sequences, std::size_t knotIndex);

/// The removal weight of the knot at knotIndex of a polynomial curve (see above). Rational curves
/// are measured on their homogeneous control points (w*P, w).
double knotRemovalWeight(const Curve& curve, std::size_t knotIndex);

/// Every distinct interior knot value with its weight, least significant first (ties by index).
std::vector<KnotSignificance> rankKnots(int degree, std::span<const double> knots,
                                        std::span<const glm::dvec3> points, std::size_t sequences);

/// rankKnots for a curve.
std::vector<KnotSignificance> rankKnots(const Curve& curve);

}  // namespace geom
