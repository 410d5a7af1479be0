#pragma once

#include "geom/Curve.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace geom {

/// The result of exact knot removal: the curve and how many occurrences were removed.
struct ExactKnotRemoval {
    Curve curve;
    int removed = 0;
};

/// Removes the interior knot value u up to `times` times where the curve allows it (The NURBS
/// Book A5.8): each removal is kept only if the curve moves by at most `tolerance` (a distance
/// in model units). For rational curves the bound on the homogeneous points' change (dX, dw),
/// taken about the centre of the points' box, is |dX| + R |dw| <= tolerance (wmin - |dw|), R the
/// points' largest distance from that centre: the book's eq. 5.30 made invariant under moving,
/// scaling and reweighting the curve, and keeping every weight positive. Stops at the first
/// removal that would move the curve more.
/// Throws GeometryError when u is not an interior knot, times < 1 or tolerance < 0.
ExactKnotRemoval removeKnot(const Curve& curve, double u, int times = 1, double tolerance = 1e-9);

/// Which control points a least-squares removal must leave alone.
struct EndConditions {
    /// Keep the first and last fixedDerivatives+1 control points at each end: 0 keeps the end
    /// points (clamped ends interpolated), 1 also the end tangents, 2 also the curvature. The
    /// first and last fixedDerivatives interior knots are kept too (the derivatives depend on them).
    /// Any non-negative value is taken: one that holds every control point leaves the curve whole.
    int fixedDerivatives = 0;
};

/// A spline after least-squares knot removal, with the coefficient range that was refitted.
struct LeastSquaresRemoval {
    std::vector<double> knots;
    std::vector<glm::dvec3> points;  ///< same layout as the input: points[i * sequences + s]
    std::size_t firstChanged = 0;    ///< first refitted coefficient index of the new spline
    std::size_t lastChanged = 0;     ///< last refitted coefficient index
    double changedFrom = 0.0;        ///< the parameter interval where the spline may differ
    double changedTo = 0.0;
};

/// Removes one occurrence of each value in `values` (distinct interior knots near each other)
/// from a polynomial spline with `sequences` coefficient sequences sharing one knot vector
/// (one for a curve, every isoparametric curve of a surface at once). The new coefficients on a
/// local window (the coefficients the removal touches plus `margin` more on each side) minimise
/// the scaled discrete l2 norm of Lyche and Morken, sum_j (t_{j+p+1}-t_j)/(p+1) |d_j - (A c)_j|^2,
/// where A is the knot insertion matrix from the reduced to the current knots; the other
/// coefficients are kept. Throws GeometryError when a value is not an interior knot or the end
/// conditions leave nothing free to fit.
LeastSquaresRemoval removeKnotsLeastSquares(int degree, std::span<const double> knots,
                                            std::span<const glm::dvec3> points, std::size_t sequences,
                                            std::span<const double> values, const EndConditions& ends = {},
                                            int margin = 1);

/// Least-squares removal of one occurrence of each value from a polynomial curve (see above).
Curve removeKnotsLeastSquares(const Curve& curve, std::span<const double> values,
                              const EndConditions& ends = {}, int margin = 1);

}  // namespace geom
