#include "CurveMapTestUtil.h"

#include "geom/GeometryError.h"
#include "geom/curvemap/SampleSurfaces.h"
#include "geom/curvemap/Staircase.h"

#include <numbers>

namespace test_curvemap_staircase {

using namespace geom;
using namespace geom::curvemap;
using namespace curvemap_test;

namespace {

double distanceToPolyline(const glm::dvec2& p, const std::vector<glm::dvec2>& poly) {
    double best = 1e300;
    for (std::size_t k = 0; k + 1 < poly.size(); ++k) {
        const glm::dvec2 ab = poly[k + 1] - poly[k];
        const double len2 = glm::dot(ab, ab);
        const double t = len2 > 0 ? std::clamp(glm::dot(p - poly[k], ab) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, glm::length(p - (poly[k] + t * ab)));
    }
    return best;
}

void checkStaircase(const std::vector<glm::dvec2>& loop, const std::vector<glm::dvec2>& stair, double tol) {
    REQUIRE(stair.size() >= 5);
    CHECK(stair.front() == stair.back());
    for (std::size_t i = 0; i + 1 < stair.size(); ++i) {
        INFO("edge " << i);
        CHECK((stair[i].x == stair[i + 1].x || stair[i].y == stair[i + 1].y));
        for (int k = 0; k <= 8; ++k)
            CHECK(distanceToPolyline(glm::mix(stair[i], stair[i + 1], k / 8.0), loop) <= tol * (1 + 1e-12));
    }
    for (const glm::dvec2& p : loop) CHECK(distanceToPolyline(p, stair) <= tol * (1 + 1e-12));
    double perimeter = 0.0;
    for (std::size_t i = 0; i + 1 < loop.size(); ++i) perimeter += glm::length(loop[i + 1] - loop[i]);
    CHECK(std::abs(signedArea(stair) - signedArea(loop)) <= perimeter * tol);
}

}  // namespace

TEST_CASE("staircase of a circle: iso-parametric steps within the tolerance", "[geom][curvemap][staircase]") {
    std::vector<glm::dvec2> circle;
    for (int k = 0; k <= 200; ++k) {
        const double a = 2 * std::numbers::pi * k / 200.0;
        circle.push_back({2 + std::cos(a), 3 + std::sin(a)});
    }
    circle.back() = circle.front();
    std::size_t previous = 1u << 30;
    for (double tol : {1e-3, 1e-2, 5e-2}) {
        INFO("tolerance " << tol);
        const std::vector<glm::dvec2> stair = staircaseApproximation(circle, tol);
        checkStaircase(circle, stair, tol);
        CHECK(stair.size() < previous);
        previous = stair.size();
    }
}

TEST_CASE("staircase of an axis-aligned rectangle is a rectangle: four steps' worth",
          "[geom][curvemap][staircase]") {
    const std::vector<glm::dvec2> rect{{0, 0}, {2, 0}, {2, 1}, {0, 1}, {0, 0}};
    const std::vector<glm::dvec2> stair = staircaseApproximation(rect, 1e-3);
    CHECK(stair.size() == 5);
    checkStaircase(rect, stair, 1e-3);
}

TEST_CASE("staircase of mapped logo loops", "[geom][curvemap][staircase]") {
    const CurveMapper wave(makeWaveSurface());
    const std::vector<Curve> logo = loadCurves("acslogo.crv");
    Placement place;
    place.reference = {4, 4};
    place.quarterTurns = 2;
    const MapResult r = wave.map(logo, place, {1e-3});
    for (const MappedPart& part : r.parts)
        for (const MappedLoop& loop : part.loops)
            checkStaircase(loop.uv, staircaseApproximation(loop.uv, 0.01), 0.01);
}

TEST_CASE("staircase rejects bad input", "[geom][curvemap][staircase]") {
    CHECK_THROWS_AS(staircaseApproximation({{0, 0}, {1, 0}, {0, 0}}, 0.0), GeometryError);
    CHECK_THROWS_WITH(staircaseApproximation({{0, 0}, {0, 0}}, 0.1), Catch::Contains("at least 3"));
    CHECK_THROWS_WITH(staircaseApproximation({{0, 0}, {std::nan(""), 0}, {1, 1}, {0, 0}}, 0.1),
                      Catch::Contains("not finite"));
}

}  // namespace test_curvemap_staircase
