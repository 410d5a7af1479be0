// Patches joined back into one surface: exact, periodic restored, creases kept, non-grids refused.
#include "ExchangeTestUtil.h"

#include "geom/BezierExtraction.h"
#include "geom/KnotInsertion.h"
#include "geom/Primitives.h"
#include "geom/exchange/OcctConversion.h"
#include "geom/exchange/PatchGrid.h"

#include <random>

namespace test_patch_grid {

using namespace geom::exchange;
using exchange_test::requireSameSurface;

namespace {

std::vector<geom::Surface> patchesOf(const geom::Surface& s) {
    std::vector<geom::Surface> pieces;
    for (auto& p : geom::extractBezier(s)) pieces.push_back(std::move(p.surface));
    return pieces;
}

/// The surface clamped at both ends of v: the ends inserted to multiplicity p, the outer knots
/// and poles dropped (they do not reach into the domain) and the end knots repeated once more.
geom::Surface clampedV(const geom::Surface& s) {
    const std::size_t p = std::size_t(s.degreeV);
    geom::Surface c = geom::insertKnotV(s, s.domainStartV(), int(p) - 1);
    c = geom::insertKnotV(c, s.domainEndV(), int(p) - 1);
    std::vector<double> knots(c.knotsV.begin() + std::ptrdiff_t(p) - 1,
                              c.knotsV.end() - std::ptrdiff_t(p) + 1);
    knots.front() = s.domainStartV();
    knots.back() = s.domainEndV();
    const std::size_t countV = c.countV - 2 * (p - 1);
    std::vector<glm::dvec3> points;
    for (std::size_t i = 0; i < c.countU; ++i)
        for (std::size_t j = p - 1; j < p - 1 + countV; ++j) points.push_back(c.point(i, j));
    return geom::Surface(s.degreeU, s.degreeV, s.knotsU, knots, s.countU, countV, points);
}

}  // namespace

TEST_CASE("patch grid: every transport component comes back from its Bézier patches", "[exchange][grid]") {
    std::mt19937 rng(5);
    for (const auto& c : exchange_test::transport().components) {
        INFO(c.name);
        std::vector<geom::Surface> pieces = patchesOf(c.surface);
        std::shuffle(pieces.begin(), pieces.end(), rng);  // the order does not matter
        const auto joined = joinPatches(pieces, 1e-9);
        REQUIRE(joined);
        requireSameSurface(*joined, c.surface);
        CHECK(periodicByConstruction(*joined, true) == c.closedW);
    }
}

TEST_CASE("patch grid: rational surfaces, kept creases and a clamped periodic surface", "[exchange][grid]") {
    const geom::Surface sphere = geom::makeSphere(2);
    const auto joined = joinPatches(patchesOf(sphere), 1e-9);
    REQUIRE(joined);
    // The sphere's circle knots are C1 (double): they stay, and so does every point.
    requireSameSurface(*joined, sphere);

    // A fuselage clamped at its seam (knot insertion) is made periodic again, poles and all.
    const geom::Surface& fuselage = exchange_test::transport().components[0].surface;
    const auto again = makePeriodic(clampedV(fuselage), true, 1e-9);
    REQUIRE(again);
    requireSameSurface(*again, fuselage);

    // A double knot that is a real C1 crease keeps its multiplicity.
    const geom::Surface& wing = exchange_test::transport().components[1].surface;
    geom::Surface creased = geom::insertKnotU(wing, 0.5, 2);
    creased.point(creased.countU / 2, 3) += glm::dvec3(0, 0, 0.01);
    const auto kept = joinPatches(patchesOf(creased), 1e-9);
    REQUIRE(kept);
    requireSameSurface(*kept, geom::insertKnotU(creased, 0.5, 0));
}

TEST_CASE("patch grid: pieces that do not tile a grid are refused", "[exchange][grid]") {
    const geom::Surface& wing = exchange_test::transport().components[1].surface;
    std::vector<geom::Surface> pieces = patchesOf(wing);
    auto missing = pieces;
    missing.erase(missing.begin() + 7);
    CHECK_FALSE(joinPatches(missing, 1e-9));
    auto doubled = pieces;
    doubled.push_back(pieces[3]);
    CHECK_FALSE(joinPatches(doubled, 1e-9));
    auto torn = pieces;
    torn[4].points[0] += glm::dvec3(1e-6, 0, 0);  // a corner off its neighbours'
    CHECK_FALSE(joinPatches(torn, 1e-9));
    auto mixed = pieces;
    mixed.push_back(geom::makeSphere(1));
    CHECK_FALSE(joinPatches(mixed, 1e-9));
    CHECK_FALSE(joinPatches({}, 1e-9));
    // Two patches side by side but offset by half a patch: not a grid.
    geom::Surface shifted = pieces[0];
    for (double& u : shifted.knotsU) u += 0.5 * (pieces[0].domainEndU() - pieces[0].domainStartU());
    CHECK_FALSE(joinPatches({pieces[0], shifted}, 1e-9));
}

TEST_CASE("patch grid: makePeriodic needs a clamped direction that closes smoothly", "[exchange][grid]") {
    const geom::Surface& wing = exchange_test::transport().components[1].surface;
    CHECK_FALSE(makePeriodic(wing, true, 1e-9));   // closed round the airfoil, with a crease
    CHECK_FALSE(makePeriodic(wing, false, 1e-9));  // open from root to tip
    const geom::Surface& fuselage = exchange_test::transport().components[0].surface;
    CHECK_FALSE(makePeriodic(fuselage, true, 1e-9));  // already unclamped
}

}  // namespace test_patch_grid
