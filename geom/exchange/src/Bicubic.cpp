#include "geom/exchange/Bicubic.h"

#include "geom/DegreeElevation.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/GlobalInterpolation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <string>

namespace geom::exchange {

namespace {

constexpr std::size_t maxSamples = 513;  ///< per direction: bounds the dense solves and the time

/// `perSpan` parameters evenly spread over each non-empty knot span of the domain, and its end.
std::vector<double> samples(const std::vector<double>& knots, int degree, std::size_t count, int perSpan) {
    std::vector<double> t;
    for (std::size_t k = std::size_t(degree); k < count; ++k)
        for (int i = 0; i < perSpan && knots[k] < knots[k + 1]; ++i)
            t.push_back(knots[k] + (knots[k + 1] - knots[k]) * i / perSpan);
    t.push_back(knots[count]);
    return t;
}

/// The largest distance between the surfaces at the parameters halfway between the samples.
double gapBetween(const Surface& a, const Surface& b, const std::vector<double>& us,
                  const std::vector<double>& vs) {
    auto halves = [](const std::vector<double>& t) {
        std::vector<double> h;
        for (std::size_t i = 0; i < t.size(); ++i) {
            h.push_back(t[i]);
            if (i + 1 < t.size()) h.push_back((t[i] + t[i + 1]) / 2);
        }
        return h;
    };
    double gap = 0;
    for (double u : halves(us))
        for (double v : halves(vs)) gap = std::max(gap, glm::length(evaluate(a, u, v) - evaluate(b, u, v)));
    return gap;
}

Surface bicubicFromPolynomial(Surface s) {
    if (s.degreeU < 3) s = elevateDegree(s, 3 - s.degreeU, false);
    if (s.degreeV < 3) s = elevateDegree(s, 3 - s.degreeV, true);
    return s;
}

}  // namespace

BicubicSurface toBicubic(const Surface& surface, double tolerance) {
    validate(surface, "toBicubic");
    if (!(tolerance > 0)) throw GeometryError("toBicubic: the tolerance must be positive");
    BicubicSurface r;
    if (!surface.rational() && surface.degreeU <= 3 && surface.degreeV <= 3) {
        r.surface = bicubicFromPolynomial(surface);
        return r;
    }
    // Interpolation through samples on the surface's own parameters, twice as dense each round.
    double gap = 0;
    for (int perSpan = 4;; perSpan *= 2) {  // 5 points or more: a cubic needs 4
        const auto us = samples(surface.knotsU, surface.degreeU, surface.countU, perSpan);
        const auto vs = samples(surface.knotsV, surface.degreeV, surface.countV, perSpan);
        if (us.size() > maxSamples || vs.size() > maxSamples)
            throw GeometryError("toBicubic: no bicubic within " + std::to_string(tolerance) + " from " +
                                std::to_string(maxSamples) + " samples a direction (the last was " +
                                std::to_string(gap) + " off)");
        std::vector<glm::dvec3> grid;
        for (double u : us)
            for (double v : vs) grid.push_back(evaluate(surface, u, v));
        r.surface = interpolateSurface(grid, us.size(), vs.size(), GridParameters{us, vs}, 3, 3,
                                       Closure::Open, Closure::Open);
        gap = gapBetween(surface, r.surface, us, vs);
        if (gap <= tolerance) break;
    }
    r.exact = false;
    r.maxError = gap;
    return r;
}

}  // namespace geom::exchange
