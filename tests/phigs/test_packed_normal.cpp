// PackedNormal over random directions of every octant and length: the direction comes back
// within its stated angle, axis directions and zero exactly, and packing what was unpacked
// stays within that angle of the original.

#include "phigs/traverse/PackedNormal.h"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include <cmath>
#include <random>

namespace test_packed_normal {

using namespace phigs;

namespace {

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace

TEST_CASE("packed normals keep their direction within 1e-4 radians", "[phigs][mesh]") {
    std::mt19937 rng(20261204);
    std::normal_distribution<float> gaussian(0.0f, 1.0f);
    std::uniform_real_distribution<float> scale(-6.0f, 6.0f), unit(-1.0f, 1.0f);
    double worst = 0.0;
    for (int i = 0; i < 200000; ++i) {
        glm::vec3 n(gaussian(rng), gaussian(rng), gaussian(rng));
        // Some lie near the octahedron's folds and the axes, where the encoding changes branch.
        if (i % 4 == 1) n[i % 3] = 1e-4f * unit(rng);
        if (i % 4 == 2) n[i % 3] = 0.0f, n[(i + 1) % 3] *= 1e-3f;
        if (glm::length(n) == 0.0f) continue;
        n *= std::pow(10.0f, scale(rng));
        const PackedNormal packed(n);
        const glm::vec3 back = packed.unpacked();
        REQUIRE(std::abs(glm::length(back) - 1.0f) < 1e-6f);
        worst = std::max(worst, angleBetween(glm::dvec3(n), glm::dvec3(back)));
        // Packing what was unpacked moves it by a quantum at most: a mesh re-packed (level curves
        // add interpolated vertices) does not drift.
        REQUIRE(angleBetween(glm::dvec3(n), glm::dvec3(PackedNormal(back).unpacked())) < 1e-4);
    }
    CHECK(worst < 1e-4);
    CHECK(worst > 0.0);  // the claim is about a real loss, not exactness
}

TEST_CASE("packed normals give axes and zero back exactly", "[phigs][mesh]") {
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {1.0f, -1.0f}) {
            glm::vec3 n(0.0f);
            n[axis] = sign * 3.0f;
            glm::vec3 expected(0.0f);
            expected[axis] = sign;
            CHECK(PackedNormal(n).unpacked() == expected);
        }
    CHECK(PackedNormal(glm::vec3(0.0f)).unpacked() == glm::vec3(0.0f));
    CHECK(PackedNormal().unpacked() == glm::vec3(0.0f));
    CHECK(PackedNormal(glm::vec3(NAN, 0.0f, 1.0f)).unpacked() == glm::vec3(0.0f));
    CHECK(PackedNormal(glm::vec3(INFINITY, 0.0f, 0.0f)).unpacked() == glm::vec3(0.0f));
}

TEST_CASE("packed normals keep the direction of huge and tiny vectors", "[phigs][mesh]") {
    // The largest component scales the vector first: a sum of 3e38s would overflow.
    const glm::vec3 huge = PackedNormal(glm::vec3(3e38f, 3e38f, -3e38f)).unpacked();
    CHECK(glm::length(huge - glm::normalize(glm::vec3(1, 1, -1))) < 1e-4f);
    // Subnormal components: the direction compared is the one the floats hold (1e-42f is not
    // exactly half of 2e-42f), normalised in double.
    const glm::vec3 small(1e-42f, -2e-42f, 0.0f);
    const glm::vec3 tiny = PackedNormal(small).unpacked();
    const glm::dvec3 expected = glm::normalize(glm::dvec3(small) * 1e42);
    CHECK(glm::length(glm::dvec3(tiny) - expected) < 1e-4);
}

}  // namespace test_packed_normal
