#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace geom {

// Each function here throws GeometryError, naming itself, for a negative degree, knots too few
// for the span (or the count) it reads, an output span too small, a parameter that is not finite
// or a negative derivative order: comparisons only, cheap enough for every evaluated point.

/// Index s of the knot span with knots[s] <= u < knots[s+1], clamped into
/// [degree, controlCount - 1] so the domain end belongs to the last non-empty span.
std::size_t findSpan(int degree, std::span<const double> knots, std::size_t controlCount, double u);

/// The degree+1 non-zero basis values N_{span-degree..span}(u) written to out (size >= degree+1).
void basisFunctions(std::size_t span, double u, int degree, std::span<const double> knots,
                    std::span<double> out);

/// Non-zero basis functions and their derivatives up to `order`: out[k * (degree+1) + j] is the
/// k-th derivative of N_{span-degree+j} at u. Derivatives above the degree are zero.
void basisDerivatives(std::size_t span, double u, int degree, std::span<const double> knots, int order,
                      std::span<double> out);

/// The degree+1 non-zero basis values and their first derivatives at u (each span of size >=
/// degree+1): the common case of basisDerivatives, from the degree-1 values without its tables.
void basisWithFirstDerivatives(std::size_t span, double u, int degree, std::span<const double> knots,
                               std::span<double> values, std::span<double> firsts);

/// Multiplicity of the knot value u in knots (exact comparison).
int knotMultiplicity(std::span<const double> knots, double u);

}  // namespace geom
