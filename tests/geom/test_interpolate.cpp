#include "geom/Basis.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/Interpolate.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>

namespace test_interpolate {

using namespace geom;

namespace {

double distance(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::length(a - b);
}

/// One-sided derivative at a knot: evaluated a hair inside the span on that side (side -1 or +1).
glm::dvec3 sidedDerivative(const Curve& c, double u, int side, int order) {
    return derivatives(c, u + side * 1e-10, order)[static_cast<std::size_t>(order)];
}

InterpolationData randomPart() {
    InterpolationData d;
    d.points = {{-2, -2, 0}, {-2, 2, 0}, {2, 2, 0}, {2, -2, 0}, {-2, -2, 0}};
    d.continuities = {Continuity::C2, Continuity::C0, Continuity::C1, Continuity::C2, Continuity::C2};
    d.tangents = {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}};
    d.closed = true;
    return d;
}

}  // namespace

TEST_CASE("interpolation knot count follows the ACSYNT thesis's formula n + 6 + 2*C0 + C1",
          "[geom][interpolate]") {
    using C = Continuity;
    CHECK(interpolationKnotCount({C::C2, C::C0, C::C1, C::C2, C::C2}, 5) == 14);
    CHECK(interpolationKnotCount({C::C2, C::C2, C::C2, C::C2, C::C2}, 5) == 11);
    // End points (or the closing point) are not interior.
    CHECK(interpolationKnotCount({C::C0, C::C2, C::C1, C::C0}, 4) == 11);

    std::mt19937 rng(7);
    for (int trial = 0; trial < 40; ++trial) {
        InterpolationData d;
        const int n = 4 + static_cast<int>(rng() % 9);
        d.closed = trial % 2 == 0;
        for (int i = 0; i < n; ++i) {
            const double a = 6.283185307179586 * i / n;
            d.points.push_back(
                {std::cos(a) * (2 + (rng() % 100) * 0.01), std::sin(a) * 2, 0.01 * (rng() % 10)});
            d.continuities.push_back(static_cast<Continuity>(rng() % 3));
        }
        if (d.closed) {
            d.points.push_back(d.points.front());
            d.continuities.push_back(d.continuities.front());
        }
        for (std::size_t i = 0; i < constraintCount(d.continuities); ++i)
            d.tangents.push_back({std::cos(i * 1.0), std::sin(i * 1.0), 0.0});
        d.parameterization = static_cast<Parameterization>(1 + trial % 3);
        const Curve c = interpolateCubic(d);
        INFO("trial " << trial);
        CHECK(c.knots.size() == interpolationKnotCount(d.continuities, d.points.size()));
        CHECK(c.points.size() == c.knots.size() - 4);
        const std::vector<double> t = interpolationParameters(d.points, d.parameterization);
        for (std::size_t i = 0; i < d.points.size(); ++i)
            CHECK(distance(evaluate(c, t[i]), d.points[i]) < 1e-9);
        // Interior knot multiplicity gives the continuity: 1, 2, 3 for C2, C1, C0.
        for (std::size_t i = 1; i + 1 < d.points.size(); ++i)
            CHECK(knotMultiplicity(c.knots, t[i]) == 3 - static_cast<int>(d.continuities[i]));
    }
}

TEST_CASE("parameterisations: uniform, chord length, centripetal", "[geom][interpolate]") {
    const std::vector<glm::dvec3> p{{0, 0, 0}, {3, 4, 0}, {3, 4, 9}};
    CHECK(interpolationParameters(p, Parameterization::Uniform) == std::vector<double>{0, 1, 2});
    CHECK(interpolationParameters(p, Parameterization::ChordLength) == std::vector<double>{0, 5, 14});
    CHECK(interpolationParameters(p, Parameterization::Centripetal) ==
          std::vector<double>{0, std::sqrt(5.0), std::sqrt(5.0) + 3});
}

TEST_CASE("tangent constraints fix the derivatives at C0 and C1 points", "[geom][interpolate]") {
    InterpolationData d;
    d.points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}, {4, 0, 1}};
    d.continuities = {Continuity::C2, Continuity::C0, Continuity::C1, Continuity::C2, Continuity::C2};
    const glm::dvec3 in{1, 2, 0}, out{1, -2, 0.5}, t1{0.5, 0.5, 0};
    d.tangents = {in, out, t1};
    d.parameterization = Parameterization::Uniform;
    const Curve c = interpolateCubic(d);
    CHECK(distance(sidedDerivative(c, 1.0, -1, 1), in) < 1e-6);
    CHECK(distance(sidedDerivative(c, 1.0, +1, 1), out) < 1e-6);
    CHECK(distance(derivatives(c, 2.0, 1)[1], t1) < 1e-9);
    // Natural (zero-curvature) open ends.
    CHECK(glm::length(derivatives(c, 0.0, 2)[2]) < 1e-9);
    CHECK(glm::length(derivatives(c, 4.0, 2)[2]) < 1e-9);

    // Tangent end conditions on an open curve: C1 end uses its tangent, a C0 end the curve-side one.
    d.continuities = {Continuity::C1, Continuity::C2, Continuity::C2, Continuity::C2, Continuity::C0};
    d.tangents = {{1, 0, 0}, {0, -3, 0}, {2, 0, 0}};
    const Curve e = interpolateCubic(d);
    CHECK(distance(derivatives(e, 0.0, 1)[1], {1, 0, 0}) < 1e-9);
    CHECK(distance(derivatives(e, 4.0, 1)[1], {0, -3, 0}) < 1e-9);
}

TEST_CASE("closed interpolation: periodic C2 closure, or clamped with tangents", "[geom][interpolate]") {
    InterpolationData circle;
    circle.points = {{-4, -4, 0}, {-4, 4, 0}, {4, 4, 0}, {4, -4, 0}, {-4, -4, 0}};
    circle.closed = true;
    circle.parameterization = Parameterization::Uniform;
    const Curve c = interpolateCubic(circle);
    REQUIRE(c.knots.size() == 11);
    for (int k = 0; k <= 2; ++k)
        CHECK(distance(derivatives(c, c.domainStart(), k)[k], derivatives(c, c.domainEnd(), k)[k]) < 1e-9);
    // Symmetric data give a curve with the square's 90-degree symmetry: circle-like.
    for (double u = 0; u < 1.0; u += 0.125) {
        const glm::dvec3 p = evaluate(c, u), q = evaluate(c, u + 1.0);
        CHECK(distance(q, glm::dvec3(p.y, -p.x, 0)) < 1e-9);
    }

    const Curve r = interpolateCubic(randomPart());
    CHECK(r.knots.size() == 14);
    const std::vector<double> t = interpolationParameters(randomPart().points, Parameterization::ChordLength);
    // The C0 point with zero tangents is a corner: both one-sided derivatives vanish.
    CHECK(glm::length(sidedDerivative(r, t[1], -1, 1)) < 1e-6);
    CHECK(glm::length(sidedDerivative(r, t[1], +1, 1)) < 1e-6);
    CHECK(distance(derivatives(r, t[2], 1)[1], {1, 0, 0}) < 1e-9);
    CHECK(distance(derivatives(r, r.domainStart(), 2)[2], derivatives(r, r.domainEnd(), 2)[2]) < 1e-9);

    // A C1 closing point: clamped, both ends take the tangent.
    InterpolationData d = randomPart();
    d.continuities = {Continuity::C1, Continuity::C2, Continuity::C2, Continuity::C2, Continuity::C1};
    d.tangents = {{0, 5, 0}, {0, 5, 0}};
    const Curve s = interpolateCubic(d);
    CHECK(s.knots.size() == 11);
    CHECK(distance(derivatives(s, s.domainStart(), 1)[1], {0, 5, 0}) < 1e-9);
    CHECK(distance(derivatives(s, s.domainEnd(), 1)[1], {0, 5, 0}) < 1e-9);
}

TEST_CASE("interpolation succeeds and passes through its points at any scale, 1e-8 to 1e8",
          "[geom][interpolate]") {
    std::mt19937 rng(2002);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-8.0, 8.0);
    for (int trial = 0; trial < 300; ++trial) {
        const double scale = std::pow(10.0, exponent(rng));
        InterpolationData d;
        const int n = 3 + static_cast<int>(rng() % 8);
        d.closed = trial % 3 == 0;
        for (int i = 0; i < n; ++i) {
            // Points along a wobbly path (ordinary data: no two close together).
            const glm::dvec3 p(i + 0.3 * unit(rng), std::sin(1.3 * i) + 0.3 * unit(rng), 0.5 * unit(rng));
            d.points.push_back(scale * p);
            d.continuities.push_back(trial % 2 == 0 ? Continuity::C2 : static_cast<Continuity>(rng() % 3));
        }
        if (d.closed) {
            d.points.push_back(d.points.front());
            d.continuities.push_back(d.continuities.front());
        }
        d.parameterization = static_cast<Parameterization>(1 + trial % 3);
        // Tangents dC/dt: about a unit for chord length, the scale for uniform, its root for centripetal.
        const double speed = d.parameterization == Parameterization::Uniform       ? scale
                             : d.parameterization == Parameterization::Centripetal ? std::sqrt(scale)
                                                                                   : 1.0;
        for (std::size_t i = 0; i < constraintCount(d.continuities); ++i)
            d.tangents.push_back(speed * glm::dvec3(1.0 + 0.2 * unit(rng), unit(rng), 0.2 * unit(rng)));
        INFO("trial " << trial << ", scale " << scale << ", parameterization "
                      << static_cast<int>(d.parameterization));
        Curve c;
        REQUIRE_NOTHROW(c = interpolateCubic(d));
        const std::vector<double> t = interpolationParameters(d.points, d.parameterization);
        for (std::size_t i = 0; i < d.points.size(); ++i)
            REQUIRE(distance(evaluate(c, t[i]), d.points[i]) < 1e-9 * scale);
    }
}

TEST_CASE("a closed curve must end at its first point at its own scale", "[geom][interpolate]") {
    // The closure test was 1e-9 of max(1, |coordinates|): a model far smaller than a unit could
    // leave a gap as large as itself. Now 1e-9 of the points' extent (and rounding far off).
    std::mt19937 rng(515);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const double size = std::pow(10.0, -8.0 + 16.0 * unit(rng));
        const glm::dvec3 offset =
            std::pow(10.0, 6.0 * unit(rng)) * size * glm::dvec3(unit(rng), unit(rng), 0.0);
        InterpolationData data;
        data.closed = true;
        for (int k = 0; k < 6; ++k) {
            const double a = 6.283185307179586 * k / 6.0;
            data.points.push_back(offset + size * glm::dvec3(std::cos(a), std::sin(a), 0.0));
        }
        data.points.push_back(data.points.front());
        INFO("size " << size << " offset " << glm::length(offset));
        CHECK_NOTHROW(interpolateCubic(data));
        data.points.back() += glm::dvec3(0.01 * size, 0.0, 0.0);  // a gap of 1% of the curve
        CHECK_THROWS_WITH(interpolateCubic(data), Catch::Contains("must end at its first point"));
    }
}

TEST_CASE("interpolation rejects bad data with the reason", "[geom][interpolate]") {
    InterpolationData d = randomPart();
    d.tangents.pop_back();
    CHECK_THROWS_WITH(interpolateCubic(d), Catch::Contains("ask for 3 tangent constraints, got 2"));
    d = randomPart();
    d.points.back() = {-2, -1.5, 0};
    CHECK_THROWS_WITH(interpolateCubic(d), Catch::Contains("must end at its first point"));
    d = randomPart();
    d.points[2] = d.points[1];
    CHECK_THROWS_WITH(interpolateCubic(d), Catch::Contains("coincide"));
    d = randomPart();
    d.continuities.pop_back();
    CHECK_THROWS_WITH(interpolateCubic(d), Catch::Contains("4 continuities for 5 data points"));
    d = randomPart();
    d.points[3].x = std::nan("");
    CHECK_THROWS_AS(interpolateCubic(d), GeometryError);
    InterpolationData one;
    one.points = {{0, 0, 0}};
    CHECK_THROWS_WITH(interpolateCubic(one), Catch::Contains("at least 2 data points"));
}

}  // namespace test_interpolate
