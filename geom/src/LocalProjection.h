#pragma once

// Private to geom: Newton point projection started from a given parameter, used where the
// reduction code already knows a parameter near the answer (the same parameter on a nearby
// curve or surface). Each returns the best distance seen, including the start, so the result
// is an upper bound of the true distance to the whole curve or surface.

#include "geom/Curve.h"
#include "geom/Evaluate.h"
#include "geom/Surface.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace geom::detail {

struct LocalCurveProjection {
    double u = 0.0;
    double distance = 0.0;
};

inline LocalCurveProjection projectFrom(const Curve& curve, const glm::dvec3& target, double u, int iterations = 8) {
    const double lo = curve.domainStart(), hi = curve.domainEnd();
    u = std::clamp(u, lo, hi);
    LocalCurveProjection best{u, glm::length(evaluate(curve, u) - target)};
    for (int it = 0; it < iterations; ++it) {
        const std::vector<glm::dvec3> d = derivatives(curve, u, 2);
        const glm::dvec3 r = d[0] - target;
        const double dist = glm::length(r);
        if (dist < best.distance) best = {u, dist};
        const double f = glm::dot(d[1], r);
        const double df = glm::dot(d[2], r) + glm::dot(d[1], d[1]);
        if (!(df > 0.0)) break;
        const double next = std::clamp(u - f / df, lo, hi);
        if (std::abs(next - u) <= 1e-15 * (hi - lo)) break;
        u = next;
    }
    const double dist = glm::length(evaluate(curve, u) - target);
    if (dist < best.distance) best = {u, dist};
    return best;
}

struct LocalSurfaceProjection {
    double u = 0.0, v = 0.0;
    double distance = 0.0;
};

inline LocalSurfaceProjection projectFrom(const Surface& surface, const glm::dvec3& target, double u, double v,
                                          int iterations = 6) {
    const double u0 = surface.domainStartU(), u1 = surface.domainEndU();
    const double v0 = surface.domainStartV(), v1 = surface.domainEndV();
    u = std::clamp(u, u0, u1);
    v = std::clamp(v, v0, v1);
    LocalSurfaceProjection best{u, v, std::numeric_limits<double>::infinity()};
    for (int it = 0; it <= iterations; ++it) {
        const SurfaceDerivatives d = derivatives(surface, u, v, it == iterations ? 0 : 2);
        const glm::dvec3 r = d.at(0, 0) - target;
        const double dist = glm::length(r);
        if (dist < best.distance) best = {u, v, dist};
        if (it == iterations) break;
        const glm::dvec3 su = d.at(1, 0), sv = d.at(0, 1);
        const double a = glm::dot(su, su) + glm::dot(r, d.at(2, 0));
        const double b = glm::dot(su, sv) + glm::dot(r, d.at(1, 1));
        const double c = glm::dot(sv, sv) + glm::dot(r, d.at(0, 2));
        const double gu = glm::dot(r, su), gv = glm::dot(r, sv);
        const double det = a * c - b * b;
        if (!(std::abs(det) > 0.0)) break;
        const double du = (-gu * c + gv * b) / det;
        const double dv = (-gv * a + gu * b) / det;
        const double nu = std::clamp(u + du, u0, u1), nv = std::clamp(v + dv, v0, v1);
        if (std::abs(nu - u) <= 1e-15 * (u1 - u0) && std::abs(nv - v) <= 1e-15 * (v1 - v0)) break;
        u = nu;
        v = nv;
    }
    return best;
}

}  // namespace geom::detail
