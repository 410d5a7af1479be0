#pragma once

#include "geom/Curve.h"
#include "geom/Surface.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <span>
#include <vector>

namespace geom {

/// One evaluated grid point: position, first partial derivatives and unit normal.
struct GridSample {
    glm::dvec3 point{0.0}, su{0.0}, sv{0.0}, normal{0.0};
};

/// The fast batch path: a surface evaluated on a tensor grid of parameters. Basis values and
/// their derivatives are computed once per u value and once per v value, and for each u row
/// the net is collapsed once into a row curve (and its u derivative), so a grid point costs a
/// (degreeV+1)-term sum; the idea of Pickelmann's (1985) precomputed per-span matrices.
class GridEvaluator {
public:
    explicit GridEvaluator(const Surface& surface);

    /// out[i * vs.size() + j] receives the sample at (us[i], vs[j]); parameters are clamped into
    /// the domain and need not be sorted. out must hold us.size() * vs.size() samples.
    void evaluate(std::span<const double> us, std::span<const double> vs, std::span<GridSample> out) const;

    /// Convenience form returning the samples.
    std::vector<GridSample> evaluate(std::span<const double> us, std::span<const double> vs) const;

private:
    Surface surface_;
    std::vector<glm::dvec4> net_;
};

/// Points of a curve at many parameters (basis values per parameter, no allocation per point).
/// Each parameter is checked as evaluate() checks it: GeometryError names the one outside the
/// domain (beyond rounding) or a point that is not finite.
std::vector<glm::dvec3> evaluateMany(const Curve& curve, std::span<const double> us);

}  // namespace geom
