#include "GeomTestUtil.h"
#include "geom/Bezier.h"
#include "geom/BezierExtraction.h"
#include "geom/DegreeElevation.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/Primitives.h"
#include "geom/Reparameterize.h"
#include "geom/Split.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <random>

namespace test_curve_ops {

using namespace geom;
using geomtest::randomCurve;
using geomtest::randomSurface;

namespace {

double lerp(double a, double b, double f) {
    return a + (b - a) * f;
}

}  // namespace

TEST_CASE("splitting a curve gives two halves that trace it exactly", "[geom][split]") {
    std::mt19937 rng(51);
    std::uniform_real_distribution<double> unit(0.05, 0.95);
    for (int trial = 0; trial < 30; ++trial) {
        const int p = 1 + trial % 5;
        const Curve c =
            randomCurve(rng, p, static_cast<std::size_t>(p + 2 + trial % 4), trial % 2 == 0, trial % 3 != 0);
        const double u = lerp(c.domainStart(), c.domainEnd(), unit(rng));
        const auto [left, right] = split(c, u);
        REQUIRE_NOTHROW(validate(left));
        REQUIRE_NOTHROW(validate(right));
        REQUIRE(left.domainEnd() == u);
        REQUIRE(right.domainStart() == u);
        REQUIRE(left.domainStart() == c.domainStart());
        for (int i = 0; i <= 20; ++i) {
            const double a = lerp(left.domainStart(), u, i / 20.0), b = lerp(u, right.domainEnd(), i / 20.0);
            REQUIRE(glm::length(evaluate(left, a) - evaluate(c, a)) < 1e-12);
            REQUIRE(glm::length(evaluate(right, b) - evaluate(c, b)) < 1e-12);
        }
        // The halves meet in a shared control point.
        REQUIRE(glm::length(left.points.back() - right.points.front()) < 1e-12);
    }
    std::mt19937 rng2(52);
    const Surface s = randomSurface(rng2, 3, 2, 6, 5, true, true);
    const auto [low, high] = split(s, 0.4, true);
    REQUIRE(glm::length(evaluate(low, 0.3, 0.2) - evaluate(s, 0.3, 0.2)) < 1e-12);
    REQUIRE(glm::length(evaluate(high, 0.7, 0.9) - evaluate(s, 0.7, 0.9)) < 1e-12);
    REQUIRE_THROWS_WITH(split(s, 1.0, false), Catch::Contains("not inside"));
}

TEST_CASE("degree elevation keeps the shape and the continuity", "[geom][elevate]") {
    std::mt19937 rng(61);
    for (int trial = 0; trial < 30; ++trial) {
        const int p = 1 + trial % 4;
        const int times = 1 + trial % 3;
        const Curve c =
            randomCurve(rng, p, static_cast<std::size_t>(p + 2 + trial % 5), trial % 2 == 0, trial % 4 != 0);
        const Curve e = elevateDegree(c, times);
        REQUIRE(e.degree == p + times);
        REQUIRE(e.domainStart() == c.domainStart());
        REQUIRE(e.domainEnd() == c.domainEnd());
        for (int i = 0; i <= 60; ++i) {
            const double u = lerp(c.domainStart(), c.domainEnd(), i / 60.0);
            REQUIRE(glm::length(evaluate(e, u) - evaluate(c, u)) < 1e-12);
        }
        // Every interior knot keeps its continuity: multiplicity rises by exactly `times`.
        for (std::size_t k = static_cast<std::size_t>(p) + 1; k < c.points.size(); ++k)
            REQUIRE(std::count(e.knots.begin(), e.knots.end(), c.knots[k]) ==
                    std::count(c.knots.begin(), c.knots.end(), c.knots[k]) + times);
    }
    // A quadratic rational circle raised to degree 4 is still the circle.
    const Curve circle = elevateDegree(makeCircle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0), 2);
    for (int i = 0; i <= 100; ++i) REQUIRE(std::abs(glm::length(evaluate(circle, i / 100.0)) - 1.0) < 1e-12);
    const Surface sphere = elevateDegree(makeSphere(1.0), 1, false);
    REQUIRE(sphere.degreeU == 3);
    REQUIRE(std::abs(glm::length(evaluate(sphere, 0.3, 0.6)) - 1.0) < 1e-12);
    REQUIRE_THROWS_WITH(elevateDegree(circle, -1), Catch::Contains("elevate"));
}

TEST_CASE("degree elevation to the highest degree stays within 1e-9 of the shape, rational too",
          "[geom][elevate]") {
    std::mt19937 rng(62);
    std::uniform_real_distribution<double> exponent(0.0, 3.0);
    auto size = [](const std::vector<glm::dvec3>& points) {
        double m = 0.0;
        for (const glm::dvec3& q : points) m = std::max({m, std::abs(q.x), std::abs(q.y), std::abs(q.z)});
        return m;
    };
    for (int trial = 0; trial < 40; ++trial) {
        const int p = 1 + trial % 9;
        const bool rational = trial % 2 == 1;
        Curve c = randomCurve(rng, p, static_cast<std::size_t>(p + 1) + rng() % 6, false, trial % 3 != 0);
        if (rational) {
            // Weights over up to three decades.
            c.weights.resize(c.points.size());
            for (double& w : c.weights) w = std::pow(10.0, exponent(rng));
        }
        const Curve e = elevateDegree(c, 64 - p);
        REQUIRE(e.degree == 64);
        double gap = 0.0;
        for (int i = 0; i <= 400; ++i) {
            const double u = lerp(c.domainStart(), c.domainEnd(), i / 400.0);
            gap = std::max(gap, glm::length(evaluate(e, u) - evaluate(c, u)));
        }
        INFO("trial " << trial << ", degree " << p << (rational ? ", rational" : ""));
        CHECK(gap < 1e-9 * size(c.points));
    }
    for (int trial = 0; trial < 8; ++trial) {
        const int p = 1 + trial % 4, q = 1 + (trial / 2) % 3;
        const bool alongV = trial % 2 == 1;
        const Surface s = randomSurface(rng, p, q, static_cast<std::size_t>(p + 3),
                                        static_cast<std::size_t>(q + 3), trial % 4 >= 2, trial % 3 != 0);
        const Surface e = elevateDegree(s, 64 - (alongV ? q : p), alongV);
        REQUIRE((alongV ? e.degreeV : e.degreeU) == 64);
        double gap = 0.0;
        for (int i = 0; i <= 30; ++i)
            for (int j = 0; j <= 30; ++j) {
                const double u = lerp(s.domainStartU(), s.domainEndU(), i / 30.0);
                const double v = lerp(s.domainStartV(), s.domainEndV(), j / 30.0);
                gap = std::max(gap, glm::length(evaluate(e, u, v) - evaluate(s, u, v)));
            }
        INFO("surface trial " << trial);
        CHECK(gap < 1e-9 * size(s.points));
    }
}

TEST_CASE("reversal and reparameterisation", "[geom][reparameterize]") {
    std::mt19937 rng(71);
    const Curve c = randomCurve(rng, 3, 8, true, true);
    const Curve r = reverse(c);
    REQUIRE_NOTHROW(validate(r));
    for (int i = 0; i <= 40; ++i) {
        const double u = i / 40.0;
        REQUIRE(glm::length(evaluate(r, u) - evaluate(c, 1.0 - u)) < 1e-12);
    }
    const Curve m = reparameterize(c, 2.0, 6.0);
    REQUIRE(m.domainStart() == 2.0);
    REQUIRE(m.domainEnd() == 6.0);
    for (int i = 0; i <= 40; ++i)
        REQUIRE(glm::length(evaluate(m, 2.0 + 4.0 * i / 40.0) - evaluate(c, i / 40.0)) < 1e-12);
    REQUIRE_THROWS_WITH(reparameterize(c, 1.0, 1.0), Catch::Contains("non-empty"));

    const Surface s = randomSurface(rng, 2, 3, 5, 6, true, true);
    const Surface sv = reverse(s, true);
    const Surface su = reverse(s, false);
    REQUIRE(glm::length(evaluate(sv, 0.3, 0.2) - evaluate(s, 0.3, 0.8)) < 1e-12);
    REQUIRE(glm::length(evaluate(su, 0.3, 0.2) - evaluate(s, 0.7, 0.2)) < 1e-12);
    const Surface sm = reparameterize(s, -1.0, 1.0, 10.0, 20.0);
    REQUIRE(glm::length(evaluate(sm, 0.0, 15.0) - evaluate(s, 0.5, 0.5)) < 1e-12);
}

TEST_CASE("de Casteljau evaluation and subdivision (Molt 1994 identities)", "[geom][bezier]") {
    // Dyadic control points and parameters: only halvings are used, so the identities hold exactly.
    std::mt19937 rng(81);
    std::uniform_int_distribution<int> coord(-64, 64);
    for (int m : {1, 2, 3, 4, 7}) {
        std::vector<glm::dvec3> P;
        for (int i = 0; i <= m; ++i) P.emplace_back(coord(rng) / 8.0, coord(rng) / 8.0, coord(rng) / 8.0);
        std::vector<glm::dvec3> Q(P.size()), R(P.size());
        subdivideBezier<glm::dvec3>(P, 0.5, Q, R);
        REQUIRE(Q.front() == P.front());
        REQUIRE(R.back() == P.back());
        REQUIRE(Q.back() == R.front());
        for (int k = 0; k <= 8; ++k) {
            const double t = k / 8.0;
            REQUIRE(deCasteljau<glm::dvec3>(Q, t) == deCasteljau<glm::dvec3>(P, t / 2));
            REQUIRE(deCasteljau<glm::dvec3>(R, t) == deCasteljau<glm::dvec3>(P, 0.5 + t / 2));
        }
        // Theorem 2: one split at least halves the largest spacing of consecutive points.
        auto spacing = [](const std::vector<glm::dvec3>& X) {
            double s = 0.0;
            for (std::size_t i = 0; i + 1 < X.size(); ++i) s = std::max(s, glm::length(X[i + 1] - X[i]));
            return s;
        };
        REQUIRE(std::max(spacing(Q), spacing(R)) <= 0.5 * spacing(P) + 1e-15);
    }
    // Degree 99 (Molt's 1994 blades): de Casteljau against the B-spline evaluation, and a split.
    std::vector<double> knots(100, 0.0);
    knots.resize(200, 1.0);
    std::vector<glm::dvec3> points;
    std::uniform_real_distribution<double> c(-1.0, 1.0);
    for (int i = 0; i < 100; ++i) points.emplace_back(i / 99.0, c(rng), c(rng));
    const Curve high(99, knots, points);
    REQUIRE(isBezier(high));
    for (double u : {0.0, 0.13, 0.5, 0.77, 1.0})
        REQUIRE(glm::length(evaluateBezier(high, u) - evaluate(high, u)) < 1e-12);
    const auto [left, right] = subdivide(high, 0.3);
    REQUIRE(glm::length(evaluateBezier(left, 0.1) - evaluate(high, 0.1)) < 1e-12);
    REQUIRE(glm::length(evaluateBezier(right, 0.9) - evaluate(high, 0.9)) < 1e-12);
}

TEST_CASE("Bezier patch subdivision into quadrants and rational patches", "[geom][bezier]") {
    std::mt19937 rng(91);
    const Surface s = randomSurface(rng, 3, 2, 7, 6, true, true);
    const auto pieces = extractBezier(s);
    const Surface& patch = pieces[1].surface;
    REQUIRE(isBezier(patch));
    const double um = 0.5 * (pieces[1].u0 + pieces[1].u1), vm = 0.5 * (pieces[1].v0 + pieces[1].v1);
    const auto [lowU, highU] = subdivide(patch, um, false);
    const auto [q00, q01] = subdivide(lowU, vm, true);
    const auto [q10, q11] = subdivide(highU, vm, true);
    for (const Surface* q : {&q00, &q01, &q10, &q11})
        for (double a : {0.0, 0.3, 1.0})
            for (double b : {0.0, 0.6, 1.0}) {
                const double u = lerp(q->domainStartU(), q->domainEndU(), a);
                const double v = lerp(q->domainStartV(), q->domainEndV(), b);
                REQUIRE(glm::length(evaluateBezier(*q, u, v) - evaluate(s, u, v)) < 1e-12);
            }
    REQUIRE_THROWS_WITH(evaluateBezier(s, 0.5, 0.5), Catch::Contains("not a single"));
}

TEST_CASE("periodic curves close smoothly", "[geom][periodic]") {
    std::mt19937 rng(101);
    for (int p = 1; p <= 5; ++p) {
        std::vector<glm::dvec3> pts;
        std::vector<double> w;
        std::uniform_real_distribution<double> wd(0.5, 2.0);
        for (int i = 0; i < 7; ++i) {
            pts.push_back(geomtest::randomPoint(rng));
            w.push_back(wd(rng));
        }
        const Curve c = makePeriodicCurve(p, pts, w);
        REQUIRE(c.domainStart() == Approx(0.0).margin(1e-15));
        REQUIRE(c.domainEnd() == Approx(1.0).margin(1e-15));
        const auto a = derivatives(c, c.domainStart(), std::min(p - 1, 2));
        const auto b = derivatives(c, c.domainEnd(), std::min(p - 1, 2));
        for (std::size_t k = 0; k < a.size(); ++k)
            REQUIRE(glm::length(a[k] - b[k]) < 1e-9 * (1 + glm::length(a[k])));
        // Knot insertion and Bézier extraction work on the unclamped closed curve too.
        const auto pieces = extractBezier(c);
        REQUIRE(pieces.size() == 7);
        REQUIRE(glm::length(evaluate(pieces[3].curve, pieces[3].start) - evaluate(c, pieces[3].start)) <
                1e-12);
    }
    REQUIRE_THROWS_WITH(makePeriodicCurve(3, {{0, 0, 0}, {1, 0, 0}}), Catch::Contains("too few"));
}

TEST_CASE("knot and Bezier operations refuse bad input and leave it unchanged", "[geom][validate]") {
    std::mt19937 rng(111);
    const Curve c = randomCurve(rng, 3, 7, true, true);
    const Curve copy = c;
    // A break: interior knot of multiplicity degree + 1.
    const Curve broken(2, {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1},
                       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {3, 2, 0}});
    REQUIRE_THROWS_WITH(split(broken, 0.5), Catch::Contains("multiplicity degree + 1"));
    REQUIRE_THROWS_WITH(elevateDegree(broken, 1), Catch::Contains("break"));
    REQUIRE_THROWS_WITH(split(c, c.domainStart()), Catch::Contains("not inside"));
    REQUIRE_THROWS_WITH(subdivide(c, 0.5), Catch::Contains("not a single"));
    const Curve bezier(2, {0, 0, 0, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}});
    REQUIRE_THROWS_WITH(subdivide(bezier, 1.0), Catch::Contains("not inside"));
    REQUIRE_THROWS_WITH(makePeriodicCurve(2, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {1, 1}),
                        Catch::Contains("weights"));
    REQUIRE_THROWS_AS(reparameterize(c, 0.0, std::nan("")), GeometryError);
    REQUIRE(c.knots == copy.knots);
    REQUIRE(c.points == copy.points);
    REQUIRE(c.weights == copy.weights);
}

}  // namespace test_curve_ops
