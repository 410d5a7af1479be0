#include "GeomTestUtil.h"
#include "geom/Evaluate.h"
#include "geom/GeometryError.h"
#include "geom/Primitives.h"
#include "geom/Tessellate.h"

#include "Sanitized.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

namespace test_tessellate {

using namespace geom;

namespace {

/// Every edge is used by one or two triangles, and the edges used once (the border) form closed
/// loops with as many edges as vertices: no T-junction or crack leaves a dangling edge.
void requireWatertightGrid(const SurfaceMesh& mesh) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            std::uint32_t a = mesh.triangles[t + static_cast<std::size_t>(e)];
            std::uint32_t b = mesh.triangles[t + static_cast<std::size_t>((e + 1) % 3)];
            if (a > b) std::swap(a, b);
            ++uses[{a, b}];
        }
    std::map<std::uint32_t, int> borderDegree;
    for (const auto& [edge, count] : uses) {
        REQUIRE(count <= 2);
        if (count == 1) {
            ++borderDegree[edge.first];
            ++borderDegree[edge.second];
        }
    }
    for (const auto& [vertex, degree] : borderDegree) REQUIRE(degree == 2);
}

}  // namespace

TEST_CASE("uniform tessellation lays a grid over the domain", "[geom][tessellate]") {
    const Surface sphere = makeSphere(1.0);
    const SurfaceMesh mesh = tessellateUniform(sphere, 8, 12);
    REQUIRE(mesh.positions.size() == 9 * 13);
    REQUIRE(mesh.normals.size() == mesh.positions.size());
    REQUIRE(mesh.uv.size() == mesh.positions.size());
    REQUIRE(mesh.triangles.size() == 8 * 12 * 6);
    for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
        REQUIRE(glm::length(mesh.positions[k] - evaluate(sphere, mesh.uv[k].x, mesh.uv[k].y)) < 1e-12);
        REQUIRE(glm::length(mesh.normals[k]) == Approx(1.0).margin(1e-12));
        // The sphere's normal is radial, even at the poles (collapsed edges).
        REQUIRE(glm::length(glm::cross(mesh.normals[k], mesh.positions[k])) < 1e-6);
    }
    REQUIRE(mesh.uv[2 * 13 + 5] == glm::dvec2(0.25, 5.0 / 12.0));
    // Triangles wind so that their normal agrees with the vertex normals.
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
        const glm::dvec3& a = mesh.positions[mesh.triangles[t]];
        const glm::dvec3& b = mesh.positions[mesh.triangles[t + 1]];
        const glm::dvec3& c = mesh.positions[mesh.triangles[t + 2]];
        const glm::dvec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) < 1e-12) continue;  // the degenerate triangles at a pole
        REQUIRE(glm::dot(n, mesh.normals[mesh.triangles[t]]) > 0.0);
    }
    REQUIRE_THROWS_WITH(tessellateUniform(sphere, 0, 4), Catch::Contains("at least 1"));
}

TEST_CASE("adaptive tessellation keeps within the tolerance of the true surface", "[geom][tessellate]") {
    const Surface torus = makeTorus(3.0, 1.0);
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::size_t previous = 0;
    for (double tolerance : {1e-1, 1e-2, 1e-3}) {
        const SurfaceMesh mesh = tessellateAdaptive(torus, tolerance);
        REQUIRE(mesh.positions.size() > previous);
        previous = mesh.positions.size();
        requireWatertightGrid(mesh);
        // Points inside triangles: their distance to the torus (exact, by the implicit form).
        double worst = 0.0;
        for (std::size_t t = 0; t < mesh.triangles.size(); t += 3)
            for (int k = 0; k < 3; ++k) {
                double a = unit(rng), b = unit(rng);
                if (a + b > 1) a = 1 - a, b = 1 - b;
                const glm::dvec3 x =
                    mesh.positions[mesh.triangles[t]] +
                    a * (mesh.positions[mesh.triangles[t + 1]] - mesh.positions[mesh.triangles[t]]) +
                    b * (mesh.positions[mesh.triangles[t + 2]] - mesh.positions[mesh.triangles[t]]);
                const double r = std::sqrt(x.x * x.x + x.y * x.y) - 3.0;
                worst = std::max(worst, std::abs(std::sqrt(r * r + x.z * x.z) - 1.0));
            }
        REQUIRE(worst <= tolerance);
        // Vertices lie on the surface.
        for (std::size_t k = 0; k < mesh.positions.size(); k += 7)
            REQUIRE(glm::length(mesh.positions[k] - evaluate(torus, mesh.uv[k].x, mesh.uv[k].y)) < 1e-12);
    }
}

TEST_CASE("adaptive tessellation of a multi-piece surface is crack-free", "[geom][tessellate]") {
    std::mt19937 rng(6);
    const Surface s = geomtest::bumpySurface(rng, 3, 2, 9, 7, true);
    const SurfaceMesh mesh = tessellateAdaptive(s, 1e-3);
    requireWatertightGrid(mesh);
    // Every Bézier piece boundary is a parameter line of the mesh, so no edge crosses one.
    for (double k : s.knotsU) {
        bool found = false;
        for (const auto& uv : mesh.uv) found = found || uv.x == k;
        REQUIRE(found);
    }
    REQUIRE_THROWS_WITH(tessellateAdaptive(s, 0.0), Catch::Contains("tolerance"));
    REQUIRE_THROWS_AS(tessellateAdaptive(s, std::nan("")), GeometryError);
}

TEST_CASE("adaptive tessellation of rational surfaces with weights over four decades keeps the tolerance",
          "[geom][tessellate]") {
    // Small weights squeeze much of a patch's shape into a sliver of its parameters, which lines
    // laid over whole spans reach only past the vertex limit.
    std::mt19937 rng(2026);
    std::uniform_real_distribution<double> unit(0.0, 1.0), side(-1.0, 1.0), decade(-2.0, 2.0);
    for (int member = 0; member < membersForBuild(12); ++member) {
        const int p = 1 + static_cast<int>(rng() % 4), q = 1 + static_cast<int>(rng() % 4);
        const std::size_t nu = static_cast<std::size_t>(p) + 1 + rng() % 4;
        const std::size_t nv = static_cast<std::size_t>(q) + 1 + rng() % 4;
        std::vector<glm::dvec3> points;
        std::vector<double> weights;
        for (std::size_t i = 0; i < nu; ++i)
            for (std::size_t j = 0; j < nv; ++j) {
                points.emplace_back(double(i) + 0.3 * side(rng), double(j) + 0.3 * side(rng), side(rng));
                weights.push_back(std::pow(10.0, decade(rng)));
            }
        const Surface s(p, q, geomtest::randomKnots(rng, p, nu, true),
                        geomtest::randomKnots(rng, q, nv, true), nu, nv, points, weights);
        const double tolerance = 2e-3 * std::hypot(double(nu), double(nv));
        const SurfaceMesh mesh = tessellateAdaptive(s, tolerance);
        requireWatertightGrid(mesh);
        for (std::size_t k = 0; k < mesh.positions.size(); k += 13)
            REQUIRE(glm::length(mesh.positions[k] - evaluate(s, mesh.uv[k].x, mesh.uv[k].y)) < 1e-9);
        // Each triangle's centroid and edge midpoints, and random points inside it, against the
        // surface at the same (u, v).
        double promised = 0.0, inside = 0.0;
        for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
            const std::uint32_t a = mesh.triangles[t], b = mesh.triangles[t + 1], c = mesh.triangles[t + 2];
            auto off = [&](double x, double y) {
                const double z = 1.0 - x - y;
                const glm::dvec2 uv = z * mesh.uv[a] + x * mesh.uv[b] + y * mesh.uv[c];
                return glm::length(evaluate(s, uv.x, uv.y) -
                                   (z * mesh.positions[a] + x * mesh.positions[b] + y * mesh.positions[c]));
            };
            promised =
                std::max({promised, off(1.0 / 3.0, 1.0 / 3.0), off(0.5, 0.0), off(0.5, 0.5), off(0.0, 0.5)});
            double x = unit(rng), y = unit(rng);
            if (x + y > 1.0) x = 1.0 - x, y = 1.0 - y;
            inside = std::max(inside, off(x, y));
        }
        CHECK(promised <= tolerance * (1.0 + 1e-9));
        CHECK(inside <= 1.5 * tolerance);
    }
}

TEST_CASE("mesh normals agree with normal() at every vertex, poles and apexes too, at any scale",
          "[geom][tessellate]") {
    std::mt19937 rng(1001);
    std::uniform_real_distribution<double> exponent(-8.0, 8.0), ratio(0.3, 3.0);
    auto requireNormalsAgree = [](const Surface& s, const SurfaceMesh& mesh) {
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::dvec3 reference = normal(s, mesh.uv[i].x, mesh.uv[i].y);
            INFO("vertex " << i << " at (" << mesh.uv[i].x << ", " << mesh.uv[i].y << ")");
            REQUIRE(glm::length(mesh.normals[i] - reference) < 1e-6);
        }
    };
    for (int trial = 0; trial < 24; ++trial) {
        const double radius = std::pow(10.0, trial < 2 ? (trial == 0 ? -8.0 : 8.0) : exponent(rng));
        INFO("radius " << radius);
        const Surface shapes[] = {makeSphere(radius), makeCone(radius, radius * ratio(rng))};
        for (const Surface& s : shapes) {
            const int segments = 4 + static_cast<int>(rng() % 13);
            requireNormalsAgree(s, tessellateUniform(s, segments, segments + static_cast<int>(rng() % 5)));
            requireNormalsAgree(s, tessellateAdaptive(s, radius * 1e-3));
        }
    }
}

TEST_CASE("curve tessellation keeps chords within the tolerance", "[geom][tessellate]") {
    const Curve circle = makeCircle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2.0);
    for (double tolerance : {1e-2, 1e-4}) {
        const std::vector<glm::dvec3> points = tessellate(circle, tolerance);
        REQUIRE(glm::length(points.front() - glm::dvec3(2, 0, 0)) < 1e-12);
        REQUIRE(glm::length(points.back() - glm::dvec3(2, 0, 0)) < 1e-12);
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            REQUIRE(std::abs(glm::length(points[i]) - 2.0) < 1e-12);
            // A chord's largest distance from the circle is at its midpoint.
            REQUIRE(2.0 - glm::length(0.5 * (points[i] + points[i + 1])) <= tolerance);
        }
        // The sagitta formula r (1 - cos(pi / n)) bounds how few chords suffice.
        const double fewest = M_PI / std::acos(1.0 - tolerance / 2.0);
        REQUIRE(static_cast<double>(points.size() - 1) >= fewest);
        REQUIRE(static_cast<double>(points.size() - 1) <= 4.0 * fewest + 8.0);
    }
    const Curve polyline(1, {0, 0, 1, 2, 2}, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    REQUIRE(tessellate(polyline, 1e-3).size() == 3);
    REQUIRE_THROWS_WITH(tessellate(circle, -1.0), Catch::Contains("tolerance"));
}

TEST_CASE("curve tessellation keeps its tolerance on every class, rational with wide weights too",
          "[geom][tessellate]") {
    // Degrees 1 to 9, random interior knots (some repeated), weights 1e-3..1e3 or none, scales
    // 1e-3..1e3 and far offsets: every point of the curve lies within tolerance of the polyline.
    std::mt19937 rng(20261206);
    std::uniform_real_distribution<double> unit(0.0, 1.0), coordinate(-1.0, 1.0);
    auto polylineDistance = [](const std::vector<glm::dvec3>& line, const glm::dvec3& q) {
        double best = 1e300;
        for (std::size_t j = 0; j + 1 < line.size(); ++j) {
            const glm::dvec3 ab = line[j + 1] - line[j];
            const double len2 = glm::dot(ab, ab);
            const double s = len2 > 0.0 ? std::clamp(glm::dot(q - line[j], ab) / len2, 0.0, 1.0) : 0.0;
            best = std::min(best, glm::length(line[j] + s * ab - q));
        }
        return best;
    };
    int exceeded = 0;
    for (int member = 0; member < 300; ++member) {
        const int p = 1 + member % 9;
        const std::size_t n = static_cast<std::size_t>(p) + 1 + std::size_t(unit(rng) * 6.0);
        std::vector<double> interior;
        for (std::size_t i = 0; i + static_cast<std::size_t>(p) + 1 < n; ++i)
            interior.push_back(interior.empty() || unit(rng) < 0.7 ? unit(rng) : interior.back());
        std::sort(interior.begin(), interior.end());
        std::vector<double> knots(static_cast<std::size_t>(p) + 1, 0.0);
        knots.insert(knots.end(), interior.begin(), interior.end());
        knots.insert(knots.end(), static_cast<std::size_t>(p) + 1, 1.0);
        const double scale = std::pow(10.0, 6.0 * unit(rng) - 3.0);
        const glm::dvec3 offset = member % 3 == 0 ? glm::dvec3(1e4 * scale) : glm::dvec3(0.0);
        std::vector<glm::dvec3> points;
        std::vector<double> weights;
        const double spread = member % 2 == 0 ? 3.0 : 0.0;  // half rational, weights 10^[-3, 3]
        for (std::size_t i = 0; i < n; ++i) {
            points.push_back(offset + scale * glm::dvec3(coordinate(rng), coordinate(rng), coordinate(rng)));
            if (spread > 0.0) weights.push_back(std::pow(10.0, spread * coordinate(rng)));
        }
        Curve curve;
        try {
            curve = Curve(p, knots, points, weights);
        } catch (const GeometryError&) {
            continue;  // a knot repeated past the degree
        }
        const double tolerance = scale * std::pow(10.0, -1.0 - 2.0 * unit(rng));
        const std::vector<glm::dvec3> line = tessellate(curve, tolerance);
        REQUIRE(line.size() < 200000);
        double worst = 0.0;
        for (int k = 0; k <= 2000; ++k)
            worst = std::max(worst, polylineDistance(line, evaluate(curve, k / 2000.0)));
        INFO("member " << member << ", degree " << p << ", " << line.size() << " vertices");
        CHECK(worst <= tolerance * (1.0 + 1e-9));
        exceeded += worst > tolerance * (1.0 + 1e-9);
    }
    REQUIRE(exceeded == 0);
    // Below what the coordinates resolve, a clear refusal at once rather than millions of halvings.
    const Curve far(
        3, {0, 0, 0, 0, 1, 1, 1, 1},
        {{1e8, 1e8, 1e8}, {1e8 + 1e-6, 1e8, 1e8}, {1e8, 1e8 + 1e-6, 1e8}, {1e8, 1e8, 1e8 + 1e-6}});
    REQUIRE_THROWS_WITH(tessellate(far, 1e-10), Catch::Contains("tolerance 1e-10 is below what coordinates"));
}

TEST_CASE("curve and surface tessellation give the same vertices at every scale of the coordinates",
          "[geom][tessellate][scale]") {
    // Scaling a curve and its tolerance by a power of two must scale the polyline and nothing
    // else, out to coordinates near 1e301 and down to 1e-181 (where squared distances overflow or
    // underflow): random curves of degree 1..7 (half rational) and random surfaces.
    std::mt19937 rng(20261207);
    const int exponents[] = {-600, -300, 200, 520, 1000};
    for (int member = 0; member < 40; ++member) {
        const int p = 1 + member % 7;
        const Curve curve = geomtest::randomCurve(rng, p, static_cast<std::size_t>(p) + 1 + member % 5,
                                                  member % 2 == 1, true);
        const double tolerance = 1e-3;
        const std::vector<glm::dvec3> base = tessellate(curve, tolerance);
        for (int e : exponents) {
            const double s = std::ldexp(1.0, e);
            Curve scaled = curve;
            for (glm::dvec3& q : scaled.points) q *= s;
            const std::vector<glm::dvec3> line = tessellate(scaled, tolerance * s);
            INFO("member " << member << ", degree " << p << ", scale 2^" << e);
            REQUIRE(line.size() == base.size());
            for (std::size_t i = 0; i < line.size(); ++i) REQUIRE(line[i] == base[i] * s);
        }
    }
    for (int member = 0; member < 12; ++member) {
        const int p = 1 + member % 3, q = 1 + (member / 3) % 3;
        const Surface surface =
            geomtest::randomSurface(rng, p, q, static_cast<std::size_t>(p) + 2,
                                    static_cast<std::size_t>(q) + 2, member % 2 == 1, true);
        const SurfaceMesh base = tessellateAdaptive(surface, 2e-2);
        for (int e : exponents) {
            const double s = std::ldexp(1.0, e);
            Surface scaled = surface;
            for (glm::dvec3& x : scaled.points) x *= s;
            const SurfaceMesh mesh = tessellateAdaptive(scaled, 2e-2 * s);
            INFO("surface " << member << ", scale 2^" << e);
            REQUIRE(mesh.positions.size() == base.positions.size());
            REQUIRE(mesh.triangles == base.triangles);
            for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
                REQUIRE(mesh.positions[i] == base.positions[i] * s);
                REQUIRE(mesh.normals[i] == base.normals[i]);
            }
        }
    }
}

TEST_CASE("a quadratic arc past 1e154 is tessellated within its tolerance", "[geom][tessellate][scale]") {
    // The tester's case: at s = 1e155 and beyond one chord came back, 354 times the tolerance off.
    for (double s : {1e100, 1e155, 1e200, 1e300}) {
        const Curve arc(2, {0, 0, 0, 1, 1, 1}, {{s, 0, 0}, {s, s, 0}, {0, s, 0}});
        const std::vector<glm::dvec3> line = tessellate(arc, 1e-3 * s);
        CAPTURE(s, line.size());
        REQUIRE(line.size() == 33);
        // Measured in units of s, where nothing overflows.
        for (int k = 0; k <= 400; ++k) {
            const glm::dvec3 x = evaluate(arc, k / 400.0) / s;
            double best = 1e300;
            for (std::size_t j = 0; j + 1 < line.size(); ++j) {
                const glm::dvec3 a = line[j] / s, ab = line[j + 1] / s - a;
                const double t = std::clamp(glm::dot(x - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
                best = std::min(best, glm::length(a + t * ab - x));
            }
            REQUIRE(best <= 1e-3);
        }
    }
}

}  // namespace test_tessellate
