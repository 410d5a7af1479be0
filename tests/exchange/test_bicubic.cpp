// toBicubic on the class that has creases: polynomial surfaces of degree 4 to 7 one way and 1 or 2
// the other, with interior knots of any multiplicity that keeps them continuous (C0 and C1 knot
// lines): within the tolerance, bicubic, and the reported error what a measure finds.
#include "geom/Evaluate.h"
#include "geom/exchange/Bicubic.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <random>

namespace test_bicubic {

using namespace geom;
using namespace geom::exchange;

namespace {

/// Clamped knots on [0, 1] with 1 to 4 interior values, each of multiplicity 1 .. degree.
std::vector<double> randomKnots(std::mt19937& rng, int degree) {
    std::vector<double> interior;
    std::uniform_real_distribution<double> at(0.1, 0.9);
    for (int k = 1 + int(rng() % 4); k > 0; --k) interior.push_back(at(rng));
    std::sort(interior.begin(), interior.end());
    std::vector<double> knots(std::size_t(degree) + 1, 0.0);
    for (double t : interior)
        for (int m = 1 + int(rng() % unsigned(degree)); m > 0; --m) knots.push_back(t);
    knots.insert(knots.end(), std::size_t(degree) + 1, 1.0);
    return knots;
}

}  // namespace

TEST_CASE("bicubic: surfaces with C0 and C1 knot lines are made bicubic within the tolerance", "[exchange]") {
    std::mt19937 rng(20261205);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 40; ++trial) {
        const bool highU = trial % 2 == 0;
        const int high = 4 + int(rng() % 4), low = 1 + int(rng() % 2);
        const int pu = highU ? high : low, pv = highU ? low : high;
        const std::vector<double> ku = randomKnots(rng, pu), kv = randomKnots(rng, pv);
        const std::size_t nu = ku.size() - std::size_t(pu) - 1, nv = kv.size() - std::size_t(pv) - 1;
        std::vector<glm::dvec3> points;
        for (std::size_t i = 0; i < nu; ++i)
            for (std::size_t j = 0; j < nv; ++j)
                points.push_back({double(i) / double(nu - 1), double(j) / double(nv - 1), 0.3 * unit(rng)});
        const Surface s(pu, pv, ku, kv, nu, nv, points);
        const double tolerance = 1e-4;
        INFO("trial " << trial << ": degrees " << pu << " x " << pv);
        const BicubicSurface b = toBicubic(s, tolerance);
        CHECK(b.surface.degreeU == 3);
        CHECK(b.surface.degreeV == 3);
        CHECK_FALSE(b.surface.rational());
        CHECK_FALSE(b.exact);
        CHECK(b.maxError <= tolerance);
        double measured = 0.0;
        for (int k = 0; k < 400; ++k) {
            const double u = unit(rng), v = unit(rng);
            measured = std::max(measured, glm::length(evaluate(s, u, v) - evaluate(b.surface, u, v)));
        }
        CHECK(measured <= 1.5 * tolerance);
    }
}

}  // namespace test_bicubic
