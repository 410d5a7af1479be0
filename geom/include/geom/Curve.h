#pragma once

#include <glm/vec3.hpp>

#include <string_view>
#include <vector>

namespace geom {

/// A non-uniform (rational) B-spline curve: degree, knot vector, control points and, when
/// rational, one positive weight per control point (empty weights mean polynomial).
struct Curve {
    int degree = 0;
    std::vector<double> knots;
    std::vector<glm::dvec3> points;
    std::vector<double> weights;

    Curve() = default;
    /// Builds the curve and checks it with validate(); throws GeometryError on bad input.
    Curve(int degree, std::vector<double> knots, std::vector<glm::dvec3> points,
          std::vector<double> weights = {});

    bool rational() const { return !weights.empty(); }
    double weight(std::size_t i) const { return weights.empty() ? 1.0 : weights[i]; }
    /// The parameter interval [knots[degree], knots[n]] on which the curve is defined.
    double domainStart() const { return knots[static_cast<std::size_t>(degree)]; }
    double domainEnd() const { return knots[points.size()]; }
};

/// Checks every rule a curve must keep: degree >= 1, knots.size() == points.size() + degree + 1,
/// non-decreasing knots with a non-empty domain and a finite span (last - first), multiplicity <=
/// degree + 1, finite numbers, weights absent or one per point, each at least the smallest normal
/// double (2.2e-308). Throws GeometryError naming the rule and index, after `where` (the calling
/// function's name) when given. Every geom entry point checks its curves so (per-point evaluation
/// checks the sizes, the domain and knot span, the span it reads and its result instead).
void validate(const Curve& curve, std::string_view where = {});

}  // namespace geom
