#pragma once

// Private to geom: Newton point projection started from a given parameter, used where the
// reduction code already knows a parameter near the answer (the same parameter on a nearby
// curve or surface). Each returns the best distance seen, including the start, so the result
// is an upper bound of the true distance to the whole curve or surface.

#include "geom/Basis.h"
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

// C(u), C'(u) and C''(u) of a polynomial curve of degree <= 15 without touching the heap (the
// projections below run it millions of times); other curves take the general path.
inline void pointAndDerivatives(const Curve& curve, double u, glm::dvec3 (&d)[3]) {
    const int p = curve.degree;
    if (curve.rational() || p > 15) {
        const std::vector<glm::dvec3> g = derivatives(curve, u, 2);
        d[0] = g[0], d[1] = g[1], d[2] = g[2];
        return;
    }
    const std::vector<double>& t = curve.knots;
    u = std::clamp(u, curve.domainStart(), curve.domainEnd());
    const std::size_t span = findSpan(p, t, curve.points.size(), u);
    // Basis functions of degree p, p-1 and p-2 by the triangular Cox-de Boor scheme; the
    // derivatives follow from the lower-degree ones (The NURBS Book eq. 2.9).
    double n[16][16];  // only the triangle j >= r is written and read
    double left[16], right[16];
    n[0][0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = u - t[span + 1 - static_cast<std::size_t>(j)];
        right[j] = t[span + static_cast<std::size_t>(j)] - u;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const double temp = n[j - 1][r] / (right[r + 1] + left[j - r]);
            n[j][r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        n[j][j] = saved;
    }
    // Control points of the first and second derivative curves on the p+1 active points.
    glm::dvec3 q[16], q1[16], q2[16];
    const std::size_t first = span - static_cast<std::size_t>(p);
    for (int i = 0; i <= p; ++i) q[i] = curve.points[first + static_cast<std::size_t>(i)];
    auto knot = [&](int i) { return t[first + static_cast<std::size_t>(i)]; };
    for (int i = 0; i < p; ++i) {
        const double h = knot(i + p + 1) - knot(i + 1);
        q1[i] = h > 0.0 ? (q[i + 1] - q[i]) * (static_cast<double>(p) / h) : glm::dvec3(0.0);
    }
    for (int i = 0; i + 1 < p; ++i) {
        const double h = knot(i + p + 1) - knot(i + 2);
        q2[i] = h > 0.0 ? (q1[i + 1] - q1[i]) * (static_cast<double>(p - 1) / h) : glm::dvec3(0.0);
    }
    d[0] = d[1] = d[2] = glm::dvec3(0.0);
    for (int i = 0; i <= p; ++i) d[0] += n[p][i] * q[i];
    for (int i = 0; i < p; ++i) d[1] += n[p - 1][i] * q1[i];
    if (p >= 2)
        for (int i = 0; i + 1 < p; ++i) d[2] += n[p - 2][i] * q2[i];
}

inline glm::dvec3 pointOf(const Curve& curve, double u) {
    glm::dvec3 d[3];
    pointAndDerivatives(curve, u, d);
    return d[0];
}

inline LocalCurveProjection projectFrom(const Curve& curve, const glm::dvec3& target, double u,
                                        int iterations = 8) {
    const double lo = curve.domainStart(), hi = curve.domainEnd();
    u = std::clamp(u, lo, hi);
    LocalCurveProjection best{u, glm::length(pointOf(curve, u) - target)};
    glm::dvec3 d[3];
    for (int it = 0; it < iterations; ++it) {
        pointAndDerivatives(curve, u, d);
        const glm::dvec3 r = d[0] - target;
        const double dist = glm::length(r);
        if (dist < best.distance) best = {u, dist};
        const double f = glm::dot(d[1], r);
        const double df = glm::dot(d[2], r) + glm::dot(d[1], d[1]);
        if (!(df > 0.0)) break;
        const double next = std::clamp(u - f / df, lo, hi);
        if (std::abs(next - u) <= 1e-13 * (hi - lo)) break;
        u = next;
    }
    const double dist = glm::length(pointOf(curve, u) - target);
    if (dist < best.distance) best = {u, dist};
    return best;
}

struct LocalSurfaceProjection {
    double u = 0.0, v = 0.0;
    double distance = 0.0;
};

inline LocalSurfaceProjection projectFrom(const Surface& surface, const glm::dvec3& target, double u,
                                          double v, int iterations = 6) {
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
        if (std::abs(nu - u) <= 1e-13 * (u1 - u0) && std::abs(nv - v) <= 1e-13 * (v1 - v0)) break;
        u = nu;
        v = nv;
    }
    return best;
}

}  // namespace geom::detail
