// C. Molt, Implementation Aspects of Bézier Surfaces to Model Complex Geometric Forms (1994):
// adaptive midpoint subdivision of Bézier patches and its tree invariants (chapter 3).
#include "geom/Bezier.h"
#include "geom/BezierSubdivision.h"
#include "geom/GeometryError.h"

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <random>
#include <tuple>

namespace test_molt_subdivision {

using namespace geom;

namespace {

std::vector<glm::dvec3> bladeNet(std::mt19937& rng, std::size_t nu, std::size_t nv) {
    std::uniform_real_distribution<double> noise(-0.02, 0.02);
    std::vector<glm::dvec3> net;
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const double x = static_cast<double>(i) / (nu - 1), y = static_cast<double>(j) / (nv - 1);
            net.emplace_back(x, y, 0.3 * std::sin(3 * x) * y + noise(rng));
        }
    return net;
}

glm::dvec3 evaluateNet(const std::vector<glm::dvec3>& net, std::size_t nu, std::size_t nv, double u,
                       double v) {
    std::vector<glm::dvec3> column(nu);
    for (std::size_t i = 0; i < nu; ++i)
        column[i] = deCasteljau<glm::dvec3>(std::span<const glm::dvec3>(net).subspan(i * nv, nv), v);
    return deCasteljau<glm::dvec3>(column, u);
}

void requireTreeInvariants(const SubdivisionStats& s, std::size_t pointsPerLeaf) {
    REQUIRE((s.leaves - 1) % 3 == 0);
    const std::size_t inner = (s.leaves - 1) / 3;
    REQUIRE(s.splits == 3 * inner);
    REQUIRE(s.gens == 1 + 4 * inner);
    REQUIRE(s.points == s.leaves * pointsPerLeaf);
}

}  // namespace

TEST_CASE("fixed-depth subdivision: 4^k leaves and the blade point counts", "[geom][molt]") {
    std::mt19937 rng(2);
    for (int k = 0; k <= 3; ++k) {
        const auto net = bladeNet(rng, 4, 4);
        SubdivisionStats stats;
        const auto leaves = subdivideAdaptive(net, 4, 4, {StoppingRule::FixedDepth, 0.0, k}, &stats);
        REQUIRE(leaves.size() == static_cast<std::size_t>(std::pow(4, k)));
        requireTreeInvariants(stats, 16);
        REQUIRE(stats.minDepth == k);
        REQUIRE(stats.maxDepth == k);
    }
    // Depth 3 on the two patches of a 50 x 11 blade gives 70,400 points (75 x 11: 105,600).
    for (const auto& [nu, expected] : {std::pair<std::size_t, std::size_t>{50, 70400}, {75, 105600}}) {
        std::size_t points = 0;
        for (int side = 0; side < 2; ++side) {
            SubdivisionStats stats;
            subdivideAdaptive(bladeNet(rng, nu, 11), nu, 11, {StoppingRule::FixedDepth, 0.0, 3}, &stats);
            points += stats.points;
        }
        REQUIRE(points == expected);
    }
}

TEST_CASE("adaptive subdivision keeps the invariants and the surface", "[geom][molt]") {
    std::mt19937 rng(3);
    const std::size_t nu = 12, nv = 6;  // bidegree (11, 5)
    const auto net = bladeNet(rng, nu, nv);
    std::size_t previous = 0;
    for (double tol : {1e-1, 1e-2, 1e-3}) {
        for (StoppingRule rule : {StoppingRule::LocalFlatness, StoppingRule::MeshRefinement,
                                  StoppingRule::FlatnessOrRefinement, StoppingRule::GlobalError}) {
            SubdivisionStats stats;
            const auto leaves = subdivideAdaptive(net, nu, nv, {rule, tol, 8}, &stats);
            requireTreeInvariants(stats, nu * nv);
            REQUIRE(stats.maxDepth <= 8);
            double area = 0.0;
            for (std::size_t index = 0; index < leaves.size(); ++index) {
                const SubdivisionLeaf& leaf = leaves[index];
                area += (leaf.u1 - leaf.u0) * (leaf.v1 - leaf.v0);
                if (index % 7 != 0) continue;
                // Each leaf is the original patch over its square (the subdivision theorem).
                for (double a : {0.0, 0.4, 1.0})
                    for (double b : {0.0, 0.7, 1.0}) {
                        const double u = leaf.u0 + a * (leaf.u1 - leaf.u0),
                                     v = leaf.v0 + b * (leaf.v1 - leaf.v0);
                        REQUIRE(glm::length(evaluateNet(leaf.net, nu, nv, a, b) -
                                            evaluateNet(net, nu, nv, u, v)) < 1e-12);
                    }
            }
            REQUIRE(area == Approx(1.0).margin(1e-12));
            if (rule == StoppingRule::FlatnessOrRefinement) {
                REQUIRE(stats.leaves >= previous);  // finer tolerance, more leaves
                previous = stats.leaves;
            }
        }
    }
    REQUIRE_THROWS_WITH(subdivideAdaptive(net, 5, 5, {}), Catch::Contains("points"));
    REQUIRE_THROWS_AS(subdivideAdaptive(net, nu, nv, {StoppingRule::LocalFlatness, -1.0, 4}), GeometryError);
}

TEST_CASE("fixed-depth subdivision gives the quadtree's leaves in its order", "[geom][molt]") {
    // The uniform path (u halvings shared by each u interval) against the recursion, which a
    // tolerance no net meets runs down to the same depth cap.
    std::mt19937 rng(4);
    for (const auto& [nu, nv, depth] :
         {std::tuple<std::size_t, std::size_t, int>{4, 4, 2}, {9, 5, 3}, {30, 11, 3}, {7, 2, 4}}) {
        const auto net = bladeNet(rng, nu, nv);
        const auto uniform = subdivideAdaptive(net, nu, nv, {StoppingRule::FixedDepth, 0.0, depth});
        const auto recursive = subdivideAdaptive(net, nu, nv, {StoppingRule::LocalFlatness, 1e-300, depth});
        REQUIRE(uniform.size() == recursive.size());
        for (std::size_t i = 0; i < uniform.size(); ++i) {
            REQUIRE(uniform[i].u0 == recursive[i].u0);
            REQUIRE(uniform[i].v1 == recursive[i].v1);
            REQUIRE(uniform[i].depth == depth);
            for (std::size_t k = 0; k < net.size(); ++k)
                REQUIRE(glm::length(uniform[i].net[k] - recursive[i].net[k]) < 1e-13);
        }
    }
}

}  // namespace test_molt_subdivision
