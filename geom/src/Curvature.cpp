#include "geom/Curvature.h"

#include "geom/Evaluate.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace geom {

SurfaceCurvature curvature(const Surface& surface, double u, double v) {
    const SurfaceDerivatives d = derivatives(surface, u, v, 2);
    const glm::dvec3 su = d.at(1, 0), sv = d.at(0, 1);
    const double E = glm::dot(su, su), F = glm::dot(su, sv), G = glm::dot(sv, sv);
    const double det = E * G - F * F;
    if (!(det > 1e-24 * (E * G)) || !(E * G > 0.0))
        throw GeometryError("curvature: the surface is degenerate at (" + std::to_string(u) + ", " +
                            std::to_string(v) + "), where curvature is undefined");
    const glm::dvec3 n = glm::cross(su, sv) / std::sqrt(det);
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
