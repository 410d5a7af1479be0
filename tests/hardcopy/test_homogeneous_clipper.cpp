// The hardcopy's clipper on polygons and polylines with one vertex far away (1e15 to 1e300).
// Interpolating from the far end put the cut of the edge coming back from a vertex at 1e20 at the
// page's other side, and a polyline entering from far away entered at the first plane's cut.
#include "phigs/hardcopy/HomogeneousClipper.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace test_homogeneous_clipper {

using namespace phigs::hardcopy;

namespace {

/// The unit cube as half spaces of (x, y, z, 1).
std::vector<HalfSpace> unitCube() {
    std::vector<HalfSpace> cube;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec4 low(0.0), high(0.0);
        low[axis] = 1.0, high[axis] = -1.0, high[3] = 1.0;
        cube.push_back({low, 0.0});
        cube.push_back({high, 0.0});
    }
    return cube;
}

/// Distance from p to the line through a and b, from the nearer end (the other may be far).
double offLine(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 d = b - a;  // scaled before its length: squares of 1e300 overflow
    const glm::dvec3 direction = glm::normalize(d / std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}));
    const glm::dvec3 near = glm::length(a / 1e100) <= glm::length(b / 1e100) ? a : b;
    return glm::length(glm::cross(p - near, direction));
}

/// A shape of 3 to 6 vertices in the cube's middle, one of them moved 1e15 to 1e300 away
/// (in the plane z = 0.5 where flat).
std::vector<ClipVertex> farShape(std::mt19937& rng, bool flat) {
    std::uniform_real_distribution<double> unit(0.05, 0.95), exponent(15.0, 300.0), sign(-1.0, 1.0);
    std::vector<ClipVertex> shape(3 + rng() % 4);
    for (ClipVertex& v : shape) v.h = {unit(rng), unit(rng), flat ? 0.5 : unit(rng), 1.0};
    const glm::dvec3 away(sign(rng), sign(rng), flat ? 0.0 : sign(rng));
    const glm::dvec3 far = glm::dvec3(0.5) + std::pow(10.0, exponent(rng)) * glm::normalize(away);
    shape[rng() % shape.size()].h = glm::dvec4(far, 1.0);
    return shape;
}

/// Even-odd inside test of a polygon's (x, y), each edge's crossing taken from its nearer end.
bool insideEvenOdd(const std::vector<ClipVertex>& polygon, double x, double y) {
    bool inside = false;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        glm::dvec2 a(polygon[i].h), b(polygon[(i + 1) % polygon.size()].h);
        if ((a.y > y) == (b.y > y)) continue;
        if (std::abs(a.x) + std::abs(a.y) > std::abs(b.x) + std::abs(b.y)) std::swap(a, b);
        if (a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x) > x) inside = !inside;
    }
    return inside;
}

}  // namespace

TEST_CASE("clipper: a polygon with a far vertex keeps exactly its part of the volume", "[hardcopy]") {
    std::mt19937 rng(6122026);
    const std::vector<HalfSpace> cube = unitCube();
    for (int member = 0; member < 200; ++member) {
        const std::vector<ClipVertex> polygon = farShape(rng, true);
        const std::vector<ClipVertex> clipped = clipPolygon(polygon, cube);
        INFO("member " << member << ", " << polygon.size() << " vertices");
        REQUIRE(clipped.size() >= 3);
        int differing = 0;
        for (int i = 0; i < 40; ++i)
            for (int j = 0; j < 40; ++j) {
                const double x = (i + 0.5) / 40.0, y = (j + 0.5) / 40.0;
                bool nearEdge = false;
                for (std::size_t k = 0; k < polygon.size(); ++k)
                    nearEdge = nearEdge || offLine({x, y, 0.5}, glm::dvec3(polygon[k].h),
                                                   glm::dvec3(polygon[(k + 1) % polygon.size()].h)) < 1e-9;
                if (!nearEdge && insideEvenOdd(polygon, x, y) != insideEvenOdd(clipped, x, y)) ++differing;
            }
        CHECK(differing == 0);
        for (const ClipVertex& v : clipped)
            for (int axis = 0; axis < 3; ++axis) CHECK((v.h[axis] >= -1e-12 && v.h[axis] <= 1.0 + 1e-12));
    }
}

TEST_CASE("clipper: a polyline's cuts by a far vertex lie on its segments and in the volume", "[hardcopy]") {
    std::mt19937 rng(7122026);
    const std::vector<HalfSpace> cube = unitCube();
    for (int member = 0; member < 200; ++member) {
        const std::vector<ClipVertex> line = farShape(rng, false);
        INFO("member " << member << ", " << line.size() << " vertices");
        std::size_t vertices = 0;
        for (const auto& run : clipPolyline(line, cube))
            for (const ClipVertex& v : run) {
                const glm::dvec3 p(v.h);
                ++vertices;
                double nearest = INFINITY;
                for (std::size_t k = 0; k + 1 < line.size(); ++k)
                    nearest = std::min(nearest, offLine(p, glm::dvec3(line[k].h), glm::dvec3(line[k + 1].h)));
                CHECK(nearest <= 1e-12);
                for (int axis = 0; axis < 3; ++axis) CHECK((p[axis] >= -1e-12 && p[axis] <= 1.0 + 1e-12));
            }
        CHECK(vertices >= 2);  // the near vertices stay
    }
}

}  // namespace test_homogeneous_clipper
