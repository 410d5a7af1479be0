#include "geom/Basis.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/GridEvaluator.h"
#include "geom/Primitives.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace test_evaluate {

using namespace geom;

namespace {

Curve quarterCircleTimesFour() {
    // Full unit circle: degree 2, nine points, weights 1 and sqrt(2)/2.
    const double s = std::sqrt(0.5);
    return Curve(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1},
                 {{1, 0, 0},
                  {1, 1, 0},
                  {0, 1, 0},
                  {-1, 1, 0},
                  {-1, 0, 0},
                  {-1, -1, 0},
                  {0, -1, 0},
                  {1, -1, 0},
                  {1, 0, 0}},
                 {1, s, 1, s, 1, s, 1, s, 1});
}

}  // namespace

TEST_CASE("basis functions form a partition of unity and their derivatives sum to zero", "[geom][basis]") {
    std::vector<double> knots{0, 0, 0, 0, 0.1, 0.3, 0.35, 0.8, 1, 1, 1, 1};
    const int p = 3;
    const std::size_t n = knots.size() - p - 1;
    for (double u = 0.0; u <= 1.0; u += 0.01) {
        const std::size_t span = findSpan(p, knots, n, u);
        REQUIRE(knots[span] <= u);
        REQUIRE(u <= knots[span + 1]);
        std::vector<double> d((p + 1) * 3);
        basisDerivatives(span, u, p, knots, 2, d);
        double sum0 = 0, sum1 = 0, sum2 = 0;
        for (int j = 0; j <= p; ++j) {
            sum0 += d[j];
            sum1 += d[(p + 1) + j];
            sum2 += d[2 * (p + 1) + j];
            REQUIRE(d[j] >= 0.0);
        }
        REQUIRE(sum0 == Approx(1.0).margin(1e-14));
        REQUIRE(sum1 == Approx(0.0).margin(1e-10));
        REQUIRE(sum2 == Approx(0.0).margin(1e-8));
        std::vector<double> plain(p + 1);
        basisFunctions(span, u, p, knots, plain);
        for (int j = 0; j <= p; ++j) REQUIRE(plain[j] == Approx(d[j]).margin(1e-15));
    }
}

TEST_CASE("rational circle evaluates on the unit circle with exact derivatives", "[geom][evaluate]") {
    const Curve circle = quarterCircleTimesFour();
    for (int i = 0; i <= 200; ++i) {
        const double u = i / 200.0;
        const auto d = derivatives(circle, u, 2);
        REQUIRE(glm::length(d[0]) == Approx(1.0).margin(1e-12));
        // Tangent is perpendicular to the radius; the second derivative's normal part gives
        // curvature 1: |C' x C''| / |C'|^3 == 1.
        REQUIRE(glm::dot(d[0], d[1]) == Approx(0.0).margin(1e-10));
        const double kappa = glm::length(glm::cross(d[1], d[2])) / std::pow(glm::length(d[1]), 3);
        REQUIRE(kappa == Approx(1.0).epsilon(1e-10));
    }
}

TEST_CASE("surface derivatives agree with finite differences", "[geom][evaluate]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-1.0, 1.0), wdist(0.5, 2.0);
    const std::size_t nu = 6, nv = 5;
    std::vector<glm::dvec3> pts;
    std::vector<double> wts;
    for (std::size_t i = 0; i < nu * nv; ++i) {
        pts.emplace_back(coord(rng), coord(rng), coord(rng));
        wts.push_back(wdist(rng));
    }
    const Surface s(3, 2, {0, 0, 0, 0, 0.4, 0.7, 1, 1, 1, 1}, {0, 0, 0, 0.2, 0.5, 1, 1, 1}, nu, nv, pts, wts);
    const double h = 1e-5;
    for (double u : {0.1, 0.45, 0.8})
        for (double v : {0.15, 0.3, 0.9}) {
            const auto d = derivatives(s, u, v, 2);
            const glm::dvec3 fu = (evaluate(s, u + h, v) - evaluate(s, u - h, v)) / (2 * h);
            const glm::dvec3 fv = (evaluate(s, u, v + h) - evaluate(s, u, v - h)) / (2 * h);
            const glm::dvec3 fuv =
                (derivatives(s, u, v + h, 1).at(1, 0) - derivatives(s, u, v - h, 1).at(1, 0)) / (2 * h);
            REQUIRE(glm::length(d.at(1, 0) - fu) < 1e-6 * (1 + glm::length(fu)));
            REQUIRE(glm::length(d.at(0, 1) - fv) < 1e-6 * (1 + glm::length(fv)));
            REQUIRE(glm::length(d.at(1, 1) - fuv) < 1e-5 * (1 + glm::length(fuv)));
        }
}

TEST_CASE("normal at a collapsed edge is the limit from inside", "[geom][evaluate]") {
    // A bilinear patch whose v = 0 edge collapses to one point: Sv vanishes there.
    const Surface s(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, {{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    const glm::dvec3 n = normal(s, 0.0, 0.0);
    REQUIRE(glm::length(n) == Approx(1.0));
    REQUIRE(std::abs(n.z) == Approx(1.0).margin(1e-9));
}

TEST_CASE("normals of a surface scaled by 1e-150 to 1e200 are those of the surface", "[geom][evaluate]") {
    // Su x Sv overflowed (or underflowed) there, and normal() gave (0, 0, 0) as for a degenerate
    // surface.
    const Surface sphere = makeSphere(1.0);
    std::mt19937 rng(6122026);
    std::uniform_real_distribution<double> unit(0.05, 0.95);
    for (const double scale : {1e-150, 1e-100, 1e100, 1e150, 1e200}) {
        Surface scaled = sphere;
        for (glm::dvec3& q : scaled.points) q *= scale;
        for (int k = 0; k < 50; ++k) {
            const double u =
                sphere.domainStartU() + unit(rng) * (sphere.domainEndU() - sphere.domainStartU());
            const double v =
                sphere.domainStartV() + unit(rng) * (sphere.domainEndV() - sphere.domainStartV());
            INFO("scale " << scale << " at (" << u << ", " << v << ")");
            CHECK(glm::length(normal(scaled, u, v) - normal(sphere, u, v)) < 1e-12);
        }
    }
}

TEST_CASE("bad curves and surfaces are refused with the rule they break", "[geom][validate]") {
    const std::vector<glm::dvec3> pts{{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 0, 0}};
    REQUIRE_THROWS_WITH(Curve(3, {0, 0, 0, 0, 1, 1, 1}, pts), Catch::Contains("knots given"));
    REQUIRE_THROWS_WITH(Curve(3, {0, 0, 0, 0, 1, 1, 0.5, 1}, pts),
                        Catch::Contains("knots decrease at index 6"));
    REQUIRE_THROWS_WITH(Curve(3, {0, 0, 0, 0, 1, 1, 1, 1}, pts, {1, 1, -1, 1}), Catch::Contains("weight 2"));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    REQUIRE_THROWS_WITH(Curve(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 0}, {1, nan, 0}, {2, 1, 0}, {3, 0, 0}}),
                        Catch::Contains("control point 1"));
    REQUIRE_THROWS_WITH(Curve(0, {0, 1, 2, 3}, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}), Catch::Contains("degree"));
    REQUIRE_THROWS_WITH(Surface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, {{0, 0, 0}}),
                        Catch::Contains("control points given"));
    REQUIRE_THROWS_AS(Curve(3, {0, 0, 0, 0, 0, 1, 1, 1}, pts), GeometryError);
}

TEST_CASE("the grid evaluator agrees with the plain de Boor path", "[geom][evaluate][grid]") {
    std::mt19937 rng(19);
    std::uniform_real_distribution<double> coord(-1.0, 1.0), wdist(0.5, 2.0), unit(0.0, 1.0);
    for (bool rational : {false, true}) {
        const std::size_t nu = 9, nv = 7;
        std::vector<glm::dvec3> pts;
        std::vector<double> wts;
        for (std::size_t i = 0; i < nu * nv; ++i) {
            pts.emplace_back(coord(rng), coord(rng), coord(rng));
            if (rational) wts.push_back(wdist(rng));
        }
        const Surface s(3, 2, {0, 0, 0, 0, 0.1, 0.3, 0.3, 0.6, 0.8, 1, 1, 1, 1},
                        {0, 0, 0, 0.2, 0.5, 0.55, 0.9, 1, 1, 1}, nu, nv, pts, wts);
        std::vector<double> us{0.0, 0.3, 1.0}, vs{1.0, 0.0, 0.55};
        for (int k = 0; k < 20; ++k) {
            us.push_back(unit(rng));
            vs.push_back(unit(rng));
        }
        const GridEvaluator grid(s);
        const std::vector<GridSample> out = grid.evaluate(us, vs);
        REQUIRE(out.size() == us.size() * vs.size());
        for (std::size_t i = 0; i < us.size(); ++i)
            for (std::size_t j = 0; j < vs.size(); ++j) {
                const SurfaceDerivatives d = derivatives(s, us[i], vs[j], 1);
                const GridSample& g = out[i * vs.size() + j];
                REQUIRE(glm::length(g.point - d.at(0, 0)) < 1e-12);
                REQUIRE(glm::length(g.su - d.at(1, 0)) < 1e-10);
                REQUIRE(glm::length(g.sv - d.at(0, 1)) < 1e-10);
                REQUIRE(glm::length(g.normal - normal(s, us[i], vs[j])) < 1e-10);
            }
        std::vector<GridSample> tooSmall(3);
        REQUIRE_THROWS_WITH(grid.evaluate(us, vs, tooSmall), Catch::Contains("samples"));
    }
    const Curve circle = quarterCircleTimesFour();
    const std::vector<double> us{0.0, 0.1, 0.25, 0.9, 1.0};
    const auto points = evaluateMany(circle, us);
    for (std::size_t k = 0; k < us.size(); ++k)
        REQUIRE(glm::length(points[k] - evaluate(circle, us[k])) < 1e-15);
}

}  // namespace test_evaluate
