// The transformation utilities (ISO 9592 clause 4.7) the C binding's p*_matrix functions use.

#include "phigs/core/TransformUtilities.h"

#include <catch2/catch.hpp>

#include <numbers>

namespace test_transform_utilities {

using namespace phigs;

namespace {

bool near(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::all(glm::lessThan(glm::abs(a - b), glm::dvec3(1e-12)));
}

}  // namespace

TEST_CASE("translate, scale and rotate act on column vectors", "[transform]") {
    const double quarter = std::numbers::pi / 2;
    CHECK(near(*transformPoint3(translate3({1, 2, 3}), {1, 1, 1}), {2, 3, 4}));
    CHECK(near(*transformPoint3(scale3({2, 3, 4}), {1, 1, 1}), {2, 3, 4}));
    CHECK(near(*transformPoint3(rotateX(quarter), {0, 1, 0}), {0, 0, 1}));
    CHECK(near(*transformPoint3(rotateY(quarter), {0, 0, 1}), {1, 0, 0}));
    CHECK(near(*transformPoint3(rotateZ(quarter), {1, 0, 0}), {0, 1, 0}));
    const glm::dvec2 r = *transformPoint2(rotate2(quarter) * scale2({2, 2}) * translate2({1, 0}), {0, 0});
    CHECK(r.x == Approx(0).margin(1e-12));
    CHECK(r.y == Approx(2));
}

TEST_CASE("build scales, rotates x, y, z about the fixed point, then shifts, compose applies it first",
          "[transform]") {
    const double quarter = std::numbers::pi / 2;
    const glm::dmat4 built = buildTransformationMatrix3({1, 1, 0}, {0, 0, 5}, {0, 0, quarter}, {2, 2, 2});
    CHECK(near(*transformPoint3(built, {2, 1, 0}), {1, 3, 5}));
    CHECK(near(*transformPoint3(built, {1, 1, 0}), {1, 1, 5}));  // the fixed point only shifts
    // x first, then y: (0, 1, 0) -> x 90 -> (0, 0, 1) -> y 90 -> (1, 0, 0)
    CHECK(near(
        *transformPoint3(buildTransformationMatrix3({0, 0, 0}, {0, 0, 0}, {quarter, quarter, 0}, {1, 1, 1}),
                         {0, 1, 0}),
        {1, 0, 0}));
    const glm::dmat4 composed = composeTransformationMatrix3(translate3({10, 0, 0}), {1, 1, 0}, {0, 0, 5},
                                                             {0, 0, quarter}, {2, 2, 2});
    // m first ((2, 1, 0) -> (12, 1, 0)), then the built transformation: scale 2 and a quarter
    // turn about (1, 1, 0), shift 5 in z.
    CHECK(near(*transformPoint3(composed, {2, 1, 0}), {1, 23, 5}));
    const glm::dmat3 built2 = buildTransformationMatrix2({1, 1}, {1, 0}, quarter, {1, 1});
    const glm::dvec2 p = *transformPoint2(built2, {2, 1});
    CHECK(p.x == Approx(2));
    CHECK(p.y == Approx(2));
    const glm::dvec2 q = *transformPoint2(
        composeTransformationMatrix2(translate2({10, 0}), {1, 1}, {1, 0}, quarter, {1, 1}), {2, 1});
    CHECK(q.x == Approx(2));  // (2, 1) -> (12, 1) -> quarter turn about (1, 1) -> (1, 12) -> shift
    CHECK(q.y == Approx(12));
}

TEST_CASE("transform point refuses w = 0", "[transform]") {
    CHECK_FALSE(transformPoint3(glm::dmat4(0.0), {1, 1, 1}));
    CHECK_FALSE(transformPoint2(glm::dmat3(0.0), {1, 1}));
}

}  // namespace test_transform_utilities
