#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/GlobalInterpolation.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace test_global_interpolation {

using namespace geom;

namespace {

std::vector<glm::dvec3> wavyGrid(std::size_t countU, std::size_t countV, bool closedV) {
    std::vector<glm::dvec3> grid;
    for (std::size_t i = 0; i < countU; ++i)
        for (std::size_t j = 0; j < countV; ++j) {
            const double x = 0.7 * static_cast<double>(i) + 0.05 * static_cast<double>(i * i);
            const double a = 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(countV);
            const double r = 1.0 + 0.3 * std::sin(0.9 * x) + 0.1 * std::cos(3.0 * a);
            if (closedV)
                grid.push_back({x, r * std::cos(a), 0.8 * r * std::sin(a)});
            else
                grid.push_back({x, static_cast<double>(j) * 0.4 + 0.02 * static_cast<double>(j * j),
                                std::sin(x) * std::cos(0.5 * static_cast<double>(j))});
        }
    return grid;
}

}  // namespace

TEST_CASE("open curve interpolation passes through its points and reproduces a line",
          "[geom][interpolation]") {
    const std::vector<glm::dvec3> points{{0, 0, 0}, {1, 2, 0}, {3, 3, 1}, {4, 1, 2}, {6, 0, 2}, {7, 2, 3}};
    const std::vector<double> t = chordLengthParameters(points, Closure::Open);
    const Curve c = interpolateCurve(points, t, 3, Closure::Open);
    REQUIRE(c.points.size() == points.size());
    for (std::size_t k = 0; k < points.size(); ++k)
        REQUIRE(glm::distance(evaluate(c, t[k]), points[k]) < 1e-12);

    // Collinear data at chord-length parameters: the interpolant is the line itself.
    const std::vector<glm::dvec3> line{{0, 0, 0}, {0.5, 1, 1.5}, {2, 4, 6}, {2.2, 4.4, 6.6}, {3, 6, 9}};
    const Curve l = interpolateCurve(line, 3, Closure::Open);
    for (double u = 0.0; u <= 1.0; u += 0.05) {
        const glm::dvec3 p = evaluate(l, u);
        REQUIRE(glm::length(glm::cross(p, glm::dvec3(1, 2, 3))) < 1e-12);
    }
}

TEST_CASE("periodic curve interpolation closes with C2 across the seam", "[geom][interpolation]") {
    std::vector<glm::dvec3> points;
    for (int k = 0; k < 7; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 7.0 + 0.1 * k * k / 7.0;
        points.push_back({2.0 * std::cos(a), std::sin(a), 0.2 * std::sin(2 * a)});
    }
    const std::vector<double> t = chordLengthParameters(points, Closure::Periodic);
    REQUIRE(t.size() == 8);
    const Curve c = interpolateCurve(points, t, 3, Closure::Periodic);
    REQUIRE(c.points.size() == 10);
    for (int i = 0; i < 3; ++i)
        REQUIRE(c.points[static_cast<std::size_t>(i)] == c.points[7 + static_cast<std::size_t>(i)]);
    REQUIRE(c.domainStart() == 0.0);
    REQUIRE(c.domainEnd() == 1.0);
    for (std::size_t k = 0; k < points.size(); ++k)
        REQUIRE(glm::distance(evaluate(c, t[k]), points[k]) < 1e-12);
    const auto start = derivatives(c, c.domainStart(), 2);
    const auto end = derivatives(c, c.domainEnd(), 2);
    for (int d = 0; d <= 2; ++d)
        REQUIRE(glm::distance(start[static_cast<std::size_t>(d)], end[static_cast<std::size_t>(d)]) <
                1e-9 * (1.0 + glm::length(start[static_cast<std::size_t>(d)])));
}

TEST_CASE("surface interpolation passes through the grid, open and periodic", "[geom][interpolation]") {
    for (const bool closed : {false, true}) {
        const std::size_t nu = 7, nv = 9;
        const std::vector<glm::dvec3> grid = wavyGrid(nu, nv, closed);
        const Closure cv = closed ? Closure::Periodic : Closure::Open;
        const GridParameters par = chordLengthGridParameters(grid, nu, nv, Closure::Open, cv);
        REQUIRE(par.u.size() == nu);
        REQUIRE(par.v.size() == (closed ? nv + 1 : nv));
        const Surface s = interpolateSurface(grid, nu, nv, par, 3, 3, Closure::Open, cv);
        REQUIRE(s.countU == nu);
        REQUIRE(s.countV == (closed ? nv + 3 : nv));
        for (std::size_t i = 0; i < nu; ++i)
            for (std::size_t j = 0; j < nv; ++j)
                REQUIRE(glm::distance(evaluate(s, par.u[i], par.v[j]), grid[i * nv + j]) < 1e-12);
        if (closed) {
            for (double u : {0.0, 0.13, 0.5, 0.77, 1.0}) {
                const SurfaceDerivatives a = derivatives(s, u, s.domainStartV(), 2);
                const SurfaceDerivatives b = derivatives(s, u, s.domainEndV(), 2);
                for (int k = 0; k <= 2; ++k)
                    for (int l = 0; k + l <= 2; ++l)
                        REQUIRE(glm::distance(a.at(k, l), b.at(k, l)) <
                                1e-9 * (1.0 + glm::length(a.at(k, l))));
            }
        }
    }
}

TEST_CASE("surface interpolation skips a collapsed row (a pole) in the parameter average",
          "[geom][interpolation]") {
    const std::size_t nu = 5, nv = 8;
    std::vector<glm::dvec3> grid;
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const double a = 2.0 * std::numbers::pi * static_cast<double>(j) / nv;
            const double r = i == 0 ? 0.0 : std::sqrt(static_cast<double>(i));
            grid.push_back({static_cast<double>(i), r * std::cos(a), r * std::sin(a)});
        }
    const Surface s = interpolateSurface(grid, nu, nv, 3, 3, Closure::Open, Closure::Periodic);
    const GridParameters par = chordLengthGridParameters(grid, nu, nv, Closure::Open, Closure::Periodic);
    for (std::size_t j = 0; j < nv; ++j)
        REQUIRE(glm::distance(evaluate(s, 0.0, par.v[j]), glm::dvec3(0.0)) < 1e-12);
    for (std::size_t j = 1; j < nv; ++j)
        REQUIRE(par.v[j] == Approx(static_cast<double>(j) / nv).margin(1e-12));
}

TEST_CASE("interpolation through many points is banded: 20,000 points, open and periodic",
          "[geom][interpolation]") {
    // A dense solve would hold 20,000^2 doubles (3.2 GB); the banded one holds a few per point.
    for (const Closure closure : {Closure::Open, Closure::Periodic}) {
        const std::size_t n = 20000;
        std::vector<glm::dvec3> data;
        for (std::size_t i = 0; i < n; ++i) {
            const double a = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
            data.push_back(
                {std::cos(a) * (1.0 + 0.1 * std::sin(37.0 * a)), std::sin(a), 0.05 * std::cos(11.0 * a)});
        }
        if (closure == Closure::Open) data.resize(n - 10);  // not closed
        for (int degree : {1, 3, 5}) {
            const std::vector<double> t = chordLengthParameters(data, closure);
            const Curve c = interpolateCurve(data, t, degree, closure);
            for (std::size_t i = 0; i < data.size(); i += 97)
                REQUIRE(glm::distance(evaluate(c, t[i]), data[i]) < 1e-9);
        }
    }
}

TEST_CASE("interpolation rejects bad input with a GeometryError", "[geom][interpolation]") {
    const std::vector<glm::dvec3> three{{0, 0, 0}, {1, 0, 0}, {2, 1, 0}};
    REQUIRE_THROWS_AS(interpolateCurve(three, 3, Closure::Open), GeometryError);
    const std::vector<glm::dvec3> repeated{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 1, 0}};
    REQUIRE_THROWS_AS(interpolateCurve(repeated, 3, Closure::Open), GeometryError);
    const std::vector<glm::dvec3> four{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    REQUIRE_THROWS_AS(interpolateCurve(four, 2, Closure::Periodic), GeometryError);
    const std::vector<glm::dvec3> nan{{0, 0, 0}, {1, 0, 0}, {1, std::nan(""), 0}, {0, 1, 0}};
    REQUIRE_THROWS_AS(interpolateCurve(nan, 3, Closure::Open), GeometryError);
    const std::vector<glm::dvec3> grid = wavyGrid(5, 5, false);
    REQUIRE_THROWS_AS(interpolateSurface(grid, 5, 4, 3, 3, Closure::Open, Closure::Open), GeometryError);
    const std::vector<double> flat{0.0, 0.5, 0.5, 0.7, 1.0};
    REQUIRE_THROWS_AS(
        interpolateCurve(std::vector<glm::dvec3>(grid.begin(), grid.begin() + 5), flat, 3, Closure::Open),
        GeometryError);
}

TEST_CASE("interpolation knots refuse parameters that are not finite or do not increase, by index",
          "[geom][interpolation]") {
    std::mt19937 rng(4004);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double nan = std::numeric_limits<double>::quiet_NaN(),
                 inf = std::numeric_limits<double>::infinity();
    for (int trial = 0; trial < 200; ++trial) {
        const int degree = 1 + 2 * static_cast<int>(rng() % 3);  // odd, so periodic knots apply too
        const std::size_t count = static_cast<std::size_t>(degree) + 2 + rng() % 8;
        std::vector<double> t(count);
        t[0] = unit(rng) * 4.0 - 2.0;
        for (std::size_t i = 1; i < count; ++i) t[i] = t[i - 1] + 0.01 + unit(rng);
        for (Closure closure : {Closure::Open, Closure::Periodic}) {
            const std::vector<double> knots = interpolationKnots(t, degree, closure);
            REQUIRE(std::is_sorted(knots.begin(), knots.end()));
            REQUIRE(std::all_of(knots.begin(), knots.end(), [](double k) { return std::isfinite(k); }));
        }
        const std::size_t bad = rng() % count;
        for (double value : {nan, inf, -inf}) {
            std::vector<double> broken = t;
            broken[bad] = value;
            for (Closure closure : {Closure::Open, Closure::Periodic})
                REQUIRE_THROWS_WITH(interpolationKnots(broken, degree, closure),
                                    Catch::Contains("parameter " + std::to_string(bad) + " is not a finite"));
        }
        if (bad == 0) continue;
        // Equal to or below its predecessor.
        std::vector<double> backwards = t;
        backwards[bad] = t[bad - 1] - unit(rng) * (trial % 2 == 0 ? 0.0 : 1.0);
        for (Closure closure : {Closure::Open, Closure::Periodic})
            REQUIRE_THROWS_WITH(interpolationKnots(backwards, degree, closure),
                                Catch::Contains("do not increase at index " + std::to_string(bad)));
    }
}

TEST_CASE("a surface periodic in both directions closes smoothly both ways", "[geom][interpolation]") {
    const std::size_t nu = 9, nv = 7;
    std::vector<glm::dvec3> grid;
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const double a = 2.0 * std::numbers::pi * static_cast<double>(i) / nu;
            const double b = 2.0 * std::numbers::pi * static_cast<double>(j) / nv;
            const double r = 3.0 + (1.0 + 0.2 * std::cos(a)) * std::cos(b);
            grid.push_back({r * std::cos(a), r * std::sin(a), std::sin(b)});
        }
    const GridParameters par = chordLengthGridParameters(grid, nu, nv, Closure::Periodic, Closure::Periodic);
    const Surface s = interpolateSurface(grid, nu, nv, par, 3, 3, Closure::Periodic, Closure::Periodic);
    REQUIRE(s.countU == nu + 3);
    REQUIRE(s.countV == nv + 3);
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j)
            REQUIRE(glm::distance(evaluate(s, par.u[i], par.v[j]), grid[i * nv + j]) < 1e-12);
    for (double t : {0.1, 0.45, 0.8}) {
        const SurfaceDerivatives a = derivatives(s, s.domainStartU(), t, 2);
        const SurfaceDerivatives b = derivatives(s, s.domainEndU(), t, 2);
        const SurfaceDerivatives c = derivatives(s, t, s.domainStartV(), 2);
        const SurfaceDerivatives d = derivatives(s, t, s.domainEndV(), 2);
        for (int k = 0; k <= 2; ++k)
            for (int l = 0; k + l <= 2; ++l) {
                REQUIRE(glm::distance(a.at(k, l), b.at(k, l)) < 1e-9 * (1.0 + glm::length(a.at(k, l))));
                REQUIRE(glm::distance(c.at(k, l), d.at(k, l)) < 1e-9 * (1.0 + glm::length(c.at(k, l))));
            }
    }
}

}  // namespace test_global_interpolation
