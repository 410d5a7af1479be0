#include "geom/Curvature.h"
#include "NumberText.h"

#include "geom/Evaluate.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace geom {

SurfaceCurvature curvature(const Surface& surface, double u, double v) {
    const SurfaceDerivatives d = derivatives(surface, u, v, 2);
    const glm::dvec3 su = d.at(1, 0), sv = d.at(0, 1);
    const double E = glm::dot(su, su), F = glm::dot(su, sv), G = glm::dot(sv, sv);
    // EG - F^2 as |su x sv|^2, without the cancellation of the difference. The normal is
    // undefined where the cross product vanishes against the derivatives' own size: at a
    // collapsed edge (a sphere's pole) rounding leaves a cross product of noise, whatever the
    // surface's scale.
    const glm::dvec3 cross = glm::cross(su, sv);
    const double det = glm::dot(cross, cross);
    if (!(std::sqrt(det) > 1e-14 * std::max(E, G)) || !std::isfinite(det))
        throw GeometryError("curvature: the surface is degenerate at (" + detail::numberText(u) + ", " +
                            detail::numberText(v) + "), where curvature is undefined");
    const glm::dvec3 n = cross / std::sqrt(det);
    const double L = glm::dot(d.at(2, 0), n), M = glm::dot(d.at(1, 1), n), N = glm::dot(d.at(0, 2), n);
    SurfaceCurvature c;
    c.gaussian = (L * N - M * M) / det;
    c.mean = (E * N - 2.0 * F * M + G * L) / (2.0 * det);
    const double disc = std::sqrt(std::max(0.0, c.mean * c.mean - c.gaussian));
    c.principalMin = c.mean - disc;
    c.principalMax = c.mean + disc;
    return c;
}

}  // namespace geom
