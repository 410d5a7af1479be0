#pragma once

#include "geom/Curve.h"
#include "geom/KnotInsertion.h"
#include "geom/Surface.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <random>
#include <vector>

namespace geomtest {

/// A random non-decreasing knot vector for `count` control points of `degree`: clamped ends
/// (multiplicity degree+1) when clamped, else strictly increasing ends; interior knots may repeat.
inline std::vector<double> randomKnots(std::mt19937& rng, int degree, std::size_t count, bool clamped) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::size_t total = count + static_cast<std::size_t>(degree) + 1;
    std::vector<double> k;
    if (clamped) {
        const std::size_t interior = total - 2 * static_cast<std::size_t>(degree + 1);
        for (std::size_t i = 0; i < interior; ++i) k.push_back(unit(rng));
        std::sort(k.begin(), k.end());
        // Repeat one interior knot now and then to cover multiple knots.
        if (degree >= 2 && interior >= 2 && unit(rng) < 0.5) k[1] = k[0];
        k.insert(k.begin(), static_cast<std::size_t>(degree + 1), 0.0);
        k.insert(k.end(), static_cast<std::size_t>(degree + 1), 1.0);
    } else {
        for (std::size_t i = 0; i < total; ++i) k.push_back(unit(rng) * 3.0 - 1.0);
        std::sort(k.begin(), k.end());
    }
    return k;
}

inline glm::dvec3 randomPoint(std::mt19937& rng) {
    std::uniform_real_distribution<double> c(-1.0, 1.0);
    return {c(rng), c(rng), c(rng)};
}

inline geom::Curve randomCurve(std::mt19937& rng, int degree, std::size_t count, bool rational,
                               bool clamped) {
    std::uniform_real_distribution<double> w(0.5, 2.0);
    std::vector<glm::dvec3> pts;
    std::vector<double> wts;
    for (std::size_t i = 0; i < count; ++i) {
        pts.push_back(randomPoint(rng));
        if (rational) wts.push_back(w(rng));
    }
    return geom::Curve(degree, randomKnots(rng, degree, count, clamped), pts, wts);
}

/// A smooth curve of degree p with many knots: a random clamped curve of p+3 control points,
/// refined with `extra` knots and its interior points then disturbed by up to `noise`, so that
/// reduction has real work to do.
inline geom::Curve noisyRefinedCurve(std::mt19937& rng, int p, std::size_t extra, double noise) {
    const geom::Curve base = randomCurve(rng, p, static_cast<std::size_t>(p + 3), false, true);
    std::uniform_real_distribution<double> unit(0.0, 1.0), jitter(-noise, noise);
    std::vector<double> inserted;
    for (std::size_t i = 0; i < extra; ++i) inserted.push_back(0.02 + 0.96 * unit(rng));
    geom::Curve c = geom::refineKnots(base, inserted);
    for (std::size_t i = 1; i + 1 < c.points.size(); ++i)
        c.points[i] += glm::dvec3(jitter(rng), jitter(rng), jitter(rng));
    return c;
}

inline geom::Surface randomSurface(std::mt19937& rng, int p, int q, std::size_t nu, std::size_t nv,
                                   bool rational, bool clamped) {
    std::uniform_real_distribution<double> w(0.5, 2.0);
    std::vector<glm::dvec3> pts;
    std::vector<double> wts;
    for (std::size_t i = 0; i < nu * nv; ++i) {
        pts.push_back(randomPoint(rng));
        if (rational) wts.push_back(w(rng));
    }
    return geom::Surface(p, q, randomKnots(rng, p, nu, clamped), randomKnots(rng, q, nv, clamped), nu, nv,
                         pts, wts);
}

/// A smooth-looking surface: a height field over a grid with random bumps (for intersection tests).
inline geom::Surface bumpySurface(std::mt19937& rng, int p, int q, std::size_t nu, std::size_t nv,
                                  bool rational) {
    std::uniform_real_distribution<double> h(-0.3, 0.3), w(0.5, 2.0);
    std::vector<glm::dvec3> pts;
    std::vector<double> wts;
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            pts.emplace_back(static_cast<double>(i) / static_cast<double>(nu - 1),
                             static_cast<double>(j) / static_cast<double>(nv - 1), h(rng));
            if (rational) wts.push_back(w(rng));
        }
    return geom::Surface(p, q, randomKnots(rng, p, nu, true), randomKnots(rng, q, nv, true), nu, nv, pts,
                         wts);
}

}  // namespace geomtest
