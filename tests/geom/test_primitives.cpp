#include "geom/Curvature.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/GridEvaluator.h"
#include "geom/KnotInsertion.h"
#include "geom/Primitives.h"
#include "geom/Tessellate.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace test_primitives {

using namespace geom;

namespace {

template <class F>
double worstOver(const Surface& s, F&& error, int samples = 40) {
    double worst = 0.0;
    for (int i = 0; i <= samples; ++i)
        for (int j = 0; j <= samples; ++j) {
            const double u = s.domainStartU() + (s.domainEndU() - s.domainStartU()) * i / samples;
            const double v = s.domainStartV() + (s.domainEndV() - s.domainStartV()) * j / samples;
            worst = std::max(worst, std::abs(error(evaluate(s, u, v), u, v)));
        }
    return worst;
}

double radial(const glm::dvec3& p) {
    return std::sqrt(p.x * p.x + p.y * p.y);
}

}  // namespace

TEST_CASE("rational quadrics evaluate to their analytic shapes within 1e-12", "[geom][exact]") {
    const Curve circle = makeCircle({1, 2, 3}, {0, 1, 0}, {0, 0, 1}, 2.5);
    for (int i = 0; i <= 400; ++i) {
        const glm::dvec3 p = evaluate(circle, i / 400.0);
        REQUIRE(std::abs(glm::length(p - glm::dvec3(1, 2, 3)) - 2.5) < 1e-12);
        REQUIRE(std::abs(p.x - 1.0) < 1e-12);
    }
    const Surface sphere = makeSphere(2.0);
    REQUIRE(worstOver(sphere, [](const glm::dvec3& p, double, double) { return glm::length(p) - 2.0; }) <
            1e-12);
    const Surface cylinder = makeCylinder(1.5, 3.0);
    REQUIRE(worstOver(cylinder, [](const glm::dvec3& p, double, double) { return radial(p) - 1.5; }) < 1e-12);
    REQUIRE(worstOver(cylinder, [](const glm::dvec3& p, double u, double) { return p.z - 3.0 * u; }) < 1e-12);
    const Surface cone = makeCone(2.0, 4.0);
    REQUIRE(worstOver(cone, [](const glm::dvec3& p, double, double) {
                return radial(p) - 2.0 * (1 - p.z / 4.0);
            }) < 1e-12);
    const Surface torus = makeTorus(3.0, 1.0);
    REQUIRE(worstOver(torus, [](const glm::dvec3& p, double, double) {
                const double a = radial(p) - 3.0;
                return std::sqrt(a * a + p.z * p.z) - 1.0;
            }) < 1e-12);
    // Knot refinement keeps them exact.
    const std::vector<double> extra{0.1, 0.3, 0.3, 0.77};
    const Surface refined = refineKnotsV(refineKnotsU(torus, extra), extra);
    REQUIRE(worstOver(refined, [](const glm::dvec3& p, double, double) {
                const double a = radial(p) - 3.0;
                return std::sqrt(a * a + p.z * p.z) - 1.0;
            }) < 1e-12);
}

TEST_CASE("normals and curvatures of the quadrics", "[geom][curvature]") {
    const Surface sphere = makeSphere(2.0);
    for (double u : {0.1, 0.3, 0.5, 0.61, 0.9})
        for (double v : {0.0, 0.2, 0.45, 0.8}) {
            const glm::dvec3 p = evaluate(sphere, u, v);
            const glm::dvec3 n = normal(sphere, u, v);
            REQUIRE(glm::length(glm::cross(n, p / 2.0)) < 1e-12);
            const SurfaceCurvature c = curvature(sphere, u, v);
            REQUIRE(c.gaussian == Approx(0.25).epsilon(1e-11));
            REQUIRE(std::abs(c.mean) == Approx(0.5).epsilon(1e-11));
        }
    // The poles are collapsed edges: the normal is still the radial direction.
    REQUIRE(glm::length(glm::cross(normal(sphere, 0.0, 0.3), glm::dvec3(0, 0, 1))) < 1e-6);
    REQUIRE(glm::length(glm::cross(normal(sphere, 1.0, 0.7), glm::dvec3(0, 0, 1))) < 1e-6);
    REQUIRE_THROWS_WITH(curvature(sphere, 0.0, 0.3), Catch::Contains("degenerate"));
    // The same at every scale: rounding leaves a cross product of noise at a pole, whose size
    // follows the sphere's; away from the poles the curvatures are 1 / r^2 and 1 / r.
    for (double r : {1e-6, 1e-4, 1e-2, 1.0, 1e2, 1e4, 1e6}) {
        INFO("radius " << r);
        const Surface scaled = makeSphere(r);
        for (double v : {0.0, 0.3, 0.77}) {
            REQUIRE_THROWS_WITH(curvature(scaled, scaled.domainStartU(), v), Catch::Contains("degenerate"));
            REQUIRE_THROWS_WITH(curvature(scaled, scaled.domainEndU(), v), Catch::Contains("degenerate"));
        }
        const SurfaceCurvature c = curvature(scaled, 0.3, 0.4);
        REQUIRE(c.gaussian * r * r == Approx(1.0).epsilon(1e-10));
        REQUIRE(std::abs(c.mean) * r == Approx(1.0).epsilon(1e-10));
    }

    const Surface cylinder = makeCylinder(1.5, 3.0);
    const SurfaceCurvature cc = curvature(cylinder, 0.4, 0.3);
    REQUIRE(std::abs(cc.gaussian) < 1e-12);
    REQUIRE(std::abs(cc.mean) == Approx(1.0 / 3.0).epsilon(1e-11));

    const Surface torus = makeTorus(3.0, 1.0);
    // On the outer equator K = 1 / (r (R + r)); on the inner one K = -1 / (r (R - r)).
    const double kOuter = curvature(torus, 0.0, 0.2).gaussian;
    const double kInner = curvature(torus, 0.5, 0.2).gaussian;
    REQUIRE(kOuter == Approx(1.0 / 4.0).epsilon(1e-10));
    REQUIRE(kInner == Approx(-1.0 / 2.0).epsilon(1e-10));
}

TEST_CASE("principal curvatures are exact at umbilics and agree with K and H elsewhere",
          "[geom][curvature]") {
    // At an umbilic (every point of a sphere) H^2 - K is a difference of near equal numbers:
    // principal curvatures taken from it lost half their digits (2.6e-8 on the unit sphere).
    std::mt19937 rng(404);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const double r = std::pow(10.0, -3.0 + 6.0 * unit(rng));
        const Surface sphere = makeSphere(r);
        const double u = 0.05 + 0.9 * unit(rng), v = unit(rng);
        const SurfaceCurvature c = curvature(sphere, u, v);
        INFO("radius " << r << " at " << u << ", " << v);
        CHECK(std::abs(c.principalMin * r) == Approx(1.0).epsilon(1e-12));
        CHECK(std::abs(c.principalMax * r) == Approx(1.0).epsilon(1e-12));
    }
    // Elsewhere (a torus, random points): min <= max, their product K and their mean H.
    const Surface torus = makeTorus(3.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const SurfaceCurvature c = curvature(torus, unit(rng), unit(rng));
        CHECK(c.principalMin <= c.principalMax);
        CHECK(c.principalMin * c.principalMax == Approx(c.gaussian).margin(1e-12));
        CHECK(0.5 * (c.principalMin + c.principalMax) == Approx(c.mean).margin(1e-12));
    }
}

TEST_CASE("normals next to and on a pole are exact at every size and place", "[geom][curvature]") {
    // Next to a collapsed edge the derivatives across it were differences of terms as large as
    // the coordinates (at the pole itself rounding noise that passed for a direction): a sphere
    // of radius 1e-3 had normals 90 degrees off at its poles, one 1e4 radii from the origin 0.6
    // rad off at 1e-12 of them. Per point (normal) and on a grid (GridEvaluator), spheres of radius
    // 1e-3..1e4 centred up to 1e4 radii away, at 0 and 1e-14..1e-2 from either pole.
    std::mt19937 rng(86);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 30; ++trial) {
        const double r = std::pow(10.0, -3.0 + 7.0 * unit(rng));
        const double away = trial % 3 == 0 ? 0.0 : r * std::pow(10.0, 4.0 * unit(rng));
        const glm::dvec3 centre =
            away * glm::normalize(glm::dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
        Surface sphere = makeSphere(r);
        for (glm::dvec3& q : sphere.points) q += centre;
        std::vector<double> us{0.0, 1.0}, vs;
        for (int k = 0; k < 6; ++k) {
            const double d = std::pow(10.0, -14.0 + 12.0 * unit(rng));
            us.push_back(d), us.push_back(1.0 - d);
            vs.push_back(unit(rng));
        }
        std::sort(us.begin(), us.end());
        std::sort(vs.begin(), vs.end());
        const std::vector<GridSample> grid = GridEvaluator(sphere).evaluate(us, vs);
        // The reference is the radial direction from the centre, good to the rounding of the
        // point's coordinates against the radius; at the pole itself too (the exact limit).
        const double reference = 1e-13 * (1.0 + away / r);
        for (std::size_t i = 0; i < us.size(); ++i)
            for (std::size_t j = 0; j < vs.size(); ++j) {
                const glm::dvec3 radial = glm::normalize(evaluate(sphere, us[i], vs[j]) - centre);
                const double allowed = 1e-10 + reference;
                INFO("radius " << r << " at " << away << ", u " << us[i]);
                REQUIRE(glm::length(glm::cross(normal(sphere, us[i], vs[j]), radial)) < allowed);
                REQUIRE(glm::length(glm::cross(grid[i * vs.size() + j].normal, radial)) < allowed);
            }
    }
}

TEST_CASE("normals at a pole row stored in single precision are the pole's, on every path",
          "[geom][curvature]") {
    // A C program hands its grid over as Pfloat homogeneous points: the pole row's points then
    // agree to 1e-8 only, and Su there was a derivative of 1e-8 in a direction of no meaning,
    // taken for the normal's (a black spot at each pole of a shaded sphere). Spheres of radius
    // 1e-2..1e2 from 1 to 1,000 radii from the origin, their homogeneous points rounded to float: the
    // normals at the poles, per point, on a grid and in the adaptive mesh, are the axis's.
    std::mt19937 rng(87);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 30; ++trial) {
        const double r = std::pow(10.0, -2.0 + 4.0 * unit(rng));
        const glm::dvec3 centre =
            std::pow(10.0, 3.0 * unit(rng)) * r *
            glm::normalize(glm::dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5));
        Surface sphere = makeSphere(r);
        for (std::size_t k = 0; k < sphere.points.size(); ++k) {
            const double w = sphere.weights.empty() ? 1.0 : sphere.weights[k];
            const float wf = static_cast<float>(w);
            sphere.points[k] = glm::dvec3(glm::vec3((sphere.points[k] + centre) * w)) / double(wf);
            if (!sphere.weights.empty()) sphere.weights[k] = wf;
        }
        const double u0 = sphere.domainStartU(), u1 = sphere.domainEndU();
        const std::vector<double> us{u0, u1}, vs{0.1, 0.37, 0.5, 0.81};
        const std::vector<GridSample> grid = GridEvaluator(sphere).evaluate(us, vs);
        INFO("radius " << r << " at " << glm::length(centre));
        for (std::size_t i = 0; i < us.size(); ++i)
            for (std::size_t j = 0; j < vs.size(); ++j) {
                const glm::dvec3 radial = glm::normalize(evaluate(sphere, us[i], vs[j]) - centre);
                CHECK(std::abs(glm::dot(normal(sphere, us[i], vs[j]), radial)) > 1.0 - 1e-6);
                CHECK(std::abs(glm::dot(grid[i * vs.size() + j].normal, radial)) > 1.0 - 1e-6);
            }
        const SurfaceMesh mesh = tessellateAdaptive(sphere, 1e-3 * r);
        for (std::size_t k = 0; k < mesh.positions.size(); ++k)
            if (mesh.uv[k].x == u0 || mesh.uv[k].x == u1) {
                const glm::dvec3 radial = glm::normalize(mesh.positions[k] - centre);
                CHECK(std::abs(glm::dot(mesh.normals[k], radial)) > 1.0 - 1e-6);
            }
    }
}

TEST_CASE("curvature next to a pole is exact at every size and place", "[geom][curvature]") {
    // Next to a collapsed edge the derivatives across it are as small as the distance to it;
    // taken from the origin they lost their digits (a unit sphere's Gaussian curvature 25% off at
    // 1e-8 of a pole, 5,800 times off at 1e-9 with radius 1e-3). Spheres of radius 1e-3..1e4
    // centred up to 1e4 radii away, at 1e-14..1e-2 of either pole.
    std::mt19937 rng(85);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 40; ++trial) {
        const double r = std::pow(10.0, -3.0 + 7.0 * unit(rng));
        const glm::dvec3 centre = r * std::pow(10.0, 4.0 * unit(rng)) *
                                  glm::dvec3(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
        Surface sphere = makeSphere(r);
        for (glm::dvec3& q : sphere.points) q += centre;
        for (int k = 0; k < 10; ++k) {
            const double d = std::pow(10.0, -14.0 + 12.0 * unit(rng)), v = unit(rng);
            const double u = k % 2 == 0 ? sphere.domainStartU() + d : sphere.domainEndU() - d;
            INFO("radius " << r << " at " << glm::length(centre) << ", " << d << " from a pole");
            const SurfaceCurvature c = curvature(sphere, u, v);
            REQUIRE(c.gaussian * r * r == Approx(1.0).epsilon(1e-9));
            REQUIRE(std::abs(c.mean) * r == Approx(1.0).epsilon(1e-9));
        }
    }
    // A surface of any other shape with a pole: the curvatures follow a move and a scale of it.
    for (int trial = 0; trial < 20; ++trial) {
        const int p = 2 + trial % 3, q = 2 + (trial / 3) % 3;
        const std::size_t nu = static_cast<std::size_t>(p) + 2, nv = static_cast<std::size_t>(q) + 3;
        std::vector<glm::dvec3> points;
        std::vector<double> weights;
        const double apex = unit(rng);
        for (std::size_t i = 0; i < nu; ++i)
            for (std::size_t j = 0; j < nv; ++j) {
                // Row 0 is the pole: one point, as many times as the row is long.
                const double angle = 6.283185307179586 * double(j) / double(nv);
                const double radius = i == 0 ? 0.0 : double(i) + 0.3 * unit(rng);
                const double height = i == 0 ? apex : -double(i * i) + unit(rng);
                points.emplace_back(radius * std::cos(angle), radius * std::sin(angle), height);
                weights.push_back(std::pow(10.0, -1.0 + 2.0 * unit(rng)));
            }
        std::vector<double> ku(static_cast<std::size_t>(p) + 1, 0.0),
            kv(static_cast<std::size_t>(q) + 1, 0.0);
        for (std::size_t k = 1; k + static_cast<std::size_t>(p) < nu; ++k)
            ku.push_back(double(k) / double(nu - p));
        for (std::size_t k = 1; k + static_cast<std::size_t>(q) < nv; ++k)
            kv.push_back(double(k) / double(nv - q));
        ku.insert(ku.end(), static_cast<std::size_t>(p) + 1, 1.0);
        kv.insert(kv.end(), static_cast<std::size_t>(q) + 1, 1.0);
        const Surface s(p, q, ku, kv, nu, nv, points, weights);
        const double scale = std::pow(10.0, -3.0 + 6.0 * unit(rng));
        const glm::dvec3 shift = 1e4 * scale * glm::dvec3(unit(rng), unit(rng), unit(rng));
        std::vector<glm::dvec3> placed = points;
        for (glm::dvec3& x : placed) x = scale * x + shift;
        const Surface moved(p, q, ku, kv, nu, nv, placed, weights);
        for (double d : {1e-3, 1e-6, 1e-9, 1e-12}) {
            const double v = unit(rng);
            const SurfaceCurvature a = curvature(s, d, v), b = curvature(moved, d, v);
            INFO("degrees " << p << " x " << q << ", scale " << scale << ", " << d << " from the pole");
            REQUIRE(b.gaussian * scale * scale == Approx(a.gaussian).epsilon(1e-7));
            REQUIRE(b.mean * scale == Approx(a.mean).epsilon(1e-7));
        }
    }
}

TEST_CASE("primitive constructors refuse bad sizes", "[geom][exact]") {
    REQUIRE_THROWS_WITH(makeSphere(-1.0), Catch::Contains("radius"));
    REQUIRE_THROWS_WITH(makeTorus(1.0, 2.0), Catch::Contains("minor radius"));
    REQUIRE_THROWS_AS(makeCylinder(1.0, std::nan("")), GeometryError);
}

}  // namespace test_primitives
