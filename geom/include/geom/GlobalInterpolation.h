#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace geom {

/// How interpolated data meet themselves in one parameter direction: Open ends are clamped;
/// Periodic closes the curve with C^(degree-1) continuity across the seam.
enum class Closure { Open, Periodic };

/// The most points uniformParameters and the reference shapes (ReferenceShapes.h) make at once.
inline constexpr std::size_t kMaxSamplePoints = std::size_t{1} << 20;

/// Parameters spaced evenly on [0, 1], one per point (2 <= count <= kMaxSamplePoints), for Open data.
std::vector<double> uniformParameters(std::size_t count);

/// Chord-length parameters of a polyline, normalized to [0, 1]. Open: one value per point, 0
/// first and 1 last. Periodic: the points do not repeat the first one; the closing chord back to
/// it counts, and the answer has one more value (1) for the closing point. Throws GeometryError
/// when the polyline has no length, a length that overflows a double, or two consecutive points
/// coincide.
std::vector<double> chordLengthParameters(std::span<const glm::dvec3> points, Closure closure);

/// Knots for interpolation at `parameters` (as chordLengthParameters returns them). Open: clamped,
/// interior knots averaged from the parameters (The NURBS Book eq. 9.8). Periodic (odd degree
/// only): the parameters themselves are the domain knots, continued periodically by `degree`
/// knots at each end, so the domain is [knots[degree], knots[count]] = [parameters.front(),
/// parameters.back()]. Throws GeometryError naming the index of a parameter that is not finite or
/// does not increase, a degree below 1, or a closure other than Open and Periodic.
std::vector<double> interpolationKnots(std::span<const double> parameters, int degree, Closure closure);

/// The B-spline curve through `points` at `parameters`. Open: points.size() control points.
/// Periodic: points.size() + degree control points whose first `degree` equal the last
/// `degree`, so C(parameters[k]) = points[k] and the curve is C^(degree-1) across the seam.
Curve interpolateCurve(std::span<const glm::dvec3> points, std::span<const double> parameters, int degree,
                       Closure closure);

/// interpolateCurve at the chord-length parameters of the points.
Curve interpolateCurve(std::span<const glm::dvec3> points, int degree, Closure closure);

/// Parameters of a grid of data points in both directions (u: the slow index).
struct GridParameters {
    std::vector<double> u;
    std::vector<double> v;
};

/// Chord-length parameters of a countU x countV grid (point (i, j) = grid[i * countV + j]),
/// averaged over all rows and columns as in The NURBS Book A9.3. Rows or columns of zero length
/// (a pole: a nose tip section collapsed to one point) are left out of the average.
GridParameters chordLengthGridParameters(std::span<const glm::dvec3> grid, std::size_t countU,
                                         std::size_t countV, Closure closureU, Closure closureV);

/// Global surface interpolation (The NURBS Book A9.4): a B-spline surface with
/// S(parameters.u[i], parameters.v[j]) = grid[i * countV + j], built by curve interpolation
/// through the columns and then through the rows of the intermediate control net. A periodic
/// direction has count + degree control points, wrapped as interpolateCurve says.
Surface interpolateSurface(std::span<const glm::dvec3> grid, std::size_t countU, std::size_t countV,
                           const GridParameters& parameters, int degreeU, int degreeV, Closure closureU,
                           Closure closureV);

/// interpolateSurface at the averaged chord-length parameters of the grid.
Surface interpolateSurface(std::span<const glm::dvec3> grid, std::size_t countU, std::size_t countV,
                           int degreeU, int degreeV, Closure closureU, Closure closureV);

}  // namespace geom
