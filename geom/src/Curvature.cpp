#include "geom/Curvature.h"
#include "NumberText.h"

#include "geom/Basis.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace geom {
namespace {

/// The one patch of the surface that holds (u, v) (its (p+1) x (q+1) control points and the knots
/// they reach), with the points taken from the one of them nearest to S(u, v). Near a collapsed
/// edge (a pole) the first and second derivatives across it are as small as the distance to it;
/// evaluated from points far from the origin they are differences of terms that large, and lose
/// their digits as the square of that distance. Taken from the pole itself, the pole's points are
/// exact zeros and every other term is small.
Surface localPatch(const Surface& s, double u, double v) {
    const std::size_t p = static_cast<std::size_t>(s.degreeU), q = static_cast<std::size_t>(s.degreeV);
    const glm::dvec3 at = evaluate(s, u, v);  // first: it checks the surface and (u, v)
    const std::size_t su = findSpan(s.degreeU, s.knotsU, s.countU, u);
    const std::size_t sv = findSpan(s.degreeV, s.knotsV, s.countV, v);
    glm::dvec3 origin = s.point(su, sv);
    for (std::size_t i = su - p; i <= su; ++i)
        for (std::size_t j = sv - q; j <= sv; ++j)
            if (glm::length(s.point(i, j) - at) < glm::length(origin - at)) origin = s.point(i, j);
    std::vector<double> ku(s.knotsU.begin() + std::ptrdiff_t(su - p),
                           s.knotsU.begin() + std::ptrdiff_t(su + p + 2));
    std::vector<double> kv(s.knotsV.begin() + std::ptrdiff_t(sv - q),
                           s.knotsV.begin() + std::ptrdiff_t(sv + q + 2));
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    for (std::size_t i = su - p; i <= su; ++i)
        for (std::size_t j = sv - q; j <= sv; ++j) {
            points.push_back(s.point(i, j) - origin);
            if (s.rational()) weights.push_back(s.weight(i, j));
        }
    return Surface(s.degreeU, s.degreeV, std::move(ku), std::move(kv), p + 1, q + 1, std::move(points),
                   std::move(weights));
}

}  // namespace

SurfaceCurvature curvature(const Surface& surface, double u, double v) {
    const SurfaceDerivatives d = derivatives(localPatch(surface, u, v), u, v, 2);
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
