// Patches joined back into one surface: exact, periodic restored, creases kept, non-grids refused.
#include "ExchangeTestUtil.h"

#include "geom/BezierExtraction.h"
#include "geom/KnotInsertion.h"
#include "geom/Primitives.h"
#include "geom/exchange/OcctConversion.h"
#include "geom/exchange/PatchGrid.h"

#include <algorithm>
#include <cmath>
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

/// Random clamped knots of `spans` spans for `degree`: uneven gaps, some interior knots
/// repeated (below the degree, so the surface stays continuous there; up to degree - 1 times).
std::vector<double> randomKnots(std::mt19937& rng, int degree, int spans) {
    std::uniform_real_distribution<double> gap(0.3, 2.0);
    std::vector<double> knots(std::size_t(degree) + 1, 0.0);
    double t = 0;
    for (int k = 1; k < spans; ++k) {
        t += gap(rng);
        const int repeat = degree > 1 && rng() % 4 == 0 ? 2 + int(rng() % std::uint32_t(degree - 1)) : 1;
        knots.insert(knots.end(), std::size_t(std::min(repeat, degree)), t);
    }
    knots.insert(knots.end(), std::size_t(degree) + 1, t + gap(rng));
    return knots;
}

/// A random rational surface of degrees 1-7, weights over 1e-2..1e2, at a scale of 1e-6..1e6
/// and as far from the origin as several times its size.
geom::Surface randomRationalSurface(std::mt19937& rng) {
    const int p = 1 + int(rng() % 7), q = 1 + int(rng() % 7);
    std::vector<double> ku = randomKnots(rng, p, 1 + int(rng() % 3)),
                        kv = randomKnots(rng, q, 1 + int(rng() % 3));
    const std::size_t nu = ku.size() - std::size_t(p) - 1, nv = kv.size() - std::size_t(q) - 1;
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const double scale = std::pow(10.0, 6.0 * unit(rng));
    const glm::dvec3 offset = scale * 5.0 * glm::dvec3(unit(rng), unit(rng), unit(rng));
    std::vector<glm::dvec3> points;
    std::vector<double> weights;
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            points.push_back(offset + scale * glm::dvec3(double(i) + 0.3 * unit(rng),
                                                         double(j) + 0.3 * unit(rng), unit(rng)));
            weights.push_back(std::pow(10.0, 2.0 * unit(rng)));
        }
    return geom::Surface(p, q, ku, kv, nu, nv, points, weights);
}

/// The largest distance between the two nets' poles, and whether knots and weights agree
/// (weights relatively).
void requireSameNet(const geom::Surface& a, const geom::Surface& b, double size) {
    REQUIRE(a.knotsU == b.knotsU);
    REQUIRE(a.knotsV == b.knotsV);
    REQUIRE(a.points.size() == b.points.size());
    for (std::size_t k = 0; k < a.points.size(); ++k) {
        CHECK(glm::length(a.points[k] - b.points[k]) <= 1e-9 * size);
        CHECK(std::abs(a.weight(k / a.countV, k % a.countV) - b.weight(k / b.countV, k % b.countV)) <=
              1e-9 * a.weight(k / a.countV, k % a.countV));
    }
}

}  // namespace

TEST_CASE("patch grid: random rational surfaces at any scale and place come back knot for knot",
          "[exchange][grid]") {
    // The reader's tolerance: 1e-11 of the net's size (CadRead). Knot removal's rational bound
    // divides it by 1 + |P|max and by the smallest weight: far from the origin, or at degree 5-7
    // with weights over 1e-2..1e2, that asked for less than rounding, and the joined surface kept
    // knots the file never had.
    std::mt19937 rng(20261205);
    for (int member = 0; member < 300; ++member) {
        const geom::Surface s = randomRationalSurface(rng);
        double size = 0;
        for (const auto& p : s.points) size = std::max({size, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
        std::vector<geom::Surface> pieces = patchesOf(s);
        std::shuffle(pieces.begin(), pieces.end(), rng);
        const auto joined = joinPatches(pieces, 1e-11 * (1.0 + size));
        INFO("member " << member << ": degrees " << s.degreeU << " x " << s.degreeV << ", size " << size);
        REQUIRE(joined);
        requireSameNet(*joined, s, size);
    }
}

TEST_CASE("patch grid: a periodic surface with as many spans as its degree is made periodic again",
          "[exchange][grid]") {
    for (int degree = 1; degree <= 5; ++degree)
        for (int spans = std::max(2, degree); spans <= degree + 2; ++spans) {
            // Closed in v by construction: the last `degree` poles of each row repeat the first.
            std::vector<double> kv(std::size_t(spans + 2 * degree + 1));
            for (std::size_t k = 0; k < kv.size(); ++k) kv[k] = double(k) - degree;
            const std::size_t nv = std::size_t(spans + degree);
            std::vector<glm::dvec3> points;
            for (int i = 0; i < 2; ++i)
                for (std::size_t j = 0; j < nv; ++j) {
                    const std::size_t jj = j % std::size_t(spans);
                    const double a = 2.0 * 3.14159265358979 * double(jj) / spans;
                    points.push_back({double(i), std::cos(a) + 0.1 * double(jj % 3), std::sin(a)});
                }
            const geom::Surface periodic(1, degree, {0, 0, 1, 1}, kv, 2, nv, points);
            INFO("degree " << degree << ", " << spans << " spans");
            REQUIRE(periodicByConstruction(periodic, true));
            const auto again = makePeriodic(clampedV(periodic), true, 1e-9);
            REQUIRE(again);
            requireSameSurface(*again, periodic, 1e-9);
        }
}

/// A random surface of degree `q` in v, periodic by construction there (uneven knot gaps that
/// repeat with the period, the last q poles of each row the first q), rational with weights over
/// 1e-1..1e1, of degree 1-3 in u.
geom::Surface randomPeriodicSurface(std::mt19937& rng, int q) {
    std::uniform_real_distribution<double> gap(0.5, 1.5), unit(-1.0, 1.0);
    const int spans = std::max(2, q) + int(rng() % 3), p = 1 + int(rng() % 3);
    std::vector<double> gaps(std::size_t(spans), 0.0);
    for (double& g : gaps) g = gap(rng);
    std::vector<double> kv{0.0};
    for (int k = 0; k < spans + q; ++k) kv.push_back(kv.back() + gaps[std::size_t(k % spans)]);
    for (int k = 0; k < q; ++k) kv.insert(kv.begin(), kv.front() - gaps[std::size_t(spans - 1 - k % spans)]);
    const std::size_t nv = std::size_t(spans + q), nu = std::size_t(p) + 1 + rng() % 2;
    std::vector<double> ku(std::size_t(p) + 1, 0.0);
    for (std::size_t i = 1; i + std::size_t(p) < nu; ++i) ku.push_back(double(i));
    ku.insert(ku.end(), std::size_t(p) + 1, double(nu - std::size_t(p)));
    std::vector<glm::dvec3> points(nu * nv);
    std::vector<double> weights(nu * nv);
    for (std::size_t i = 0; i < nu; ++i)
        for (std::size_t j = 0; j < nv; ++j) {
            const std::size_t k = i * nv + j;
            if (j >= std::size_t(spans)) {
                points[k] = points[k - std::size_t(spans)], weights[k] = weights[k - std::size_t(spans)];
                continue;
            }
            const double a = 2.0 * 3.14159265358979 * double(j) / spans;
            points[k] = {double(i), std::cos(a) + 0.2 * unit(rng), std::sin(a) + 0.2 * unit(rng)};
            weights[k] = std::pow(10.0, unit(rng));
        }
    return geom::Surface(p, q, ku, kv, nu, nv, points, weights);
}

TEST_CASE("patch grid: random periodic rational surfaces of degree 1-7 are made periodic again",
          "[exchange][grid]") {
    // Unclamping at degree 6 and 7 loses digits: the two copies of the first poles differed by up
    // to 1e-9 of the size, and a check on them refused about a third of those surfaces.
    std::mt19937 rng(4242);
    for (int member = 0; member < 140; ++member) {
        const int q = 1 + member % 7;
        const geom::Surface s = randomPeriodicSurface(rng, q);
        REQUIRE(periodicByConstruction(s, true));
        std::vector<geom::Surface> pieces = patchesOf(s);
        std::shuffle(pieces.begin(), pieces.end(), rng);
        const auto joined = joinPatches(pieces, 1e-11 * 3.0);
        INFO("member " << member << ": degree " << q << " in v, " << s.countV - std::size_t(q) << " spans");
        REQUIRE(joined);
        CHECK(periodicByConstruction(*joined, true));
        requireSameSurface(*joined, s, 1e-9);
    }
}

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
