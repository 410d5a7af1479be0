#include "GeomTestUtil.h"
#include "geom/CurveProjector.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/Inversion.h"
#include "geom/Primitives.h"
#include "geom/SurfaceProjector.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace test_inversion {

using namespace geom;

TEST_CASE("closest points on a sphere and a circle are exact", "[geom][inversion]") {
    const Surface sphere = makeSphere(2.0);
    const SurfaceProjector projector(sphere);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> c(-3.0, 3.0);
    for (int trial = 0; trial < 100; ++trial) {
        const glm::dvec3 p(c(rng), c(rng), c(rng));
        if (glm::length(p) < 0.3) continue;
        const SurfacePoint q = projector.closestPoint(p);
        REQUIRE(std::abs(q.distance - std::abs(glm::length(p) - 2.0)) < 1e-12);
        REQUIRE(glm::length(q.point - 2.0 * glm::normalize(p)) < 1e-11);
        REQUIRE(glm::length(evaluate(sphere, q.uv.x, q.uv.y) - q.point) < 1e-12);
    }
    const Curve circle = makeCircle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.5);
    const CurveProjector curveProjector(circle);
    for (int trial = 0; trial < 100; ++trial) {
        const glm::dvec3 p(c(rng), c(rng), 0.5 * c(rng));
        const CurvePoint q = curveProjector.closestPoint(p);
        const double r = std::sqrt(p.x * p.x + p.y * p.y);
        if (r < 0.1) continue;
        REQUIRE(std::abs(q.distance - std::hypot(r - 1.5, p.z)) < 1e-12);
        REQUIRE(glm::length(evaluate(circle, q.u) - q.point) < 1e-12);
    }
}

TEST_CASE("points just off a surface invert to their foot point", "[geom][inversion]") {
    std::mt19937 rng(8);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int surfaceIndex = 0; surfaceIndex < 3; ++surfaceIndex) {
        const Surface s = geomtest::bumpySurface(rng, 3, 3, 8, 8, surfaceIndex == 1);
        const SurfaceProjector projector(s);
        for (int trial = 0; trial < 60; ++trial) {
            const double u = 0.02 + 0.96 * unit(rng), v = 0.02 + 0.96 * unit(rng);
            const glm::dvec3 foot = evaluate(s, u, v);
            const double h = (unit(rng) - 0.5) * 2e-3;
            const glm::dvec3 p = foot + h * normal(s, u, v);
            const SurfacePoint q = projector.closestPoint(p);
            REQUIRE(std::abs(q.distance - std::abs(h)) < 1e-12);
            REQUIRE(glm::length(q.point - foot) < 1e-9);
            const SurfacePoint local = closestPoint(s, p, glm::dvec2(u + 0.01, v - 0.01));
            REQUIRE(std::abs(local.distance - std::abs(h)) < 1e-12);
        }
    }
}

TEST_CASE("closest points are no farther than dense sampling finds", "[geom][inversion]") {
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> c(-1.5, 1.5);
    const Surface s = geomtest::randomSurface(rng, 3, 2, 6, 5, true, true);
    const SurfaceProjector projector(s);
    const Curve curve = geomtest::randomCurve(rng, 3, 9, true, true);
    const CurveProjector curveProjector(curve);
    for (int trial = 0; trial < 20; ++trial) {
        const glm::dvec3 p(c(rng), c(rng), c(rng));
        double sampled = 1e300;
        for (int i = 0; i <= 120; ++i)
            for (int j = 0; j <= 120; ++j)
                sampled = std::min(sampled, glm::length(evaluate(s, i / 120.0, j / 120.0) - p));
        const SurfacePoint q = projector.closestPoint(p);
        REQUIRE(q.distance <= sampled + 1e-12);
        REQUIRE(std::abs(glm::length(q.point - p) - q.distance) < 1e-12);
        double curveSampled = 1e300;
        for (int i = 0; i <= 4000; ++i)
            curveSampled = std::min(curveSampled, glm::length(evaluate(curve, i / 4000.0) - p));
        const CurvePoint cq = curveProjector.closestPoint(p);
        REQUIRE(cq.distance <= curveSampled + 1e-12);
        REQUIRE(glm::length(evaluate(curve, cq.u) - cq.point) < 1e-12);
    }
}

TEST_CASE("a local closest point on a straight rational segment reaches its one minimum",
          "[geom][inversion]") {
    // Weights decades apart put most of the segment in a sliver of its parameter: Newton's last
    // steps there are tiny in the parameter yet gain much, and stopping at them left the answer
    // short (2 of 8,605 random queries at seven decades, 0.6% farther than the minimum).
    std::mt19937 rng(1993);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int checked = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const double size = std::pow(10.0, -2.0 + 7.0 * unit(rng));
        const glm::dvec3 a = size * glm::dvec3(unit(rng), unit(rng), unit(rng)) - 0.5 * size;
        const glm::dvec3 b = size * glm::dvec3(unit(rng), unit(rng), unit(rng)) - 0.5 * size;
        const double w0 = std::pow(10.0, -4.0 + 8.0 * unit(rng)), w1 = std::pow(10.0, -4.0 + 8.0 * unit(rng));
        const double start = unit(rng), end = start + 0.1 + 2.0 * unit(rng);
        const Curve line(1, {start, start, end, end}, {a, b}, {w0, w1});
        const glm::dvec3 p = 2.0 * size * glm::dvec3(unit(rng), unit(rng), unit(rng)) - size;
        const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
        const double exact = glm::length(a + t * (b - a) - p);
        const CurvePoint local = closestPoint(line, p, start + (end - start) * unit(rng));
        INFO("trial " << trial << ": weights " << w0 << ", " << w1 << ", size " << size);
        CHECK(local.distance <= exact * (1.0 + 1e-9) + 1e-12 * size);
        ++checked;
    }
    CHECK(checked == 3000);
}

TEST_CASE("a local closest point on a flat rational patch is never left on a slope", "[geom][inversion]") {
    // A bilinear square with corner weights decades apart: Newton from a guess crawled through
    // the squeezed parameters and stopped on a slope (133 of 1,500 queries, up to 44 times too
    // far); a point that is not stationary gives way to the global answer.
    std::mt19937 rng(2027);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int farther = 0;
    for (int trial = 0; trial < 1500; ++trial) {
        const double size = std::pow(10.0, -2.0 + 6.0 * unit(rng));
        std::vector<double> weights;
        for (int k = 0; k < 4; ++k) weights.push_back(std::pow(10.0, -4.0 + 8.0 * unit(rng)));
        const Surface square(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                             {{0, 0, 0}, {0, size, 0}, {size, 0, 0}, {size, size, 0}}, weights);
        const glm::dvec3 p = size * glm::dvec3(3.0 * unit(rng) - 1.0, 3.0 * unit(rng) - 1.0, unit(rng) - 0.5);
        const glm::dvec3 foot(std::clamp(p.x, 0.0, size), std::clamp(p.y, 0.0, size), 0.0);
        const SurfacePoint local = closestPoint(square, p, glm::dvec2(unit(rng), unit(rng)));
        farther += !(local.distance <= glm::length(p - foot) * (1.0 + 1e-9) + 1e-12 * size);
    }
    CHECK(farther == 0);
}

TEST_CASE("point inversion refuses non-finite input", "[geom][inversion]") {
    const Surface sphere = makeSphere(1.0);
    REQUIRE_THROWS_WITH(closestPoint(sphere, glm::dvec3(std::nan(""), 0, 0)), Catch::Contains("non-finite"));
    const Curve circle = makeCircle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0);
    REQUIRE_THROWS_AS(closestPoint(circle, glm::dvec3(0, INFINITY, 0)), GeometryError);
    REQUIRE_THROWS_WITH(closestPoint(circle, glm::dvec3(0, 1, 0), std::nan("")), Catch::Contains("guess"));
}

}  // namespace test_inversion
