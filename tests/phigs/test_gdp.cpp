// Generalized drawing primitives and structure elements: the registered GDPs draw exact
// circles and arcs through their points, others and GSEs draw nothing; bad points are refused.
#include "ErrorNumber.h"
#include "PostedScene.h"
#include "phigs/Phigs.h"
#include "phigs/store/Gdp.h"

#include "geom/Inversion.h"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <random>

namespace test_gdp {

using namespace phigs;
using phigs::test::errorOf;

namespace {

using Scene = phigs::test::PostedScene;

glm::dvec3 randomPoint(std::mt19937& rng) {
    std::uniform_real_distribution<double> d(-10.0, 10.0);
    return {d(rng), d(rng), d(rng)};
}

}  // namespace

TEST_CASE("GDP circles: every drawn point on the circle, in the plane of the three points", "[gdp]") {
    std::mt19937 rng(7);
    Scene s;
    for (int trial = 0; trial < 200; ++trial) {
        const glm::dvec3 c = randomPoint(rng), p = randomPoint(rng), q = randomPoint(rng);
        const GdpElement circle{gdp::Circle, {c, p, q}, "", false};
        if (!checkGdp(circle).empty()) continue;  // collinear by chance: refused, tested below
        const DrawList& list = s.draw({circle});
        REQUIRE(list.items.size() == 1);
        const auto& drawn = primitiveAs<DrawCurve>(list.items[0].primitive);
        REQUIRE(drawn.curve);
        const double radius = glm::length(p - c);
        const glm::dvec3 normal = glm::normalize(glm::cross(p - c, q - c));
        for (const glm::dvec3& x : drawn.points) {
            CHECK(std::abs(glm::length(x - c) - radius) <= 1e-9 * (1.0 + radius));
            CHECK(std::abs(glm::dot(x - c, normal)) <= 1e-9 * (1.0 + radius));
        }
        CHECK(glm::length(drawn.points.front() - p) <= 1e-9 * (1.0 + radius));  // starts at p
        CHECK(glm::length(drawn.points.back() - p) <= 1e-9 * (1.0 + radius));   // and closes
    }
}

TEST_CASE("GDP arcs: from the first point through the second to the third, on their circle", "[gdp]") {
    std::mt19937 rng(11);
    Scene s;
    for (int trial = 0; trial < 200; ++trial) {
        const bool twoD = trial % 2 == 1;
        glm::dvec3 a = randomPoint(rng), b = randomPoint(rng), c = randomPoint(rng);
        if (twoD) a.z = b.z = c.z = 0.0;
        const GdpElement arc{gdp::ThreePointArc, {a, b, c}, "", twoD};
        if (!checkGdp(arc).empty()) continue;
        const DrawList& list = s.draw({arc});
        REQUIRE(list.items.size() == 1);
        const auto& drawn = primitiveAs<DrawCurve>(list.items[0].primitive);
        const double size = glm::length(b - a) + glm::length(c - a) + 1.0;
        CHECK(glm::length(drawn.points.front() - a) <= 1e-9 * size);
        CHECK(glm::length(drawn.points.back() - c) <= 1e-9 * size);
        // b lies on the drawn arc, not on the rest of its circle: the exact curve passes through it.
        REQUIRE(drawn.curve);
        CHECK(geom::closestPoint(*drawn.curve, b).distance <= 1e-7 * size);
        // The centre solved from the perpendicular bisectors and the plane; every drawn point
        // is on the circle about it.
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const glm::dmat3 rows = glm::transpose(glm::dmat3(b - a, c - a, n));
        const glm::dvec3 rhs(glm::dot(b - a, 0.5 * (a + b)), glm::dot(c - a, 0.5 * (a + c)), glm::dot(n, a));
        const glm::dvec3 centre = glm::inverse(rows) * rhs;
        const double radius = glm::length(a - centre);
        for (const glm::dvec3& x : drawn.points)
            CHECK(std::abs(glm::length(x - centre) - radius) <= 1e-7 * (1.0 + radius));
    }
}

TEST_CASE("GDPs of other identifiers and GSEs are stored and draw nothing", "[gdp]") {
    Scene s;
    CHECK(s.draw({GdpElement{4711, {{0, 0, 0}, {1, 1, 1}}, std::string("\0rec", 4), false}}).items.empty());
    CHECK(s.draw({GseElement{-3, "record"}}).items.empty());
    const Element stored = s.store->elementAt(1, 1);
    CHECK(stored == Element{GseElement{-3, "record"}});
    CHECK(elementType(stored) == ElementType::GeneralizedStructureElement);
    CHECK(elementType(GdpElement{1, {}, "", true}) == ElementType::GeneralizedDrawingPrimitive);
}

TEST_CASE("a registered GDP with points it cannot use is refused and changes nothing", "[gdp]") {
    Scene s;
    s.draw({polyline3({{0, 0, 0}, {1, 0, 0}})});
    s.store->openStructure(1);
    const auto refused = [&](GdpElement e) { return errorOf([&] { s.store->insert(e); }); };
    CHECK(refused({gdp::Circle, {{0, 0, 0}, {1, 0, 0}}, "", false}) == errors::InvalidElementData);
    CHECK(refused({gdp::Circle, {{0, 0, 0}, {0, 0, 0}, {0, 1, 0}}, "", false}) == errors::InvalidElementData);
    CHECK(refused({gdp::Circle, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, "", false}) == errors::InvalidElementData);
    CHECK(refused({gdp::ThreePointArc, {{0, 0, 0}, {1, 1, 0}, {2, 2, 0}}, "", true}) ==
          errors::InvalidElementData);
    CHECK(refused({gdp::ThreePointArc, {{0, 0, 0}, {1, 1, 0}}, "", true}) == errors::InvalidElementData);
    CHECK(refused({gdp::Circle, {{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}}, "", false}) ==
          errors::InvalidElementData);
    CHECK(s.store->structure(1).elements.size() == 1);
    s.store->closeStructure();
    // A 2D circle needs only its centre and a point.
    CHECK(checkGdp({gdp::Circle, {{0, 0, 0}, {1, 0, 0}}, "", true}).empty());
}

}  // namespace test_gdp
