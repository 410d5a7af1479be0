// Iso-parametric curves of a surface (SET PARAMETRIC SURFACE CHARACTERISTICS, style 3): over
// random surfaces and counts, each curve runs along a row or column of the tessellation grid,
// no row is drawn twice, a count below the rows gives that many curves, and a count beyond them
// (up to INT_MAX, accepted at insert) gives every row once, in bounded time and memory; uniform
// placement spaces the curves evenly in parameter, non-uniform puts one at each knot and the
// count evenly inside each knot span.

#include "RandomElements.h"

#include "phigs/Phigs.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <vector>

namespace test_iso_curves {

using namespace phigs;

namespace {

/// The mesh of one surface drawn with these characteristics (and approximation criteria, when
/// given) on its own workstation.
std::shared_ptr<const MeshData> meshOf(const geom::Surface& surface,
                                       const SurfaceCharacteristicsAttribute& characteristics,
                                       std::optional<ApproximationAttribute> approximation = std::nullopt) {
    Phigs phigs;
    phigs.open();
    StructureStore& store = phigs.store();
    store.openStructure(1);
    if (approximation) store.insert(*approximation);
    store.insert(characteristics);
    store.insert(NurbsSurfaceElement{surface, {}});
    store.closeStructure();
    Workstation& ws = phigs.openWorkstation(1, WorkstationType::Window);
    ws.postStructure(1, 0.5);
    const DrawList& list = ws.display();
    REQUIRE(list.items.size() == 1);
    const auto* mesh = primitiveIf<DrawMesh>(list.items[0].primitive);
    REQUIRE(mesh);
    REQUIRE(mesh->mesh);
    return mesh->mesh;
}

/// The iso-lines (grid index lists) of one surface drawn with `curvesU` iso-curves of constant u
/// and none of constant v, and the number of grid positions.
std::vector<std::vector<std::uint32_t>> isoLinesOf(const geom::Surface& surface, int curvesU,
                                                   std::size_t& positions) {
    const auto mesh = meshOf(surface, SurfaceCharacteristicsAttribute{3, 0, curvesU, 0});
    positions = mesh->positions.size();
    return {mesh->isoLines.begin(), mesh->isoLines.end()};
}

}  // namespace

TEST_CASE("iso-curves: one per row at most, every row once for any larger count",
          "[traverse][iso][bad-input]") {
    std::mt19937 rng(31);
    for (int trial = 0; trial < 40; ++trial) {
        const geom::Surface surface = phigs::testing::randomSurface(rng);
        // Every curve of constant u runs along the grid's other direction: nv positions; the
        // untrimmed grid is nu x nv.
        std::size_t positions = 0;
        const auto every = isoLinesOf(surface, INT_MAX, positions);
        REQUIRE_FALSE(every.empty());
        const std::size_t nv = every.front().size(), nu = positions / nv;
        INFO("trial " << trial << ": grid " << nu << " x " << nv);
        REQUIRE(nu * nv == positions);
        CHECK(every.size() == nu);
        for (int count :
             {0, 1, 2, 3, int(nu) - 2, int(nu) - 1, int(nu), int(2 * nu), int(2 * nu) + 1, 100000}) {
            if (count < 0) continue;
            const auto lines = isoLinesOf(surface, count, positions);
            INFO("count " << count);
            const std::set<std::vector<std::uint32_t>> distinct(lines.begin(), lines.end());
            CHECK(distinct.size() == lines.size());  // no row twice
            for (const auto& line : lines) CHECK(line.size() == nv);
            // Curves at least a row apart are all distinct rows; no more rows can be drawn than
            // there are, and from 2 x rows on every row is.
            if (count <= int(nu) - 2) CHECK(lines.size() == std::size_t(count));
            CHECK(lines.size() <= nu);
            if (count >= int(2 * nu)) CHECK(lines.size() == nu);
        }
    }
}

TEST_CASE("iso-curves: uniform placement evenly in parameter, non-uniform at and between the knots",
          "[traverse][iso]") {
    // Degree 1 in u with knots 0, 0.2, 0.3, 1 and x = u on the surface: a line of constant u
    // lies at x = u. 20 grid steps per span: rows 0.01, 0.005 and 0.035 apart.
    const std::vector<double> knotsU{0, 0, 0.2, 0.3, 1, 1}, knotsV{0, 0, 1, 1};
    std::vector<glm::dvec3> points;
    for (double x : {0.0, 0.2, 0.3, 1.0})
        for (double y : {0.0, 1.0}) points.push_back({x, y, 0.0});
    const geom::Surface surface(1, 1, knotsU, knotsV, 4, 2, points);
    auto curvesAt = [&](int placement, int count) {
        const auto mesh =
            meshOf(surface, SurfaceCharacteristicsAttribute{3, placement, count, 0},
                   ApproximationAttribute{ElementType::SurfaceApproximationCriteria, 2, 20, 20});
        std::vector<double> xs;
        for (const auto& line : mesh->isoLines) xs.push_back(mesh->positions.at(line.front()).x);
        std::sort(xs.begin(), xs.end());
        return xs;
    };
    auto near = [](const std::vector<double>& got, const std::vector<double>& want) {
        if (got.size() != want.size()) return false;
        for (std::size_t i = 0; i < got.size(); ++i)
            if (std::abs(got[i] - want[i]) > 0.0176) return false;
        return true;
    };
    CHECK(near(curvesAt(0, 3), {0.25, 0.5, 0.75}));
    CHECK(near(curvesAt(1, 0), {0.2, 0.3}));
    CHECK(near(curvesAt(1, 1), {0.1, 0.2, 0.25, 0.3, 0.65}));
    CHECK(near(curvesAt(1, 3), {0.05, 0.1, 0.15, 0.2, 0.225, 0.25, 0.275, 0.3, 0.475, 0.65, 0.825}));
}

TEST_CASE("iso-curves: many spans and few rows each still get theirs, up to the last span",
          "[traverse][iso]") {
    // 20 spans of degree 1, one grid step each (21 rows at the knots): non-uniform placement with
    // 3 per span asks for 79 parameters, each landing on a knot row: all 21 rows are drawn.
    std::vector<double> knotsU{0};
    std::vector<glm::dvec3> points;
    for (int i = 0; i <= 20; ++i) {
        knotsU.push_back(i / 20.0);
        for (double y : {0.0, 1.0}) points.push_back({i / 20.0, y, 0.0});
    }
    knotsU.push_back(1.0);
    const geom::Surface surface(1, 1, knotsU, {0, 0, 1, 1}, 21, 2, points);
    const auto mesh = meshOf(surface, SurfaceCharacteristicsAttribute{3, 1, 3, 0},
                             ApproximationAttribute{ElementType::SurfaceApproximationCriteria, 2, 1, 1});
    std::set<long> rows;
    for (const auto& line : mesh->isoLines)
        rows.insert(std::lround(20.0 * mesh->positions.at(line.front()).x));
    CHECK(rows.size() == 21);
    CHECK(mesh->isoLines.size() == 21);
}

}  // namespace test_iso_curves
