#include "GeomTestUtil.h"
#include "geom/BezierExtraction.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/Intersect.h"
#include "geom/Primitives.h"
#include "geom/SurfaceIntersector.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>

namespace test_intersect {

using namespace geom;

namespace {

/// Every hit lies on the line and on the surface within 1e-9, and hits come sorted by t.
void requireHitsValid(const Surface& s, const std::vector<LineSurfaceHit>& hits, const glm::dvec3& o,
                      const glm::dvec3& d) {
    for (std::size_t i = 0; i < hits.size(); ++i) {
        const LineSurfaceHit& h = hits[i];
        REQUIRE(glm::length(h.point - (o + h.t * d)) < 1e-9);
        REQUIRE(glm::length(evaluate(s, h.uv.x, h.uv.y) - h.point) < 1e-9);
        if (i > 0) REQUIRE(hits[i - 1].t <= h.t);
    }
}

bool hasHitNear(const std::vector<LineSurfaceHit>& hits, const glm::dvec3& p, double tolerance) {
    for (const LineSurfaceHit& h : hits)
        if (glm::length(h.point - p) < tolerance) return true;
    return false;
}

/// A unit direction making the given angle with the unit normal n, turned by phi about it.
glm::dvec3 tilted(const glm::dvec3& n, double angle, double phi) {
    const glm::dvec3 helper = std::abs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 a = glm::normalize(glm::cross(n, helper));
    const glm::dvec3 b = glm::cross(n, a);
    return std::cos(angle) * n + std::sin(angle) * (std::cos(phi) * a + std::sin(phi) * b);
}

}  // namespace

TEST_CASE("lines meet a sphere exactly twice at the right points", "[geom][intersect]") {
    const Surface sphere = makeSphere(1.0);
    const SurfaceIntersector intersector(sphere);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> c(-1.0, 1.0);
    for (int trial = 0; trial < 100; ++trial) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(c(rng), c(rng), c(rng)));
        // Offset the line from the centre by up to 0.9 across it.
        glm::dvec3 off = glm::dvec3(c(rng), c(rng), c(rng));
        off -= glm::dot(off, d) * d;
        if (glm::length(off) > 0.9) off *= 0.9 / glm::length(off);
        const glm::dvec3 o = off - 3.0 * d;
        const auto hits = intersector.intersect(o, d);
        REQUIRE(hits.size() == 2);
        requireHitsValid(sphere, hits, o, d);
        const double half = std::sqrt(1.0 - glm::dot(off, off));
        REQUIRE(hits[0].t == Approx(3.0 - half).margin(1e-10));
        REQUIRE(hits[1].t == Approx(3.0 + half).margin(1e-10));
    }
    // A line missing the sphere, and the z axis through both poles (collapsed edges).
    REQUIRE(intersector.intersect({2, 0, 0}, {0, 1, 0}).empty());
    const auto poles = intersector.intersect({0, 0, -5}, {0, 0, 2});
    REQUIRE(poles.size() == 2);
    REQUIRE(poles[0].t == Approx(2.0).margin(1e-10));
    REQUIRE(poles[1].t == Approx(3.0).margin(1e-10));
}

TEST_CASE("no hit is missed on random lines through known surface points", "[geom][intersect]") {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int surfaceIndex = 0; surfaceIndex < 4; ++surfaceIndex) {
        const Surface s = geomtest::bumpySurface(rng, 3, 2 + surfaceIndex % 2, 9, 8, surfaceIndex % 2 == 1);
        const SurfaceIntersector intersector(s);
        const auto pieces = extractBezier(s);
        for (int trial = 0; trial < 150; ++trial) {
            double u = unit(rng), v = unit(rng);
            if (trial % 5 == 0) {
                // Through a patch corner (knot values in both directions).
                const auto& piece = pieces[static_cast<std::size_t>(trial) % pieces.size()];
                u = piece.u0;
                v = piece.v0;
            } else if (trial % 5 == 1) {
                u = pieces[static_cast<std::size_t>(trial) % pieces.size()].u1;  // on a patch edge
            }
            const glm::dvec3 p = evaluate(s, u, v);
            const glm::dvec3 n = normal(s, u, v);
            // Angles up to 45 degrees from the normal, and some within 1e-2..1e-5 rad of the tangent plane.
            double angle = unit(rng) * 0.785;
            if (trial % 7 == 3) angle = 1.5707963267948966 - std::pow(10.0, -2.0 - 3.0 * unit(rng));
            const glm::dvec3 d = tilted(n, angle, unit(rng) * 6.283);
            const glm::dvec3 o = p - (0.5 + unit(rng)) * d;
            const auto hits = intersector.intersect(o, d);
            INFO("surface " << surfaceIndex << " trial " << trial << " u " << u << " v " << v << " angle "
                            << angle);
            REQUIRE(hasHitNear(hits, p, 1e-7));
            requireHitsValid(s, hits, o, d);
        }
    }
}

TEST_CASE("vertical lines cross a height field exactly once", "[geom][intersect]") {
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> unit(0.05, 0.95);
    const Surface s = geomtest::bumpySurface(rng, 3, 3, 10, 10, false);
    const SurfaceIntersector intersector(s);
    for (int trial = 0; trial < 200; ++trial) {
        const glm::dvec3 o(unit(rng), unit(rng), 5.0);
        const auto hits = intersector.intersect(o, {0, 0, -1});
        REQUIRE(hits.size() == 1);
        requireHitsValid(s, hits, o, {0, 0, -1});
        REQUIRE(hits[0].piece < extractBezier(s).size());
    }
}

TEST_CASE("tangent lines touch a cylinder once and rays keep only forward hits", "[geom][intersect]") {
    const Surface cylinder = makeCylinder(1.0, 2.0);
    const auto touching = intersectLine(cylinder, {1.0, -3.0, 0.7}, {0, 1, 0});
    REQUIRE(touching.size() == 1);
    REQUIRE(glm::length(touching[0].point - glm::dvec3(1.0, 0.0, 0.7)) < 1e-7);
    const auto through = intersectLine(cylinder, {0.2, 0.1, 1.0}, {1, 0, 0});
    REQUIRE(through.size() == 2);
    const auto forward = intersectRay(cylinder, {0.2, 0.1, 1.0}, {1, 0, 0});
    REQUIRE(forward.size() == 1);
    REQUIRE(forward[0].t > 0.0);
}

TEST_CASE("a line along the torus seams finds all four crossings once", "[geom][intersect]") {
    const Surface torus = makeTorus(3.0, 1.0);
    const SurfaceIntersector intersector(torus);
    // The x axis crosses the torus where both parameter seams (u = 0 / 1, v = 0 / 1) lie.
    const auto hits = intersector.intersect({-10, 0, 0}, {1, 0, 0});
    REQUIRE(hits.size() == 4);
    requireHitsValid(torus, hits, {-10, 0, 0}, {1, 0, 0});
    const double expected[4] = {6, 8, 12, 14};
    for (int k = 0; k < 4; ++k)
        REQUIRE(hits[static_cast<std::size_t>(k)].t == Approx(expected[k]).margin(1e-10));
    // A line over the torus misses it; one along the top circle of the tube touches it once.
    const auto top = intersector.intersect({0, 3, 5}, {1, 0, 0});
    REQUIRE(top.empty());
    const auto tangent = intersector.intersect({-10, 3, 1}, {1, 0, 0});
    // The contact is of fourth order (z = 1 - x^4 / 72 along the line), so its place along the
    // line is only defined to about (1e-12 * 72)^(1/4) = 3e-3.
    REQUIRE(tangent.size() == 1);
    REQUIRE(glm::length(tangent[0].point - glm::dvec3(0, 3, 1)) < 1e-2);
    requireHitsValid(torus, tangent, {-10, 3, 1}, {1, 0, 0});
}

TEST_CASE("a line from a distant origin keeps its accuracy", "[geom][intersect]") {
    const Surface sphere = makeSphere(1.0);
    const SurfaceIntersector intersector(sphere);
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.3, -0.2, 1.0));
    const glm::dvec3 through(0.1, 0.2, 0.0);
    for (double far : {1e3, 1e5, 1e6}) {
        const glm::dvec3 o = through - far * d;
        const auto hits = intersector.intersect(o, 2.0 * d);
        REQUIRE(hits.size() == 2);
        requireHitsValid(sphere, hits, o, 2.0 * d);
        for (const auto& h : hits) REQUIRE(std::abs(glm::length(h.point) - 1.0) < 1e-9);
    }
}

TEST_CASE("a line with no direction is refused", "[geom][intersect]") {
    const Surface sphere = makeSphere(1.0);
    REQUIRE_THROWS_WITH(intersectLine(sphere, {0, 0, 0}, {0, 0, 0}), Catch::Contains("direction"));
    REQUIRE_THROWS_WITH(intersectLine(sphere, {std::nan(""), 0, 0}, {0, 0, 1}), Catch::Contains("origin"));
}

TEST_CASE("lines hit a Bezier patch of bidegree 99 x 10 (Molt 1994's size)", "[geom][intersect]") {
    std::mt19937 rng(77);
    std::uniform_real_distribution<double> unit(0.0, 1.0), noise(-0.01, 0.01);
    const std::size_t nu = 100, nv = 11;
    std::vector<glm::dvec3> pts;
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const double x = static_cast<double>(i) / (nu - 1), y = static_cast<double>(j) / (nv - 1);
            pts.emplace_back(x, y, 0.2 * std::sin(4 * x) * (0.5 + y) + noise(rng));
        }
    std::vector<double> ku(nu, 0.0), kv(nv, 0.0);
    ku.resize(2 * nu, 1.0);
    kv.resize(2 * nv, 1.0);
    const Surface blade(99, 10, ku, kv, nu, nv, pts);
    const SurfaceIntersector intersector(blade);
    for (int trial = 0; trial < 10; ++trial) {
        const double u = unit(rng), v = unit(rng);
        const glm::dvec3 p = evaluate(blade, u, v);
        const glm::dvec3 d = tilted(normal(blade, u, v), unit(rng) * 0.7, unit(rng) * 6.283);
        const auto hits = intersector.intersect(p - 0.3 * d, d);
        REQUIRE(hasHitNear(hits, p, 1e-9));
        requireHitsValid(blade, hits, p - 0.3 * d, d);
    }
}

}  // namespace test_intersect
