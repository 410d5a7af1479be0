// The even-odd rule of geom/EvenOdd.h against an independent answer: random star-shaped polygons,
// where a point is inside when it lies on the centre's side of the edge its angle falls under.
#include "geom/EvenOdd.h"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace test_even_odd {

namespace {

/// A polygon star-shaped about the origin: corners at increasing jittered angles (no gap of half
/// a turn, so the origin is inside) and random radii.
std::vector<glm::dvec3> randomStar(std::mt19937& random, double scale) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int corners = 4 + int(random() % 12);
    std::vector<glm::dvec3> star;
    for (int i = 0; i < corners; ++i) {
        const double a = 2.0 * std::numbers::pi * (i + 0.8 * unit(random)) / corners;
        const double r = scale * (0.3 + unit(random));
        star.emplace_back(r * std::cos(a), r * std::sin(a), unit(random));  // z: any, unused
    }
    return star;
}

double angleOf(glm::dvec2 p) {
    const double a = std::atan2(p.y, p.x);
    return a < 0.0 ? a + 2.0 * std::numbers::pi : a;
}

/// Whether p is inside the star: on the origin's side of the edge whose angular span holds p.
bool insideStar(glm::dvec2 p, const std::vector<glm::dvec3>& star) {
    auto cross = [](glm::dvec2 u, glm::dvec2 v) { return u.x * v.y - u.y * v.x; };
    const double angle = angleOf(p);
    const std::size_t n = star.size();
    std::size_t edge = n - 1;  // the last corner's edge spans the wrap past a full turn
    for (std::size_t i = 0; i + 1 < n; ++i)
        if (angleOf(glm::dvec2(star[i])) <= angle && angle < angleOf(glm::dvec2(star[i + 1]))) edge = i;
    const glm::dvec2 a(star[edge]), b(star[(edge + 1) % n]);
    return (cross(b - a, p - a) > 0.0) == (cross(b - a, -a) > 0.0);
}

glm::dvec2 xyOf(const glm::dvec3& q) {
    return glm::dvec2(q);
}

}  // namespace

TEST_CASE("even-odd: random star polygons and holes agree with the wedge test", "[geom]") {
    std::mt19937 random(7120602);
    std::uniform_real_distribution<double> coordinate(-1.4, 1.4);
    int inside = 0, outside = 0;
    for (int shape = 0; shape < 200; ++shape) {
        const std::vector<glm::dvec3> outer = randomStar(random, 1.0);
        // A hole: the same star shrunk, its corners in the other order (winding does not matter).
        std::vector<glm::dvec3> hole;
        for (auto it = outer.rbegin(); it != outer.rend(); ++it) hole.push_back(0.25 * *it);
        std::vector<glm::dvec3> closed = outer;
        closed.push_back(outer.front());  // a repeated first point adds no crossing
        const std::vector<std::vector<glm::dvec3>> withHole{outer, hole};
        for (int query = 0; query < 100; ++query) {
            const glm::dvec2 p(coordinate(random), coordinate(random));
            const bool expected = insideStar(p, outer);
            INFO("shape " << shape << " point " << p.x << ", " << p.y);
            CHECK(geom::oddCrossings(p, outer, xyOf) == expected);
            CHECK(geom::oddCrossings(p, closed, xyOf) == expected);
            CHECK(geom::insideEvenOdd(p, withHole, xyOf) == (expected && !insideStar(4.0 * p, outer)));
            (expected ? inside : outside) += 1;
        }
    }
    CHECK(inside > 2000);
    CHECK(outside > 2000);
}

TEST_CASE("even-odd: a bow-tie fills both lobes and a contour twice over is empty", "[geom]") {
    const std::vector<glm::dvec2> bowTie{{0, 0}, {2, 2}, {2, 0}, {0, 2}};
    auto same = [](glm::dvec2 q) { return q; };
    CHECK(geom::oddCrossings({0.2, 1.0}, bowTie, same));
    CHECK(geom::oddCrossings({1.8, 1.0}, bowTie, same));
    CHECK_FALSE(geom::oddCrossings({1.0, 0.2}, bowTie, same));
    CHECK_FALSE(geom::oddCrossings({3.0, 1.0}, bowTie, same));
    const std::vector<std::vector<glm::dvec2>> twice{bowTie, bowTie}, none{};
    CHECK_FALSE(geom::insideEvenOdd({0.2, 1.0}, twice, same));
    CHECK_FALSE(geom::insideEvenOdd({0.2, 1.0}, none, same));
    CHECK_FALSE(geom::oddCrossings({0.2, 1.0}, std::vector<glm::dvec2>{}, same));
}

}  // namespace test_even_odd
