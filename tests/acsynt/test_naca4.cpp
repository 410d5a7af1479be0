#include "acsynt/Naca4.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

namespace test_naca4 {

using namespace acsynt;

TEST_CASE("NACA 4-digit codes are read and bad ones refused", "[acsynt][naca]") {
    const Naca4Airfoil a = parseNaca4("2412");
    REQUIRE(a.maxCamber == Approx(0.02));
    REQUIRE(a.camberPosition == Approx(0.4));
    REQUIRE(a.thickness == Approx(0.12));
    REQUIRE(parseNaca4("0012").maxCamber == 0.0);
    REQUIRE_THROWS_AS(parseNaca4("241"), std::invalid_argument);
    REQUIRE_THROWS_AS(parseNaca4("24a2"), std::invalid_argument);
    REQUIRE_THROWS_AS(parseNaca4("2400"), std::invalid_argument);
    REQUIRE_THROWS_AS(parseNaca4("2012"), std::invalid_argument);
    REQUIRE_THROWS_AS(parseNaca4("0412"), std::invalid_argument);
}

TEST_CASE("NACA thickness and camber match the published values", "[acsynt][naca]") {
    // NACA 0012: maximum half thickness 0.06 near x = 0.3 (tabulated 0.06002 at 0.3).
    REQUIRE(naca4HalfThickness(0.12, 0.3) == Approx(0.06).margin(1e-4));
    REQUIRE(naca4HalfThickness(0.12, 0.3) == Approx(0.0600172).margin(1e-6));
    REQUIRE(naca4HalfThickness(0.12, 0.0) == 0.0);
    // Open trailing edge: 0.00126 half thickness at x = 1 for 12 %; the closed one ends at zero.
    REQUIRE(naca4HalfThickness(0.12, 1.0) == Approx(0.00126).margin(1e-6));
    REQUIRE(std::abs(naca4HalfThickness(0.12, 1.0, TrailingEdge::Closed)) < 1e-15);
    const Naca4Airfoil a = parseNaca4("2412");
    REQUIRE(naca4Camber(a, 0.4) == Approx(0.02).margin(1e-15));
    REQUIRE(naca4CamberSlope(a, 0.4) == Approx(0.0).margin(1e-15));
    REQUIRE(naca4Camber(a, 0.0) == 0.0);
    REQUIRE(std::abs(naca4Camber(a, 1.0)) < 1e-15);
    REQUIRE(naca4Camber(a, 0.2) == Approx(0.02 / 0.16 * (0.16 - 0.04)));
    REQUIRE(naca4Camber(a, 0.7) == Approx(0.02 / 0.36 * (0.2 + 0.56 - 0.49)));
    // Upper and lower points are the camber point +- the thickness normal to the camber line.
    const glm::dvec2 up = naca4Upper(a, 0.4), lo = naca4Lower(a, 0.4);
    REQUIRE(up.x == Approx(0.4));
    REQUIRE(up.y == Approx(0.02 + naca4HalfThickness(0.12, 0.4)));
    REQUIRE(lo.y == Approx(0.02 - naca4HalfThickness(0.12, 0.4)));
}

TEST_CASE("an airfoil contour runs from the trailing edge over the top and back underneath",
          "[acsynt][naca]") {
    const std::vector<glm::dvec2> c = naca4Contour(parseNaca4("4415"), 21);
    REQUIRE(c.size() == 21);
    REQUIRE(c.front() == glm::dvec2(1.0, 0.0));
    REQUIRE(c.back() == glm::dvec2(1.0, 0.0));
    REQUIRE(c[10] == glm::dvec2(0.0, 0.0));
    for (std::size_t i = 1; i < 10; ++i) {
        REQUIRE(c[i].y > 0.0);
        REQUIRE(c[i].x < c[i - 1].x);
        REQUIRE(c[i].y > c[20 - i].y);
    }
    REQUIRE_THROWS_AS(naca4Contour(parseNaca4("0012"), 20), std::invalid_argument);
    REQUIRE_THROWS_AS(naca4Contour(parseNaca4("0012"), 3), std::invalid_argument);
}

}  // namespace test_naca4
