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
    // The principal curvatures as eigenvalues of the second form in an orthonormal tangent frame
    // (e1 along su): the half difference is a root of a sum of squares, which H^2 - K, two near
    // equal numbers at an umbilic, loses half the digits of.
    const double f = F / E, h2 = det / E;  // e2 = (sv - f su) / sqrt(h2)
    const double a = L / E, b = (M - f * L) / std::sqrt(E * h2), cc = (N - 2.0 * f * M + f * f * L) / h2;
    const double middle = 0.5 * (a + cc), half = std::hypot(0.5 * (a - cc), b);
    c.principalMin = middle - half;
    c.principalMax = middle + half;
    return c;
}

}  // namespace geom
